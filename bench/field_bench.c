/* The field and the growth on one core: Laplace solve time at 33^3 to 257^3
 * for the multigrid solver (V-cycles, MGPCG where they stall) and SOR,
 * cold (phi = 0 on free nodes) and warm (the previous frame's solution
 * after the origin moved by half a cell), and the time to produce a
 * spark-ball and a plasma-ball discharge (shapes + a solve to the growth's
 * tolerance, FG_GROWTH_FIELD_TOLERANCE, + tree) at 33^3 and 65^3, with
 * their mean segment counts against Matsuyama's table 2.
 * Times are the thread's CPU time (the solver runs on the calling thread),
 * so that a loaded machine's waits do not count. Writes
 * bench/results/field_solve.csv. SOR is capped by a sweep budget at the
 * larger sizes; the CSV says where the cap stopped it. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fulgur/fulgur.h"

#define MAX_REPEATS 25
#define SEEDS 20
#define SEEDS_LONG 200

typedef struct size_plan {
    int size;
    int repeats;      /* multigrid */
    int sor_repeats;
    int sor_sweeps;   /* the budget: 0 means the solver's default */
} size_plan;

static const size_plan plans[] = {
    {33, 15, 5, 0},
    {65, 9, 3, 0},
    {129, 3, 1, 1500},
    {257, 3, 1, 150},
};

static void check(fg_result r, const char *what)
{
    if (r != FG_OK && r != FG_ERR_NOT_CONVERGED) {
        fprintf(stderr, "field_bench: %s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

/* The spark-ball scene with the origin moved along x by dx_m. */
static void set_scene(fg_field *f, fg_field_scene *s, double dx_m)
{
    fg_shape shapes[FG_FIELD_SCENE_MAX_SHAPES];
    for (size_t i = 0; i < s->shape_count; i++)
        shapes[i] = s->shapes[i];
    shapes[0].centre_m[0] += dx_m;
    check(fg_field_set_shapes(f, shapes, s->shape_count, NULL), "shapes");
}

static void solve_row(FILE *out, const size_plan *p, fg_solver solver, int warm)
{
    fg_field_scene s;
    check(fg_field_scene_preset(FG_PRESET_SPARK_BALLS, p->size, &s), "preset");
    fg_field *f;
    check(fg_field_create(&s.grid, &f), "create");
    double cell[3];
    fg_field_cell(f, cell);
    int repeats = solver == FG_SOLVER_MULTIGRID ? p->repeats : p->sor_repeats;
    int budget = solver == FG_SOLVER_SOR ? p->sor_sweeps : 0;
    fg_solve_config c = {.solver = solver, .max_iterations = budget, .cold = !warm};
    double t[MAX_REPEATS];
    fg_solve_report rep = {0};
    fg_result last = FG_OK;
    set_scene(f, &s, 0.0);
    if (warm) /* the previous frame, solved with multigrid */
        check(fg_field_solve(f, NULL, NULL), "warm-up");
    for (int k = 0; k < repeats; k++) {
        set_scene(f, &s, (k % 2 ? 0.0 : 0.5) * cell[0]);
        double t0 = bench_cpu_s();
        last = fg_field_solve(f, &c, &rep);
        t[k] = bench_cpu_s() - t0;
        check(last, "solve");
        if (warm && last != FG_OK) /* keep the next start a converged one */
            check(fg_field_solve(f, NULL, NULL), "re-solve");
    }
    double med = bench_median(t, (size_t)repeats) * 1e3;
    const char *name = solver == FG_SOLVER_MULTIGRID ? "multigrid" : "sor";
    fprintf(out, "solve,%d,%s,%s,%d,%.3f,%d,%.2e,%s\n", p->size, name, warm ? "warm" : "cold",
            repeats, med, rep.iterations, rep.residual,
            last == FG_OK ? "converged" : "capped by the sweep budget");
    printf("%3d^3 %-9s %-4s %9.2f ms  %5d it  residual %.1e%s\n", p->size, name,
           warm ? "warm" : "cold", med, rep.iterations, rep.residual,
           last == FG_OK ? "" : "  (capped)");
    fflush(stdout);
    fg_field_destroy(f);
}

/* A whole discharge: shapes, a cold solve, the tree; and the warm case (the
 * field kept from the previous discharge: a re-solve that finds it
 * converged, then the tree). */
static void discharge_rows(FILE *out, fg_preset preset, int size)
{
    fg_field_scene s;
    check(fg_field_scene_preset(preset, size, &s), "preset");
    fg_field *f;
    fg_tree *tree;
    check(fg_field_create(&s.grid, &f), "create");
    check(fg_tree_create(256, &tree), "tree");
    fg_field_source src;
    fg_field_source_init(f, &src);
    double cold[SEEDS], warm[SEEDS], grow[SEEDS], segs = 0.0, segs_long = 0.0;
    const fg_solve_config grow_solve = {.tolerance = FG_GROWTH_FIELD_TOLERANCE, .cold = 1};
    for (int k = 0; k < SEEDS; k++) {
        s.growth.seed = (uint64_t)k + 1;
        double t0 = bench_cpu_s();
        check(fg_field_set_shapes(f, s.shapes, s.shape_count, NULL), "shapes");
        check(fg_field_solve(f, &grow_solve, NULL), "solve");
        double t1 = bench_cpu_s();
        check(fg_grow_matsuyama(&src, &s.growth, tree, NULL), "grow");
        double t2 = bench_cpu_s();
        check(fg_field_solve(f, &(fg_solve_config){.tolerance = FG_GROWTH_FIELD_TOLERANCE}, NULL),
              "warm solve");
        check(fg_grow_matsuyama(&src, &s.growth, tree, NULL), "grow");
        double t3 = bench_cpu_s();
        cold[k] = t2 - t0;
        grow[k] = t2 - t1;
        warm[k] = t3 - t2;
        segs += (double)(fg_tree_count(tree) - 1);
    }
    for (int k = 0; k < SEEDS_LONG; k++) {
        s.growth.seed = (uint64_t)k + 1;
        check(fg_grow_matsuyama(&src, &s.growth, tree, NULL), "grow");
        segs_long += (double)(fg_tree_count(tree) - 1);
    }
    const char *name = fg_preset_name(preset);
    double paper = preset == FG_PRESET_SPARK_BALLS ? 72.0 : 78.0;
    double mc = bench_median(cold, SEEDS) * 1e3, mw = bench_median(warm, SEEDS) * 1e3,
           mg = bench_median(grow, SEEDS) * 1e3;
    fprintf(out, "discharge,%d,%s,cold,%d,%.3f,,,shapes + cold multigrid solve to %.0e + Matsuyama "
                 "tree\n",
            size, name, SEEDS, mc, FG_GROWTH_FIELD_TOLERANCE);
    fprintf(out, "discharge,%d,%s,warm,%d,%.3f,,,field kept: warm re-solve + tree\n", size,
            name, SEEDS, mw);
    fprintf(out, "discharge,%d,%s,tree,%d,%.3f,,,Matsuyama growth alone\n", size, name, SEEDS,
            mg);
    fprintf(out, "segments,%d,%s,mean,%d,%.1f,,,paper table 2: %.0f\n", size, name, SEEDS,
            segs / SEEDS, paper);
    fprintf(out, "segments,%d,%s,mean,%d,%.1f,,,paper table 2: %.0f\n", size, name,
            SEEDS_LONG, segs_long / SEEDS_LONG, paper);
    printf("%s at %d^3: cold %.2f ms, warm %.2f ms, tree alone %.3f ms; mean segments %.1f "
           "(%d seeds), %.1f (%d seeds), paper %.0f\n",
           name, size, mc, mw, mg, segs / SEEDS, SEEDS, segs_long / SEEDS_LONG, SEEDS_LONG, paper);
    fflush(stdout);

    if (size != 65) {
        fg_tree_destroy(tree);
        fg_field_destroy(f);
        return;
    }
    /* DBM: slower by design; a few seeds, at 65^3 only. */
    double dbm[3];
    fg_growth_report rep;
    for (int k = 0; k < 3; k++) {
        check(fg_field_solve(f, &(fg_solve_config){.cold = 1}, NULL), "solve");
        s.growth.seed = (uint64_t)k + 1;
        double t0 = bench_cpu_s();
        check(fg_grow_dbm(f, &s.growth, tree, &rep), "dbm");
        dbm[k] = bench_cpu_s() - t0;
    }
    double md = bench_median(dbm, 3) * 1e3;
    fprintf(out, "dbm,65,%s,cold,3,%.3f,%d,,DBM growth after a cold solve (%zu nodes last)\n",
            name, md, rep.solver_iterations, rep.nodes);
    printf("%s DBM at 65^3: %.1f ms (%d solver iterations, %zu nodes last seed)\n", name, md,
           rep.solver_iterations, rep.nodes);
    fg_tree_destroy(tree);
    fg_field_destroy(f);
}

int main(void)
{
    FILE *out = bench_open_result("field_solve.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    fprintf(out, "# fulgur field_bench, one thread, CPU time; %s\n", machine);
    fprintf(out, "# solve rows: the spark-ball scene; warm = previous solution, origin moved "
                 "half a cell; tolerance 1e-5 relative residual\n");
    fprintf(out, "kind,size,what,start,repeats,median_ms,iterations,residual,note\n");
    for (size_t i = 0; i < sizeof plans / sizeof plans[0]; i++)
        for (int warm = 0; warm < 2; warm++) {
            solve_row(out, &plans[i], FG_SOLVER_MULTIGRID, warm);
            solve_row(out, &plans[i], FG_SOLVER_SOR, warm);
        }
    for (int size = 33; size <= 65; size += 32) {
        discharge_rows(out, FG_PRESET_SPARK_BALLS, size);
        discharge_rows(out, FG_PRESET_PLASMA_BALL, size);
    }
    fclose(out);
    return 0;
}
