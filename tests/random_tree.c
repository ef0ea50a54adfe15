#include <math.h>

#include "random_tree.h"

void random_tree(fg_rng *rng, fg_node *nodes, size_t count, const double root[3], double step_m,
                 const double drift[3], double branch)
{
    nodes[0] = (fg_node){root[0], root[1], root[2], -1, 0};
    for (size_t i = 1; i < count; i++) {
        size_t parent = i - 1;
        if (i > 1 && fg_rng_uniform(rng) < branch)
            parent = (size_t)(fg_rng_uniform(rng) * (double)(i - 1));
        double d[3], len2 = 0;
        for (int k = 0; k < 3; k++) {
            d[k] = fg_rng_range(rng, -1.0, 1.0) + drift[k];
            len2 += d[k] * d[k];
        }
        /* a degenerate draw steps straight down */
        double scale = len2 > 1e-12 ? step_m / sqrt(len2) : 0.0;
        const fg_node *p = &nodes[parent];
        nodes[i] = (fg_node){p->x + scale * d[0], p->y + scale * d[1],
                             p->z + (scale > 0 ? scale * d[2] : -step_m), (int32_t)parent, 0};
    }
}
