/* A kd-tree for approximate nearest neighbours in the feature spaces of
 * the texture synthesis (Arya, Mount et al. 1998, the method of the ANN
 * library the paper used; this is our own C).
 *
 * Build: each node splits its points at the median of the dimension of
 * widest spread; leaves hold at most FG_KD_LEAF points. Search: depth
 * first, nearer child first, with the incremental distance from the query
 * to each node's cell (only the coordinate of the split changes from a
 * node to its far child). A subtree is skipped when (1 + eps) times that
 * distance is not below the best distance so far, so the point returned is
 * within (1 + eps) of the true nearest (eps = 0: exact), up to the float
 * rounding of the leaf distances (1e-7 relative; the priority-queue order
 * of ANN's other search examined no fewer points on our features).
 * [sim-thread]: build allocates; search never does, and a built tree may be
 * searched from several threads at once. */
#ifndef FULGUR_FIRE_KDTREE_INTERNAL_H
#define FULGUR_FIRE_KDTREE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define FG_KD_LEAF 8
#define FG_KD_MAX_DIM 256

typedef struct fg_kd_node {
    uint32_t first, count;   /* leaf: its points in tree order; count 0: inner */
    uint32_t left, right;    /* inner: children */
    uint32_t dim;
    float split;
} fg_kd_node;

typedef struct fg_kdtree {
    size_t dim, count;
    float *points;           /* count * dim, in tree order */
    uint32_t *ids;           /* original index of each point in tree order */
    fg_kd_node *nodes;
    size_t node_count;
    float *lo, *hi;          /* the bounding box */
} fg_kdtree;

/* The bytes a tree of count points of dim dimensions holds. */
size_t fg_kdtree_bytes(size_t count, size_t dim);

/* Builds a tree over points[0 .. count * dim) (copied), 1 <= count <
 * 2^32, 1 <= dim <= FG_KD_MAX_DIM. Returns false when out of memory. */
bool fg_kdtree_build(fg_kdtree *t, const float *points, size_t count, size_t dim);
void fg_kdtree_free(fg_kdtree *t);

/* The original index of a point within (1 + eps) of the nearest to
 * query (eps >= 0); *dist2 (may be NULL) its squared distance. */
size_t fg_kdtree_nearest(const fg_kdtree *t, const float *query, double eps, double *dist2);

#endif
