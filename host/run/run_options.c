/* fulgur run's command line: its option table. */
#include "run.h"

static const char about[] =
    "Runs the scene as a VR application would: a frame thread moves the listener at\n"
    "--frame-rate, a sim thread builds and posts each discharge at its time, an audio\n"
    "thread pulls blocks through a driver.\n";

static const char notes[] =
    "Plays live: fulgur run SCENE --audio raw:- | aplay -f FLOAT_LE -c2 -r48000\n"
    "Layouts (docs/spatial.md; --layout, else the scene's \"layout\"): stereo, binaural\n"
    "(two channels on any device), ambisonics:ORDER (AmbiX, (ORDER+1)^2 channels, to\n"
    "wav: and raw: only: the live devices open 1 or 2).\n"
    "Prints a JSON report (timing, post-to-adoption latency, late events) to stdout,\n"
    "to stderr with raw:-, or to --report FILE.\n"
    "Exit: 0 done, 1 runtime error, 2 bad arguments or scene (a generator's error is\n"
    "found when the sim thread builds that discharge: no report, no WAV).\n";

options_result run_parse_options(int argc, char **argv, run_options *o)
{
    static const uint32_t blocks[] = {64, 128, 256, 512, 0};
    static const uint32_t rates[] = {44100, 48000, 96000, 0};
    *o = (run_options){.audio = {AUDIO_DRIVER_NULL, NULL}, .frame_hz = 90};
    const option table[] = {
        audio_output_option(&o->audio, "where the blocks go:\n"
                                       "null      a clock-paced device: one block per block\n"
                                       "          period, in real time (the default)\n"
                                       "wav:FILE  32-bit float WAV, as fast as possible,\n"
                                       "          deterministic\n"
                                       "raw:-     interleaved float32 to stdout, deterministic"),
        {"--block", OPTION_INTEGER, &o->block_frames, NULL,
         .help = "frames per block (default: the scene's)", .one_of = blocks},
        {"--rate", OPTION_INTEGER, &o->rate_hz, NULL,
         .help = "the sample rate (default: the scene's)", .one_of = rates},
        {"--seconds", OPTION_NUMBER, &o->seconds, "S",
         .help = "how long to run (default: the scene's duration, else until\n"
                 "every discharge has sounded)",
         .range = {0, SCENE_MAX_DURATION_S, .lo_open = true}},
        {"--report", OPTION_TEXT, &o->report_path, "FILE", .help = "where the JSON report goes"},
        {"--voices", OPTION_INTEGER, &o->voices, "N",
         .help = "the engine's voice pool (default 64)", .range = {.lo = 1, .hi = 4096}},
        {"--segments", OPTION_INTEGER, &o->segments, "N",
         .help = "the engine's segment capacity, for all sounding discharges\n"
                 "together (default: 131072, or the explicit trees' total\n"
                 "when larger; generated trees are built during the run)",
         .range = {.lo = 1, .hi = RUN_MAX_SEGMENTS}},
        SCENE_LAYOUT_OPTIONS(&o->layout, &o->sofa, ": wav: and raw: only"),
        {"--frame-rate", OPTION_NUMBER, &o->frame_hz, "HZ",
         .help = "the frame thread's rate (default 90; at least 10: a head pose\n"
                 "older than 100 ms, and the last tick's wait, would hold the run)",
         .range = {.lo = 10, .hi = 1000}},
        {0},
    };
    const command_line cl = {"fulgur run", "SCENE.json", 1, 1, about, notes, table};
    size_t operands;
    return options_parse(&cl, argc, argv, &o->scene_path, &operands);
}
