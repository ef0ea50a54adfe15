/* Matsuyama table 2, side by side: for each scale, the mean segments and
 * sound length of our generated discharges and the time to synthesize the
 * whole sound (post + render, one thread), against the paper's figures
 * (3.8 GHz Pentium 4). Pattern generation is timed apart: the paper's
 * times are for the sound. Writes bench/results/table2.csv. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_render.h"
#include "bench_util.h"

#define SEEDS 15

typedef struct scale {
    fg_preset preset;
    double paper_segments, paper_sound_s, paper_ms;
    const char *paper_time;
    double listener_m[3];
} scale;

static void must(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "table2: %s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

/* A tree of the scale's preset; the field is kept between seeds, as a host
 * re-triggering a discharge would keep it. */
static double generate(fg_preset preset, uint64_t seed, fg_field *field, fg_field_scene *setup,
                       fg_tree *tree)
{
    fg_tree_clear(tree);
    double t0 = bench_now_s();
    if (preset == FG_PRESET_LIGHTNING) {
        fg_lightning_config p = {.strike_m = {0, 0}, .seed = seed};
        must(fg_lightning_generate(&p, tree, NULL), "lightning");
    } else {
        fg_field_source src;
        fg_field_source_init(field, &src);
        setup->growth.seed = seed;
        must(fg_grow_matsuyama(&src, &setup->growth, tree, NULL), "grow");
    }
    return bench_now_s() - t0;
}

int main(void)
{
    static const scale scales[] = {
        {FG_PRESET_SPARK_BALLS, 72, 0, 16, "< 16", {0, -1.0, 0}},
        {FG_PRESET_PLASMA_BALL, 78, 0, 16, "< 16", {0, -1.0, 0}},
        {FG_PRESET_LIGHTNING, 9438, 13.6, 812, "812", {3000, 0, 1.7}},
    };
    char cpu[256];
    bench_machine(cpu, sizeof cpu);
    FILE *csv = bench_open_result("table2.csv");
    fprintf(csv, "# %s; means over %d seeds; synthesis = post + every render block of the "
                 "whole sound, median; paper: Matsuyama table 2, 3.8 GHz Pentium 4\n",
            cpu, SEEDS);
    fprintf(csv, "scale,paper_segments,segments,paper_sound_s,sound_s,paper_ms,synth_ms,"
                 "speedup,generate_ms\n");
    fg_tree *tree;
    must(fg_tree_create(16384, &tree), "tree");
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
        const scale *sc = &scales[i];
        fg_sound_config sound;
        must(fg_preset_sound(sc->preset, &sound), "preset");
        fg_field_scene setup;
        fg_field *field = NULL;
        if (sc->preset != FG_PRESET_LIGHTNING) {
            must(fg_field_scene_preset(sc->preset, 0, &setup), "setup");
            must(fg_field_create(&setup.grid, &field), "field");
            must(fg_field_set_shapes(field, setup.shapes, setup.shape_count, NULL), "shapes");
            must(fg_field_solve(field, NULL, NULL), "solve");
        }
        fg_listener head = {.position = {sc->listener_m[0], sc->listener_m[1], sc->listener_m[2]},
                            .forward = {0, 1, 0}, .up = {0, 0, 1}};
        double segs = 0, sound_s = 0, synth[SEEDS], gen[SEEDS];
        for (int k = 0; k < SEEDS; k++) {
            gen[k] = generate(sc->preset, (uint64_t)k + 1, field, &setup, tree);
            bench_run r = bench_render_tree(fg_tree_nodes(tree), fg_tree_count(tree), &sound,
                                            &head, 512);
            synth[k] = r.post_s + r.render_s;
            segs += (double)(fg_tree_count(tree) - 1) / SEEDS;
            sound_s += r.sound_s / SEEDS;
        }
        double ms = 1e3 * bench_median(synth, SEEDS), gen_ms = 1e3 * bench_median(gen, SEEDS);
        fprintf(csv, "%s,%.0f,%.0f,%.1f,%.2f,%.0f,%.3f,%.0f,%.3f\n", fg_preset_name(sc->preset),
                sc->paper_segments, segs, sc->paper_sound_s, sound_s, sc->paper_ms, ms,
                sc->paper_ms / ms, gen_ms);
        printf("%-12s segments %6.0f (paper %5.0f), sound %6.2f s, synthesis %8.3f ms (paper %s "
               "ms): %5.0fx; pattern %7.3f ms\n",
               fg_preset_name(sc->preset), segs, sc->paper_segments, sound_s, ms, sc->paper_time,
               sc->paper_ms / ms, gen_ms);
        fg_field_destroy(field);
    }
    fg_tree_destroy(tree);
    fclose(csv);
    return 0;
}
