/* The real-time callback's cost: the distribution of fg_engine_render
 * times at 48 kHz while many bolts and a spark stream sound at once, the
 * number of concurrent bolts before the 99th percentile passes half the
 * block's budget, and the worst block: a thunderclap whose every segment
 * arrives at once (thread CPU time). Writes bench/results/callback.csv,
 * stress.csv and worst_block.csv (`bench_callback worst`: only that one);
 * and callback_layouts.csv: the issue 15 load (10 bolts and 100 sparks/s
 * in 128-frame blocks) in every output layout, binaural through the MIT
 * KEMAR set that Debian's libmysofa1 installs, each callback timed in the
 * thread's CPU time, the median of three runs' p50 and p99 against the
 * goals (binaural p99 <= 15 % of the budget, third-order ambisonics <=
 * 20 %) (`bench_callback layouts`: only that file). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "fulgur/fulgur.h"
#include "sofa_hrir.h"
#include "synth_tree.h"

#define FS 48000.0
#define BOLT_SEGMENTS 10000
#define SPARK_SEGMENTS 72
#define SPARKS_PER_S 100.0
/* every bolt below sounds throughout this window of its audio */
#define WINDOW_START_S 9.0
#define WINDOW_END_S 15.0

static const unsigned blocks[] = {64, 128, 256};

typedef struct load {
    int bolts;
    int sparks;   /* non-zero: the 100/s spark stream */
    unsigned block;
    fg_layout layout;          /* 0: stereo */
    uint32_t order;            /* ambisonics */
    const fg_hrir_set *hrirs;  /* binaural */
    double (*clock)(void);     /* NULL: bench_now_s (wall); bench_cpu_s */
} load;

typedef struct timing {
    double p50, p99, max; /* microseconds */
    double budget_us;
    unsigned long blocks, late_events;
} timing;

static void die(const char *what, fg_result r)
{
    fprintf(stderr, "%s: %s\n", what, fg_result_str(r));
    exit(1);
}

/* Bolt k: the fixture tree moved to 2-3 km around the listener. */
static void make_bolt(fg_node *nodes, int k)
{
    synth_tree(nodes, BOLT_SEGMENTS, 5000.0, 3.0, (uint64_t)k + 11);
    double a = 2.399963 * k, d = 2000.0 + 1000.0 * fmod(0.618034 * k, 1.0);
    fg_tree_translate(nodes, BOLT_SEGMENTS + 1, (double[]){d * cos(a), d * sin(a), 0.0});
}

static void make_spark(fg_node *nodes, int k)
{
    synth_tree(nodes, SPARK_SEGMENTS, 0.02, 0.002, (uint64_t)k + 1000);
    double a = 1.3 * k;
    fg_tree_translate(nodes, SPARK_SEGMENTS + 1, (double[]){1.5 * cos(a), 1.5 * sin(a), 1.0});
}

static timing run(const load *L, fg_node *tree)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = L->block,
                            .max_voices = (uint32_t)L->bolts + 64,
                            .segment_capacity = (uint32_t)(L->bolts * BOLT_SEGMENTS + 64 * SPARK_SEGMENTS),
                            .layout = L->layout, .ambisonic_order = L->order,
                            .hrirs = L->hrirs};
    double (*clock)(void) = L->clock ? L->clock : bench_now_s;
    fg_engine *e;
    fg_result r = fg_engine_create(&cfg, &e);
    if (r != FG_OK)
        die("create", r);
    fg_engine_get_config(e, &cfg);
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    if ((r = fg_engine_set_listener(e, &head)) != FG_OK)
        die("listener", r);
    fg_sound_config bolt, spark;
    if (fg_preset_sound(FG_PRESET_LIGHTNING, &bolt) != FG_OK ||
        fg_preset_sound(FG_PRESET_SPARK_BALLS, &spark) != FG_OK)
        exit(1);
    for (int k = 0; k < L->bolts; k++) {
        make_bolt(tree, k);
        fg_discharge d = {.nodes = tree, .node_count = BOLT_SEGMENTS + 1, .sound = bolt,
                          .emit_time_s = 0, .strokes = 1, .seed = (uint64_t)k};
        if ((r = fg_engine_post(e, &d, NULL)) != FG_OK)
            die("post bolt", r);
    }
    float *planes[16];
    for (uint32_t ch = 0; ch < cfg.channels; ch++)
        planes[ch] = malloc(L->block * sizeof(float));
    size_t cap = (size_t)((WINDOW_END_S - WINDOW_START_S) * FS / L->block) + 2, n = 0;
    double *us = malloc(cap * sizeof *us);
    int next_spark = 0;
    for (uint64_t frame = 0; frame < (uint64_t)(WINDOW_END_S * FS); frame += L->block) {
        double t = frame / FS;
        while (L->sparks && t >= WINDOW_START_S - 0.1 && next_spark / SPARKS_PER_S <= t - WINDOW_START_S + 0.1) {
            make_spark(tree, next_spark);
            fg_discharge d = {.nodes = tree, .node_count = SPARK_SEGMENTS + 1, .sound = spark,
                              .emit_time_s = FG_EMIT_NOW, .strokes = 1, .seed = (uint64_t)next_spark};
            if ((r = fg_engine_post(e, &d, NULL)) != FG_OK)
                die("post spark", r);
            next_spark++;
        }
        double t0 = clock();
        if ((r = fg_engine_render(e, planes, L->block)) != FG_OK)
            die("render", r);
        double dt = clock() - t0;
        if (t >= WINDOW_START_S && n < cap)
            us[n++] = 1e6 * dt;
        fg_engine_collect(e);
    }
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    timing out = {.p50 = bench_quantile(us, n, 0.5), .p99 = bench_quantile(us, n, 0.99),
                  .max = bench_quantile(us, n, 1.0), .budget_us = 1e6 * L->block / FS,
                  .blocks = n, .late_events = st.late_events};
    free(us);
    for (uint32_t ch = 0; ch < cfg.channels; ch++)
        free(planes[ch]);
    fg_engine_destroy(e);
    return out;
}

/* callback_layouts.csv: the issue 15 load in every layout. */
static void layouts(const char *cpu, fg_node *tree)
{
    typedef struct {
        const char *name;
        fg_layout layout;
        uint32_t order;
        double goal; /* p99 / budget, 0: none */
    } layout_case;
    static const layout_case cases[] = {
        {"stereo", FG_LAYOUT_STEREO, 0, 0.0},
        {"ambisonics order 1", FG_LAYOUT_AMBISONICS, 1, 0.0},
        {"ambisonics order 2", FG_LAYOUT_AMBISONICS, 2, 0.0},
        {"ambisonics order 3", FG_LAYOUT_AMBISONICS, 3, 0.20},
        {"binaural", FG_LAYOUT_BINAURAL, 0, 0.15},
    };
    enum { CASES = sizeof cases / sizeof cases[0], RUNS = 3 };
    sofa_hrirs kemar;
    char err[512];
    if (sofa_hrirs_read(SOFA_DEFAULT_FILE, FS, &kemar, err, sizeof err) != 0) {
        fprintf(stderr, "bench_callback: %s\n", err);
        exit(1);
    }
    static double p50[CASES][RUNS], p99[CASES][RUNS];
    double budget_us = 0;
    for (int k = 0; k < RUNS; k++) {
        for (int c = 0; c < CASES; c++) {
            load L = {.bolts = 10, .sparks = 1, .block = 128, .layout = cases[c].layout,
                      .order = cases[c].order,
                      .hrirs = cases[c].layout == FG_LAYOUT_BINAURAL ? &kemar.set : NULL,
                      .clock = bench_cpu_s};
            timing t = run(&L, tree);
            p50[c][k] = t.p50;
            p99[c][k] = t.p99;
            budget_us = t.budget_us;
        }
    }
    FILE *csv = bench_open_result("callback_layouts.csv");
    fprintf(csv, "# %s; 48 kHz, 128-frame blocks, 10 %d-segment bolts at 2-3 km and 100 "
                 "sparks/s, callbacks over %.0f-%.0f s in the thread's CPU time, median of %d "
                 "runs; binaural through %s\n",
            cpu, BOLT_SEGMENTS, WINDOW_START_S, WINDOW_END_S, RUNS, SOFA_DEFAULT_FILE);
    fprintf(csv, "layout,p50_us,p99_us,budget_us,p99_of_budget,goal,ratio_p50_to_stereo,"
                 "ratio_p99_to_stereo\n");
    double base50 = 0, base99 = 0;
    for (int c = 0; c < CASES; c++) {
        double m50 = bench_median(p50[c], RUNS), m99 = bench_median(p99[c], RUNS);
        if (c == 0) {
            base50 = m50;
            base99 = m99;
        }
        char goal[32] = "";
        if (cases[c].goal > 0)
            snprintf(goal, sizeof goal, "%.2f", cases[c].goal);
        fprintf(csv, "%s,%.2f,%.2f,%.1f,%.4f,%s,%.2f,%.2f\n", cases[c].name, m50, m99, budget_us,
                m99 / budget_us, goal, m50 / base50, m99 / base99);
        printf("%-20s p50 %7.1f us, p99 %7.1f us = %5.1f %% of %.0f us%s%s; x%.2f / x%.2f "
               "stereo\n",
               cases[c].name, m50, m99, 100 * m99 / budget_us, budget_us,
               cases[c].goal > 0 ? ", goal " : "", goal, m50 / base50, m99 / base99);
    }
    fclose(csv);
    sofa_hrirs_free(&kemar);
}

/* All segments of an arc centred on the listener arrive in one block: the
 * fastest return stroke the engine takes (FG_SOUND_MAX_RETURN_STROKE_M_S)
 * crosses the 30 km arc in 0.1 ms. Writes the thread CPU time of each of
 * its blocks, microseconds, to us[0 .. cap) and returns how many there
 * were; the work units the per-block bound left undone
 * (fg_engine_config.work_per_frame at its default) in *skipped. */
static size_t arc_blocks(unsigned block, fg_node *tree, double *us, size_t cap, uint64_t *skipped)
{
    double radius = 2000.0, step = 3.0;
    for (size_t i = 0; i <= BOLT_SEGMENTS; i++) {
        double a = step * (double)i / radius;
        tree[i] = (fg_node){radius * cos(a), radius * sin(a), 500.0, (int32_t)i - 1, 0};
    }
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = block,
                            .segment_capacity = BOLT_SEGMENTS};
    fg_engine *e;
    if (fg_engine_create(&cfg, &e) != FG_OK)
        exit(1);
    fg_listener head = {.position = {0, 0, 500.0}, .forward = {1, 0, 0}, .up = {0, 0, 1}};
    fg_sound_config p;
    if (fg_engine_set_listener(e, &head) != FG_OK || fg_preset_sound(FG_PRESET_LIGHTNING, &p) != FG_OK)
        exit(1);
    p.return_stroke_speed_m_s = FG_SOUND_MAX_RETURN_STROKE_M_S; /* the whole arc emits at once */
    fg_discharge d = {.nodes = tree, .node_count = BOLT_SEGMENTS + 1, .sound = p, .strokes = 1};
    fg_result r = fg_engine_post(e, &d, NULL);
    if (r != FG_OK)
        die("worst block: post", r);
    float *planes[2] = {malloc(block * sizeof(float)), malloc(block * sizeof(float))};
    fg_engine_report st = {0};
    size_t n = 0;
    while (st.finished == 0 && n < cap) {
        double t0 = bench_cpu_s();
        if (fg_engine_render(e, planes, block) != FG_OK)
            exit(1);
        us[n++] = 1e6 * (bench_cpu_s() - t0);
        fg_engine_get_report(e, &st);
    }
    if (st.finished == 0) {
        fprintf(stderr, "worst block: the arc outlasts %zu blocks\n", cap);
        exit(1);
    }
    *skipped = st.skipped_work;
    free(planes[0]);
    free(planes[1]);
    fg_engine_destroy(e);
    return n;
}

/* worst_block.csv: each block's median over WORST_RUNS runs (a preempted
 * or interrupted block in one run does not count), the costliest of those. */
#define WORST_RUNS 5
#define WORST_CAP 65536

static void worst_blocks(const char *cpu, fg_node *tree)
{
    double *us = malloc(WORST_RUNS * WORST_CAP * sizeof *us);
    if (!us)
        exit(1);
    FILE *worst = bench_open_result("worst_block.csv");
    fprintf(worst, "# %s; a %d-segment arc centred on the listener: all arrive in one block; "
            "thread CPU time, the costliest block's median over %d runs\n",
            cpu, BOLT_SEGMENTS, WORST_RUNS);
    fprintf(worst, "block,worst_us,budget_us,worst_of_budget,skipped_work\n");
    for (size_t b = 0; b < 3; b++) {
        uint64_t skipped = 0;
        size_t n = WORST_CAP;
        for (int k = 0; k < WORST_RUNS; k++) {
            size_t got = arc_blocks(blocks[b], tree, us + (size_t)k * WORST_CAP, WORST_CAP, &skipped);
            n = got < n ? got : n;
        }
        double w = 0;
        for (size_t i = 0; i < n; i++) {
            double at[WORST_RUNS];
            for (int k = 0; k < WORST_RUNS; k++)
                at[k] = us[(size_t)k * WORST_CAP + i];
            w = fmax(w, bench_median(at, WORST_RUNS));
        }
        double budget = 1e6 * blocks[b] / FS;
        fprintf(worst, "%u,%.1f,%.1f,%.3f,%llu\n", blocks[b], w, budget, w / budget,
                (unsigned long long)skipped);
        printf("worst block (%u frames): %.1f us of %.0f us (%.1f %%), %llu work units skipped\n",
               blocks[b], w, budget, 100 * w / budget, (unsigned long long)skipped);
    }
    fclose(worst);
    free(us);
}

/* usage: bench_callback [MAX_STRESS | worst]; worst: worst_block.csv alone */
int main(int argc, char **argv)
{
    int only_layouts = argc > 1 && strcmp(argv[1], "layouts") == 0;
    int max_stress = argc > 1 && !only_layouts ? atoi(argv[1]) : 400;
    char cpu[256];
    bench_machine(cpu, sizeof cpu);
    fg_node *tree = malloc((BOLT_SEGMENTS + 1) * sizeof *tree);
    if (!tree)
        return 1;
    if (argc > 1 && strcmp(argv[1], "worst") == 0) {
        worst_blocks(cpu, tree);
        free(tree);
        return 0;
    }
    layouts(cpu, tree);
    if (only_layouts) {
        free(tree);
        return 0;
    }

    FILE *csv = bench_open_result("callback.csv");
    fprintf(csv, "# %s; 48 kHz, 2 ears; %d-segment bolts at 2-3 km; render times over %.0f-%.0f s\n",
            cpu, BOLT_SEGMENTS, WINDOW_START_S, WINDOW_END_S);
    fprintf(csv, "block,bolts,sparks_per_s,p50_us,p99_us,max_us,budget_us,p99_of_budget,late_events\n");
    static const int bolts[] = {1, 10, 100};
    for (size_t b = 0; b < 3; b++) {
        for (size_t k = 0; k < 3; k++) {
            load L = {.bolts = bolts[k], .sparks = 1, .block = blocks[b]};
            timing t = run(&L, tree);
            fprintf(csv, "%u,%d,%.0f,%.2f,%.2f,%.2f,%.1f,%.4f,%lu\n", L.block, L.bolts, SPARKS_PER_S,
                    t.p50, t.p99, t.max, t.budget_us, t.p99 / t.budget_us, t.late_events);
            printf("block %3u, %3d bolts + sparks: p50 %7.1f us, p99 %7.1f us, max %7.1f us "
                   "(budget %6.0f us, p99 = %4.1f %%)\n",
                   L.block, L.bolts, t.p50, t.p99, t.max, t.budget_us, 100 * t.p99 / t.budget_us);
        }
    }
    fclose(csv);

    FILE *stress = bench_open_result("stress.csv");
    fprintf(stress, "# %s; 128-frame blocks at 48 kHz; bolts of %d segments\n", cpu, BOLT_SEGMENTS);
    fprintf(stress, "bolts,p99_us,p99_of_budget\n");
    int limit = 0;
    for (int n = 25; n <= max_stress; n *= 2) {
        load L = {.bolts = n, .sparks = 0, .block = 128};
        timing t = run(&L, tree);
        fprintf(stress, "%d,%.2f,%.4f\n", n, t.p99, t.p99 / t.budget_us);
        printf("stress: %4d bolts, p99 %7.1f us = %5.1f %% of budget\n", n, t.p99,
               100 * t.p99 / t.budget_us);
        if (t.p99 > 0.5 * t.budget_us)
            break;
        limit = n;
    }
    fprintf(stress, "# largest count tried with p99 under half the budget: %d\n", limit);
    fclose(stress);

    worst_blocks(cpu, tree);
    free(tree);
    return 0;
}
