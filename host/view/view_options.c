/* fulgur view's command line: its option table. */
#include <stdio.h>
#include <stdlib.h>

#include "view.h"

static const char about[] =
    "Shows the scene's discharges as gpu/ draws them and sounds them through the engine.\n"
    "Controls (docs/viewer.md): left click a positive charge, right click (or shift-click)\n"
    "a negative one, C clears them; space discharges (between the charges, else the\n"
    "scene's first discharge); H holds a continuous discharge until H again; drag with\n"
    "the middle button (or alt) to orbit, scroll to zoom, Esc to quit.\n";

static const char notes[] =
    "Prints a JSON report (frames, discharges posted, late events) at the end, to stderr\n"
    "with raw:-. Exit: 0 done, 1 runtime error (no display, GL), 2 bad arguments or scene.\n";

static int parse_backend(const char *text, void *backend, char *why, size_t why_size)
{
    if (fgg_backend_from_name(text, backend) == FG_OK)
        return 0;
    snprintf(why, why_size, "%s", fgg_error_message());
    return -1;
}

options_result view_parse_options(int argc, char **argv, view_options *o)
{
    *o = (view_options){.backend = FGG_BACKEND_WINDOW, .audio = {AUDIO_DRIVER_AUTO, NULL},
                        .fps = 60, .size = {960, 540}};
    const option table[] = {
        {"--gl", OPTION_PARSED, &o->backend, "window|egl|osmesa",
         .help = "window (the default) needs a display; egl and osmesa run\n"
                 "headless, lock-step, for --frames N frames, drawn at frame / fps\n"
                 "seconds",
         .parse = parse_backend},
        audio_output_option(&o->audio, "as fulgur run: null, a 32-bit float WAV, raw\n"
                                       "float32 on stdout, or a live device. Default: in a\n"
                                       "window, a running JACK server, else PortAudio's\n"
                                       "default output, else none; headless, none"),
        {"--frames", OPTION_INTEGER, &o->frames, "N",
         .help = "frames to draw (default: until Esc; headless: required)",
         .range = {.lo = 1, .hi = 1e7}},
        {"--fps", OPTION_NUMBER, &o->fps, "HZ", .help = "frames per second (default 60)",
         .range = {.lo = 1, .hi = 1000}},
        {"--size", OPTION_PARSED, &o->size, "WxH",
         .help = "the window and its picture in pixels (default 960x540)",
         .parse = option_parse_size},
        {"--png-dir", OPTION_TEXT, &o->png_dir, "DIR",
         .help = "headless: write DIR/frame_0000.png, frame_0001.png, ..."},
        SCENE_LAYOUT_OPTIONS(&o->layout, &o->sofa, ": not on a live device"),
        {"--script", OPTION_TEXT, &o->script_path, "FILE",
         .help = "input events by frame: \"frame 3 key space\",\n"
                 "\"frame 5 click 0.4 0.5 left\", \"frame 6 key h\",\n"
                 "\"frame 7 drag 0.1 0\", \"frame 8 scroll 2\""},
        {0},
    };
    const command_line cl = {"fulgur view", "SCENE.json", 1, 1, about, notes, table};
    size_t operands;
    options_result r = options_parse(&cl, argc, argv, &o->scene_path, &operands);
    if (r == OPTIONS_OK && o->backend != FGG_BACKEND_WINDOW && o->frames == 0)
        return options_fail(&cl, "--gl %s runs headless: give --frames N",
                            fgg_backend_name(o->backend));
    return r;
}
