/* The GPU field solver against the CPU one, on llvmpipe: the same scenes
 * solved cold and warm agree to 1e-4; growth reads either field alike (and
 * to the bit when the node values are equal); the thin-tree scene that
 * stalls plain V-cycles converges through the MGPCG fallback; bad input is
 * refused and changes nothing. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fulgur/field_scene.h"
#include "fulgur/growth.h"
#include "fulgur/gpu.h"
#include "fulgur/tree.h"

static fgg_context *ctx;

static int setup(void **state)
{
    (void)state;
    if (fgg_context_create(NULL, &ctx) != FG_OK) {
        print_error("no GL 4.3 context: %s\n", fgg_error_message());
        return -1;
    }
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    fgg_context_destroy(ctx);
    return 0;
}

/* ---- scenes ---- */

typedef enum { SCENE_SPARK, SCENE_PLASMA, SCENE_THIN } scene_kind;

/* A one-node-thick tree (trunk and side branches, like a DBM channel) held
 * at 0 inside a unit box whose top is 1. x0 on an odd node keeps the trunk
 * off every coarse grid. */
static size_t thin_tree(fg_shape *s, int size)
{
    double h = 1.0 / (size - 1), x0 = (size / 2 - 1) * h;
    size_t n = 0;
    s[n++] = (fg_shape){.kind = FG_SHAPE_PLANE, .role = FG_ROLE_TARGET, .centre_m = {0, 0, 0.95},
                        .normal = {0, 0, -1}};
    s[n++] = (fg_shape){.kind = FG_SHAPE_BOX, .role = FG_ROLE_ORIGIN,
                        .box_min_m = {x0, 0.5, 0.1}, .box_max_m = {x0, 0.5, 0.8}};
    for (int b = 0; b < 6; b++) {
        /* Heights and lengths on nodes of any 2^k + 1 grid. */
        double z = round((13 + 6 * b) / 64.0 / h) * h, len = round((6 + 3 * b) / 64.0 / h) * h;
        if (b % 2)
            s[n++] = (fg_shape){.kind = FG_SHAPE_BOX, .role = FG_ROLE_ORIGIN,
                                .box_min_m = {x0, 0.5, z}, .box_max_m = {x0 + len, 0.5, z}};
        else
            s[n++] = (fg_shape){.kind = FG_SHAPE_BOX, .role = FG_ROLE_ORIGIN,
                                .box_min_m = {x0, 0.5 - len, z}, .box_max_m = {x0, 0.5, z}};
    }
    /* Point shapes: single nodes hanging off the trunk's end, as a DBM
     * channel grows them. */
    for (int p = 1; p <= 4; p++)
        s[n++] = (fg_shape){.kind = FG_SHAPE_POINT, .role = FG_ROLE_ORIGIN,
                            .centre_m = {x0 + p * h, 0.5 + p * h, 0.8}};
    return n;
}

typedef struct scene {
    fg_grid_config grid;
    fg_shape shapes[32];
    size_t count;
    fg_growth_config growth;
} scene;

static void make_scene(scene_kind kind, int size, scene *out)
{
    memset(out, 0, sizeof *out);
    if (kind == SCENE_THIN) {
        out->grid = (fg_grid_config){.size = {size, size, size}, .max_m = {1, 1, 1}};
        out->count = thin_tree(out->shapes, size);
        out->growth = (fg_growth_config){.step_m = 2.0 / (size - 1)};
        return;
    }
    fg_field_scene s;
    fg_preset p = kind == SCENE_SPARK ? FG_PRESET_SPARK_BALLS : FG_PRESET_PLASMA_BALL;
    assert_int_equal(fg_field_scene_preset(p, size, &s), FG_OK);
    out->grid = s.grid;
    out->count = s.shape_count;
    memcpy(out->shapes, s.shapes, s.shape_count * sizeof s.shapes[0]);
    out->growth = s.growth;
}

/* Moves every sphere and point shape by a fraction of a cell (a warm
 * re-solve's small change between frames). */
static void nudge(scene *sc, double by_m)
{
    for (size_t i = 0; i < sc->count; i++)
        if (sc->shapes[i].kind == FG_SHAPE_SPHERE || sc->shapes[i].kind == FG_SHAPE_POINT) {
            sc->shapes[i].centre_m[0] += sc->shapes[i].kind == FG_SHAPE_POINT ? 2.5 * by_m : by_m;
            if (sc->shapes[i].kind == FG_SHAPE_SPHERE && !sc->shapes[i].outside)
                sc->shapes[i].radius_m *= 1.02;
        }
}

static fg_field *cpu_field(const scene *sc)
{
    fg_field *f = NULL;
    assert_int_equal(fg_field_create(&sc->grid, &f), FG_OK);
    assert_int_equal(fg_field_set_shapes(f, sc->shapes, sc->count, NULL), FG_OK);
    return f;
}

static void cpu_solve(fg_field *f)
{
    fg_solve_config c = {.tolerance = 1e-8, .max_iterations = 100};
    assert_int_equal(fg_field_solve(f, &c, NULL), FG_OK);
}

static double max_difference(fg_field *cpu, fgg_field *gpu)
{
    size_t n = fg_field_node_count(cpu);
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(fg_field_get_potential(cpu, a), FG_OK);
    assert_int_equal(fgg_field_read_potential(gpu, b), FG_OK);
    double worst = 0.0;
    for (size_t i = 0; i < n; i++)
        worst = fmax(worst, fabs(a[i] - b[i]));
    free(a);
    free(b);
    return worst;
}

/* ---- GPU against CPU, cold and warm ---- */

typedef struct match_case {
    const char *name;
    scene_kind kind;
    int size;
} match_case;

static const match_case match_cases[] = {
    {"spark balls 33", SCENE_SPARK, 33},
    {"spark balls 65", SCENE_SPARK, 65},
    {"plasma ball 33", SCENE_PLASMA, 33},
    {"plasma ball 65", SCENE_PLASMA, 65},
    {"thin tree 33", SCENE_THIN, 33},
};

static void gpu_matches_cpu(void **state)
{
    (void)state;
    for (size_t t = 0; t < sizeof match_cases / sizeof match_cases[0]; t++) {
        const match_case *mc = &match_cases[t];
        scene sc;
        make_scene(mc->kind, mc->size, &sc);
        fg_field *cpu = cpu_field(&sc);
        fgg_field *gpu = NULL;
        assert_int_equal(fgg_field_create(ctx, cpu, &gpu), FG_OK);
        cpu_solve(cpu);
        /* A relative residual of 1e-5 leaves errors near 1e-4 at 65^3. */
        const fgg_solve_config tight = {.tolerance = 1e-6};
        fgg_solve_report cold, warm;
        assert_int_equal(fgg_field_solve(gpu, &tight, &cold), FG_OK);
        double d_cold = max_difference(cpu, gpu);

        nudge(&sc, 0.4 * (sc.grid.max_m[0] - sc.grid.min_m[0]) / (mc->size - 1));
        assert_int_equal(fg_field_set_shapes(cpu, sc.shapes, sc.count, NULL), FG_OK);
        assert_int_equal(fgg_field_update(gpu, cpu), FG_OK);
        cpu_solve(cpu);
        assert_int_equal(fgg_field_solve(gpu, &tight, &warm), FG_OK);
        double d_warm = max_difference(cpu, gpu);
        print_message("%-15s cold: %2d cycles %2d CG, residual %.1e, max |gpu - cpu| %.1e; "
                      "warm: %2d cycles %2d CG, from %.1e, max |gpu - cpu| %.1e\n",
                      mc->name, cold.cycles, cold.cg_iterations, cold.residual, d_cold,
                      warm.cycles, warm.cg_iterations, warm.initial_residual, d_warm);
        assert_true(cold.residual <= 1e-6 && warm.residual <= 1e-6);
        assert_true(d_cold < 1e-4);
        assert_true(d_warm < 1e-4);
        assert_true(warm.initial_residual < cold.initial_residual);
        fgg_field_destroy(gpu);
        fg_field_destroy(cpu);
    }
}

/* ---- the fallback ---- */

static void thin_tree_falls_back_to_mgpcg(void **state)
{
    (void)state;
    scene sc;
    make_scene(SCENE_THIN, 65, &sc);
    fg_field *cpu = cpu_field(&sc);
    fgg_field *gpu = NULL;
    assert_int_equal(fgg_field_create(ctx, cpu, &gpu), FG_OK);
    /* Plain cycles alone: they stall. */
    fgg_solve_report plain, rep;
    fgg_solve_config only = {.max_cycles = 20, .vcycles_only = 1};
    fg_result r = fgg_field_solve(gpu, &only, &plain);
    assert_int_equal(fgg_field_solve(gpu, &(fgg_solve_config){.cold = 1}, &rep), FG_OK);
    cpu_solve(cpu);
    double d = max_difference(cpu, gpu);
    print_message("thin tree 65: plain V-cycles: %d cycles, residual %.1e (%s); full solve: %d cycles, "
                  "then %d MGPCG iterations to %.1e; max |gpu - cpu| %.1e\n",
                  plain.cycles, plain.residual, fg_result_str(r), rep.cycles, rep.cg_iterations,
                  rep.residual, d);
    assert_int_equal(r, FG_ERR_NOT_CONVERGED);
    assert_true(plain.residual > 1e-3);
    assert_true(rep.cg_iterations > 0);
    assert_true(rep.cycles <= 3);
    assert_true(rep.residual <= 1e-5);
    assert_true(d < 1e-4);
    fgg_field_destroy(gpu);
    fg_field_destroy(cpu);
}

/* ---- growth on either field ---- */

typedef struct tree_stats {
    size_t count;
    int depth;     /* edges on the longest root-to-node path */
    double reach;  /* farthest node from the root, metres */
} tree_stats;

static tree_stats stats_of(fg_tree *t)
{
    tree_stats s = {fg_tree_count(t), 0, 0.0};
    fg_node *n = fg_tree_nodes(t);
    int *depth = calloc(s.count ? s.count : 1, sizeof *depth);
    assert_non_null(depth);
    for (size_t i = 1; i < s.count; i++) {
        depth[i] = depth[n[i].parent] + 1;
        s.depth = depth[i] > s.depth ? depth[i] : s.depth;
        s.reach = fmax(s.reach, hypot(hypot(n[i].x - n[0].x, n[i].y - n[0].y), n[i].z - n[0].z));
    }
    free(depth);
    return s;
}

static void growth_reads_either_field(void **state)
{
    (void)state;
    scene sc;
    make_scene(SCENE_SPARK, 65, &sc);
    fg_field *cpu = cpu_field(&sc);
    fgg_field *gpu = NULL;
    assert_int_equal(fgg_field_create(ctx, cpu, &gpu), FG_OK);
    cpu_solve(cpu);
    assert_int_equal(fgg_field_solve(gpu, NULL, NULL), FG_OK);
    fg_field_source cs, gs;
    fg_field_source_init(cpu, &cs);
    fgg_field_source_init(gpu, cpu, &gs);
    assert_true(gs.cell_m == cs.cell_m);
    fg_tree *a = NULL, *b = NULL;
    assert_int_equal(fg_tree_create(0, &a), FG_OK);
    assert_int_equal(fg_tree_create(0, &b), FG_OK);

    /* Fields within 1e-4 of each other: the same statistics over seeds. */
    enum { SEEDS = 6 };
    double mean[2][3] = {{0}};
    for (uint64_t seed = 1; seed <= SEEDS; seed++) {
        fg_growth_config g = sc.growth;
        g.seed = seed;
        assert_int_equal(fg_grow_matsuyama(&cs, &g, a, NULL), FG_OK);
        assert_int_equal(fg_grow_matsuyama(&gs, &g, b, NULL), FG_OK);
        tree_stats s[2] = {stats_of(a), stats_of(b)};
        for (int w = 0; w < 2; w++) {
            mean[w][0] += (double)s[w].count / SEEDS;
            mean[w][1] += (double)s[w].depth / SEEDS;
            mean[w][2] += s[w].reach / SEEDS;
        }
    }
    print_message("growth over %d seeds, cpu / gpu field: nodes %.1f / %.1f, depth %.1f / %.1f, "
                  "reach %.4f / %.4f m\n", SEEDS, mean[0][0], mean[1][0], mean[0][1], mean[1][1],
                  mean[0][2], mean[1][2]);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(mean[0][k] - mean[1][k]) <= 0.1 * mean[0][k]);

    /* The GPU's node values on the CPU field: identical trees. */
    size_t n = fg_field_node_count(cpu);
    double *phi = malloc(n * sizeof *phi);
    assert_non_null(phi);
    assert_int_equal(fgg_field_read_potential(gpu, phi), FG_OK);
    assert_int_equal(fg_field_set_potential(cpu, phi), FG_OK);
    free(phi);
    for (uint64_t seed = 1; seed <= 3; seed++) {
        fg_growth_config g = sc.growth;
        g.seed = seed;
        assert_int_equal(fg_grow_matsuyama(&cs, &g, a, NULL), FG_OK);
        assert_int_equal(fg_grow_matsuyama(&gs, &g, b, NULL), FG_OK);
        assert_int_equal(fg_tree_count(a), fg_tree_count(b));
        assert_memory_equal(fg_tree_nodes(a), fg_tree_nodes(b), fg_tree_count(a) * sizeof(fg_node));
    }
    /* And samples equal to the bit at arbitrary points. */
    double pts[3 * 64], va[64], vb[64];
    for (int i = 0; i < 64; i++)
        for (int k = 0; k < 3; k++)
            pts[3 * i + k] = sc.grid.min_m[k] + (sc.grid.max_m[k] - sc.grid.min_m[k]) *
                                                    ((i * 37 + k * 11) % 64 + 0.3) / 64.0;
    assert_int_equal(fg_field_sample(cpu, pts, 64, va), FG_OK);
    assert_int_equal(fgg_field_sample(gpu, pts, 64, vb), FG_OK);
    assert_memory_equal(va, vb, sizeof va);
    fg_tree_destroy(a);
    fg_tree_destroy(b);
    fgg_field_destroy(gpu);
    fg_field_destroy(cpu);
}

/* ---- bad input ---- */

static void bad_input_changes_nothing(void **state)
{
    (void)state;
    scene sc;
    make_scene(SCENE_SPARK, 33, &sc);
    fg_field *cpu = cpu_field(&sc);
    fgg_field *gpu = NULL, *none = NULL;
    double p[3] = {0, 0, 0}, v = 0.0;

    assert_int_equal(fgg_field_create(NULL, cpu, &gpu), FG_ERR_NULL);
    assert_int_equal(fgg_field_create(ctx, NULL, &gpu), FG_ERR_NULL);
    assert_int_equal(fgg_field_create(ctx, cpu, NULL), FG_ERR_NULL);
    assert_null(gpu);
    fg_field *empty = NULL;
    assert_int_equal(fg_field_create(&sc.grid, &empty), FG_OK);
    assert_int_equal(fgg_field_create(ctx, empty, &none), FG_ERR_ARGUMENT);
    assert_null(none);
    assert_true(strstr(fgg_error_message(), "no shapes") != NULL);

    assert_int_equal(fgg_field_create(ctx, cpu, &gpu), FG_OK);
    assert_int_equal(fgg_field_solve(gpu, NULL, NULL), FG_OK);
    size_t n = fg_field_node_count(cpu);
    double *before = malloc(n * sizeof *before), *after = malloc(n * sizeof *after);
    assert_non_null(before);
    assert_non_null(after);
    assert_int_equal(fgg_field_read_potential(gpu, before), FG_OK);

    assert_int_equal(fgg_field_solve(NULL, NULL, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_field_update(NULL, cpu), FG_ERR_NULL);
    assert_int_equal(fgg_field_update(gpu, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_field_read_potential(gpu, NULL), FG_ERR_NULL);
    assert_int_equal(fgg_field_sample(NULL, p, 1, &v), FG_ERR_NULL);
    assert_int_equal(fgg_field_sample(gpu, NULL, 1, &v), FG_ERR_NULL);
    assert_int_equal(fgg_field_sample(gpu, p, 1, NULL), FG_ERR_NULL);
    const fgg_solve_config bad_configs[] = {
        {.tolerance = -1e-3}, {.tolerance = 1.0}, {.tolerance = NAN}, {.max_cycles = -1}};
    for (size_t i = 0; i < sizeof bad_configs / sizeof bad_configs[0]; i++)
        assert_int_equal(fgg_field_solve(gpu, &bad_configs[i], NULL), FG_ERR_ARGUMENT);

    /* An update from a field of another grid: refused. */
    const int sizes[][3] = {{65, 65, 65}, {33, 33, 17}};
    for (size_t i = 0; i < 2; i++) {
        scene other = sc;
        memcpy(other.grid.size, sizes[i], sizeof sizes[i]);
        fg_field *o = cpu_field(&other);
        assert_int_equal(fgg_field_update(gpu, o), FG_ERR_ARGUMENT);
        fg_field_destroy(o);
    }
    scene moved = sc;
    moved.grid.max_m[2] *= 1.5;
    fg_field *o = cpu_field(&moved);
    assert_int_equal(fgg_field_update(gpu, o), FG_ERR_ARGUMENT);
    fg_field_destroy(o);
    /* A description with its shapes gone: refused. */
    assert_int_equal(fgg_field_update(gpu, empty), FG_ERR_ARGUMENT);

    /* NaN or infinite points: refused, out untouched. */
    double pts[6] = {0, 0, 0, 0, 0, 0}, out[2] = {-7.0, -7.0};
    for (int k = 0; k < 6; k++) {
        double keep = pts[k];
        pts[k] = k % 2 ? INFINITY : NAN;
        assert_int_equal(fgg_field_sample(gpu, pts, 2, out), FG_ERR_NOT_FINITE);
        assert_true(out[0] == -7.0 && out[1] == -7.0);
        pts[k] = keep;
    }
    assert_int_equal(fgg_field_sample(gpu, pts, 0, NULL), FG_OK);

    assert_int_equal(fgg_field_read_potential(gpu, after), FG_OK);
    assert_memory_equal(before, after, n * sizeof *before);
    free(before);
    free(after);
    fgg_field_destroy(gpu);
    fgg_field_destroy(NULL);
    fg_field_destroy(empty);
    fg_field_destroy(cpu);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gpu_matches_cpu),
        cmocka_unit_test(thin_tree_falls_back_to_mgpcg),
        cmocka_unit_test(growth_reads_either_field),
        cmocka_unit_test(bad_input_changes_nothing),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
