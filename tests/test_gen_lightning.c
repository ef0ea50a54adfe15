/* The "lightning" and "charges" scene generators: JSON in, tree out, and
 * errors that name the JSON path of the field at fault. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "scene/generator.h"

static const gen_context ctx = {.seed = 11, .listener_m = {100, 50, 1.7}};

static int run(gen_fn *fn, const char *json, fg_tree *t, char *err, size_t size)
{
    cJSON *spec = cJSON_Parse(json);
    assert_non_null(spec);
    err[0] = '\0';
    int rc = fn(spec, "discharges[0].generator", &ctx, t, err, size);
    cJSON_Delete(spec);
    return rc;
}

static void lightning_placed_from_listener(void **state)
{
    (void)state;
    fg_tree *t;
    char err[256];
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    assert_int_equal(run(gen_lightning,
                         "{\"type\":\"lightning\",\"distance\":3000,\"azimuth_deg\":90,"
                         "\"branch_probability\":0,"
                         "\"design\":[{\"feature\":\"clap\",\"start\":0.3,\"end\":0.4}]}",
                         t, err, sizeof err),
                     0);
    const fg_node *n = fg_tree_nodes(t);
    size_t count = fg_tree_count(t);
    assert_true(count > 1000);
    /* no branches: every node is on the main channel, which ends 3 km north
     * of the listener, within a step */
    assert_true(n[count - 1].flags & FG_NODE_MAIN);
    assert_float_equal(n[count - 1].z, 0, 1e-9);
    assert_float_equal(n[count - 1].x, 100, 3.0);
    assert_float_equal(n[count - 1].y, 3050, 3.0);
    fg_tree_destroy(t);
}

static void skeleton_moved_to_distance(void **state)
{
    (void)state;
    fg_tree *t;
    char err[256];
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    assert_int_equal(run(gen_lightning,
                         "{\"type\":\"lightning\",\"distance\":1000,"
                         "\"skeleton\":[[0,0,2000],[300,0,1000],[0,0,0]]}",
                         t, err, sizeof err),
                     0);
    const fg_node *n = fg_tree_nodes(t);
    /* the root is the skeleton's, moved with it: strike at (1100, 50) */
    assert_float_equal(n[0].x, 1100, 1e-9);
    assert_float_equal(n[0].y, 50, 1e-9);
    assert_float_equal(n[0].z, 2000, 1e-9);
    fg_tree_destroy(t);
}

static void charges_grow(void **state)
{
    (void)state;
    fg_tree *t;
    char err[256];
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    assert_int_equal(run(gen_charges,
                         "{\"type\":\"charges\",\"start\":[0,0,300],\"step\":2,"
                         "\"charges\":[{\"position\":[0,0,350],\"charge\":-1},"
                         "{\"position\":[0,0,-350],\"charge\":1}]}",
                         t, err, sizeof err),
                     0);
    const fg_node *n = fg_tree_nodes(t);
    size_t count = fg_tree_count(t);
    assert_float_equal(n[0].z, 300, 1e-9);
    assert_float_equal(n[count - 1].z, 0, 1e-9);
    assert_true(count > 150);
    fg_tree_destroy(t);
}

/* "in_cloud": the same tree, then a channel from the root 5 km along
 * "in_cloud_azimuth_deg" at the root's height; "in_cloud": 0 is no key. */
static void in_cloud_channel_from_json(void **state)
{
    (void)state;
    fg_tree *plain, *zero, *cloud;
    char err[256];
    assert_int_equal(fg_tree_create(0, &plain), FG_OK);
    assert_int_equal(fg_tree_create(0, &zero), FG_OK);
    assert_int_equal(fg_tree_create(0, &cloud), FG_OK);
    assert_int_equal(run(gen_lightning, "{\"type\":\"lightning\",\"distance\":3000}", plain, err,
                         sizeof err),
                     0);
    assert_int_equal(run(gen_lightning, "{\"type\":\"lightning\",\"distance\":3000,\"in_cloud\":0}",
                         zero, err, sizeof err),
                     0);
    assert_int_equal(run(gen_lightning,
                         "{\"type\":\"lightning\",\"distance\":3000,\"in_cloud\":5000,"
                         "\"in_cloud_azimuth_deg\":-90}",
                         cloud, err, sizeof err),
                     0);
    size_t n0 = fg_tree_count(plain);
    assert_int_equal(fg_tree_count(zero), n0);
    assert_memory_equal(fg_tree_nodes(zero), fg_tree_nodes(plain), n0 * sizeof(fg_node));
    assert_true(fg_tree_count(cloud) > n0 + 5000 / 3);
    const fg_node *n = fg_tree_nodes(cloud);
    assert_memory_equal(n, fg_tree_nodes(plain), n0 * sizeof(fg_node));
    /* the in-cloud channel comes first after the old tree, ending 5 km
     * toward -y of the root at its height */
    size_t last = n0;
    while (last + 1 < fg_tree_count(cloud) && n[last + 1].parent == (int32_t)last)
        last++;
    assert_int_equal(n[n0].parent, 0);
    assert_float_equal(n[last].x, n[0].x, 1e-6);
    assert_float_equal(n[last].y, n[0].y - 5000, 1e-6);
    assert_float_equal(n[last].z, n[0].z, 1e-6);
    fg_tree_destroy(plain);
    fg_tree_destroy(zero);
    fg_tree_destroy(cloud);
}

static void errors_name_the_path(void **state)
{
    (void)state;
    struct {
        gen_fn *fn;
        const char *json, *message;
    } cases[] = {
        {gen_lightning, "{\"type\":\"lightning\",\"segment\":0}",
         "discharges[0].generator.segment: 0 is outside (0, 10000000]"},
        {gen_lightning, "{\"type\":\"lightning\",\"segment\":-3}",
         "discharges[0].generator.segment: -3 is outside (0, 10000000]"},
        {gen_lightning, "{\"type\":\"lightning\",\"skeleton\":[]}",
         "discharges[0].generator.skeleton: expected an array of 2 to 65536 points [x, y, z]"},
        {gen_lightning, "{\"type\":\"lightning\",\"skeleton\":[[0,0,9],[0,0,-1]]}",
         "discharges[0].generator.skeleton[1]: below the ground (z < 0)"},
        {gen_lightning,
         "{\"type\":\"lightning\",\"design\":[{\"feature\":\"clap\",\"start\":0.2,\"end\":1.5}]}",
         "discharges[0].generator.design[0].end: 1.5 is outside 0..1"},
        {gen_lightning,
         "{\"type\":\"lightning\",\"design\":[{\"feature\":\"roar\",\"start\":0.2,\"end\":0.5},"
         "{\"feature\":\"rumble\",\"start\":0.4,\"end\":0.6}]}",
         "discharges[0].generator.design[1]: overlaps discharges[0].generator.design[0]"},
        {gen_lightning,
         "{\"type\":\"lightning\",\"design\":[{\"feature\":\"boom\",\"start\":0.2,\"end\":0.5}]}",
         "discharges[0].generator.design[0].feature: required: \"clap\", \"rumble\" or \"roar\""},
        {gen_lightning, "{\"type\":\"lightning\",\"in_cloud\":25000}",
         "discharges[0].generator.in_cloud: 25000 is outside 0..20000"},
        {gen_lightning, "{\"type\":\"lightning\",\"in_cloud\":-1}",
         "discharges[0].generator.in_cloud: -1 is outside 0..20000"},
        {gen_lightning, "{\"type\":\"lightning\",\"in_cloud\":5000,\"in_cloud_azimuth_deg\":400}",
         "discharges[0].generator.in_cloud_azimuth_deg: 400 is outside -360..360"},
        {gen_lightning, "{\"type\":\"lightning\",\"strike\":[0,0],\"distance\":5}",
         "discharges[0].generator.strike: give \"strike\" or \"distance\", not both"},
        {gen_charges, "{\"type\":\"charges\",\"start\":[0,0,300]}",
         "discharges[0].generator.charges: expected an array of 1 to 4096 charges"},
        {gen_charges,
         "{\"type\":\"charges\",\"start\":[0,0,300],\"chosen\":9,"
         "\"charges\":[{\"position\":[0,0,350],\"charge\":-1}]}",
         "discharges[0].generator.chosen: more than the candidates (default 8)"},
        {gen_charges,
         "{\"type\":\"charges\",\"start\":[0,0,-1],"
         "\"charges\":[{\"position\":[0,0,350],\"charge\":-1}]}",
         "discharges[0].generator.start: must be above the ground (z > 0)"},
        {gen_charges,
         "{\"type\":\"charges\",\"start\":[0,0,300],"
         "\"charges\":[{\"position\":[0,0,350]}]}",
         "discharges[0].generator.charges[0]: \"position\" and \"charge\" are required"},
    };
    fg_tree *t;
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char err[256];
        assert_int_equal(run(cases[i].fn, cases[i].json, t, err, sizeof err), -1);
        assert_string_equal(err, cases[i].message);
        assert_int_equal(fg_tree_count(t), 0);
    }
    fg_tree_destroy(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lightning_placed_from_listener),
        cmocka_unit_test(skeleton_moved_to_distance),
        cmocka_unit_test(charges_grow),
        cmocka_unit_test(in_cloud_channel_from_json),
        cmocka_unit_test(errors_name_the_path),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
