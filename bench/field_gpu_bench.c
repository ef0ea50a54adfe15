/* The GPU field solver (whatever GL 4.3 device the EGL context finds: on a
 * machine without a GPU, Mesa's llvmpipe on the CPU) next to the CPU MGPCG
 * solver in the same run: spark-ball scene, 33^3 to 257^3, cold (phi = 0 on
 * free nodes) and warm (the previous solution after the origin moved by
 * half a cell), relative residual 1e-5 for both. Writes
 * bench/results/field_gpu.csv naming the device (GL_RENDERER). 257^3 is run
 * once per row (the CSV's repeats column says so). */
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fulgur/fulgur.h"
#include "fulgur/gpu.h"

#define MAX_REPEATS 9

typedef struct size_plan {
    int size;
    int repeats;
} size_plan;

static const size_plan plans[] = {{33, 7}, {65, 5}, {129, 3}, {257, 1}};

static void check(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "field_gpu_bench: %s: %s %s\n", what, fg_result_str(r),
                fgg_error_message());
        exit(1);
    }
}

static void set_scene(fg_field *f, const fg_field_scene *s, double dx_m)
{
    fg_shape shapes[FG_FIELD_SCENE_MAX_SHAPES];
    for (size_t i = 0; i < s->shape_count; i++)
        shapes[i] = s->shapes[i];
    shapes[0].centre_m[0] += dx_m;
    check(fg_field_set_shapes(f, shapes, s->shape_count, NULL), "shapes");
}

static void rows(FILE *out, fgg_context *ctx, const size_plan *p, int warm)
{
    fg_field_scene s;
    check(fg_field_scene_preset(FG_PRESET_SPARK_BALLS, p->size, &s), "preset");
    fg_field *f;
    check(fg_field_create(&s.grid, &f), "create");
    double cell[3];
    fg_field_cell(f, cell);
    set_scene(f, &s, 0.0);
    fgg_field *g;
    check(fgg_field_create(ctx, f, &g), "gpu create");
    if (warm) {
        check(fg_field_solve(f, NULL, NULL), "warm-up");
        check(fgg_field_solve(g, NULL, NULL), "gpu warm-up");
    }
    double tc[MAX_REPEATS], tg[MAX_REPEATS];
    fg_solve_report rc = {0};
    fgg_solve_report rg = {0};
    for (int k = 0; k < p->repeats; k++) {
        set_scene(f, &s, (k % 2 ? 0.0 : 0.5) * cell[0]);
        double t0 = bench_now_s();
        check(fgg_field_update(g, f), "gpu update");
        check(fgg_field_solve(g, &(fgg_solve_config){.cold = !warm}, &rg), "gpu solve");
        /* The gather of 8 candidates: what a growth step reads back. */
        double pt[24] = {0}, v[8];
        check(fgg_field_sample(g, pt, 8, v), "gpu sample");
        double t1 = bench_now_s();
        check(fg_field_solve(f, &(fg_solve_config){.cold = !warm}, &rc), "cpu solve");
        double t2 = bench_now_s();
        tg[k] = t1 - t0;
        tc[k] = t2 - t1;
    }
    double mc = bench_median(tc, (size_t)p->repeats) * 1e3;
    double mg = bench_median(tg, (size_t)p->repeats) * 1e3;
    const char *start = warm ? "warm" : "cold";
    fprintf(out, "%d,cpu-mgpcg,%s,%d,%.3f,%d,0,%.2e\n", p->size, start, p->repeats, mc,
            rc.iterations, rc.residual);
    fprintf(out, "%d,gpu,%s,%d,%.3f,%d,%d,%.2e\n", p->size, start, p->repeats, mg, rg.cycles,
            rg.cg_iterations, rg.residual);
    printf("%3d^3 %s: cpu mgpcg %9.2f ms (%d it)   gpu %9.2f ms (%d cycles + %d CG, "
           "residual %.1e)\n", p->size, start, mc, rc.iterations, mg, rg.cycles,
           rg.cg_iterations, rg.residual);
    fflush(stdout);
    fgg_field_destroy(g);
    fg_field_destroy(f);
}

int main(void)
{
    fgg_context *ctx;
    check(fgg_context_create(NULL, &ctx), "GL context");
    fgg_context_info info;
    fgg_context_get_info(ctx, &info);
    FILE *out = bench_open_result("field_gpu.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    fprintf(out, "# fulgur field_gpu_bench; CPU (one thread): %s\n", machine);
    fprintf(out, "# GPU device (GL_RENDERER): %s, %s, via %s\n", info.renderer, info.version,
            info.platform);
    fprintf(out, "# spark-ball scene; warm = previous solution, origin moved half a cell; "
                 "relative residual 1e-5; GPU time includes the boundary update and an "
                 "8-point gather\n");
    fprintf(out, "size,solver,start,repeats,median_ms,cycles_or_iterations,cg_iterations,"
                 "residual\n");
    printf("GPU: %s (%s)\n", info.renderer, info.platform);
    for (size_t i = 0; i < sizeof plans / sizeof plans[0]; i++)
        for (int warm = 0; warm < 2; warm++)
            rows(out, ctx, &plans[i], warm);
    fclose(out);
    fgg_context_destroy(ctx);
    return 0;
}
