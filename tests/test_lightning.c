/* Statistical lightning (Glassner) and designer thunder: the geometry. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "fg_math.h"
#include "fulgur/lightning.h"

#define DEG (FG_PI / 180)

/* A straight vertical 5 km skeleton over the origin. */
static const double vertical[] = {0, 0, 5000, 0, 0, 0};
static const double listener[3] = {3000, 0, 1.7};

static fg_tree *generate(const fg_lightning_config *p, fg_lightning_report *info)
{
    fg_tree *t;
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    fg_result r = fg_lightning_generate(p, t, info);
    if (r != FG_OK)
        fail_msg("generate: %s", fg_result_str(r));
    return t;
}

static double len3(double x, double y, double z)
{
    return sqrt(x * x + y * y + z * z);
}

static double seg_len(const fg_node *n, size_t i)
{
    const fg_node *a = &n[n[i].parent];
    return len3(n[i].x - a->x, n[i].y - a->y, n[i].z - a->z);
}

static double to_listener(const fg_node *n)
{
    return len3(n->x - listener[0], n->y - listener[1], n->z - listener[2]);
}

/* Angle between segment (i-1 -> i) and (i -> i+1) on the main channel. */
static double turn_at(const fg_node *n, size_t i)
{
    double a[3] = {n[i].x - n[i - 1].x, n[i].y - n[i - 1].y, n[i].z - n[i - 1].z};
    double b[3] = {n[i + 1].x - n[i].x, n[i + 1].y - n[i].y, n[i + 1].z - n[i].z};
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    return atan2(len3(c[0], c[1], c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

static void preset_reaches_ground(void **state)
{
    (void)state;
    double total = 0;
    enum { RUNS = 10 };
    for (uint64_t seed = 1; seed <= RUNS; seed++) {
        fg_lightning_config p = {.strike_m = {100, -200}, .seed = seed};
        fg_lightning_report info;
        fg_tree *t = generate(&p, &info);
        const fg_node *n = fg_tree_nodes(t);
        size_t count = fg_tree_count(t);
        assert_int_equal(fg_tree_check(n, count, NULL), FG_OK);
        assert_int_equal(info.segments, count - 1);
        /* main channel: nodes 0 .. main-1 in a chain from the cloud to the strike */
        assert_float_equal(n[0].z, 5000, 1e-9);
        const fg_node *last = &n[info.main_nodes - 1];
        assert_float_equal(last->z, 0, 1e-9);
        assert_true(len3(last->x - 100, last->y + 200, 0) < 3.0 + 1e-9);
        for (size_t i = 0; i < count; i++) {
            int main_ch = i < info.main_nodes;
            assert_int_equal((n[i].flags & FG_NODE_MAIN) != 0, main_ch);
            if (main_ch && i > 0)
                assert_int_equal(n[i].parent, (int32_t)i - 1);
            assert_true(n[i].z >= 0);
        }
        assert_true(info.main_length_m >= info.skeleton_length_m);
        total += (double)info.segments;
        fg_tree_destroy(t);
    }
    /* Matsuyama table 2: 9438 segments on average for lightning. */
    assert_true(total / RUNS > 7000 && total / RUNS < 12000);
}

static void seeded_identical(void **state)
{
    (void)state;
    const fg_thunder_feature features[] = {{FG_THUNDER_CLAP, 0.3, 0.4, 1}};
    fg_lightning_config p = {.seed = 77,
                             .features = features,
                             .feature_count = 1,
                             .listener_m = {3000, 0, 1.7}};
    fg_tree *a = generate(&p, NULL), *b = generate(&p, NULL);
    p.seed = 78;
    fg_tree *c = generate(&p, NULL);
    assert_int_equal(fg_tree_count(a), fg_tree_count(b));
    assert_memory_equal(fg_tree_nodes(a), fg_tree_nodes(b), fg_tree_count(a) * sizeof(fg_node));
    assert_true(fg_tree_count(a) != fg_tree_count(c) ||
                memcmp(fg_tree_nodes(a), fg_tree_nodes(c), fg_tree_count(a) * sizeof(fg_node)));
    fg_tree_destroy(a);
    fg_tree_destroy(b);
    fg_tree_destroy(c);
}

/* Every segment is segment_m long except the few of the final approach;
 * the turns follow the half-normal law of the given mean, scaled from the
 * 3 m step to segment_m by sqrt(segment_m / 3). */
static void segment_and_turn_statistics(void **state)
{
    (void)state;
    double sum = 0, sum2 = 0, max_off = 0;
    size_t turns = 0;
    for (uint64_t seed = 1; seed <= 6; seed++) {
        fg_lightning_config p = {.skeleton_m = vertical,
                                 .skeleton_points = 2,
                                 .segment_m = 2.5,
                                 .turn_mean_deg = 12,
                                 .branch_probability = -1,
                                 .seed = seed};
        fg_lightning_report info;
        fg_tree *t = generate(&p, &info);
        const fg_node *n = fg_tree_nodes(t);
        assert_int_equal(info.main_nodes, fg_tree_count(t)); /* no branches */
        size_t straight = info.main_nodes - 6; /* the final approach is straight in */
        for (size_t i = 1; i < info.main_nodes; i++) {
            if (i < straight)
                assert_float_equal(seg_len(n, i), 2.5, 1e-9);
            else
                assert_true(seg_len(n, i) <= 2.5 + 1e-9);
            max_off = fmax(max_off, hypot(n[i].x, n[i].y));
        }
        for (size_t i = 1; i + 1 < straight; i++) {
            double a = turn_at(n, i);
            sum += a;
            sum2 += a * a;
            turns++;
        }
        fg_tree_destroy(t);
    }
    double mean = sum / turns, rms = sqrt(sum2 / turns), m = 12.0 * sqrt(2.5 / 3.0);
    /* half-normal of mean m: rms = m sqrt(pi / 2); standard error ~0.1 deg */
    assert_float_equal(mean / DEG, m, 0.5);
    assert_float_equal(rms / DEG, m * sqrt(FG_PI / 2), 0.6);
    /* tortuous, yet it follows the skeleton */
    assert_true(max_off > 5 && max_off < 150);
}

/* Branch rule: per-node probability, exponential lengths of the given mean. */
static void branch_statistics(void **state)
{
    (void)state;
    size_t branches = 0, measured = 0, branch_nodes = 0, main_nodes = 0;
    for (uint64_t seed = 1; seed <= 30; seed++) {
        fg_lightning_config p = {.skeleton_m = vertical,
                                 .skeleton_points = 2,
                                 .branch_probability = 0.01,
                                 .branch_length_m = 150,
                                 .branch_depth = 1,
                                 .seed = seed};
        fg_lightning_report info;
        fg_tree *t = generate(&p, &info);
        const fg_node *n = fg_tree_nodes(t);
        size_t count = fg_tree_count(t);
        main_nodes += info.main_nodes - 1; /* the root cannot branch */
        /* depth 1 only: each branch is a run of nodes starting on the main channel */
        for (size_t i = info.main_nodes; i < count; i++) {
            assert_float_equal(seg_len(n, i), 3.0, 1e-9);
            if ((size_t)n[i].parent >= info.main_nodes) {
                assert_int_equal(n[i].parent, (int32_t)i - 1);
                continue;
            }
            branches++;
            size_t len = 1;
            while (i + len < count && (size_t)n[i + len].parent >= info.main_nodes)
                len++;
            if (n[i].z > 1000) { /* far from the ground, which would cut it short */
                measured++;
                branch_nodes += len;
            }
        }
        fg_tree_destroy(t);
    }
    double expect = 0.01 * (double)main_nodes;
    assert_true(fabs((double)branches - expect) < 4 * sqrt(expect));
    /* ceil(L / 3 m) nodes for an exponential L of mean 150 m: 50.5 on average */
    assert_true(measured > 300);
    assert_float_equal((double)branch_nodes / (double)measured, 50.5, 0.15 * 50.5);
}

static void clap_rumble_roar(void **state)
{
    (void)state;
    const fg_thunder_feature features[] = {{FG_THUNDER_CLAP, 0.3, 0.5, 1},
                                       {FG_THUNDER_RUMBLE, 0.6, 0.8, 1},
                                       {FG_THUNDER_ROAR, 0.85, 1.0, 1}};
    for (uint64_t seed = 1; seed <= 4; seed++) {
        fg_lightning_config p = {.skeleton_m = vertical,
                                 .skeleton_points = 2,
                                 .features = features,
                                 .feature_count = 3,
                                 .listener_m = {listener[0], listener[1], listener[2]},
                                 .seed = seed};
        fg_lightning_report info;
        fg_tree *t = generate(&p, &info);
        const fg_node *n = fg_tree_nodes(t);
        assert_float_equal(n[info.main_nodes - 1].z, 0, 1e-9); /* still strikes the ground */

        /* clap: an arc about the listener through the skeleton at 0.3 */
        const fg_lightning_stretch *c = &info.features[0];
        double radius = len3(listener[0], listener[1], 3500 - listener[2]);
        assert_float_equal(c->distance_m, radius, 1e-6);
        size_t on = 0, nodes = c->last_node - c->first_node + 1;
        assert_true(nodes > 250); /* ~1000 m of 3 m steps */
        for (size_t i = c->first_node; i <= c->last_node; i++)
            on += fabs(to_listener(&n[i]) - radius) < 1e-3;
        assert_true(on >= 0.9 * nodes);

        /* rumble: nearly end-on, so the distance spans most of its length */
        const fg_lightning_stretch *r = &info.features[1];
        const fg_node *a = &n[r->first_node], *b = &n[r->last_node];
        double chord[3] = {b->x - a->x, b->y - a->y, b->z - a->z};
        double rad[3] = {a->x - listener[0], a->y - listener[1], a->z - listener[2]};
        double cosang = fabs(chord[0] * rad[0] + chord[1] * rad[1] + chord[2] * rad[2]) /
                        (len3(chord[0], chord[1], chord[2]) * len3(rad[0], rad[1], rad[2]));
        assert_true(acos(cosang) < 15 * DEG);
        assert_true(fabs(to_listener(b) - to_listener(a)) > 850);

        /* roar: the mean turn is 16 (1 + 3) = 64 degrees (turns past 180
         * fold back, so a little less is measured) */
        const fg_lightning_stretch *o = &info.features[2];
        double sum = 0;
        size_t turns = 0;
        for (size_t i = o->first_node + 1; i + 6 < o->last_node; i++, turns++)
            sum += turn_at(n, i);
        assert_true(turns > 50);
        assert_float_equal(sum / turns / DEG, 62, 8);
        fg_tree_destroy(t);
    }
}

static void bad_input(void **state)
{
    (void)state;
    const double one_point[] = {0, 0, 100};
    const double underground[] = {0, 0, 100, 0, 0, -5};
    const double repeated[] = {0, 0, 100, 0, 0, 100, 0, 0, 0};
    const double nan_skel[] = {0, 0, 100, NAN, 0, 0};
    const fg_thunder_feature outside[] = {{FG_THUNDER_ROAR, -0.1, 0.5, 1}};
    const fg_thunder_feature beyond[] = {{FG_THUNDER_ROAR, 0.5, 1.2, 1}};
    const fg_thunder_feature reversed[] = {{FG_THUNDER_CLAP, 0.5, 0.4, 1}};
    const fg_thunder_feature overlap[] = {{FG_THUNDER_CLAP, 0.2, 0.5, 1},
                                        {FG_THUNDER_RUMBLE, 0.4, 0.6, 1}};
    const fg_thunder_feature clap_to_end[] = {{FG_THUNDER_CLAP, 0.8, 1.0, 1}};
    const fg_thunder_feature unknown[] = {{(fg_thunder_kind)7, 0.2, 0.3, 1}};
    const fg_thunder_feature loud[] = {{FG_THUNDER_CLAP, 0.2, 0.3, 1.5}};
    const fg_thunder_feature nan_block[] = {{FG_THUNDER_CLAP, NAN, 0.3, 1}};
    struct {
        const char *what;
        fg_lightning_config p;
        fg_result want;
    } cases[] = {
        {"negative step", {.segment_m = -3}, FG_ERR_ARGUMENT},
        {"NaN step", {.segment_m = NAN}, FG_ERR_NOT_FINITE},
        {"infinite height", {.height_m = INFINITY}, FG_ERR_NOT_FINITE},
        {"turn of 90 degrees", {.turn_mean_deg = 90}, FG_ERR_ARGUMENT},
        {"branch probability 2", {.branch_probability = 2}, FG_ERR_ARGUMENT},
        {"branch depth 9", {.branch_depth = 9}, FG_ERR_ARGUMENT},
        {"NaN listener", {.listener_m = {0, NAN, 0}}, FG_ERR_NOT_FINITE},
        {"empty skeleton", {.skeleton_m = vertical, .skeleton_points = 0}, FG_ERR_ARGUMENT},
        {"skeleton NULL", {.skeleton_m = NULL, .skeleton_points = 3}, FG_ERR_NULL},
        {"one point", {.skeleton_m = one_point, .skeleton_points = 1}, FG_ERR_ARGUMENT},
        {"underground", {.skeleton_m = underground, .skeleton_points = 2}, FG_ERR_ARGUMENT},
        {"repeated point", {.skeleton_m = repeated, .skeleton_points = 3}, FG_ERR_ARGUMENT},
        {"NaN skeleton", {.skeleton_m = nan_skel, .skeleton_points = 2}, FG_ERR_NOT_FINITE},
        {"feature below 0", {.features = outside, .feature_count = 1}, FG_ERR_ARGUMENT},
        {"feature above 1", {.features = beyond, .feature_count = 1}, FG_ERR_ARGUMENT},
        {"feature reversed", {.features = reversed, .feature_count = 1}, FG_ERR_ARGUMENT},
        {"features overlap", {.features = overlap, .feature_count = 2}, FG_ERR_ARGUMENT},
        {"clap to the end", {.features = clap_to_end, .feature_count = 1}, FG_ERR_ARGUMENT},
        {"unknown feature", {.features = unknown, .feature_count = 1}, FG_ERR_ARGUMENT},
        {"amplitude 1.5", {.features = loud, .feature_count = 1}, FG_ERR_ARGUMENT},
        {"NaN feature", {.features = nan_block, .feature_count = 1}, FG_ERR_NOT_FINITE},
        {"features NULL", {.features = NULL, .feature_count = 1}, FG_ERR_NULL},
        {"too many features", {.features = loud, .feature_count = FG_THUNDER_MAX_FEATURES + 1},
         FG_ERR_ARGUMENT},
    };
    fg_tree *t;
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fg_lightning_config out;
        memset(&out, 0x5A, sizeof out);
        fg_lightning_config before = out;
        if (fg_lightning_config_resolve(&cases[i].p, &out) != cases[i].want)
            fail_msg("%s: resolve", cases[i].what);
        assert_memory_equal(&out, &before, sizeof out);
        fg_lightning_report info;
        memset(&info, 0x5A, sizeof info);
        fg_lightning_report info_before = info;
        if (fg_lightning_generate(&cases[i].p, t, &info) != cases[i].want)
            fail_msg("%s: generate", cases[i].what);
        assert_int_equal(fg_tree_count(t), 0);
        assert_memory_equal(&info, &info_before, sizeof info);
    }
    fg_lightning_config p = {.seed = 1};
    assert_int_equal(fg_lightning_generate(&p, NULL, NULL), FG_ERR_NULL);
    assert_int_equal(fg_lightning_generate(NULL, t, NULL), FG_ERR_NULL);
    assert_int_equal(fg_tree_add(t, 1, 2, 3, -1, 0, NULL), FG_OK);
    assert_int_equal(fg_lightning_generate(&p, t, NULL), FG_ERR_ARGUMENT);
    assert_int_equal(fg_tree_count(t), 1);
    fg_tree_clear(t);
    p.max_nodes = 100;
    assert_int_equal(fg_lightning_generate(&p, t, NULL), FG_ERR_CAPACITY);
    assert_int_equal(fg_tree_count(t), 0);
    /* a clap arc longer than half its circle: the listener is too close */
    const fg_thunder_feature clap[] = {{FG_THUNDER_CLAP, 0.1, 0.9, 1}};
    fg_lightning_config near = {.skeleton_m = vertical,
                                .skeleton_points = 2,
                                .features = clap,
                                .feature_count = 1,
                                .listener_m = {10, 0, 4000}};
    assert_int_equal(fg_lightning_generate(&near, t, NULL), FG_ERR_ARGUMENT);
    assert_int_equal(fg_tree_count(t), 0);
    fg_tree_destroy(t);
}

/* The in-cloud channel: none by default; with in_cloud_m a walk from the
 * root along a jittered horizontal course of that length, appended after
 * the tree grown without it, which it leaves node for node. (That the
 * default tree is the one from before the option is the sound hashes'
 * and cli_render_in_cloud's to show: a stored count or hash of it would
 * hold for one compiler only, as gcc and clang grow different trees.) */
static void in_cloud_channel(void **state)
{
    (void)state;
    fg_lightning_config p = {.seed = 1};
    fg_lightning_report r0, r5;
    fg_tree *t0 = generate(&p, &r0);
    assert_int_equal(r0.in_cloud_nodes, 0);
    assert_int_equal(r0.in_cloud_first, fg_tree_count(t0));
    assert_true(r0.in_cloud_length_m == 0);

    const double length = 5000, az = 120 * DEG;
    p.in_cloud_m = length;
    p.in_cloud_azimuth_deg = 120;
    fg_tree *t5 = generate(&p, &r5), *again = generate(&p, NULL);
    size_t n0 = fg_tree_count(t0), n5 = fg_tree_count(t5);
    const fg_node *n = fg_tree_nodes(t5);
    /* the same seed repeats byte for byte; the tree without it is kept */
    assert_int_equal(fg_tree_count(again), n5);
    assert_memory_equal(fg_tree_nodes(again), n, n5 * sizeof(fg_node));
    assert_memory_equal(fg_tree_nodes(t0), n, n0 * sizeof(fg_node));
    assert_int_equal(r5.main_nodes, r0.main_nodes);
    assert_int_equal(r5.in_cloud_first, n0);
    size_t first = r5.in_cloud_first, end = first + r5.in_cloud_nodes;
    /* at least one 3 m segment per 3 m of course, and its branches after it */
    assert_true(r5.in_cloud_nodes >= (size_t)(length / 3));
    assert_true(n5 > end);
    /* a channel from the root, not the main one, ending on the course's end */
    assert_int_equal(n[first].parent, 0);
    const fg_node *root = &n[0], *last = &n[end - 1];
    assert_float_equal(last->x, root->x + length * cos(az), 1e-6);
    assert_float_equal(last->y, root->y + length * sin(az), 1e-6);
    assert_float_equal(last->z, root->z, 1e-6);
    double along_max = 0, side_max = 0, dz_max = 0, channel = 0;
    for (size_t i = first; i < end; i++) {
        assert_int_equal(n[i].parent, i == first ? 0 : (int32_t)(i - 1));
        assert_int_equal(n[i].flags & FG_NODE_MAIN, 0);
        assert_float_equal(seg_len(n, i), 3.0, 1e-6 + (i + 4 >= end ? 3.0 : 0));
        double dx = n[i].x - root->x, dy = n[i].y - root->y;
        double along = dx * cos(az) + dy * sin(az), side = -dx * sin(az) + dy * cos(az);
        along_max = fmax(along_max, along);
        side_max = fmax(side_max, fabs(side));
        dz_max = fmax(dz_max, fabs(n[i].z - root->z));
        channel += seg_len(n, i);
    }
    /* horizontal extent at the cloud's height: the course, within 1 % */
    assert_true(along_max >= length && along_max <= 1.01 * length);
    /* the course's joints: up to 0.08 L in x and y, 0.04 L up or down */
    assert_true(side_max > 0.01 * length && side_max < 0.12 * length + 50);
    assert_true(dz_max < 0.04 * length + 50);
    assert_float_equal(r5.in_cloud_length_m, channel, 1e-6);
    /* tortuous like the main channel: longer than its course */
    assert_true(channel > 1.05 * length && channel < 1.5 * length);
    for (size_t i = end; i < n5; i++) /* the in-cloud channel's branches */
        assert_true((size_t)n[i].parent >= first);
    /* a different course, a different channel; bad values refused */
    p.in_cloud_azimuth_deg = 0;
    fg_tree *t6 = generate(&p, NULL);
    assert_true(memcmp(fg_tree_nodes(t6), n, n0 * sizeof(fg_node)) == 0);
    assert_true(fg_tree_nodes(t6)[first + 10].x != n[first + 10].x);
    fg_lightning_config out;
    p.in_cloud_m = -1;
    assert_int_equal(fg_lightning_config_resolve(&p, &out), FG_ERR_ARGUMENT);
    p.in_cloud_m = NAN;
    assert_int_equal(fg_lightning_config_resolve(&p, &out), FG_ERR_NOT_FINITE);
    p.in_cloud_m = 100;
    p.in_cloud_azimuth_deg = INFINITY;
    assert_int_equal(fg_lightning_config_resolve(&p, &out), FG_ERR_NOT_FINITE);
    fg_tree_destroy(t0);
    fg_tree_destroy(t5);
    fg_tree_destroy(again);
    fg_tree_destroy(t6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(preset_reaches_ground),
        cmocka_unit_test(seeded_identical),
        cmocka_unit_test(segment_and_turn_statistics),
        cmocka_unit_test(branch_statistics),
        cmocka_unit_test(clap_rumble_roar),
        cmocka_unit_test(bad_input),
        cmocka_unit_test(in_cloud_channel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
