/* Point-charge leader growth (Sosorbaram / Abe §4.1). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "growth/charges_internal.h"
#include "fulgur/charges.h"

/* A cloud: negative charge region above a positive one, and the ground's
 * induced positive charge as an image below z = 0. */
static const fg_point_charge cloud[] = {
    {{0, 0, 600}, -2.0},
    {{0, 0, 900}, 1.0},
    {{0, 0, -600}, 2.0},
};

static fg_charges_config cloud_params(uint64_t seed)
{
    return (fg_charges_config){
        .charges = cloud, .charge_count = 3, .start_m = {0, 0, 550}, .step_m = 3, .seed = seed};
}

static fg_tree *grow(const fg_charges_config *p)
{
    fg_tree *t;
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    assert_int_equal(fg_charges_grow(p, t), FG_OK);
    return t;
}

static double dist(const fg_node *a, const fg_node *b)
{
    return sqrt((a->x - b->x) * (a->x - b->x) + (a->y - b->y) * (a->y - b->y) +
                (a->z - b->z) * (a->z - b->z));
}

static void potential_closed_form(void **state)
{
    (void)state;
    const fg_point_charge q = {{1, 2, 3}, 1e-9};
    const double p[3] = {1, 2, 5};
    /* 1 nC at 2 m: 8.98755e9 * 1e-9 / 2 V */
    assert_float_equal(fg_charges_potential(&q, 1, p), 4.493775, 1e-5);
}

static void reaches_ground_main_connected(void **state)
{
    (void)state;
    for (uint64_t seed = 1; seed <= 5; seed++) {
        fg_charges_config p = cloud_params(seed);
        fg_tree *t = grow(&p);
        const fg_node *n = fg_tree_nodes(t);
        size_t count = fg_tree_count(t), ground = count, flagged = 0;
        assert_int_equal(fg_tree_check(n, count, NULL), FG_OK);
        for (size_t i = 0; i < count; i++) {
            assert_true(n[i].z >= 0);
            if (n[i].z == 0)
                ground = i;
            flagged += (n[i].flags & FG_NODE_MAIN) != 0;
        }
        assert_int_equal(ground, count - 1); /* it stops on reaching the ground */
        size_t path = 0;
        for (int32_t i = (int32_t)ground; i >= 0; i = n[i].parent) {
            assert_true(n[i].flags & FG_NODE_MAIN);
            path++;
        }
        assert_int_equal(path, flagged);
        assert_true(path >= 550 / 3); /* at least the straight drop in 3 m steps */
        for (size_t i = 1; i < count; i++)
            if (n[i].z > 0)
                assert_float_equal(dist(&n[i], &n[n[i].parent]), 3.0, 1e-9);
        fg_tree_destroy(t);
    }
}

static void sphere_target(void **state)
{
    (void)state;
    /* intracloud: from between the regions up to the positive one */
    fg_charges_config p = cloud_params(9);
    p.start_m[2] = 700;
    p.target_m[0] = 0, p.target_m[1] = 0, p.target_m[2] = 900;
    p.target_radius_m = 20;
    fg_tree *t = grow(&p);
    const fg_node *n = fg_tree_nodes(t);
    size_t last = fg_tree_count(t) - 1;
    fg_node centre = {0, 0, 900, 0, 0};
    assert_true(dist(&n[last], &centre) <= 20);
    assert_true(n[last].flags & FG_NODE_MAIN);
    for (size_t i = 0; i < last; i++)
        assert_true(dist(&n[i], &centre) > 20);
    fg_tree_destroy(t);
}

static void seeded_runs_identical(void **state)
{
    (void)state;
    fg_charges_config p = cloud_params(42);
    fg_tree *a = grow(&p), *b = grow(&p);
    p.seed = 43;
    fg_tree *c = grow(&p);
    assert_int_equal(fg_tree_count(a), fg_tree_count(b));
    assert_memory_equal(fg_tree_nodes(a), fg_tree_nodes(b), fg_tree_count(a) * sizeof(fg_node));
    assert_true(fg_tree_count(a) != fg_tree_count(c) ||
                memcmp(fg_tree_nodes(a), fg_tree_nodes(c), fg_tree_count(a) * sizeof(fg_node)));
    fg_tree_destroy(a);
    fg_tree_destroy(b);
    fg_tree_destroy(c);
}

/* Abe eq. 2: the first choice is candidate k with probability E_k / sum E_j,
 * E_k = |Phi_k - Phi_i| / d; a step back up the potential has E = 0. */
static void probability_rule(void **state)
{
    (void)state;
    const fg_vec3 tip = fg_v3(0, 0, 550);
    const double d = 3;
    fg_vec3 cand[6] = {fg_v3(0, 0, -1), fg_v3(1, 0, 0),   fg_v3(0, 1, -1),
                       fg_v3(1, 1, -1), fg_v3(-1, 0, -2), fg_v3(0, 0, 1)};
    for (int k = 0; k < 6; k++)
        cand[k] = fg_v3_add(tip, fg_v3_scale(fg_v3_unit(cand[k]), d));
    double tip_p[3] = {tip.x, tip.y, tip.z};
    double phi_tip = fg_charges_potential(cloud, 3, tip_p);
    double e[6], expect[6], total = 0;
    fg_charges_field(cloud, 3, phi_tip, 1.0, cand, 6, d, e);
    for (int k = 0; k < 6; k++) {
        double q[3] = {cand[k].x, cand[k].y, cand[k].z};
        double dphi = fg_charges_potential(cloud, 3, q) - phi_tip;
        expect[k] = dphi > 0 ? fabs(dphi) / d : 0;
        assert_float_equal(e[k], expect[k], 1e-9 * fabs(expect[k]) + 1e-12);
        total += expect[k];
    }
    assert_true(e[0] > 0);
    assert_true(e[5] == 0); /* straight up, toward the negative region */
    enum { DRAWS = 200000 };
    long hits[6] = {0};
    fg_rng rng;
    fg_rng_seed(&rng, 7);
    for (int i = 0; i < DRAWS; i++) {
        double scratch[6];
        size_t pick;
        memcpy(scratch, e, sizeof e);
        assert_int_equal(fg_charges_choose(&rng, cand, scratch, 6, 1, 0, &pick), 1);
        hits[pick]++;
    }
    for (int k = 0; k < 6; k++) {
        double prob = expect[k] / total;
        double sigma = sqrt(DRAWS * prob * (1 - prob));
        assert_true(fabs(hits[k] - DRAWS * prob) <= 4 * sigma + 1e-9);
    }
    assert_int_equal(hits[5], 0);
}

static void exclusion_radius(void **state)
{
    (void)state;
    /* Two candidates 1 m apart and one far away: with R = 2 m, choosing
     * either of the close pair rules out the other. */
    fg_vec3 cand[3] = {fg_v3(0, 0, 0), fg_v3(1, 0, 0), fg_v3(10, 0, 0)};
    fg_rng rng;
    fg_rng_seed(&rng, 1);
    for (int i = 0; i < 1000; i++) {
        double e[3] = {1, 1, 1};
        size_t chosen[3];
        size_t got = fg_charges_choose(&rng, cand, e, 3, 3, 2.0, chosen);
        assert_int_equal(got, 2);
        assert_true(chosen[0] == 2 || chosen[1] == 2);
    }
    /* In grown trees: siblings (all drawn in one round) are R apart. */
    fg_charges_config p = cloud_params(5);
    p.candidates = 16, p.chosen = 4, p.exclusion_m = 4.0;
    fg_tree *t = grow(&p);
    const fg_node *n = fg_tree_nodes(t);
    size_t count = fg_tree_count(t), pairs = 0;
    for (size_t i = 1; i < count; i++)
        for (size_t j = i + 1; j < count && j < i + 8; j++)
            if (n[i].parent == n[j].parent && n[i].z > 0 && n[j].z > 0) {
                assert_true(dist(&n[i], &n[j]) >= 4.0);
                pairs++;
            }
    assert_true(pairs > 100);
    fg_tree_destroy(t);
}

static void bad_input(void **state)
{
    (void)state;
    const fg_point_charge nan_q[] = {{{0, 0, 600}, NAN}};
    struct {
        const char *what;
        fg_charges_config p;
        fg_result want;
    } cases[] = {
        {"no charges", {.charges = cloud, .charge_count = 0, .start_m = {0, 0, 550}},
         FG_ERR_ARGUMENT},
        {"charges NULL", {.charges = NULL, .charge_count = 2, .start_m = {0, 0, 550}},
         FG_ERR_NULL},
        {"NaN charge", {.charges = nan_q, .charge_count = 1, .start_m = {0, 0, 550}},
         FG_ERR_NOT_FINITE},
        {"NaN start", {.charges = cloud, .charge_count = 3, .start_m = {0, NAN, 550}},
         FG_ERR_NOT_FINITE},
        {"negative step",
         {.charges = cloud, .charge_count = 3, .start_m = {0, 0, 550}, .step_m = -1},
         FG_ERR_ARGUMENT},
        {"N > M",
         {.charges = cloud, .charge_count = 3, .start_m = {0, 0, 550}, .candidates = 3,
          .chosen = 4},
         FG_ERR_ARGUMENT},
        {"R >= 2d",
         {.charges = cloud, .charge_count = 3, .start_m = {0, 0, 550}, .step_m = 1,
          .exclusion_m = 2},
         FG_ERR_ARGUMENT},
        {"start on the ground", {.charges = cloud, .charge_count = 3, .start_m = {0, 0, 0}},
         FG_ERR_ARGUMENT},
        {"start in target",
         {.charges = cloud, .charge_count = 3, .start_m = {0, 0, 550}, .target_m = {0, 0, 540},
          .target_radius_m = 20},
         FG_ERR_ARGUMENT},
        {"too many candidates",
         {.charges = cloud, .charge_count = 3, .start_m = {0, 0, 550}, .candidates = 5000},
         FG_ERR_ARGUMENT},
    };
    fg_tree *t;
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fg_charges_config out;
        memset(&out, 0xA5, sizeof out);
        fg_charges_config before = out;
        if (fg_charges_config_resolve(&cases[i].p, &out) != cases[i].want)
            fail_msg("%s: resolve", cases[i].what);
        assert_memory_equal(&out, &before, sizeof out);
        if (fg_charges_grow(&cases[i].p, t) != cases[i].want)
            fail_msg("%s: grow", cases[i].what);
        assert_int_equal(fg_tree_count(t), 0);
    }
    fg_charges_config p = cloud_params(1);
    assert_int_equal(fg_charges_grow(&p, NULL), FG_ERR_NULL);
    assert_int_equal(fg_charges_grow(NULL, t), FG_ERR_NULL);
    /* a tree that is not empty is refused and kept */
    assert_int_equal(fg_tree_add(t, 1, 2, 3, -1, 0, NULL), FG_OK);
    assert_int_equal(fg_charges_grow(&p, t), FG_ERR_ARGUMENT);
    assert_int_equal(fg_tree_count(t), 1);
    fg_tree_clear(t);
    /* too few nodes allowed to get there */
    p.max_nodes = 50;
    assert_int_equal(fg_charges_grow(&p, t), FG_ERR_UNREACHABLE);
    assert_int_equal(fg_tree_count(t), 0);
    fg_tree_destroy(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(potential_closed_form),
        cmocka_unit_test(reaches_ground_main_connected),
        cmocka_unit_test(sphere_target),
        cmocka_unit_test(seeded_runs_identical),
        cmocka_unit_test(probability_rule),
        cmocka_unit_test(exclusion_radius),
        cmocka_unit_test(bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
