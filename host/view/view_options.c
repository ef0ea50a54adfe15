/* fulgur view's command line. */
#include <stdlib.h>
#include <string.h>

#include "view.h"

const char view_usage[] =
    "usage: fulgur view SCENE.json [--gl window|egl|osmesa] [--audio null|wav:FILE|raw:-]\n"
    "                   [--frames N] [--fps HZ] [--size WxH] [--png-dir DIR] [--script FILE]\n"
    "Shows the scene's discharges as gpu/ draws them and sounds them through the engine.\n"
    "Controls (docs/viewer.md): left click a positive charge, right click (or shift-click)\n"
    "a negative one, C clears them; space discharges (between the charges, else the\n"
    "scene's first discharge); H holds a continuous discharge until H again; drag with\n"
    "the middle button (or alt) to orbit, scroll to zoom, Esc to quit.\n"
    "  --gl       window (default) needs a display; egl and osmesa run headless, lock-step,\n"
    "             for --frames N frames (required), drawn at frame / fps seconds\n"
    "  --audio    as fulgur run: null (default), a 32-bit float WAV, or raw float32 on stdout\n"
    "  --png-dir  headless: write DIR/frame_0000.png, frame_0001.png, ...\n"
    "  --script   input events by frame: \"frame 3 key space\", \"frame 5 click 0.4 0.5 left\",\n"
    "             \"frame 6 key h\", \"frame 7 drag 0.1 0\", \"frame 8 scroll 2\"\n"
    "Prints a JSON summary (frames, discharges posted, late events) at the end, to stderr\n"
    "with raw:-. Exit: 0 done, 1 runtime error (no display, GL), 2 bad arguments or scene.\n";

static int parse_count(const char *text, double lo, double hi, double *out)
{
    char *end;
    double v = strtod(text, &end);
    if (*end || end == text || !(v >= lo && v <= hi))
        return -1;
    *out = v;
    return 0;
}

static int parse_size(const char *text, view_options *o)
{
    char *end;
    long w = strtol(text, &end, 10);
    if (*end != 'x')
        return -1;
    long h = strtol(end + 1, &end, 10);
    if (*end || w < 16 || h < 16 || w > 8192 || h > 8192)
        return -1;
    o->width = (int)w, o->height = (int)h;
    return 0;
}

int view_parse_options(int argc, char **argv, view_options *o)
{
    *o = (view_options){.backend = FGG_BACKEND_WINDOW, .audio = AUDIO_DRIVER_NULL, .fps = 60,
                        .width = 960, .height = 540};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        double x = 0;
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
        } else if (strcmp(a, "--gl") == 0) {
            if (fgg_backend_from_name(v, &o->backend) != FG_OK) {
                fprintf(stderr, "fulgur view: --gl %s: %s\n", v, fgg_error_message());
                return -1;
            }
        } else if (strcmp(a, "--audio") == 0) {
            bad = audio_driver_parse(v, &o->audio, &o->wav_path);
        } else if (strcmp(a, "--frames") == 0) {
            bad = parse_count(v, 1, 1e7, &x);
            o->frames = (uint32_t)x;
            bad |= x != (double)o->frames;
        } else if (strcmp(a, "--fps") == 0) {
            bad = parse_count(v, 1, 1000, &o->fps);
        } else if (strcmp(a, "--size") == 0) {
            bad = parse_size(v, o);
        } else if (strcmp(a, "--png-dir") == 0) {
            o->png_dir = v;
        } else if (strcmp(a, "--script") == 0) {
            o->script_path = v;
        } else {
            bad = 1;
        }
        if (bad) {
            fprintf(stderr, "fulgur view: bad argument \"%s%s%s\"\n%s", a, v ? " " : "",
                    v ? v : "", view_usage);
            return -1;
        }
        i++;
    }
    if (!o->scene_path) {
        fputs(view_usage, stderr);
        return -1;
    }
    if (o->backend != FGG_BACKEND_WINDOW && o->frames == 0) {
        fprintf(stderr, "fulgur view: --gl %s runs headless: give --frames N\n",
                fgg_backend_name(o->backend));
        return -1;
    }
    return 0;
}
