/* fulgur run's command line. */
#include <stdlib.h>
#include <string.h>

#include "run.h"

const char run_usage[] =
    "usage: fulgur run SCENE.json [--audio null|wav:FILE|raw:-] [--block 64|128|256|512]\n"
    "                  [--rate 44100|48000|96000] [--seconds S] [--report FILE]\n"
    "                  [--voices N] [--frame-rate HZ]\n"
    "Runs the scene as a VR application would: a frame thread moves the listener at\n"
    "--frame-rate (90 Hz), a sim thread builds and posts each discharge at its time,\n"
    "an audio thread pulls blocks through a driver:\n"
    "  null     a clock-paced device: one block per block period, in real time (default)\n"
    "  wav:FILE 32-bit float WAV, as fast as possible, deterministic\n"
    "  raw:-    interleaved float32 to stdout, deterministic:\n"
    "           fulgur run SCENE --audio raw:- | aplay -f FLOAT_LE -c2 -r48000\n"
    "Block and rate default to the scene's; --seconds to the scene's duration, else\n"
    "until every discharge has sounded. --voices sizes the engine's pool (64).\n"
    "Prints a JSON report (timing, post-to-adoption latency, late events) to stdout,\n"
    "to stderr with raw:-, or to --report FILE.\n"
    "Exit: 0 done, 1 runtime error, 2 bad arguments or scene (a generator's error is\n"
    "found when the sim thread builds that discharge: no report, no WAV).\n";

/* One of allowed[0..count), or with count 0 any of 1..4096. */
static int parse_u32(const char *text, const uint32_t *allowed, size_t count, uint32_t *out)
{
    char *end;
    unsigned long v = strtoul(text, &end, 10);
    bool ok = !*end && end != text && (count == 0 && v >= 1 && v <= 4096);
    for (size_t i = 0; i < count; i++)
        ok |= !*end && end != text && v == allowed[i];
    if (ok)
        *out = (uint32_t)v;
    return ok ? 0 : -1;
}

/* A number in (0, hi]. */
static int parse_positive(const char *text, double hi, double *out)
{
    char *end;
    double v = strtod(text, &end);
    if (*end || end == text || !(v > 0) || !(v <= hi))
        return -1;
    *out = v;
    return 0;
}

int run_parse_options(int argc, char **argv, run_options *o)
{
    static const uint32_t blocks[] = {64, 128, 256, 512};
    static const uint32_t rates[] = {44100, 48000, 96000};
    *o = (run_options){.audio = AUDIO_DRIVER_NULL, .frame_hz = 90};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        uint32_t rate = 0;
        int bad = 0;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0)
            return 1;
        if (a[0] != '-') {
            bad = o->scene_path != NULL;
            o->scene_path = a;
            if (!bad)
                continue;
        } else if (!v) {
            bad = 1;
        } else if (strcmp(a, "--audio") == 0) {
            bad = audio_driver_parse(v, &o->audio, &o->wav_path);
        } else if (strcmp(a, "--block") == 0) {
            bad = parse_u32(v, blocks, 4, &o->block_frames);
        } else if (strcmp(a, "--rate") == 0) {
            bad = parse_u32(v, rates, 3, &rate);
            o->rate_hz = rate;
        } else if (strcmp(a, "--seconds") == 0) {
            bad = parse_positive(v, SCENE_MAX_DURATION_S, &o->seconds);
        } else if (strcmp(a, "--frame-rate") == 0) {
            bad = parse_positive(v, 1000, &o->frame_hz);
        } else if (strcmp(a, "--voices") == 0) {
            bad = parse_u32(v, NULL, 0, &o->voices);
        } else if (strcmp(a, "--report") == 0) {
            o->report_path = v;
        } else {
            bad = 1;
        }
        if (bad) {
            fprintf(stderr, "fulgur run: bad argument \"%s%s%s\"\n%s", a, v ? " " : "",
                    v ? v : "", run_usage);
            return -1;
        }
        i++;
    }
    if (!o->scene_path) {
        fputs(run_usage, stderr);
        return -1;
    }
    return 0;
}
