/* What each effect of the air costs: a lightning bolt of ~10 000 segments
 * heard from 3 km, rendered with each effect alone and all together, as
 * render time per second of sound next to the pure render, and the post
 * (where the first absorbing discharge designs the band filters). Writes
 * bench/results/effects.csv. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_render.h"
#include "bench_util.h"
#include "synth_tree.h"

#define SEGMENTS 10000
#define REPEATS 5

typedef struct effect {
    const char *name;
    fg_propagation_config prop;
    fg_voice_model model;
} effect;

int main(void)
{
    static const effect effects[] = {
        {"none (free air)", {.refraction_radius_m = 0}, FG_MODEL_WM},
        {"refraction", {.refraction_radius_m = FG_REFRACTION_STORM_M}, FG_MODEL_WM},
        {"turbulence", {.turbulence_s = FG_TURBULENCE_DEFAULT_S}, FG_MODEL_WM},
        {"absorption iso9613", {.absorption = FG_ABSORPTION_ISO9613}, FG_MODEL_WM},
        {"absorption abe_fir", {.absorption = FG_ABSORPTION_ABE_FIR}, FG_MODEL_WM},
        {"ground reflection", {.ground_reflection = FG_GROUND_DEFAULT_REFLECTION}, FG_MODEL_WM},
        {"head shadow", {.head_shadow = 1}, FG_MODEL_WM},
        {"all of the above but abe_fir",
         {.refraction_radius_m = FG_REFRACTION_STORM_M, .turbulence_s = FG_TURBULENCE_DEFAULT_S,
          .absorption = FG_ABSORPTION_ISO9613, .ground_reflection = FG_GROUND_DEFAULT_REFLECTION,
          .head_shadow = 1},
         FG_MODEL_WM},
        {"Abe's voice model (512 sources)", {.refraction_radius_m = 0}, FG_MODEL_ABE},
    };
    fg_sound_config p;
    fg_node *nodes = synth_far_bolt(SEGMENTS);
    if (fg_preset_sound(FG_PRESET_LIGHTNING, &p) != FG_OK || !nodes)
        return 1;
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    char cpu[256];
    bench_machine(cpu, sizeof cpu);
    FILE *csv = bench_open_result("effects.csv");
    fprintf(csv, "# %s; %d segments heard from 3 km by two ears, 48 kHz, 512-frame blocks, "
                 "median of %d\n", cpu, SEGMENTS, REPEATS);
    fprintf(csv, "effect,post_ms,render_ms,sound_s,render_ms_per_s_of_sound,extra_ms_per_s\n");
    double base = 0;
    for (size_t e = 0; e < sizeof effects / sizeof effects[0]; e++) {
        double post[REPEATS], render[REPEATS];
        bench_run r = {0};
        for (int k = 0; k < REPEATS; k++) {
            r = bench_render_tree_with(nodes, SEGMENTS + 1, &p, &effects[e].prop,
                                       effects[e].model, &head, 512);
            post[k] = r.post_s;
            render[k] = r.render_s;
        }
        double post_ms = 1e3 * bench_median(post, REPEATS);
        double ms = 1e3 * bench_median(render, REPEATS), per_s = ms / r.sound_s;
        if (e == 0)
            base = per_s;
        fprintf(csv, "%s,%.3f,%.3f,%.2f,%.3f,%.3f\n", effects[e].name, post_ms, ms, r.sound_s,
                per_s, per_s - base);
        printf("%-32s post %7.2f ms, render %8.2f ms for %5.2f s: %7.3f ms per second (%+.3f)\n",
               effects[e].name, post_ms, ms, r.sound_s, per_s, per_s - base);
    }
    fclose(csv);
    free(nodes);
    return 0;
}
