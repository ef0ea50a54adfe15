/* Aero objects in the engine (fulgur/aero_object.h) at run time, on one
 * core: the cost of one 16-source object (Dobashi et al.'s 50 cm rod of
 * 1 cm) per 128-frame block at 48 kHz, two ears, swung with a pose every
 * other block, against the block's 2.667 ms budget (goal: at most 2 %);
 * and how many such objects one engine renders before the 99th
 * percentile of a block's CPU time passes half the budget. CPU time of
 * this thread, per block (the machine is shared); a hand-made texture
 * (one direction; the lookup's cost does not depend on the count).
 * Writes bench/results/aero_object.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fg_math.h"
#include "fulgur/aero_object.h"

#define FS 48000.0
#define BLOCK 128
#define BLOCKS 1500 /* 4 s */
#define BUDGET_S (BLOCK / FS)
#define FRAMES 1600

static void check(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "aero_object_bench: %s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

static fg_aero_texture *make_texture(void)
{
    static float samples[2 * FRAMES];
    for (int i = 0; i < FRAMES; i++) {
        samples[2 * i] = (float)(0.2 * cos(4.0 * FG_PI * 20 * i / FRAMES));
        samples[2 * i + 1] = (float)cos(2.0 * FG_PI * 20 * i / FRAMES);
    }
    static const fg_aero_source one = {0.0, 1.0};
    fg_aero_direction dir = {.frontal_m = 0.01, .frequency_hz = 200, .strouhal = 0.2,
                             .periods = 20, .frames = FRAMES, .samples = samples};
    fg_aero_texture_desc d = {.shape = FG_AERO_CIRCLE, .dims = 2, .components = 2,
                              .length_m = 0.01, .reference_m = 0.01, .speed_m_s = 10,
                              .viscosity_m2_s = 1.5e-5, .density_kg_m3 = 1.204,
                              .sample_rate_hz = 16000, .cells_per_length = 32, .sources = 1,
                              .source = &one, .directions = 1, .direction = &dir};
    d.reynolds = d.reference_m * d.speed_m_s / d.viscosity_m2_s;
    fg_aero_texture *t;
    check(fg_aero_texture_create(&d, &t), "texture");
    return t;
}

static fg_aero_pose swing_pose(unsigned k, double t_s)
{
    double a = 20.0 * t_s + 0.3 * k, x = 0.7 * (k % 8), y = 3.0 + 0.5 * (k / 8);
    return (fg_aero_pose){.position = {x, y, 1.5}, .axis = {sin(a), 0, cos(a)},
                          .normal = {cos(a), 0, -sin(a)}, .time_s = t_s};
}

typedef struct timing {
    double median_s, p99_s;
} timing;

/* Renders BLOCKS blocks of n swung rods; the CPU time of each block. */
static timing run(const fg_aero_texture *t, unsigned n)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = BLOCK,
                            .max_voices = n + 1};
    fg_engine *e;
    check(fg_engine_create(&cfg, &e), "engine");
    fg_voice_id *ids = calloc(n + 1, sizeof *ids);
    for (unsigned k = 0; k < n; k++) {
        fg_aero_object o = {.texture = t, .body = FG_AERO_STICK, .start_m = 0.0,
                            .end_m = 0.5, .pose = swing_pose(k, 0.0)};
        check(fg_aero_object_post(e, &o, &ids[k]), "post");
    }
    float l[BLOCK], r[BLOCK];
    float *planes[2] = {l, r};
    double *cpu = malloc(BLOCKS * sizeof *cpu);
    for (unsigned b = 0; b < BLOCKS; b++) {
        double now = b * BLOCK / FS;
        if (b % 2 == 0) /* 187 Hz of poses, each ahead of the audio */
            for (unsigned k = 0; k < n; k++) {
                fg_aero_pose p = swing_pose(k, now + 0.011);
                check(fg_aero_object_set_pose(e, ids[k], &p), "pose");
            }
        double c0 = bench_cpu_s();
        check(fg_engine_render(e, planes, BLOCK), "render");
        cpu[b] = bench_cpu_s() - c0;
    }
    fg_engine_report rep;
    fg_engine_get_report(e, &rep);
    if (rep.skipped_work || rep.non_finite_voices) {
        fprintf(stderr, "aero_object_bench: %u objects: work skipped or voices retired\n", n);
        exit(1);
    }
    timing out = {bench_median(cpu + 100, BLOCKS - 100), 0.0};
    out.p99_s = bench_quantile(cpu + 100, BLOCKS - 100, 0.99);
    free(cpu);
    free(ids);
    fg_engine_destroy(e);
    return out;
}

int main(void)
{
    fg_aero_texture *t = make_texture();
    FILE *csv = bench_open_result("aero_object.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    fprintf(csv, "# %s; 48 kHz, 128-frame blocks (budget %.3f ms), 2 ears, 16 sources per "
                 "object, CPU time per block\n", machine, 1e3 * BUDGET_S);
    fprintf(csv, "objects,median_us,p99_us,p99_of_budget\n");
    timing none = run(t, 0), one = run(t, 1);
    double per = one.median_s - none.median_s;
    printf("one 16-source object: %.1f us per 128-frame block (median, engine alone %.1f us): "
           "%.2f %% of the %.3f ms budget (goal <= 2 %%)\n",
           1e6 * per, 1e6 * none.median_s, 100.0 * per / BUDGET_S, 1e3 * BUDGET_S);
    fprintf(csv, "0,%.2f,%.2f,%.4f\n", 1e6 * none.median_s, 1e6 * none.p99_s,
            none.p99_s / BUDGET_S);
    fprintf(csv, "1,%.2f,%.2f,%.4f\n", 1e6 * one.median_s, 1e6 * one.p99_s,
            one.p99_s / BUDGET_S);
    unsigned fits = 1;
    for (unsigned n = 4; n <= 256; n += 4) {
        timing m = run(t, n);
        fprintf(csv, "%u,%.2f,%.2f,%.4f\n", n, 1e6 * m.median_s, 1e6 * m.p99_s,
                m.p99_s / BUDGET_S);
        printf("%3u objects: median %.1f us, p99 %.1f us (%.1f %% of the budget)\n", n,
               1e6 * m.median_s, 1e6 * m.p99_s, 100.0 * m.p99_s / BUDGET_S);
        if (m.p99_s > 0.5 * BUDGET_S)
            break;
        fits = n;
    }
    printf("objects with p99 within half the budget: %u (steps of 4)\n", fits);
    fclose(csv);
    fg_aero_texture_destroy(t);
    return 0;
}
