/* The streaming reader of explicit trees (host/scene/scene_nodes_stream.c):
 * it takes the arrays it should, leaves the rest of the text for cJSON,
 * converts every number exactly as the C library's strtod does, and leaves
 * everything it does not take to cJSON, whose messages stay the same. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "scene/scene_internal.h"

#define HEAD "{\"discharges\":[{\"time\":0,\"preset\":\"spark_balls\",\"tree\":{\"nodes\":"

static uint64_t next_random(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* A coordinate's text in one of several forms writers use. */
static void number_text(uint64_t *state, char *out, size_t size)
{
    uint64_t r = next_random(state);
    double unit = (double)(r >> 11) / 9007199254740992.0;
    double v = (unit * 2 - 1) * pow(10.0, (double)(next_random(state) % 13) - 6);
    switch (next_random(state) % 9) {
    case 7: snprintf(out, size, "%.18g", v); break; /* 19 digits: extended precision */
    case 8: snprintf(out, size, "%.16e", v); break;
    case 0: snprintf(out, size, "%.17g", v); break;
    case 1: snprintf(out, size, "%.6f", v); break;
    case 2: snprintf(out, size, "%.3e", v); break;
    case 3: snprintf(out, size, "%lld", (long long)v); break;
    case 4: snprintf(out, size, "%.25f", v * 1e-3); break; /* > 19 digits: strtod */
    case 5: snprintf(out, size, "%.15E", v * 1e-30);         /* 10^-45: strtod */ break;
    default: snprintf(out, size, "%.9g", v); break;
    }
}

/* A tree of n nodes, node k > 0 at [x_k, y_k, 1] under the root, written
 * with numbers in every form; *text is malloc'ed. */
static size_t tree_scene(size_t n, uint64_t seed, char **text)
{
    size_t cap = 128 + n * 160, len = 0;
    char *t = malloc(cap);
    assert_non_null(t);
    len += (size_t)snprintf(t + len, cap - len, "%s[[0,0,0,-1]", HEAD);
    for (size_t k = 1; k < n; k++) {
        char x[64], y[64];
        number_text(&seed, x, sizeof x);
        number_text(&seed, y, sizeof y);
        len += (size_t)snprintf(t + len, cap - len, ",\n [%s, %s, 1, 0%s]", x, y,
                                k % 3 ? "" : ", 1");
    }
    len += (size_t)snprintf(t + len, cap - len, "]}}]}");
    *text = t;
    return len;
}

static void takes_the_nodes_and_keeps_the_rest(void **state)
{
    (void)state;
    char *text;
    size_t size = tree_scene(2000, 7, &text), rest_size;
    scene_node_lists lists;
    char *rest = scene_nodes_stream(text, size, &lists, &rest_size);
    assert_non_null(rest);
    assert_int_equal(lists.count, 1);
    assert_int_equal(lists.list[0].count, 2000);
    /* the rest is the text with the array written [] */
    const scene_node_list *l = &lists.list[0];
    assert_int_equal(l->start, strlen(HEAD));
    assert_int_equal(l->end, size - strlen("}}]}"));
    assert_int_equal(rest_size, strlen(HEAD "[]}}]}"));
    assert_memory_equal(rest, HEAD "[]}}]}", rest_size);
    free(rest);
    scene_node_lists_free(&lists);
    free(text);
}

/* Each number as strtod reads its text, bit for bit (the outside
 * reference: the C library's correctly rounded conversion). */
static void numbers_are_strtod_exact(void **state)
{
    (void)state;
    char *text;
    size_t size = tree_scene(20000, 11, &text);
    scene_node_lists lists;
    size_t rest_size;
    char *rest = scene_nodes_stream(text, size, &lists, &rest_size);
    assert_non_null(rest);
    assert_int_equal(lists.list[0].count, 20000);
    const char *p = text + strlen(HEAD) + strlen("[[0,0,0,-1]");
    for (size_t k = 1; k < 20000; k++) {
        p = strchr(p, '[') + 1;
        char *after;
        double x = strtod(p, &after), y = strtod(after + 1, NULL);
        const fg_node *node = &lists.list[0].nodes[k];
        assert_memory_equal(&node->x, &x, sizeof x);
        assert_memory_equal(&node->y, &y, sizeof y);
        assert_true(node->z == 1 && node->parent == 0);
        assert_int_equal(node->flags, k % 3 ? 0u : FG_NODE_MAIN);
    }
    free(rest);
    scene_node_lists_free(&lists);
    free(text);
}

/* The same scene through the reader and through cJSON alone (a --set into
 * "discharges" turns the reader off): identical nodes. */
static void same_nodes_as_cjson(void **state)
{
    (void)state;
    char *text;
    size_t size = tree_scene(5000, 3, &text);
    const char *keep[] = {"discharges[0].time=0"};
    scene fast, plain;
    char err[512] = "";
    assert_int_equal(scene_parse(text, size, &fast, err, sizeof err), 0);
    assert_int_equal(scene_parse_with(text, size, keep, 1, &plain, err, sizeof err), 0);
    assert_int_equal(fast.discharges[0].post.node_count, 5000);
    assert_int_equal(plain.discharges[0].post.node_count, 5000);
    assert_memory_equal(fast.discharges[0].post.nodes, plain.discharges[0].post.nodes,
                        5000 * sizeof(fg_node));
    scene_deinit(&fast);
    scene_deinit(&plain);
    free(text);
}

static void expect_error(const char *json, const char *message)
{
    scene s;
    char err[512] = "";
    assert_int_equal(scene_parse(json, strlen(json), &s, err, sizeof err), -1);
    assert_string_equal(err, message);
}

/* What the reader does not take keeps cJSON's message. */
static void leaves_the_rest_to_cjson(void **state)
{
    (void)state;
    scene_node_lists lists;
    static const char *const refused[] = {
        HEAD "[[0,0,0,-1],[0,0,1,\"0\"]]}}]}",         /* a string */
        HEAD "[[0,0,0,-1],[0,0,1,0,1,1]]}}]}",        /* six elements */
        HEAD "[[0,0,0,-1],[0,0,1e8,0]]}}]}",          /* out of range */
        HEAD "[[0,0,0,-1],[0,0,1,0.5]]}}]}",          /* not an integer */
        HEAD "[[0,0,0,-1],[0,0,01,0]]}}]}",           /* not JSON's grammar */
        HEAD "[[0,0,0,-1],[0,0,1.,0]]}}]}",
        HEAD "[[0,0,0,-1],[0,0,"
             "1.00000000000000000000000000000000000000000000000000000000000000001,0]]}}]}",
        HEAD "[]}}]}",                                 /* empty */
        "{\"discharges\":[{\"tree\":{\"nod\\u0065s\":[[0,0,0,-1],[0,0,1,0]]}}]}",
    };
    for (size_t i = 0; i < sizeof refused / sizeof *refused; i++) {
        size_t rest_size;
        assert_null(scene_nodes_stream(refused[i], strlen(refused[i]), &lists, &rest_size));
        assert_int_equal(lists.count, 0);
    }
    expect_error(HEAD "[[0,0,0,-1],[0,0,1e8,0]]}}]}",
                 "discharges[0].tree.nodes[1][2]: 100000000 is outside -10000000..10000000");
    /* taken, and a syntax error after it: the line and column of the file */
    expect_error(HEAD "[[0,0,0,-1],\n[0,0,1,0]]}}],\n  x}",
                 "scene: JSON syntax error at line 3, column 4");
    /* a second discharge's bad tree after a taken one */
    expect_error("{\"discharges\":[{\"time\":0,\"preset\":\"spark_balls\",\"tree\":{\"nodes\":"
                 "[[0,0,0,-1],[0,0,1,0]]}},{\"time\":0,\"preset\":\"spark_balls\",\"tree\":"
                 "{\"nodes\":[[0,0,0,-1],[0,0,1,7]]}}]}",
                 "discharges[1].tree.nodes[1]: parent 7 is not before node 1");
    /* the tree check still names the node of a taken tree */
    expect_error(HEAD "[[0,0,0,-1],[0,0,1,0],[0,0,1,1]]}}]}",
                 "discharges[0].tree.nodes[2]: node 2 lies on its parent 1 (zero-length "
                 "segment)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(takes_the_nodes_and_keeps_the_rest),
        cmocka_unit_test(numbers_are_strtod_exact),
        cmocka_unit_test(same_nodes_as_cjson),
        cmocka_unit_test(leaves_the_rest_to_cjson),
    };
    return cmocka_run_group_tests(tests, 0, NULL);
}
