#include <math.h>

#include <stdlib.h>

#include "synth_tree.h"

static uint64_t next(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

static double uniform(uint64_t *s)
{
    return (double)(next(s) >> 11) * 0x1.0p-53;
}

/* A step from node p in a direction jittered around (dx, dy, dz). */
static void step(fg_node *nodes, size_t i, size_t p, double dx, double dy, double dz, double len,
                 uint64_t *s)
{
    double x = dx + 0.6 * (uniform(s) - 0.5), y = dy + 0.6 * (uniform(s) - 0.5),
           z = dz + 0.3 * (uniform(s) - 0.5);
    double norm = sqrt(x * x + y * y + z * z);
    nodes[i] = (fg_node){nodes[p].x + len * x / norm, nodes[p].y + len * y / norm,
                         fmax(0.0, nodes[p].z + len * z / norm), (int32_t)p, 0};
    if (nodes[i].z == nodes[p].z && nodes[i].x == nodes[p].x && nodes[i].y == nodes[p].y)
        nodes[i].x += len;
}

void synth_tree(fg_node *nodes, size_t segments, double height_m, double step_m, uint64_t seed)
{
    uint64_t s = seed * 2654435761u + 1;
    nodes[0] = (fg_node){0, 0, height_m, -1, 0};
    size_t main_len = (size_t)(1.2 * height_m / step_m);
    if (main_len > segments)
        main_len = segments;
    size_t i = 1;
    /* the main channel descends height_m over main_len steps */
    double fall = height_m / (double)main_len / step_m;
    for (; i <= main_len; i++) {
        step(nodes, i, i - 1, 0, 0, -fall, step_m, &s);
        nodes[i].flags = FG_NODE_MAIN;
    }
    while (i <= segments) {
        size_t p = (size_t)(uniform(&s) * (double)i);
        double a = 6.283185307179586 * uniform(&s);
        size_t length = 20 + (size_t)(uniform(&s) * 180);
        for (size_t k = 0; k < length && i <= segments; k++, i++) {
            step(nodes, i, p, cos(a), sin(a), -0.8, step_m, &s);
            p = i;
        }
    }
}

fg_node *synth_far_bolt(size_t segments)
{
    fg_node *nodes = malloc((segments + 1) * sizeof *nodes);
    if (!nodes)
        return NULL;
    synth_tree(nodes, segments, 5000.0, 3.0, 5);
    for (size_t i = 0; i <= segments; i++)
        nodes[i].y += 3000.0;
    return nodes;
}
