/* Fire voices in the engine (fulgur/fire_voice.h) at run time, on one
 * core: the audio thread's cost of one fire per 128-frame block at 48 kHz,
 * two ears, for a fire standing still and for one carried past at 3 m/s
 * (a pose every other block, 187 Hz), each without and with ISO 9613-1
 * absorption; and the block's 99th percentile with every fire an engine
 * holds (FG_FIRE_VOICE_MAX) carried at once. The stream is pushed before
 * each block, outside the timing: its making (bandwidth extension, texture
 * synthesis) is the sim thread's, in bench/results/fire.csv. CPU time of
 * this thread per block (the machine is shared), the engine alone
 * subtracted. Writes bench/results/fire_voice.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fulgur/fire_voice.h"

#define FS 48000.0
#define BLOCK 128
#define BLOCKS 1500 /* 4 s */
#define WARM_BLOCKS 100
#define BUDGET_S (BLOCK / FS)

static void check(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "fire_voice_bench: %s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

typedef struct setup {
    bool carried;
    fg_absorption absorption;
} setup;

/* Fire k at t_s: standing 3 m ahead, or carried left to right 2 m ahead
 * at 3 m/s (each fire a metre further back). */
static fg_fire_pose pose_at(const setup *s, unsigned k, double t_s)
{
    double y = 3.0 + k;
    if (!s->carried)
        return (fg_fire_pose){.position = {0.0, y, 1.5}, .time_s = t_s};
    return (fg_fire_pose){.position = {-6.0 + 3.0 * t_s, y, 1.5}, .velocity = {3.0, 0.0, 0.0},
                          .time_s = t_s};
}

typedef struct timing {
    double median_s, p99_s;
} timing;

/* Renders BLOCKS blocks of n fires; the CPU time of each block. */
static timing run(const setup *s, unsigned n)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = BLOCK,
                            .max_voices = n + 1};
    fg_engine *e;
    check(fg_engine_create(&cfg, &e), "engine");
    fg_voice_id ids[FG_FIRE_VOICE_MAX];
    for (unsigned k = 0; k < n; k++) {
        fg_fire_voice f = {.pose = pose_at(s, k, 0.0), .absorption = s->absorption,
                           .emit_time_s = 0.0};
        f.pose.time_s = 1e-9; /* 0 would mean "at the call" */
        check(fg_fire_voice_post(e, &f, &ids[k]), "post");
    }
    /* a roar-like stream: noise at 0.1 Pa at 1 m */
    static float noise[4 * BLOCK];
    uint32_t x = 12345;
    for (size_t i = 0; i < sizeof noise / sizeof *noise; i++) {
        x = x * 1664525u + 1013904223u;
        noise[i] = (float)(0.1 * ((double)(x >> 8) / (1u << 23) - 1.0));
    }
    float l[BLOCK], r[BLOCK];
    float *planes[2] = {l, r};
    double *cpu = malloc(BLOCKS * sizeof *cpu);
    if (!cpu)
        check(FG_ERR_NO_MEMORY, "timings");
    for (unsigned b = 0; b < BLOCKS; b++) {
        double now = b * BLOCK / FS;
        for (unsigned k = 0; k < n; k++) {
            size_t pushed = 1;
            while (pushed > 0) /* keeps each ring full */
                check(fg_fire_voice_push(e, ids[k], noise, sizeof noise / sizeof *noise, &pushed),
                      "push");
            if (s->carried && b % 2 == 0) {
                fg_fire_pose p = pose_at(s, k, now + 0.011);
                check(fg_fire_voice_set_pose(e, ids[k], &p), "pose");
            }
        }
        double c0 = bench_cpu_s();
        check(fg_engine_render(e, planes, BLOCK), "render");
        cpu[b] = bench_cpu_s() - c0;
    }
    for (unsigned k = 0; k < n; k++) {
        fg_fire_voice_report rep;
        check(fg_fire_voice_get_report(e, ids[k], &rep), "report");
        if (rep.underrun_frames) {
            fprintf(stderr, "fire_voice_bench: fire %u ran dry\n", k);
            exit(1);
        }
    }
    timing out = {bench_median(cpu + WARM_BLOCKS, BLOCKS - WARM_BLOCKS), 0.0};
    out.p99_s = bench_quantile(cpu + WARM_BLOCKS, BLOCKS - WARM_BLOCKS, 0.99);
    free(cpu);
    fg_engine_destroy(e);
    return out;
}

int main(void)
{
    static const struct {
        const char *name;
        setup s;
    } cases[] = {
        {"standing", {false, FG_ABSORPTION_OFF}},
        {"standing_iso9613", {false, FG_ABSORPTION_ISO9613}},
        {"carried", {true, FG_ABSORPTION_OFF}},
        {"carried_iso9613", {true, FG_ABSORPTION_ISO9613}},
    };
    FILE *csv = bench_open_result("fire_voice.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    fprintf(csv, "# %s; 48 kHz, 128-frame blocks (budget %.3f ms), 2 ears, CPU time per block; "
                 "per_fire: the median less the engine alone's\n", machine, 1e3 * BUDGET_S);
    fprintf(csv, "case,fires,median_us,p99_us,per_fire_us,p99_of_budget\n");
    timing none = run(&cases[0].s, 0);
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        unsigned counts[] = {1, FG_FIRE_VOICE_MAX};
        for (size_t i = 0; i < 2; i++) {
            timing m = run(&cases[c].s, counts[i]);
            double per = (m.median_s - none.median_s) / counts[i];
            fprintf(csv, "%s,%u,%.2f,%.2f,%.2f,%.4f\n", cases[c].name, counts[i],
                    1e6 * m.median_s, 1e6 * m.p99_s, 1e6 * per, m.p99_s / BUDGET_S);
            printf("%-17s %2u fire(s): %.2f us per fire per block (%.2f %% of the %.3f ms "
                   "budget); block p99 %.1f us (%.1f %%)\n",
                   cases[c].name, counts[i], 1e6 * per, 100.0 * per / BUDGET_S, 1e3 * BUDGET_S,
                   1e6 * m.p99_s, 100.0 * m.p99_s / BUDGET_S);
        }
    }
    printf("engine alone: %.2f us per block (median)\n", 1e6 * none.median_s);
    fclose(csv);
    return 0;
}
