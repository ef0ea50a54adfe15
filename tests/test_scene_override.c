/* --set KEY=VALUE (scene/scene_override.h): a table of assignments on one
 * document, each with the exact document it leaves or the exact message
 * (and the document unchanged); then through scene_parse_with, where the
 * parser checks what was set. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "scene/scene.h"
#include "scene/scene_override.h"

#define BASE "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":[0,3000,0]}]}"

static const struct {
    const char *set;
    const char *json;     /* the document after, or NULL for an error */
    const char *message;  /* the error */
} cases[] = {
    {"discharges[0].offset[1]=8000", "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":"
                                     "[0,8000,0]}]}", NULL},
    {"seed=7", "{\"seed\":7,\"discharges\":[{\"time\":0.5,\"offset\":[0,3000,0]}]}", NULL},
    {"propagation.ground=true", "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":"
                                "[0,3000,0]}],\"propagation\":{\"ground\":true}}", NULL},
    {"discharges[0].preset=lightning", "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":"
                                       "[0,3000,0],\"preset\":\"lightning\"}]}", NULL},
    {"discharges[0].preset=\"lightning\"", "{\"seed\":1,\"discharges\":[{\"time\":0.5,"
                                           "\"offset\":[0,3000,0],\"preset\":\"lightning\"}]}",
     NULL},
    {"discharges[1]={\"time\":2}", "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":"
                                   "[0,3000,0]},{\"time\":2}]}", NULL},
    {"discharges[0].offset=[1,2,3]", "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":"
                                     "[1,2,3]}]}", NULL},
    {"listener.position=[0, 0, 2]", "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":"
                                    "[0,3000,0]}],\"listener\":{\"position\":[0,0,2]}}", NULL},
    {"description=", "{\"seed\":1,\"discharges\":[{\"time\":0.5,\"offset\":[0,3000,0]}],"
                     "\"description\":\"\"}", NULL},
    {"discharges[2].time=1", NULL,
     "discharges[2]: past the end of discharges (1 elements), setting discharges[2].time"},
    {"seed.x=1", NULL, "seed: is not an object, so it has no key \"x\", setting seed.x"},
    {"seed[0]=1", NULL, "seed: is not an array, so it has no element [0], setting seed[0]"},
    {"a.b[0]=1", NULL,
     "a.b: no such key, so no element [0] (set a.b whole), setting a.b[0]"},
    {"discharges[x]=1", NULL,
     "discharges[x]: expected an index (digits) and ']' at character 12"},
    {"discharges..time=1", NULL,
     "discharges..time: expected a key of 1 to 63 characters at character 12"},
    {"[0]=1", NULL, "(the scene): is an object: the path starts with a key, setting [0]"},
    {"=5", NULL, "expected KEY=VALUE, KEY a JSON path such as discharges[0].time"},
    {"seed", NULL, "seed: expected KEY=VALUE, KEY a JSON path such as discharges[0].time"},
};

static void test_assignments(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cJSON *doc = cJSON_Parse(BASE);
        assert_non_null(doc);
        char err[512] = "";
        int rc = scene_override(doc, cases[i].set, err, sizeof err);
        char *text = cJSON_PrintUnformatted(doc);
        print_message("%-36s -> %s\n", cases[i].set, rc == 0 ? text : err);
        if (cases[i].json) {
            assert_int_equal(rc, 0);
            assert_string_equal(text, cases[i].json);
        } else {
            assert_int_equal(rc, -1);
            assert_string_equal(err, cases[i].message);
            assert_string_equal(text, BASE); /* unchanged */
        }
        free(text);
        cJSON_Delete(doc);
    }
}

#define SCENE "{\"discharges\":[{\"time\":0.25,\"preset\":\"spark_balls\",\"tree\":{\"nodes\":" \
              "[[0,1,1.7,-1],[0,1.01,1.7,0]]}}]}"

/* What is set is parsed as if the file said it, in order; errors are the
 * parser's. */
static void test_through_the_parser(void **state)
{
    (void)state;
    const char *sets[] = {"seed=42", "sample_rate=96000", "discharges[0].time=0.75",
                          "discharges[0].time=1.5", "humidity=20"};
    scene s;
    char err[512];
    assert_int_equal(scene_parse_with(SCENE, strlen(SCENE), sets, 5, &s, err, sizeof err), 0);
    assert_int_equal(s.seed, 42);
    assert_true(s.sample_rate_hz == 96000);
    assert_true(s.discharges[0].post.emit_time_s == 1.5); /* the last one wins */
    assert_true(s.humidity_pct == 20);
    scene_deinit(&s);
    const char *bad[] = {"sample_rate=1000"};
    assert_int_equal(scene_parse_with(SCENE, strlen(SCENE), bad, 1, &s, err, sizeof err), -1);
    assert_string_equal(err, "sample_rate: 1000 is outside 8000..384000");
    const char *path[] = {"discharges[0].tree.nodes[1][3]=7"};
    assert_int_equal(scene_parse_with(SCENE, strlen(SCENE), path, 1, &s, err, sizeof err), -1);
    assert_string_equal(err, "discharges[0].tree.nodes[1]: parent 7 is not before node 1");
    const char *typo[] = {"discharges[0].tiem=1"};
    assert_int_equal(scene_parse_with(SCENE, strlen(SCENE), typo, 1, &s, err, sizeof err), -1);
    assert_non_null(strstr(err, "discharges[0].tiem: unknown key"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_assignments),
        cmocka_unit_test(test_through_the_parser),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
