/* Moving a tree: fg_tree_translate adds the offset to every node, exactly
 * as x += dx would, and leaves the structure (parents, flags) and so the
 * tree's validity as they were. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "fulgur/tree.h"

static const fg_node base[] = {
    {0.0, 0.0, 1000.0, -1, FG_NODE_MAIN},
    {0.5, -0.25, 997.0, 0, FG_NODE_MAIN},
    {1.0e-3, 3.0, 994.0, 1, 0},
    {-2.0, 1.0e6, 990.5, 1, FG_NODE_MAIN},
};
#define COUNT (sizeof base / sizeof base[0])

static void translates_every_node(void **state)
{
    (void)state;
    static const double offsets[][3] = {
        {0, 1, 1.7}, {-3000.0, 250.0, 0.0}, {1e-9, -1e-9, 5e3}, {0, 0, 0},
    };
    for (size_t k = 0; k < sizeof offsets / sizeof offsets[0]; k++) {
        fg_node nodes[COUNT];
        memcpy(nodes, base, sizeof nodes);
        fg_tree_translate(nodes, COUNT, offsets[k]);
        for (size_t i = 0; i < COUNT; i++) {
            double x = base[i].x, y = base[i].y, z = base[i].z;
            x += offsets[k][0];
            y += offsets[k][1];
            z += offsets[k][2];
            assert_true(nodes[i].x == x && nodes[i].y == y && nodes[i].z == z);
            assert_int_equal(nodes[i].parent, base[i].parent);
            assert_int_equal(nodes[i].flags, base[i].flags);
        }
        assert_int_equal(fg_tree_check(nodes, COUNT, NULL), FG_OK);
    }
    /* a round trip restores the positions to rounding */
    fg_node nodes[COUNT];
    memcpy(nodes, base, sizeof nodes);
    fg_tree_translate(nodes, COUNT, (double[]){2.5, -7.0, 0.125});
    fg_tree_translate(nodes, COUNT, (double[]){-2.5, 7.0, -0.125});
    for (size_t i = 0; i < COUNT; i++)
        assert_true(fabs(nodes[i].x - base[i].x) <= 1e-12 && fabs(nodes[i].y - base[i].y) <= 1e-9 &&
                    fabs(nodes[i].z - base[i].z) <= 1e-12);
    /* no nodes: nothing to do */
    fg_tree_translate(NULL, 0, (double[]){1, 1, 1});
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(translates_every_node),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
