/* Growth: trees reach the target, avoid obstacles, carry a connected main
 * channel, repeat with their seed; eq. 2's probabilities (chi-square on a
 * fixed field); the field-source seam with an analytic field; DBM; the
 * presets' segment counts; the growth's field tolerance against a
 * converged field; bad input. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "fulgur/fulgur.h"
#include "growth/growth_internal.h"

typedef struct scene {
    fg_field_scene setup;
    fg_field *field;
    fg_field_source src;
    fg_tree *tree;
} scene;

static void scene_init(scene *s, fg_preset preset, int size)
{
    assert_int_equal(fg_field_scene_preset(preset, size, &s->setup), FG_OK);
    assert_int_equal(fg_field_create(&s->setup.grid, &s->field), FG_OK);
    assert_int_equal(fg_field_set_shapes(s->field, s->setup.shapes, s->setup.shape_count, NULL),
                     FG_OK);
    assert_int_equal(fg_field_solve(s->field, NULL, NULL), FG_OK);
    fg_field_source_init(s->field, &s->src);
    assert_int_equal(fg_tree_create(64, &s->tree), FG_OK);
}

static void scene_deinit(scene *s)
{
    fg_tree_destroy(s->tree);
    fg_field_destroy(s->field);
}

static double seg_len(const fg_node *v, size_t i)
{
    const fg_node *p = &v[v[i].parent];
    return sqrt((v[i].x - p->x) * (v[i].x - p->x) + (v[i].y - p->y) * (v[i].y - p->y) +
                (v[i].z - p->z) * (v[i].z - p->z));
}

/* The checks every grown tree must pass; returns the number of nodes that
 * reached the target. */
static size_t check_tree(fg_field *f, fg_tree *t, double step_m, int lattice)
{
    fg_node *v = fg_tree_nodes(t);
    size_t n = fg_tree_count(t), hits = 0, main = 0, end = 0;
    assert_int_equal(fg_tree_check(v, n, NULL), FG_OK);
    for (size_t i = 0; i < n; i++) {
        double x[3] = {v[i].x, v[i].y, v[i].z};
        uint8_t region;
        assert_int_equal(fg_field_classify(f, x, 1, &region), FG_OK);
        /* Never in an obstacle or the origin; only connecting nodes in the target. */
        assert_true(region == FG_REGION_FREE || region == FG_REGION_TARGET);
        if (region == FG_REGION_TARGET) {
            hits++;
            if (v[i].flags & FG_NODE_MAIN)
                end = i;
        }
        if (v[i].flags & FG_NODE_MAIN)
            main++;
        if (i > 0 && !lattice && region == FG_REGION_FREE)
            assert_float_equal(seg_len(v, i), step_m, 1e-9 * step_m);
        if (i > 0)
            assert_true(seg_len(v, i) <= step_m * (lattice ? 3.0 : 1.0) + 1e-12);
    }
    /* Main channel: the path from the target node up to the root, exactly. */
    assert_true(hits >= 1 && end > 0);
    size_t walk = 0;
    for (int32_t i = (int32_t)end; i >= 0; i = v[i].parent) {
        assert_true(v[i].flags & FG_NODE_MAIN);
        walk++;
    }
    assert_int_equal(walk, main);
    return hits;
}

static void spark_reaches_target(void **state)
{
    (void)state;
    scene s;
    scene_init(&s, FG_PRESET_SPARK_BALLS, 33);
    for (uint64_t seed = 1; seed <= 10; seed++) {
        s.setup.growth.seed = seed;
        fg_growth_report rep;
        assert_int_equal(fg_grow_matsuyama(&s.src, &s.setup.growth, s.tree, &rep), FG_OK);
        assert_int_equal(check_tree(s.field, s.tree, s.setup.growth.step_m, 0), 1);
        assert_int_equal(rep.nodes, fg_tree_count(s.tree));
        /* At least the 2 cm gap in 2 mm steps. */
        assert_true(rep.main_nodes >= 11);
    }
    scene_deinit(&s);
}

static void plasma_filaments_all_connect(void **state)
{
    (void)state;
    scene s;
    scene_init(&s, FG_PRESET_PLASMA_BALL, 33);
    size_t filaments = 0;
    for (uint64_t seed = 1; seed <= 10; seed++) {
        s.setup.growth.seed = seed;
        assert_int_equal(fg_grow_matsuyama(&s.src, &s.setup.growth, s.tree, NULL), FG_OK);
        filaments += check_tree(s.field, s.tree, s.setup.growth.step_m, 0);
    }
    /* Branches grow on to the glass: more than one filament on average. */
    assert_true(filaments > 15);
    scene_deinit(&s);
}

/* A fixed plate between the plates: leaders must go round it, and no
 * node of any tree may lie in it. */
static void trees_avoid_an_obstacle(void **state)
{
    (void)state;
    fg_grid_config c = {.size = {33, 33, 33}, .max_m = {1, 1, 1}};
    fg_field *f;
    assert_int_equal(fg_field_create(&c, &f), FG_OK);
    fg_shape s[3] = {
        {.kind = FG_SHAPE_GROUND, .role = FG_ROLE_ORIGIN},
        {.kind = FG_SHAPE_PLANE, .role = FG_ROLE_TARGET, .centre_m = {0, 0, 1}, .normal = {0, 0, -1}},
        {.kind = FG_SHAPE_BOX, .role = FG_ROLE_FIXED, .potential = 0.4,
         .box_min_m = {0.2, 0.2, 0.4}, .box_max_m = {0.8, 0.8, 0.5}},
    };
    assert_int_equal(fg_field_set_shapes(f, s, 3, NULL), FG_OK);
    assert_int_equal(fg_field_solve(f, NULL, NULL), FG_OK);
    fg_field_source src;
    fg_field_source_init(f, &src);
    fg_tree *t;
    assert_int_equal(fg_tree_create(8, &t), FG_OK);
    int beside = 0;
    for (uint64_t seed = 1; seed <= 10; seed++) {
        fg_growth_config g = {.step_m = 0.04, .seed = seed};
        assert_int_equal(fg_grow_matsuyama(&src, &g, t, NULL), FG_OK);
        check_tree(f, t, g.step_m, 0);
        /* Where the main channel crosses the obstacle's height, it is beside it. */
        const fg_node *v = fg_tree_nodes(t);
        for (size_t i = 0; i < fg_tree_count(t); i++)
            if ((v[i].flags & FG_NODE_MAIN) && v[i].z > 0.4 && v[i].z < 0.5)
                beside += v[i].x < 0.2 || v[i].x > 0.8 || v[i].y < 0.2 || v[i].y > 0.8;
    }
    assert_true(beside >= 10);
    fg_tree_destroy(t);
    fg_field_destroy(f);
}

static void same_seed_same_tree(void **state)
{
    (void)state;
    scene s;
    scene_init(&s, FG_PRESET_SPARK_BALLS, 33);
    fg_tree *b;
    assert_int_equal(fg_tree_create(8, &b), FG_OK);
    s.setup.growth.seed = 77;
    assert_int_equal(fg_grow_matsuyama(&s.src, &s.setup.growth, s.tree, NULL), FG_OK);
    assert_int_equal(fg_grow_matsuyama(&s.src, &s.setup.growth, b, NULL), FG_OK);
    assert_int_equal(fg_tree_count(s.tree), fg_tree_count(b));
    assert_memory_equal(fg_tree_nodes(s.tree), fg_tree_nodes(b),
                        fg_tree_count(b) * sizeof(fg_node));
    s.setup.growth.seed = 78;
    assert_int_equal(fg_grow_matsuyama(&s.src, &s.setup.growth, b, NULL), FG_OK);
    assert_true(fg_tree_count(s.tree) != fg_tree_count(b) ||
                memcmp(fg_tree_nodes(s.tree), fg_tree_nodes(b),
                       fg_tree_count(b) * sizeof(fg_node)) != 0);
    fg_tree_destroy(b);
    scene_deinit(&s);
}

/* Plates: phi = z on [0, 1]^3, exactly representable by trilinear sampling. */
static fg_field *plates(void)
{
    fg_grid_config c = {.size = {17, 17, 17}, .max_m = {1, 1, 1}};
    fg_field *f;
    assert_int_equal(fg_field_create(&c, &f), FG_OK);
    fg_shape s[3] = {
        {.kind = FG_SHAPE_GROUND, .role = FG_ROLE_ORIGIN},
        {.kind = FG_SHAPE_PLANE, .role = FG_ROLE_TARGET, .centre_m = {0, 0, 1}, .normal = {0, 0, -1}},
        /* an obstacle on one candidate's path, a flat plate held at the
         * potential phi = z already has there, so the field stays linear */
        {.kind = FG_SHAPE_BOX, .role = FG_ROLE_FIXED, .potential = 0.5,
         .box_min_m = {0.625, 0.4375, 0.5}, .box_max_m = {0.6875, 0.5625, 0.5}},
    };
    assert_int_equal(fg_field_set_shapes(f, s, 3, NULL), FG_OK);
    assert_int_equal(fg_field_solve(f, NULL, NULL), FG_OK);
    return f;
}

static void eq2_probabilities_chi_square(void **state)
{
    (void)state;
    fg_field *f = plates();
    fg_field_source src;
    fg_field_source_init(f, &src);
    /* Eight directions from a tip at z = 0.3: seven free, one (+x) blocked. */
    enum { N = 8, DRAWS = 40000 };
    double tip[3] = {0.5, 0.2, 0.3}, dirs[3 * N], w[N], gamma = 2.5, step = 0.1;
    for (int i = 0; i < N - 1; i++) {
        double th = 0.2 * i, ph = 0.9 * i;
        dirs[3 * i] = sin(th) * cos(ph);
        dirs[3 * i + 1] = sin(th) * sin(ph);
        dirs[3 * i + 2] = cos(th) * (i % 2 ? 1 : -1);
    }
    double blocked_tip[3] = {0.5, 0.5, 0.5};
    int hit;
    /* From the second tip, the candidate +x ends in the obstacle. */
    double one[3] = {1, 0, 0};
    assert_int_equal(fg_matsuyama_weigh(&src, blocked_tip, one, 1, 0.15, gamma, w, &hit), FG_OK);
    assert_true(w[0] == 0.0 && hit == -1);
    dirs[3 * (N - 1)] = 0.0;
    dirs[3 * (N - 1) + 1] = 0.0;
    dirs[3 * (N - 1) + 2] = 1.0;
    assert_int_equal(fg_matsuyama_weigh(&src, tip, dirs, N, step, gamma, w, &hit), FG_OK);
    assert_int_equal(hit, -1);
    double expect[N], sum = 0.0;
    for (int i = 0; i < N; i++) {
        double z = tip[2] + step * dirs[3 * i + 2];
        expect[i] = pow(z, gamma);
        sum += expect[i];
    }
    double wsum = 0.0;
    for (int i = 0; i < N; i++)
        wsum += w[i];
    for (int i = 0; i < N; i++) {
        expect[i] /= sum;
        assert_float_equal(w[i] / wsum, expect[i], 1e-5);
    }
    fg_rng rng;
    fg_rng_seed(&rng, 12345);
    int count[N] = {0};
    for (int d = 0; d < DRAWS; d++)
        count[fg_pick(w, N, fg_rng_uniform(&rng))]++;
    double chi2 = 0.0;
    for (int i = 0; i < N; i++) {
        double e = DRAWS * expect[i];
        chi2 += (count[i] - e) * (count[i] - e) / e;
    }
    print_message("eq. 2 chi-square, 7 degrees of freedom: %.2f\n", chi2);
    assert_true(chi2 < 24.32); /* p = 0.001 */
    /* And a skewed draw must fail it: the test has power. */
    double flat[N] = {1, 1, 1, 1, 1, 1, 1, 1};
    int fcount[N] = {0};
    for (int d = 0; d < DRAWS; d++)
        fcount[fg_pick(flat, N, fg_rng_uniform(&rng))]++;
    double chi2_flat = 0.0;
    for (int i = 0; i < N; i++) {
        double e = DRAWS * expect[i];
        chi2_flat += (fcount[i] - e) * (fcount[i] - e) / e;
    }
    assert_true(chi2_flat > 100.0);
    fg_field_destroy(f);
}

/* The seam: a source that is not a grid. phi = z, target z >= 1, origin
 * z <= 0 with sites on a line. */
static fg_result an_sample(void *ctx, const double *p, size_t n, double *out)
{
    (void)ctx;
    for (size_t i = 0; i < n; i++)
        out[i] = p[3 * i + 2];
    return FG_OK;
}

static fg_result an_classify(void *ctx, const double *p, size_t n, uint8_t *out)
{
    int *calls = ctx;
    ++*calls;
    for (size_t i = 0; i < n; i++) {
        double z = p[3 * i + 2];
        out[i] = z >= 1.0 ? FG_REGION_TARGET : (z <= 0.0 ? FG_REGION_ORIGIN : FG_REGION_FREE);
    }
    return FG_OK;
}

static size_t an_sites(void *ctx, double *p, size_t max)
{
    (void)ctx;
    for (size_t i = 0; i < 4 && i < max && p; i++) {
        p[3 * i] = 0.1 * (double)i;
        p[3 * i + 1] = 0.0;
        p[3 * i + 2] = 0.05;
    }
    return 4;
}

static void analytic_source(void **state)
{
    (void)state;
    int calls = 0;
    fg_field_source src = {&calls, an_sample, an_classify, an_sites, 0.01};
    fg_tree *t;
    assert_int_equal(fg_tree_create(8, &t), FG_OK);
    fg_growth_config c = {.step_m = 0.05, .seed = 3, .max_tips = 1};
    fg_growth_report rep;
    assert_int_equal(fg_grow_matsuyama(&src, &c, t, &rep), FG_OK);
    const fg_node *v = fg_tree_nodes(t);
    size_t n = fg_tree_count(t);
    assert_true(calls > 0);
    /* No branching: a single chain, all of it main, climbing to z = 1. */
    assert_int_equal(rep.main_nodes, n);
    assert_float_equal(v[n - 1].z, 1.0, 0.05 / 256 + 1e-12);
    assert_true(v[n - 1].z >= 1.0);
    assert_float_equal(v[0].z, 0.05, 1e-12);
    /* 0.95 of height in 5 cm steps inside a 45-degree cone, mostly upward. */
    assert_true(n >= 20 && n < 60);
    fg_tree_destroy(t);
}

static void dbm_grows_and_restores(void **state)
{
    (void)state;
    /* 17^3 keeps the many solves of DBM cheap (ThreadSanitizer runs this);
     * the output is resampled to two cells. */
    scene s;
    scene_init(&s, FG_PRESET_SPARK_BALLS, 17);
    double cell[3];
    fg_field_cell(s.field, cell);
    fg_tree *b;
    assert_int_equal(fg_tree_create(8, &b), FG_OK);
    s.setup.growth.seed = 5;
    s.setup.growth.step_m = 2.0 * cell[0];
    fg_growth_report rep;
    assert_int_equal(fg_grow_dbm(s.field, &s.setup.growth, s.tree, &rep), FG_OK);
    check_tree(s.field, s.tree, s.setup.growth.step_m, 1);
    assert_true(rep.solves >= 1 && rep.solver_iterations >= rep.solves);
    assert_true(rep.steps >= 4); /* 2 cm at 4.4 mm per lattice step */
    /* The channel is gone from the field: a middle node is free again. */
    const fg_node *v = fg_tree_nodes(s.tree);
    double mid[3] = {v[1].x, v[1].y, v[1].z};
    uint8_t region;
    assert_int_equal(fg_field_classify(s.field, mid, 1, &region), FG_OK);
    assert_int_equal(region, FG_REGION_FREE);
    /* Same seed, re-solved field: the same tree. */
    assert_int_equal(fg_field_solve(s.field, &(fg_solve_config){.cold = 1}, NULL), FG_OK);
    assert_int_equal(fg_grow_dbm(s.field, &s.setup.growth, b, NULL), FG_OK);
    assert_int_equal(fg_tree_count(s.tree), fg_tree_count(b));
    assert_memory_equal(fg_tree_nodes(s.tree), fg_tree_nodes(b),
                        fg_tree_count(b) * sizeof(fg_node));
    fg_tree_destroy(b);
    scene_deinit(&s);
}

/* eta sharpens the choice: a high exponent grows a nearly straight
 * channel, a low one a bushy cluster (NPW's fractal dimension falls with
 * eta). */
static void dbm_eta_shapes_the_channel(void **state)
{
    (void)state;
    scene s;
    scene_init(&s, FG_PRESET_SPARK_BALLS, 17);
    double cell[3];
    fg_field_cell(s.field, cell);
    int steps[2] = {0, 0};
    const double eta[2] = {0.5, 4.0};
    for (int e = 0; e < 2; e++)
        for (uint64_t seed = 1; seed <= 4; seed++) {
            fg_growth_config g = s.setup.growth;
            g.step_m = 2.0 * cell[0];
            g.eta = eta[e];
            g.seed = seed;
            fg_growth_report rep;
            assert_int_equal(fg_field_solve(s.field, NULL, NULL), FG_OK);
            assert_int_equal(fg_grow_dbm(s.field, &g, s.tree, &rep), FG_OK);
            check_tree(s.field, s.tree, g.step_m, 1);
            steps[e] += rep.steps;
        }
    print_message("DBM lattice steps over 4 seeds: eta 0.5: %d, eta 4: %d\n", steps[0], steps[1]);
    assert_true(steps[0] > 3 * steps[1]);
    scene_deinit(&s);
}

static double mean_segments(fg_preset preset)
{
    scene s;
    scene_init(&s, preset, 65);
    double sum = 0.0;
    for (uint64_t seed = 1; seed <= 20; seed++) {
        s.setup.growth.seed = seed;
        fg_growth_report rep;
        assert_int_equal(fg_grow_matsuyama(&s.src, &s.setup.growth, s.tree, &rep), FG_OK);
        sum += (double)(rep.nodes - 1);
    }
    scene_deinit(&s);
    return sum / 20.0;
}

static void presets_match_table_2(void **state)
{
    (void)state;
    double spark = mean_segments(FG_PRESET_SPARK_BALLS);
    double plasma = mean_segments(FG_PRESET_PLASMA_BALL);
    print_message("mean segments over 20 seeds at 65^3: spark balls %.1f (paper 72), "
                  "plasma ball %.1f (paper 78)\n",
                  spark, plasma);
    assert_true(spark > 50.0 && spark < 100.0);
    assert_true(plasma > 55.0 && plasma < 100.0);
}

/* A source reading one field that also samples a reference field at the
 * same points and keeps the largest relative difference of phi. */
typedef struct paired_source {
    fg_field_source field, reference;
    double worst;
} paired_source;

static fg_result paired_sample(void *context, const double *points_m, size_t n, double *out)
{
    paired_source *p = context;
    double ref[2 * 3 * FG_GROWTH_MAX_CANDIDATES];
    fg_result r = p->field.sample(p->field.context, points_m, n, out);
    if (r != FG_OK)
        return r;
    for (size_t at = 0; at < n; at += sizeof ref / sizeof ref[0]) {
        size_t m = n - at < sizeof ref / sizeof ref[0] ? n - at : sizeof ref / sizeof ref[0];
        assert_int_equal(p->reference.sample(p->reference.context, points_m + 3 * at, m, ref),
                         FG_OK);
        for (size_t i = 0; i < m; i++)
            if (ref[i] > 0.0)
                p->worst = fmax(p->worst, fabs(out[at + i] / ref[i] - 1.0));
    }
    return FG_OK;
}

static fg_result paired_classify(void *context, const double *points_m, size_t n, uint8_t *out)
{
    paired_source *p = context;
    return p->field.classify(p->field.context, points_m, n, out);
}

static size_t paired_origin_sites(void *context, double *points_m, size_t max)
{
    paired_source *p = context;
    return p->field.origin_sites(p->field.context, points_m, max);
}

enum { STATS = 4 };

/* Segments, branch points (nodes with two children or more), the longest
 * root-to-node path in segments and the farthest node from the root. */
static void tree_statistics(fg_tree *t, double out[STATS])
{
    const fg_node *v = fg_tree_nodes(t);
    size_t n = fg_tree_count(t);
    int children[4096] = {0}, depth[4096] = {0};
    assert_true(n <= 4096);
    out[0] = (double)(n - 1);
    out[1] = out[2] = out[3] = 0.0;
    for (size_t i = 1; i < n; i++) {
        children[v[i].parent]++;
        depth[i] = depth[v[i].parent] + 1;
        out[2] = fmax(out[2], depth[i]);
        out[3] = fmax(out[3], hypot(hypot(v[i].x - v[0].x, v[i].y - v[0].y), v[i].z - v[0].z));
    }
    for (size_t i = 0; i < n; i++)
        out[1] += children[i] >= 2;
}

/* The growth's field tolerance (FG_GROWTH_FIELD_TOLERANCE) against a field
 * solved to 1e-11: phi at every point the trees sample within 4e-3 of
 * itself (so eq. 2's probabilities within 2 %), and over 200 seeds the
 * mean segments, branch points, depth and reach within four standard
 * errors of the difference of two means. */
static void tolerance_keeps_statistics(void **state)
{
    (void)state;
    enum { SEEDS = 200 };
    const char *names[STATS] = {"segments", "branch points", "depth", "reach"};
    for (int p = 0; p < 2; p++) {
        fg_field_scene s;
        fg_preset preset = p ? FG_PRESET_PLASMA_BALL : FG_PRESET_SPARK_BALLS;
        assert_int_equal(fg_field_scene_preset(preset, 65, &s), FG_OK);
        const double tol[2] = {FG_GROWTH_FIELD_TOLERANCE, 1e-11};
        fg_field *f[2];
        fg_tree *t[2];
        for (int w = 0; w < 2; w++) {
            assert_int_equal(fg_field_create(&s.grid, &f[w]), FG_OK);
            assert_int_equal(fg_field_set_shapes(f[w], s.shapes, s.shape_count, NULL), FG_OK);
            assert_int_equal(fg_field_solve(f[w], &(fg_solve_config){.tolerance = tol[w]}, NULL),
                             FG_OK);
            assert_int_equal(fg_tree_create(0, &t[w]), FG_OK);
        }
        paired_source pair = {.worst = 0.0};
        fg_field_source_init(f[0], &pair.field);
        fg_field_source_init(f[1], &pair.reference);
        fg_field_source src = pair.field;
        src.context = &pair;
        src.sample = paired_sample;
        src.classify = paired_classify;
        src.origin_sites = paired_origin_sites;
        double sum[2][STATS] = {{0}}, squares[2][STATS] = {{0}};
        for (uint64_t seed = 1; seed <= SEEDS; seed++) {
            fg_growth_config g = s.growth;
            g.seed = seed;
            assert_int_equal(fg_grow_matsuyama(&src, &g, t[0], NULL), FG_OK);
            assert_int_equal(fg_grow_matsuyama(&pair.reference, &g, t[1], NULL), FG_OK);
            for (int w = 0; w < 2; w++) {
                double x[STATS];
                tree_statistics(t[w], x);
                for (int k = 0; k < STATS; k++) {
                    sum[w][k] += x[k];
                    squares[w][k] += x[k] * x[k];
                }
            }
        }
        print_message("%s, phi to %.0e against 1e-11: worst relative phi %.1e\n",
                      fg_preset_name(preset), tol[0], pair.worst);
        assert_true(pair.worst < 4e-3);
        for (int k = 0; k < STATS; k++) {
            double mean[2], var[2];
            for (int w = 0; w < 2; w++) {
                mean[w] = sum[w][k] / SEEDS;
                var[w] = (squares[w][k] - SEEDS * mean[w] * mean[w]) / (SEEDS - 1);
            }
            double se = sqrt((var[0] + var[1]) / SEEDS);
            print_message("  %s %.4g / %.4g (standard error of the difference %.2g)\n",
                          names[k], mean[0], mean[1], se);
            assert_true(fabs(mean[0] - mean[1]) <= 4.0 * se);
        }
        for (int w = 0; w < 2; w++) {
            fg_tree_destroy(t[w]);
            fg_field_destroy(f[w]);
        }
    }
}

static void enclosed_origin_is_unreachable(void **state)
{
    (void)state;
    fg_grid_config c = {.size = {33, 33, 33}, .min_m = {-0.5, -0.5, -0.5}, .max_m = {0.5, 0.5, 0.5}};
    fg_field *f;
    assert_int_equal(fg_field_create(&c, &f), FG_OK);
    /* Origin inside a closed fixed shell (everything beyond r = 0.3); the
     * target in a corner, outside the shell (the later shape wins). */
    fg_shape shell[3] = {
        {.kind = FG_SHAPE_SPHERE, .role = FG_ROLE_FIXED, .potential = 0.3, .radius_m = 0.3, .outside = 1},
        {.kind = FG_SHAPE_SPHERE, .role = FG_ROLE_ORIGIN, .radius_m = 0.05},
        {.kind = FG_SHAPE_SPHERE, .role = FG_ROLE_TARGET, .radius_m = 0.05,
         .centre_m = {0.4, 0.4, 0.4}},
    };
    assert_int_equal(fg_field_set_shapes(f, shell, 3, NULL), FG_OK);
    assert_int_equal(fg_field_solve(f, NULL, NULL), FG_OK);
    fg_field_source src;
    fg_field_source_init(f, &src);
    fg_tree *t;
    assert_int_equal(fg_tree_create(8, &t), FG_OK);
    size_t idx;
    assert_int_equal(fg_tree_add(t, 0, 0, 0, -1, 0, &idx), FG_OK);
    assert_int_equal(fg_tree_add(t, 1, 0, 0, 0, 0, &idx), FG_OK);
    fg_growth_config g = {.step_m = 0.05, .max_steps = 500};
    assert_int_equal(fg_grow_matsuyama(&src, &g, t, NULL), FG_ERR_UNREACHABLE);
    assert_int_equal(fg_tree_count(t), 2);
    g.max_steps = 40;
    assert_int_equal(fg_grow_dbm(f, &g, t, NULL), FG_ERR_UNREACHABLE);
    assert_int_equal(fg_tree_count(t), 2);
    fg_tree_destroy(t);
    fg_field_destroy(f);
}

static void bad_growth_input(void **state)
{
    (void)state;
    scene s;
    scene_init(&s, FG_PRESET_SPARK_BALLS, 17);
    size_t idx;
    assert_int_equal(fg_tree_add(s.tree, 0, 0, 0, -1, 0, &idx), FG_OK);
    struct {
        fg_growth_config c;
        fg_result want;
    } cases[] = {
        {{.step_m = 0.0}, FG_ERR_ARGUMENT},
        {{.step_m = -0.002}, FG_ERR_ARGUMENT},
        {{.step_m = NAN}, FG_ERR_NOT_FINITE},
        {{.step_m = 0.002, .gamma = INFINITY}, FG_ERR_NOT_FINITE},
        {{.step_m = 0.002, .candidates = 65}, FG_ERR_ARGUMENT},
        {{.step_m = 0.002, .cone_rad = 4.0}, FG_ERR_ARGUMENT},
        {{.step_m = 0.002, .branch_probability = 1.5}, FG_ERR_ARGUMENT},
        {{.step_m = 0.002, .max_steps = -1}, FG_ERR_ARGUMENT},
        {{.step_m = 0.002, .eta = -1}, FG_ERR_ARGUMENT},
    };
    fg_growth_config used = {.seed = 77};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(fg_grow_matsuyama(&s.src, &cases[i].c, s.tree, NULL), cases[i].want);
        assert_int_equal(fg_grow_dbm(s.field, &cases[i].c, s.tree, NULL), cases[i].want);
        assert_int_equal(fg_growth_config_resolve(&cases[i].c, &used), cases[i].want);
        assert_int_equal(fg_tree_count(s.tree), 1);
        assert_int_equal(used.seed, 77); /* untouched */
    }
    fg_growth_config ok = {.step_m = 0.002};
    /* the defaults growth.h documents; what is given is kept */
    fg_growth_config some = {.step_m = 0.002, .candidates = 12, .seed = 5};
    assert_int_equal(fg_growth_config_resolve(&some, &used), FG_OK);
    assert_true(used.gamma == 2.5 && used.candidates == 12 &&
                fabs(used.cone_rad - 1.57079632679489661923) < 1e-15 &&
                used.branch_probability == 0.1 && used.max_tips == 16 &&
                fabs(used.branch_length_m - 6 * 0.002) < 1e-15 && used.max_steps == 4096 &&
                used.eta == 2.0 && used.dbm_global_every == 8 && used.dbm_relax_radius == 3 &&
                used.seed == 5 && used.step_m == 0.002);
    assert_int_equal(fg_growth_config_resolve(NULL, &used), FG_ERR_NULL);
    assert_int_equal(fg_grow_matsuyama(NULL, &ok, s.tree, NULL), FG_ERR_NULL);
    assert_int_equal(fg_grow_matsuyama(&s.src, &ok, NULL, NULL), FG_ERR_NULL);
    assert_int_equal(fg_grow_dbm(NULL, &ok, s.tree, NULL), FG_ERR_NULL);
    fg_field_scene d;
    assert_int_equal(fg_field_scene_preset(FG_PRESET_LIGHTNING, 65, &d), FG_ERR_ARGUMENT);
    assert_int_equal(fg_field_scene_preset(FG_PRESET_SPARK_BALLS, 300, &d), FG_ERR_ARGUMENT);
    assert_int_equal(fg_field_scene_preset(FG_PRESET_SPARK_BALLS, 65, NULL), FG_ERR_NULL);
    scene_deinit(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spark_reaches_target),
        cmocka_unit_test(plasma_filaments_all_connect),
        cmocka_unit_test(trees_avoid_an_obstacle),
        cmocka_unit_test(same_seed_same_tree),
        cmocka_unit_test(eq2_probabilities_chi_square),
        cmocka_unit_test(analytic_source),
        cmocka_unit_test(dbm_grows_and_restores),
        cmocka_unit_test(dbm_eta_shapes_the_channel),
        cmocka_unit_test(presets_match_table_2),
        cmocka_unit_test(tolerance_keeps_statistics),
        cmocka_unit_test(enclosed_origin_is_unreachable),
        cmocka_unit_test(bad_growth_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
