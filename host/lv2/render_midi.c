/* fulgur-lv2-render: a MIDI file through fulgur.lv2, offline, into a WAV.
 * The plugin is loaded by liblilv as any host loads it (LV2_PATH, else
 * ~/.lv2 and the system's lib/lv2) and driven block by block; its worker
 * runs between blocks, as LV2 allows an offline host to. */
#include <errno.h>
#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/temp_file.h"
#include "lilv_host.h"
#include "smf.h"

#define BLOCK 256

static const char usage[] =
    "usage: fulgur-lv2-render IN.mid -o OUT.wav [-r RATE_HZ] [-t TAIL_S] [SYMBOL=VALUE]...\n"
    "Plays IN.mid through fulgur.lv2 and writes a stereo 32-bit float WAV, until TAIL_S\n"
    "(default 5) after the last MIDI event. SYMBOL=VALUE sets a control port, e.g.\n"
    "preset=2 distance=3000 gain=-50 (see fulgur.ttl). RATE_HZ defaults to 48000.\n"
    "Exit: 0 done, 1 runtime error, 2 bad arguments or MIDI file.\n";

typedef struct options {
    const char *in, *out;
    double rate_hz, tail_s;
    const char *controls[64];
    size_t control_count;
} options;

static int parse_number(const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !(v >= lo && v <= hi))
        return -1;
    *out = v;
    return 0;
}

static int parse_args(int argc, char **argv, options *o)
{
    *o = (options){.rate_hz = 48000, .tail_s = 5};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int has_value = i + 1 < argc;
        if (!strcmp(a, "-o") && has_value) {
            o->out = argv[++i];
        } else if (!strcmp(a, "-r") && has_value) {
            if (parse_number(argv[++i], 8000, 384000, &o->rate_hz))
                return fprintf(stderr, "fulgur-lv2-render: -r: a rate in 8000..384000 Hz\n"), -1;
        } else if (!strcmp(a, "-t") && has_value) {
            if (parse_number(argv[++i], 0, 3600, &o->tail_s))
                return fprintf(stderr, "fulgur-lv2-render: -t: seconds in 0..3600\n"), -1;
        } else if (strchr(a, '=') && a[0] != '-') {
            if (o->control_count == sizeof o->controls / sizeof o->controls[0])
                return fprintf(stderr, "fulgur-lv2-render: too many controls\n"), -1;
            o->controls[o->control_count++] = a;
        } else if (!o->in && a[0] != '-') {
            o->in = a;
        } else {
            return fprintf(stderr, "fulgur-lv2-render: unexpected argument '%s'\n%s", a, usage), -1;
        }
    }
    if (!o->in || !o->out)
        return fprintf(stderr, "%s", usage), -1;
    return 0;
}

static int set_controls(lv2_host *h, const options *o)
{
    for (size_t i = 0; i < o->control_count; i++) {
        char name[64];
        const char *eq = strchr(o->controls[i], '=');
        size_t len = (size_t)(eq - o->controls[i]);
        double v;
        if (len >= sizeof name || parse_number(eq + 1, -1e9, 1e9, &v)) {
            fprintf(stderr, "fulgur-lv2-render: '%s': expected SYMBOL=NUMBER\n", o->controls[i]);
            return -1;
        }
        memcpy(name, o->controls[i], len);
        name[len] = 0;
        if (lv2_host_set(h, name, (float)v) != 0) {
            fprintf(stderr, "fulgur-lv2-render: the plugin has no control '%s'\n", name);
            return -1;
        }
    }
    return 0;
}

/* Plays the events block by block into wav. */
static int render(lv2_host *h, const smf_event *ev, size_t count, double rate_hz, double tail_s,
                  SNDFILE *wav)
{
    double end_s = (count ? ev[count - 1].time_s : 0) + tail_s;
    uint64_t frames = (uint64_t)ceil(end_s * rate_hz), next = 0;
    float left[BLOCK], right[BLOCK], frame[2 * BLOCK];
    for (uint64_t start = 0; start < frames; start += BLOCK) {
        uint32_t n = frames - start < BLOCK ? (uint32_t)(frames - start) : BLOCK;
        for (; next < count && (uint64_t)(ev[next].time_s * rate_hz) < start + n; next++) {
            uint64_t at = (uint64_t)(ev[next].time_s * rate_hz);
            if (lv2_host_midi(h, (uint32_t)(at - start), ev[next].status, ev[next].data1,
                              ev[next].data2) != 0) {
                fprintf(stderr, "fulgur-lv2-render: more MIDI in one %d-frame block than the "
                                "plugin's input holds, at %.3f s\n", BLOCK, ev[next].time_s);
                return -1;
            }
        }
        lv2_host_run(h, n, left, right);
        lv2_host_work(h);
        for (uint32_t i = 0; i < n; i++) {
            frame[2 * i] = left[i];
            frame[2 * i + 1] = right[i];
        }
        if (sf_writef_float(wav, frame, n) != n) {
            fprintf(stderr, "fulgur-lv2-render: writing: %s\n", sf_strerror(wav));
            return -1;
        }
    }
    float failures = lv2_host_get(h, "failures");
    printf("%.3f s, %.0f discharges", (double)frames / rate_hz, lv2_host_get(h, "discharges"));
    if (failures > 0)
        printf(", %.0f notes failed (voice pool full or a tree that did not grow)", failures);
    printf("\n");
    return 0;
}

int main(int argc, char **argv)
{
    options o;
    if (parse_args(argc, argv, &o))
        return 2;
    char err[512];
    smf_event *events;
    size_t count;
    if (smf_read(o.in, &events, &count, err, sizeof err)) {
        fprintf(stderr, "fulgur-lv2-render: %s\n", err);
        return 2;
    }
    lv2_host *h = lv2_host_create(o.rate_hz);
    if (!h || set_controls(h, &o)) {
        lv2_host_destroy(h);
        free(events);
        return h ? 2 : 1;
    }
    temp_file out;
    if (temp_file_open(&out, o.out, err, sizeof err)) {
        fprintf(stderr, "fulgur-lv2-render: %s\n", err);
        lv2_host_destroy(h);
        free(events);
        return 1;
    }
    SF_INFO info = {.samplerate = (int)o.rate_hz, .channels = 2,
                    .format = SF_FORMAT_WAV | SF_FORMAT_FLOAT};
    SNDFILE *wav = sf_open_fd(out.fd, SFM_WRITE, &info, SF_FALSE);
    int ok = wav && render(h, events, count, o.rate_hz, o.tail_s, wav) == 0;
    if (!wav)
        fprintf(stderr, "fulgur-lv2-render: %s: %s\n", o.out, sf_strerror(NULL));
    if (wav && sf_close(wav) != 0 && ok) {
        fprintf(stderr, "fulgur-lv2-render: %s: closing the WAV failed\n", o.out);
        ok = 0;
    }
    if (ok && temp_file_commit(&out, err, sizeof err)) {
        fprintf(stderr, "fulgur-lv2-render: %s\n", err);
        ok = 0;
    } else if (!ok) {
        temp_file_abort(&out);
    }
    lv2_host_destroy(h);
    free(events);
    return ok ? 0 : 1;
}
