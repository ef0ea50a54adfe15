/* The per-block work bound's price list (docs/limits.md): what one unit
 * costs in CPU time for each voice model, and what a block costs when the
 * bound is all spent. Eight continuous discharges of 24 nodes 20 m away,
 * repeating every 0.1 ms (FG_REPEAT_MIN_S: as many emissions at once as a
 * voice may hold), rendered in 256-frame blocks at 48 kHz, stereo, for each
 * model (WM-wave, Abe) at work_per_frame 8 and the default 64. For every
 * block the thread's CPU time and the units it spent (fg_engine_report
 * .work_units); reported: the median CPU time per unit over the blocks
 * that spent at least half the bound, and the worst block's CPU time as a
 * multiple of the block's duration (the real-time budget). Writes
 * bench/results/work_bound.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fulgur/fulgur.h"

#define FS 48000.0
#define BLOCK 256
#define BLOCKS 400
#define VOICES 8
#define NODES 24

static float left[BLOCK], right[BLOCK];

static fg_node nodes[VOICES][NODES];

typedef struct measured {
    double ns_per_unit; /* median over the saturated blocks */
    double worst_budget; /* worst block's CPU time / block duration */
    double median_budget;
    double units_per_block; /* median */
    unsigned saturated;
} measured;

static measured measure(fg_voice_model model, uint32_t work_per_frame)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = BLOCK, .channels = 2,
                            .max_voices = VOICES, .work_per_frame = work_per_frame};
    fg_engine *e;
    fg_listener pose = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    if (fg_engine_create(&cfg, &e) != FG_OK || fg_engine_set_listener(e, &pose) != FG_OK)
        exit(1);
    fg_engine_get_config(e, &cfg);
    for (int v = 0; v < VOICES; v++) {
        for (int i = 0; i < NODES; i++)
            nodes[v][i] = (fg_node){v - 3.5 + 0.05 * sin(1.7 * i), 20.0, 2.0 + 0.25 * i, i - 1,
                                    FG_NODE_MAIN};
        fg_discharge d = {.nodes = nodes[v], .node_count = NODES, .emit_time_s = 0,
                          .strokes = 1, .seed = (uint64_t)v + 1, .continuous = 1,
                          .repeat_min_s = FG_REPEAT_MIN_S, .repeat_max_s = FG_REPEAT_MIN_S,
                          .model = model};
        if (fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound) != FG_OK ||
            fg_engine_post(e, &d, NULL) != FG_OK)
            exit(1);
    }
    const double bound = (double)cfg.work_per_frame * BLOCK + FG_WORK_BLOCK_FLOOR;
    static double per_unit[BLOCKS], budget[BLOCKS], units[BLOCKS];
    size_t saturated = 0;
    float *planes[2] = {left, right};
    uint64_t spent_before = 0;
    for (int b = 0; b < BLOCKS; b++) {
        double t = bench_cpu_s();
        if (fg_engine_render(e, planes, BLOCK) != FG_OK)
            exit(1);
        double cpu = bench_cpu_s() - t;
        fg_engine_report rep;
        fg_engine_get_report(e, &rep);
        double spent = (double)(rep.work_units - spent_before);
        spent_before = rep.work_units;
        budget[b] = cpu / (BLOCK / FS);
        units[b] = spent;
        if (spent >= 0.5 * bound)
            per_unit[saturated++] = cpu / spent * 1e9;
    }
    fg_engine_destroy(e);
    measured m = {.saturated = (unsigned)saturated};
    m.ns_per_unit = saturated ? bench_median(per_unit, saturated) : NAN;
    m.units_per_block = bench_median(units, BLOCKS);
    m.median_budget = bench_median(budget, BLOCKS);
    m.worst_budget = bench_quantile(budget, BLOCKS, 1.0);
    return m;
}

int main(void)
{
    FILE *csv = bench_open_result("work_bound.csv");
    fprintf(csv, "model,work_per_frame,bound_units,median_units,saturated_blocks,ns_per_unit,"
                 "median_cpu_over_budget,worst_cpu_over_budget\n");
    static const struct {
        fg_voice_model model;
        const char *name;
    } models[] = {{FG_MODEL_WM, "wm"}, {FG_MODEL_ABE, "abe"}};
    static const uint32_t bounds[] = {8, FG_WORK_PER_FRAME_DEFAULT};
    printf("%-4s %6s %8s %8s %5s %9s %9s %9s\n", "model", "w/f", "bound", "units", "sat",
           "ns/unit", "cpu/bud", "worst");
    for (size_t m = 0; m < 2; m++)
        for (size_t k = 0; k < 2; k++) {
            measured r = measure(models[m].model, bounds[k]);
            unsigned bound = bounds[k] * BLOCK + FG_WORK_BLOCK_FLOOR;
            printf("%-5s %6u %8u %8.0f %5u %9.1f %9.3f %9.3f\n", models[m].name, bounds[k], bound,
                   r.units_per_block, r.saturated, r.ns_per_unit, r.median_budget,
                   r.worst_budget);
            fprintf(csv, "%s,%u,%u,%.0f,%u,%.2f,%.4f,%.4f\n", models[m].name, bounds[k], bound,
                    r.units_per_block, r.saturated, r.ns_per_unit, r.median_budget,
                    r.worst_budget);
        }
    fclose(csv);
    return 0;
}
