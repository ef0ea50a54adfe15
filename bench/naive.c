/* Against the naive method: Glassner's "string of pearls", point-source
 * N-waves placed along the channel and point-sampled. For a lightning tree
 * heard from 3 km, the number of points per segment the naive render needs
 * before its error energy falls under 1 % of the WM-wave render's energy,
 * and the time of each. Writes bench/results/naive.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "fulgur/fulgur.h"
#include "synth_tree.h"

#define FS 48000.0
#define C 343.0
#define SEGMENTS 9438
#define MAX_POINTS 512
#define REPEATS 3

/* The naive render: P points per segment, each an N-wave of its own r. */
static void naive(const fg_node *nodes, size_t count, const fg_sound_config *p, const double ear[3],
                  int points, float *out, size_t frames)
{
    memset(out, 0, frames * sizeof *out);
    for (size_t i = 1; i < count; i++) {
        const fg_node *a = &nodes[i], *b = &nodes[nodes[i].parent];
        for (int k = 0; k < points; k++) {
            double u = (k + 0.5) / points;
            double x = b->x + u * (a->x - b->x), y = b->y + u * (a->y - b->y),
                   z = b->z + u * (a->z - b->z);
            double r = sqrt((ear[0] - x) * (ear[0] - x) + (ear[1] - y) * (ear[1] - y) +
                            (ear[2] - z) * (ear[2] - z));
            if (r < p->r0_m)
                r = p->r0_m;
            double stretch = sqrt(1 + p->sigma0 * log(r / p->r0_m));
            double t = p->t0_s * stretch, ps = p->r0_m * p->ps0_pa / (r * stretch) / points;
            double arrival = r / C * FS, half = t * FS;
            long n0 = (long)ceil(arrival - half), n1 = (long)floor(arrival + half);
            for (long n = n0 > 0 ? n0 : 0; n <= n1 && n < (long)frames; n++)
                out[n] += (float)(-ps * (n - arrival) / half);
        }
    }
}

/* The engine's render of the same tree, one ear, no strokes or jitter. */
static double wm_render(const fg_node *nodes, size_t count, const fg_sound_config *p,
                        const fg_listener *head, float *out, size_t frames)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .channels = 1, .max_block_frames = 512,
                            .segment_capacity = (uint32_t)count, .speed_of_sound_m_s = C};
    fg_engine *e;
    if (fg_engine_create(&cfg, &e) != FG_OK || fg_engine_set_listener(e, head) != FG_OK)
        exit(1);
    fg_discharge d = {.nodes = nodes, .node_count = count, .sound = *p, .strokes = 1, .seed = 1};
    double t0 = bench_now_s();
    if (fg_engine_post(e, &d, NULL) != FG_OK)
        exit(1);
    for (size_t at = 0; at < frames; at += 512) {
        float *plane = out + at;
        if (fg_engine_render(e, &plane, frames - at < 512 ? (uint32_t)(frames - at) : 512) != FG_OK)
            exit(1);
    }
    double t = bench_now_s() - t0;
    fg_engine_destroy(e);
    return t;
}

int main(void)
{
    fg_sound_config p;
    if (fg_preset_sound(FG_PRESET_LIGHTNING, &p) != FG_OK)
        return 1;
    p.t0_jitter = 0;
    p.return_stroke_speed_m_s = 1e12; /* the naive method has no return stroke */
    fg_node *nodes = malloc((SEGMENTS + 1) * sizeof *nodes);
    synth_tree(nodes, SEGMENTS, 5000.0, 3.0, 3);
    fg_listener head = {.position = {3000, 0, 1.7}, .forward = {-1, 0, 0}, .up = {0, 0, 1}};
    size_t frames = (size_t)(25 * FS);
    float *ref = malloc(frames * sizeof *ref), *got = malloc(frames * sizeof *got);

    double wm_times[REPEATS];
    for (int k = 0; k < REPEATS; k++)
        wm_times[k] = wm_render(nodes, SEGMENTS + 1, &p, &head, ref, frames);
    double wm_s = bench_median(wm_times, REPEATS);
    double energy = 0;
    for (size_t n = 0; n < frames; n++)
        energy += (double)ref[n] * ref[n];

    char cpu[256];
    bench_machine(cpu, sizeof cpu);
    FILE *csv = bench_open_result("naive.csv");
    fprintf(csv, "# %s; %d-segment lightning tree heard from 3 km, mono, 48 kHz\n", cpu, SEGMENTS);
    fprintf(csv, "# WM-wave (engine) time %.3f ms\n", 1e3 * wm_s);
    fprintf(csv, "points_per_segment,naive_ms,error_energy_ratio,time_ratio_naive_over_wm\n");
    printf("WM-wave render: %.3f ms\n", 1e3 * wm_s);
    for (int points = 1; points <= MAX_POINTS; points *= 2) {
        double times[REPEATS];
        for (int k = 0; k < REPEATS; k++) {
            double t0 = bench_now_s();
            naive(nodes, SEGMENTS + 1, &p, head.position, points, got, frames);
            times[k] = bench_now_s() - t0;
        }
        double err = 0;
        for (size_t n = 0; n < frames; n++)
            err += ((double)got[n] - ref[n]) * ((double)got[n] - ref[n]);
        double t = bench_median(times, REPEATS);
        fprintf(csv, "%d,%.3f,%.5f,%.2f\n", points, 1e3 * t, err / energy, t / wm_s);
        printf("%4d points/segment: %9.3f ms, error energy %.4f, %.1fx the WM-wave time\n", points,
               1e3 * t, err / energy, t / wm_s);
        if (err / energy < 0.01)
            break;
    }
    fclose(csv);
    free(nodes);
    free(ref);
    free(got);
    return 0;
}
