/* One node of an explicit tree: [x, y, z, parent] or [x, y, z, parent,
 * main], each element within its range; shared by the cJSON reading
 * (scene_tree.c) and the streaming reader (scene_nodes_stream.c). */
#include <stdint.h>

#include "scene_internal.h"

/* Coordinates are metres, within the engine's limit (10 000 km). */
static const number_range coordinate = {.lo = -FG_TREE_MAX_COORDINATE_M,
                                        .hi = FG_TREE_MAX_COORDINATE_M};
static const number_range parent_index = {-1, INT32_MAX, .integer = true};
static const number_range main_flag = {0, 1, .integer = true};

number_range scene_node_element_range(int k)
{
    return k < 3 ? coordinate : k == 3 ? parent_index : main_flag;
}

int scene_node_values(const double *v, int n)
{
    if (n < 4 || n > 5)
        return 0;
    for (int k = 0; k < n; k++)
        if (!number_range_holds(scene_node_element_range(k), v[k]))
            return 0;
    return 1;
}

fg_node scene_node_from(const double v[5])
{
    return (fg_node){v[0], v[1], v[2], (int32_t)v[3], v[4] != 0 ? FG_NODE_MAIN : 0u};
}
