#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kdtree_internal.h"

static size_t node_count_for(size_t n)
{
    if (n <= FG_KD_LEAF)
        return 1;
    return 1 + node_count_for(n / 2) + node_count_for(n - n / 2);
}

size_t fg_kdtree_bytes(size_t count, size_t dim)
{
    return count * dim * sizeof(float) + count * sizeof(uint32_t) +
           node_count_for(count) * sizeof(fg_kd_node) + 2 * dim * sizeof(float);
}

static void swap_points(fg_kdtree *t, size_t a, size_t b)
{
    if (a == b)
        return;
    float *pa = t->points + a * t->dim, *pb = t->points + b * t->dim;
    for (size_t d = 0; d < t->dim; d++) {
        float s = pa[d];
        pa[d] = pb[d];
        pb[d] = s;
    }
    uint32_t s = t->ids[a];
    t->ids[a] = t->ids[b];
    t->ids[b] = s;
}

static float key(const fg_kdtree *t, size_t i, size_t d)
{
    return t->points[i * t->dim + d];
}

/* Reorders [first, first + n) so that point first + k has the k-th
 * smallest coordinate d, smaller ones before it and larger after. */
static void select_kth(fg_kdtree *t, size_t first, size_t n, size_t k, size_t d)
{
    size_t lo = first, hi = first + n - 1, target = first + k;
    while (lo < hi) {
        /* median of three as the pivot, moved to hi */
        size_t mid = lo + (hi - lo) / 2;
        if (key(t, mid, d) < key(t, lo, d))
            swap_points(t, mid, lo);
        if (key(t, hi, d) < key(t, lo, d))
            swap_points(t, hi, lo);
        if (key(t, mid, d) < key(t, hi, d))
            swap_points(t, mid, hi);
        float pivot = key(t, hi, d);
        size_t store = lo;
        for (size_t i = lo; i < hi; i++)
            if (key(t, i, d) < pivot)
                swap_points(t, i, store++);
        swap_points(t, store, hi);
        if (store == target)
            return;
        if (store < target)
            lo = store + 1;
        else
            hi = store - 1;
    }
}

static uint32_t build_node(fg_kdtree *t, size_t first, size_t n)
{
    uint32_t id = (uint32_t)t->node_count++;
    fg_kd_node *node = &t->nodes[id];
    if (n <= FG_KD_LEAF) {
        *node = (fg_kd_node){.first = (uint32_t)first, .count = (uint32_t)n};
        return id;
    }
    size_t best = 0;
    float spread = -1.0f;
    for (size_t d = 0; d < t->dim; d++) {
        float lo = FLT_MAX, hi = -FLT_MAX;
        for (size_t i = first; i < first + n; i++) {
            float v = key(t, i, d);
            lo = v < lo ? v : lo;
            hi = v > hi ? v : hi;
        }
        if (hi - lo > spread) {
            spread = hi - lo;
            best = d;
        }
    }
    size_t half = n / 2;
    select_kth(t, first, n, half, best);
    float split = key(t, first + half, best);
    uint32_t left = build_node(t, first, half);
    uint32_t right = build_node(t, first + half, n - half);
    node = &t->nodes[id];
    *node = (fg_kd_node){.left = left, .right = right, .dim = (uint32_t)best, .split = split};
    return id;
}

bool fg_kdtree_build(fg_kdtree *t, const float *points, size_t count, size_t dim)
{
    memset(t, 0, sizeof *t);
    if (count == 0 || count >= UINT32_MAX || dim == 0 || dim > FG_KD_MAX_DIM)
        return false;
    t->dim = dim;
    t->count = count;
    t->points = malloc(sizeof(float) * count * dim);
    t->ids = malloc(sizeof(uint32_t) * count);
    t->nodes = malloc(sizeof(fg_kd_node) * node_count_for(count));
    t->lo = malloc(sizeof(float) * dim);
    t->hi = malloc(sizeof(float) * dim);
    if (!t->points || !t->ids || !t->nodes || !t->lo || !t->hi) {
        fg_kdtree_free(t);
        return false;
    }
    memcpy(t->points, points, sizeof(float) * count * dim);
    for (size_t i = 0; i < count; i++)
        t->ids[i] = (uint32_t)i;
    for (size_t d = 0; d < dim; d++) {
        t->lo[d] = FLT_MAX;
        t->hi[d] = -FLT_MAX;
        for (size_t i = 0; i < count; i++) {
            float v = points[i * dim + d];
            t->lo[d] = v < t->lo[d] ? v : t->lo[d];
            t->hi[d] = v > t->hi[d] ? v : t->hi[d];
        }
    }
    build_node(t, 0, count);
    return true;
}

void fg_kdtree_free(fg_kdtree *t)
{
    free(t->points);
    free(t->ids);
    free(t->nodes);
    free(t->lo);
    free(t->hi);
    memset(t, 0, sizeof *t);
}

typedef struct search {
    const fg_kdtree *t;
    const float *q;
    double scale2;     /* (1 + eps)^2 */
    double best2;
    size_t best;
    double off[FG_KD_MAX_DIM];
} search;

static void visit(search *s, uint32_t id, double rd)
{
    const fg_kd_node *node = &s->t->nodes[id];
    if (node->count) {
        size_t dim = s->t->dim;
        for (uint32_t i = node->first; i < node->first + node->count; i++) {
            const float *p = s->t->points + (size_t)i * dim;
            /* in float, 8 dimensions at a time (which the compiler
             * vectorises), stopping once past the best */
            float d2f = 0.0f, bound = (float)s->best2;
            size_t d = 0;
            for (; d + 8 <= dim && d2f < bound; d += 8) {
                float acc = 0.0f;
                for (size_t k = 0; k < 8; k++) {
                    float e = s->q[d + k] - p[d + k];
                    acc += e * e;
                }
                d2f += acc;
            }
            for (; d < dim && d2f < bound; d++) {
                float e = s->q[d] - p[d];
                d2f += e * e;
            }
            double d2 = d2f;
            if (d2 < s->best2) {
                s->best2 = d2;
                s->best = i;
            }
        }
        return;
    }
    double diff = (double)s->q[node->dim] - (double)node->split;
    uint32_t near = diff < 0.0 ? node->left : node->right;
    uint32_t far = diff < 0.0 ? node->right : node->left;
    visit(s, near, rd);
    double old = s->off[node->dim];
    double far_rd = rd - old * old + diff * diff;
    if (far_rd * s->scale2 < s->best2) {
        s->off[node->dim] = diff;
        visit(s, far, far_rd);
        s->off[node->dim] = old;
    }
}

size_t fg_kdtree_nearest(const fg_kdtree *t, const float *query, double eps, double *dist2)
{
    search s = {.t = t, .q = query, .scale2 = (1.0 + eps) * (1.0 + eps), .best2 = INFINITY};
    double rd = 0.0;
    for (size_t d = 0; d < t->dim; d++) {
        double q = query[d], o = 0.0;
        if (q < t->lo[d])
            o = q - t->lo[d];
        else if (q > t->hi[d])
            o = q - t->hi[d];
        s.off[d] = o;
        rd += o * o;
    }
    visit(&s, 0, rd);
    if (dist2)
        *dist2 = s.best2;
    return t->ids[s.best];
}
