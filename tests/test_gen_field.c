/* The "spark_gap", "plasma_ball" and "field" scene generators: JSON in,
 * tree out, and errors that name the JSON path of the field at fault. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "scene/generator.h"

static const gen_context ctx = {.seed = 11, .listener_m = {0, -1, 0}};

static int run(gen_fn *fn, const char *json, fg_tree *t, char *err, size_t size)
{
    cJSON *spec = cJSON_Parse(json);
    assert_non_null(spec);
    err[0] = '\0';
    int rc = fn(spec, "discharges[0].generator", &ctx, t, err, size);
    cJSON_Delete(spec);
    return rc;
}

static size_t main_count(fg_tree *t)
{
    size_t m = 0;
    for (size_t i = 0; i < fg_tree_count(t); i++)
        m += (fg_tree_nodes(t)[i].flags & FG_NODE_MAIN) != 0;
    return m;
}

static void presets_grow_between_their_electrodes(void **state)
{
    (void)state;
    fg_tree *t;
    char err[256];
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    assert_int_equal(run(gen_spark_gap, "{\"type\":\"spark_gap\",\"size\":33}", t, err, sizeof err),
                     0);
    const fg_node *n = fg_tree_nodes(t);
    size_t count = fg_tree_count(t);
    /* From the origin ball's surface (x near -1 cm) to the target ball (x = +1 cm). */
    assert_true(count >= 11 && main_count(t) >= 11);
    double cell = 0.07 / 32;
    assert_float_equal(hypot(hypot(n[0].x + 0.02, n[0].y), n[0].z), 0.01, cell);
    const fg_node *end = NULL;
    for (size_t i = 0; i < count; i++)
        if (n[i].flags & FG_NODE_MAIN)
            end = &n[i];
    assert_float_equal(hypot(hypot(end->x - 0.02, end->y), end->z), 0.01, cell);
    /* Same seed, same tree; the plasma ball reaches its glass at 20 cm. */
    fg_tree *again;
    assert_int_equal(fg_tree_create(0, &again), FG_OK);
    assert_int_equal(run(gen_spark_gap, "{\"type\":\"spark_gap\",\"size\":33}", again, err,
                         sizeof err),
                     0);
    assert_int_equal(fg_tree_count(again), count);
    assert_memory_equal(fg_tree_nodes(again), n, count * sizeof *n);
    assert_int_equal(run(gen_plasma_ball, "{\"type\":\"plasma_ball\",\"size\":33}", t, err,
                         sizeof err),
                     0);
    n = fg_tree_nodes(t);
    const fg_node *last = &n[fg_tree_count(t) - 1];
    assert_float_equal(sqrt(last->x * last->x + last->y * last->y + last->z * last->z), 0.20,
                       0.02);
    fg_tree_destroy(again);
    fg_tree_destroy(t);
}

#define GRID "\"grid\":{\"size\":17,\"min\":[0,0,0],\"max\":[1,1,1]}"
#define PLATES                                                                              \
    "{\"kind\":\"ground\",\"role\":\"origin\"},"                                            \
    "{\"kind\":\"plane\",\"center\":[0,0,1],\"normal\":[0,0,-1],\"role\":\"target\"}"

static void field_type_grows_in_the_scene_field(void **state)
{
    (void)state;
    fg_tree *t;
    char err[256];
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    for (int dbm = 0; dbm < 2; dbm++) {
        char json[512];
        snprintf(json, sizeof json,
                 "{\"type\":\"field\"," GRID ",\"shapes\":[" PLATES "],"
                 "\"growth\":{\"model\":\"%s\",\"step\":0.1,\"max_tips\":1}}",
                 dbm ? "dbm" : "matsuyama");
        assert_int_equal(run(gen_field, json, t, err, sizeof err), 0);
        const fg_node *n = fg_tree_nodes(t);
        size_t count = fg_tree_count(t);
        /* Up from the ground to the top plate: its nodes at z = 1 claim
         * the half cell below them. */
        assert_true(n[0].z < 0.1);
        double top = 0.0;
        for (size_t i = 0; i < count; i++)
            if (n[i].flags & FG_NODE_MAIN)
                top = fmax(top, n[i].z);
        assert_true(top >= 1.0 - 1.0 / 32 - 1e-9);
        if (!dbm)
            assert_int_equal(main_count(t), count);
    }
    fg_tree_destroy(t);
}

static void errors_name_the_path(void **state)
{
    (void)state;
    static const struct {
        gen_fn *fn;
        const char *json, *err;
    } cases[] = {
        {gen_spark_gap, "{\"size\":300}", "discharges[0].generator.size: 300 is outside 9..257"},
        {gen_plasma_ball, "{\"growth\":{\"model\":\"lattice\"}}",
         "discharges[0].generator.growth.model: expected one of \"matsuyama\", \"dbm\""},
        {gen_field, "{\"shapes\":[]}", "discharges[0].generator.grid: is required"},
        {gen_field, "{\"grid\":{\"size\":17,\"min\":[0,0,0],\"max\":[1,0,1]}}",
         "discharges[0].generator.grid.max: must exceed grid.min"},
        {gen_field, "{" GRID ",\"shapes\":[" PLATES "],\"growth\":{\"step\":0}}",
         "discharges[0].generator.growth.step: must be > 0"},
        {gen_field, "{" GRID ",\"shapes\":[" PLATES "],\"growth\":{\"step\":-1}}",
         "discharges[0].generator.growth.step: must be > 0"},
        {gen_field, "{" GRID ",\"shapes\":[" PLATES "]}", "discharges[0].generator.growth.step: is required"},
        {gen_field,
         "{" GRID ",\"shapes\":[" PLATES ",{\"kind\":\"sphere\",\"center\":[5,5,5],\"radius\":0.1}],"
         "\"growth\":{\"step\":0.1}}",
         "discharges[0].generator.shapes[2]: covers no node of the grid"},
        {gen_field,
         "{" GRID ",\"shapes\":[" PLATES ",{\"kind\":\"sphere\",\"center\":[0.5,0.5,0.5]}],"
         "\"growth\":{\"step\":0.1}}",
         "discharges[0].generator.shapes[2].radius: is required"},
        {gen_field,
         "{" GRID ",\"shapes\":[{\"kind\":\"ground\",\"role\":\"origin\"},{\"kind\":\"ground\"}],"
         "\"growth\":{\"step\":0.1}}",
         "discharges[0].generator.shapes: needs at least one \"origin\" and one \"target\""},
        {gen_field,
         "{" GRID ",\"shapes\":[{\"kind\":\"cone\",\"role\":\"origin\"}," PLATES "],"
         "\"growth\":{\"step\":0.1}}",
         "discharges[0].generator.shapes[0].kind: expected one of"},
        /* a closed fixed box round the origin: no way out */
        {gen_field,
         "{" GRID ",\"shapes\":[" PLATES ",{\"kind\":\"box\",\"min\":[0.25,0.25,0.25],"
         "\"max\":[0.75,0.75,0.75],\"outside\":true,\"potential\":0.5},"
         "{\"kind\":\"point\",\"center\":[0.5,0.5,0.5],\"role\":\"origin\"},"
         "{\"kind\":\"plane\",\"center\":[0,0,1],\"normal\":[0,0,-1],\"role\":\"target\"}],"
         "\"growth\":{\"step\":0.05,\"max_steps\":300}}",
         "discharges[0].generator.shapes: the target cannot be reached from the origin"},
        {gen_field,
         "{\"grid\":{\"size\":257,\"min\":[0,0,0],\"max\":[1,1,1]},\"shapes\":[" PLATES
         "],\"growth\":{\"step\":0.1,\"gamma\":-1}}",
         "discharges[0].generator.growth.gamma: must be >= 0"},
    };
    fg_tree *t;
    assert_int_equal(fg_tree_create(0, &t), FG_OK);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char err[512];
        assert_int_equal(run(cases[i].fn, cases[i].json, t, err, sizeof err), -1);
        if (strncmp(err, cases[i].err, strlen(cases[i].err)) != 0)
            fail_msg("case %zu: got \"%s\", want \"%s...\"", i, err, cases[i].err);
        assert_int_equal(fg_tree_count(t), 0);
    }
    fg_tree_destroy(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(presets_grow_between_their_electrodes),
        cmocka_unit_test(field_type_grows_in_the_scene_field),
        cmocka_unit_test(errors_name_the_path),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
