/* fulgur: the sound of electric discharges. Dispatches to a subcommand. */
#include <stdio.h>
#include <string.h>

#include "common/commands.h"
#include "common/text_escape.h"
#include "fulgur/version.h"
#ifdef FULGUR_HAVE_GPU
#include "gl_module.h"
#include "scene/generator_field_gpu.h"
#endif

static const struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} commands[] = {
    {"render", render_main, "render a scene to a 32-bit float WAV through the real-time engine"},
    {"run", run_main, "run a scene in real time, as a VR application would, and report timing as JSON"},
#ifdef FULGUR_HAVE_GPU
    {"view", gl_view_main, "show and sound discharges in a window (or headless): place charges, trigger"},
#endif
    {"analyze", analyze_main, "write a WAV's waveform envelope and spectrogram for gnuplot"},
    {"aerotex", aerotex_main, "compute an aerodynamic sound texture of a shape by CFD (or show one)"},
    {"flame", flame_main, "simulate a flame offline: its flux series (CSV) and its sound (WAV)"},
};

#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

static void usage(FILE *to)
{
    fprintf(to, "usage: fulgur COMMAND [ARGS...]   (fulgur COMMAND --help for each)\n"
                "       fulgur --version\n\n");
    for (size_t i = 0; i < COMMAND_COUNT; i++)
        fprintf(to, "  %-8s %s\n", commands[i].name, commands[i].summary);
}

int main(int argc, char **argv)
{
#ifdef FULGUR_HAVE_GPU
    gen_field_set_gpu_grower(gl_field_gpu_grow); /* opens the GL module when a scene asks */
#endif
    if (argc < 2) {
        usage(stderr);
        return CLI_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(stdout);
        return CLI_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("%s\n", fg_version_string());
        return CLI_OK;
    }
    for (size_t i = 0; i < COMMAND_COUNT; i++)
        if (strcmp(argv[1], commands[i].name) == 0)
            return commands[i].run(argc - 1, argv + 1);
    char name[256];
    text_escape(name, sizeof name, argv[1]);
    fprintf(stderr, "fulgur: unknown command \"%s\"\n", name);
    usage(stderr);
    return CLI_USAGE;
}
