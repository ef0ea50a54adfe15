/* fulgur-lv2-render: a MIDI file through fulgur.lv2, offline, into a WAV.
 * The plugin is loaded by liblilv as any host loads it (LV2_PATH, else
 * ~/.lv2 and the system's lib/lv2) and driven block by block; its worker
 * runs between blocks, as LV2 allows an offline host to. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/audio_file.h"
#include "common/options.h"
#include "common/sofa_hrir.h"
#include "common/temp_file.h"
#include "lilv_host.h"
#include "scene/scene.h"
#include "smf.h"

#define BLOCK 256
/* The latest MIDI event a render plays, as a scene's longest duration; the
 * tail (-t) adds at most as much again. */
#define RENDER_MAX_EVENT_S 3600.0

static const char about[] =
    "Plays IN.mid through fulgur.lv2 and writes a 32-bit float WAV of the plugin's\n"
    "outputs: 2 (stereo, binaural) or 4, 9, 16 (ambisonics, ACN order, SN3D). SYMBOL=VALUE\n"
    "sets a control port, e.g. preset=2 distance=3000 gain=-50 (see fulgur.ttl).\n";

static const char notes[] = "Exit: 0 done, 1 runtime error, 2 bad arguments or MIDI file.\n";

#define MAX_CONTROLS 64

typedef struct options {
    const char *in, *out;
    scene_layout_choice layout; /* the plugin played */
    const char *sofa;
    double rate_hz, tail_s;
    const char *controls[MAX_CONTROLS];
    size_t control_count;
} options;

/* The operands: IN.mid, and the SYMBOL=VALUE controls in any place. */
static int parse_args(int argc, char **argv, options *o)
{
    *o = (options){.rate_hz = 48000, .tail_s = 5};
    const option table[] = {
        {"-o", OPTION_TEXT, &o->out, "OUT.wav", .help = "the WAV to write", .required = true},
        {"-r", OPTION_NUMBER, &o->rate_hz, "RATE_HZ", .help = "the sample rate (default 48000)",
         .range = {.lo = 8000, .hi = 384000}},
        {"-t", OPTION_NUMBER, &o->tail_s, "TAIL_S",
         .help = "seconds rendered after the last MIDI event (default 5)",
         .range = {.lo = 0, .hi = 3600}},
        {"--layout", OPTION_PARSED, &o->layout, "LAYOUT", .parse = scene_layout_option,
         .help = "the plugin played: stereo (default), binaural or\n"
                 "ambisonics:ORDER (1..3: 4, 9 or 16 channels)"},
        {"--sofa", OPTION_TEXT, &o->sofa, "FILE",
         .help = "the binaural plugin's SOFA file, set through its parameter\n"
                 "(default " SOFA_DEFAULT_FILE ")"},
        {0},
    };
    const command_line cl = {"fulgur-lv2-render", "IN.mid [SYMBOL=VALUE]...", 1,
                             MAX_CONTROLS + 1, about, notes, table};
    const char *operands[MAX_CONTROLS + 1];
    size_t count;
    options_result r = options_parse(&cl, argc, argv, operands, &count);
    if (r != OPTIONS_OK)
        return r == OPTIONS_HELP ? 1 : -1;
    for (size_t i = 0; i < count; i++) {
        if (strchr(operands[i], '=') && o->control_count == MAX_CONTROLS)
            return options_fail(&cl, "more than %d controls", MAX_CONTROLS), -1;
        if (strchr(operands[i], '='))
            o->controls[o->control_count++] = operands[i];
        else if (!o->in)
            o->in = operands[i];
        else
            return options_fail(&cl, "unexpected argument \"%s\"", operands[i]), -1;
    }
    if (!o->in)
        return options_fail(&cl, "give IN.mid"), -1;
    if (o->sofa && o->layout.layout.layout != FG_LAYOUT_BINAURAL)
        return options_fail(&cl, "--sofa %s: only with --layout binaural", o->sofa), -1;
    return 0;
}

/* The plugin of the layout asked for. */
static lv2_host *open_plugin(const options *o)
{
    char uri[256];
    scene_layout l = o->layout.layout;
    snprintf(uri, sizeof uri, "%s%s", FULGUR_LV2_URI,
             l.layout == FG_LAYOUT_BINAURAL ? "-binaural" : "");
    if (l.layout == FG_LAYOUT_AMBISONICS)
        snprintf(uri, sizeof uri, "%s-ambisonics%u", FULGUR_LV2_URI, l.order);
    return lv2_host_create_plugin(uri, o->rate_hz);
}

/* --sofa through the plugin's parameter, before the first frame: the
 * worker reads it between two runs of no frames. Returns 0, or -1 when the
 * plugin refused the file (its message is on stderr, from its log). */
static int set_sofa(lv2_host *h, const char *sofa)
{
    if (!sofa)
        return 0;
    if (lv2_host_set_path(h, FULGUR_LV2_URI "#sofa", sofa) != 0) {
        fprintf(stderr, "fulgur-lv2-render: --sofa %s: a path too long\n", sofa);
        return -1;
    }
    static float none[1];
    float *planes[LV2_HOST_CHANNELS_MAX];
    for (unsigned k = 0; k < LV2_HOST_CHANNELS_MAX; k++)
        planes[k] = none;
    lv2_host_run_planes(h, 0, planes);
    lv2_host_work(h);
    lv2_host_run_planes(h, 0, planes);
    if (strcmp(lv2_host_notified_path(h), sofa) != 0) {
        fprintf(stderr, "fulgur-lv2-render: --sofa %s: the plugin refused it\n", sofa);
        return -1;
    }
    return 0;
}

static int set_controls(lv2_host *h, const options *o)
{
    for (size_t i = 0; i < o->control_count; i++) {
        char name[64];
        const char *eq = strchr(o->controls[i], '=');
        size_t len = (size_t)(eq - o->controls[i]);
        double v;
        if (len >= sizeof name || option_number(eq + 1, (number_range){.lo = -1e9, .hi = 1e9}, &v) != 0) {
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

/* The frames rendered: up to the last event (events are in time order),
 * then the tail. */
static uint64_t render_frames(const smf_event *ev, size_t count, double rate_hz, double tail_s)
{
    double end_s = (count ? ev[count - 1].time_s : 0) + tail_s;
    return (uint64_t)ceil(end_s * rate_hz);
}

/* The frames the plugin's output lags its notes, from its latency output
 * (lv2:reportsLatency), which it writes in its first run; 0 without one,
 * or for one over a second (no plugin of fulgur.lv2 lags that much). */
static uint64_t plugin_latency(const lv2_host *h, double rate_hz)
{
    float latency = lv2_host_get(h, "latency");
    return latency > 0 && latency <= rate_hz ? (uint64_t)latency : 0;
}

/* Plays the events block by block into wav, as a host compensating the
 * plugin's latency does: the first latency frames of its output are not
 * written and as many more are rendered after the last, so that the WAV's
 * frames stand where the notes are. */
static int render(lv2_host *h, const smf_event *ev, size_t count, double rate_hz, double tail_s,
                  audio_wav *wav)
{
    uint64_t frames = render_frames(ev, count, rate_hz, tail_s), next = 0;
    uint64_t latency = 0, end = frames;
    unsigned channels = lv2_host_channels(h);
    static float plane[LV2_HOST_CHANNELS_MAX][BLOCK], frame[LV2_HOST_CHANNELS_MAX * BLOCK];
    float *planes[LV2_HOST_CHANNELS_MAX], *kept[LV2_HOST_CHANNELS_MAX];
    for (unsigned k = 0; k < channels; k++)
        planes[k] = plane[k];
    for (uint64_t start = 0, n; start < end; start += n) {
        n = end - start < BLOCK ? end - start : BLOCK;
        for (; next < count && (uint64_t)(ev[next].time_s * rate_hz) < start + n; next++) {
            uint64_t at = (uint64_t)(ev[next].time_s * rate_hz);
            if (lv2_host_midi(h, (uint32_t)(at - start), ev[next].status, ev[next].data1,
                              ev[next].data2) != 0) {
                fprintf(stderr, "fulgur-lv2-render: more MIDI in one %d-frame block than the "
                                "plugin's input holds, at %.3f s\n", BLOCK, ev[next].time_s);
                return -1;
            }
        }
        lv2_host_run_planes(h, (uint32_t)n, planes);
        lv2_host_work(h);
        if (start == 0) {
            latency = plugin_latency(h, rate_hz);
            end = frames + latency;
        }
        uint64_t skip = start < latency ? (latency - start < n ? latency - start : n) : 0;
        if (skip == n)
            continue;
        for (unsigned k = 0; k < channels; k++)
            kept[k] = planes[k] + skip;
        audio_interleave(kept, channels, (uint32_t)(n - skip), 1, frame);
        char err[256];
        if (audio_wav_write(wav, frame, (uint32_t)(n - skip), err, sizeof err) != 0) {
            fprintf(stderr, "fulgur-lv2-render: %s\n", err);
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
    int parsed = parse_args(argc, argv, &o);
    if (parsed != 0)
        return parsed > 0 ? 0 : 2;
    char err[512];
    if (temp_file_check_output(o.out, o.in, err, sizeof err)) {
        fprintf(stderr, "fulgur-lv2-render: %s\n", err);
        return 2;
    }
    smf_event *events;
    size_t count;
    if (smf_read(o.in, &events, &count, err, sizeof err)) {
        fprintf(stderr, "fulgur-lv2-render: %s\n", err);
        return 2;
    }
    /* a few bytes of MIDI (a slow tempo, a long delta) can name any time */
    if (count && events[count - 1].time_s > RENDER_MAX_EVENT_S) {
        fprintf(stderr,
                "fulgur-lv2-render: %s: an event at %.6g s, after the %.0f s a render may "
                "reach\n",
                o.in, events[count - 1].time_s, RENDER_MAX_EVENT_S);
        free(events);
        return 2;
    }
    lv2_host *h = open_plugin(&o);
    if (!h || set_controls(h, &o) || set_sofa(h, o.sofa)) {
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
    audio_wav *wav = audio_wav_open(out.fd, o.out, o.rate_hz, lv2_host_channels(h),
                                    render_frames(events, count, o.rate_hz, o.tail_s), err,
                                    sizeof err);
    int ok = wav && render(h, events, count, o.rate_hz, o.tail_s, wav) == 0;
    if (!wav)
        fprintf(stderr, "fulgur-lv2-render: %s\n", err);
    if (wav && audio_wav_close(wav) != 0 && ok) {
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
