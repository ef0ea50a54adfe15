/* Matsuyama fig. 14, reproduced: the time to synthesize a discharge's whole
 * sound against its number of segments, 1e2 to 1e6, with a least-squares
 * line; and the cost per segment as the waveform's length changes at a
 * fixed count (thread CPU time). Writes bench/results/linearity.csv,
 * linearity_fit.txt and waveform_length.csv; "bench_linearity 5 sweep" the
 * last alone. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_render.h"
#include "bench_util.h"
#include "synth_tree.h"

#define SIZES 13
#define SWEEP_SEGMENTS 10000

static fg_listener at_3km(void)
{
    return (fg_listener){.position = {3000, 0, 1.7}, .forward = {-1, 0, 0}, .up = {0, 0, 1}};
}

#define MAX_REPEATS 19

static bench_run median_run(const fg_node *nodes, size_t count, const fg_sound_config *p,
                            int repeats)
{
    double post[MAX_REPEATS], render[MAX_REPEATS], post_cpu[MAX_REPEATS], render_cpu[MAX_REPEATS];
    bench_run r = {0};
    for (int k = 0; k < repeats; k++) {
        fg_listener head = at_3km();
        r = bench_render_tree(nodes, count, p, &head, 512);
        post[k] = r.post_s;
        render[k] = r.render_s;
        post_cpu[k] = r.post_cpu_s;
        render_cpu[k] = r.render_cpu_s;
    }
    r.post_s = bench_median(post, (size_t)repeats);
    r.render_s = bench_median(render, (size_t)repeats);
    r.post_cpu_s = bench_median(post_cpu, (size_t)repeats);
    r.render_cpu_s = bench_median(render_cpu, (size_t)repeats);
    return r;
}

/* waveform_length.csv: the waveform's length, T0 and l, at a fixed count,
 * in the thread's CPU time (this machine is shared), each render's cost
 * against the shortest T0's at the same l. */
static void waveform_sweep(fg_node *nodes, const fg_sound_config *preset, const char *cpu,
                           int repeats)
{
    const fg_sound_config p = *preset;
    int sweep_repeats = 2 * repeats + 1;
    FILE *sweep = bench_open_result("waveform_length.csv");
    fprintf(sweep, "# %s, %d segments, 512-frame blocks, thread CPU time, median of %d\n", cpu,
            SWEEP_SEGMENTS, sweep_repeats);
    fprintf(sweep, "t0_ms,half_step_m,wave_ms,ns_per_segment,render_ns_per_segment,render_vs_shortest_t0\n");
    static const double t0s[] = {0.1, 0.5, 2.0, 8.0};
    static const double halves[] = {0.5, 1.5, 5.0};
    double worst_ratio = 0;
    enum { T0S = sizeof t0s / sizeof t0s[0] };
    for (size_t b = 0; b < sizeof halves / sizeof halves[0]; b++) {
        double ns[T0S], render_ns[T0S], wave_ms[T0S], low = INFINITY, high = 0;
        for (size_t a = 0; a < T0S; a++) {
            synth_tree(nodes, SWEEP_SEGMENTS, 5000.0, 2 * halves[b], 2);
            fg_sound_config q = p;
            q.t0_s = 1e-3 * t0s[a];
            bench_run r = median_run(nodes, SWEEP_SEGMENTS + 1, &q, sweep_repeats);
            /* the longest a segment's wave can be: 2 (T + l/c) at 3 km */
            wave_ms[a] = 2e3 * (q.t0_s * 1.99 + halves[b] / 343.0);
            ns[a] = 1e9 * (r.post_cpu_s + r.render_cpu_s) / SWEEP_SEGMENTS;
            render_ns[a] = 1e9 * r.render_cpu_s / SWEEP_SEGMENTS;
            low = fmin(low, render_ns[a]);
            high = fmax(high, render_ns[a]);
        }
        worst_ratio = fmax(worst_ratio, high / low);
        for (size_t a = 0; a < T0S; a++) {
            fprintf(sweep, "%.2f,%.2f,%.3f,%.1f,%.1f,%.3f\n", t0s[a], halves[b], wave_ms[a], ns[a],
                    render_ns[a], render_ns[a] / render_ns[0]);
            printf("T0 %5.2f ms, l %4.1f m (wave <= %6.2f ms): %7.1f ns/segment, render %7.1f "
                   "(%.2fx the shortest T0's)\n",
                   t0s[a], halves[b], wave_ms[a], ns[a], render_ns[a], render_ns[a] / render_ns[0]);
        }
    }
    fprintf(sweep, "# the render's cost per segment across T0 at one l: at most %.2fx its least\n",
            worst_ratio);
    printf("render cost per segment across T0: at most %.2fx its least\n", worst_ratio);
    fclose(sweep);
}

/* usage: bench_linearity [REPEATS] [sweep]; sweep: waveform_length.csv alone */
int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    if (repeats < 1 || 2 * repeats + 1 > MAX_REPEATS)
        repeats = 5;
    fg_sound_config p;
    if (fg_preset_sound(FG_PRESET_LIGHTNING, &p) != FG_OK)
        return 1;
    char cpu[256];
    bench_machine(cpu, sizeof cpu);

    size_t max_segments = 1000000;
    fg_node *nodes = malloc((max_segments + 1) * sizeof *nodes);
    if (!nodes)
        return 1;
    if (argc > 2 && strcmp(argv[2], "sweep") == 0) {
        waveform_sweep(nodes, &p, cpu, repeats);
        free(nodes);
        return 0;
    }
    FILE *csv = bench_open_result("linearity.csv");
    fprintf(csv, "# %s, one thread, 48 kHz, 512-frame blocks, median of %d\n", cpu, repeats);
    fprintf(csv, "segments,post_ms,render_ms,total_ms,sound_s\n");
    double x[SIZES], y[SIZES];
    for (int i = 0; i < SIZES; i++) {
        size_t n = (size_t)llround(pow(10.0, 2.0 + 4.0 * i / (SIZES - 1)));
        synth_tree(nodes, n, 5000.0, 3.0, 1);
        bench_run r = median_run(nodes, n + 1, &p, n > 100000 ? (repeats + 1) / 2 : repeats);
        x[i] = (double)n;
        y[i] = 1e3 * (r.post_s + r.render_s);
        fprintf(csv, "%zu,%.4f,%.4f,%.4f,%.3f\n", n, 1e3 * r.post_s, 1e3 * r.render_s, y[i],
                r.sound_s);
        printf("%8zu segments: post %8.3f ms, render %8.3f ms, %.1f s of sound\n", n,
               1e3 * r.post_s, 1e3 * r.render_s, r.sound_s);
    }
    fclose(csv);
    bench_fit f = bench_fit_line(x, y, SIZES);
    FILE *fit = bench_open_result("linearity_fit.txt");
    fprintf(fit, "slope_ns_per_segment %.1f\nintercept_ms %.3f\nr2 %.5f\nmachine %s\n",
            1e6 * f.slope, f.intercept, f.r2, cpu);
    fclose(fit);
    printf("fit: %.1f ns/segment, intercept %.2f ms, R^2 %.5f\n", 1e6 * f.slope, f.intercept, f.r2);

    waveform_sweep(nodes, &p, cpu, repeats);
    free(nodes);
    return 0;
}
