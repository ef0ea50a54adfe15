/* The flame simulation's cost on one core (fulgur/flame.h): a campfire (a
 * 4 cm sphere releasing a litre of mixture a second, about 2 kW) on an
 * n^3 grid 0.64 m across, stepped at 360 Hz. After 0.3 s of start-up (the
 * flame reaches its height), each of the next steps is timed, and the
 * flame front's share measured by running a second front on the same
 * burn field and velocity. The flux-to-sound cost is bench_fire's.
 * Times are CPU seconds of this thread (the machine is shared); wall
 * times beside them. Writes bench/results/flame.csv. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fulgur/flame.h"

#define STEP_HZ 360.0
#define WARMUP_STEPS 108
#define TIMED_STEPS 36

static void check(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "flame_bench: %s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

static void bench_grid(FILE *out, int n)
{
    fg_flame_sim_config c = {.cells = {n, n, n}, .cell_m = 0.64 / n, .emitters = 1};
    c.emitter[0] = (fg_flame_emitter){.kind = FG_FLAME_EMITTER_SOURCE,
                                      .shape = FG_FLAME_SPHERE,
                                      .centre_m = {0.32, 0.32, 0.08},
                                      .radius_m = 0.04,
                                      .fuel_m3_s = 1e-3};
    size_t bytes = fg_flame_sim_memory_bytes(&c);
    fg_flame_sim *sim;
    check(fg_flame_sim_create(&c, &sim), "create");
    fg_flame_sim_get_config(sim, &c);
    fg_flame_front_config fc = {.grid = {.size = {n, n, n}, .cell_m = c.cell_m},
                                .iso_level = c.iso_level};
    fg_flame_front *front;
    check(fg_flame_front_create(&fc, &front), "front");
    double step[TIMED_STEPS], wall[TIMED_STEPS], edge[TIMED_STEPS];
    double triangles = 0.0, iterations = 0.0;
    for (int s = 0; s < WARMUP_STEPS + TIMED_STEPS; s++) {
        double c0 = bench_cpu_s(), w0 = bench_now_s();
        check(fg_flame_sim_step(sim, NULL), "step");
        double c1 = bench_cpu_s(), w1 = bench_now_s();
        if (s < WARMUP_STEPS)
            continue;
        int t = s - WARMUP_STEPS;
        step[t] = c1 - c0;
        wall[t] = w1 - w0;
        fg_flame_field_view burn;
        fg_flame_velocity v;
        check(fg_flame_sim_field(sim, FG_FLAME_FIELD_BURN, &burn), "field");
        check(fg_flame_sim_velocity(sim, &v), "velocity");
        fg_flame_flux flux;
        double c2 = bench_cpu_s();
        check(fg_flame_front_flux(front, burn.data, &v, &flux), "flux");
        edge[t] = bench_cpu_s() - c2;
        fg_flame_sim_stats st;
        fg_flame_sim_get_stats(sim, &st);
        triangles += (double)flux.triangles / TIMED_STEPS;
        iterations += (double)st.projection_iterations / TIMED_STEPS;
    }
    double ms = bench_median(step, TIMED_STEPS) * 1e3;
    double wall_ms = bench_median(wall, TIMED_STEPS) * 1e3;
    double front_ms = bench_median(edge, TIMED_STEPS) * 1e3;
    double p90 = bench_quantile(step, TIMED_STEPS, 0.9) * 1e3;
    double budget_ms = 1e3 / STEP_HZ;
    printf("%d^3 (h %.2f cm, %.1f MiB): %.2f ms a step (p90 %.2f, wall %.2f), front %.2f ms; "
           "%.1f s per simulated second; real-time factor %.3f; %.0f triangles, %.1f CG "
           "iterations\n",
           n, c.cell_m * 100, bytes / 1048576.0, ms, p90, wall_ms, front_ms, ms * STEP_HZ / 1e3,
           budget_ms / ms, triangles, iterations);
    fprintf(out, "%d,%.4f,%.1f,%.3f,%.3f,%.3f,%.3f,%.2f,%.4f,%.0f,%.1f\n", n, c.cell_m,
            bytes / 1048576.0, ms, p90, wall_ms, front_ms, ms * STEP_HZ / 1e3, budget_ms / ms,
            triangles, iterations);
    fg_flame_front_destroy(front);
    fg_flame_sim_destroy(sim);
}

int main(int argc, char **argv)
{
    /* the grids: 16 24 32 48, or those given */
    int grids[8] = {16, 24, 32, 48}, count = 4;
    if (argc > 1) {
        count = 0;
        for (int i = 1; i < argc && count < 8; i++)
            grids[count++] = atoi(argv[i]);
    }
    char machine[256];
    bench_machine(machine, sizeof machine);
    FILE *out = bench_open_result("flame.csv");
    fprintf(out, "# flame_bench: campfire, %d steps timed after %d at %.0f Hz; %s\n", TIMED_STEPS,
            WARMUP_STEPS, STEP_HZ, machine);
    fprintf(out, "cells,cell_m,mib,step_cpu_ms_median,step_cpu_ms_p90,step_wall_ms_median,"
                 "front_cpu_ms_median,cpu_s_per_sim_s,realtime_factor,triangles,cg_iterations\n");
    for (int i = 0; i < count; i++)
        bench_grid(out, grids[i]);
    fclose(out);
    return 0;
}
