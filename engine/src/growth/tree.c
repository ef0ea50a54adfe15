/* Tree validation and the growable tree used by the generators. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fg_array.h"
#include "fg_rules.h"
#include "fulgur/tree.h"
#include "tree_internal.h"

struct fg_tree {
    fg_node *nodes;
    size_t count;
    size_t capacity;
};

static fg_result fault(fg_tree_fault *out, fg_tree_fault_kind kind, size_t node, int32_t parent,
                       double value)
{
    if (out)
        *out = (fg_tree_fault){kind, node, parent, value};
    return FG_ERR_TREE;
}

/* The coordinate of n farthest from the origin. */
static double farthest_coordinate(const fg_node *n)
{
    double c = n->x;
    if (fabs(n->y) > fabs(c))
        c = n->y;
    if (fabs(n->z) > fabs(c))
        c = n->z;
    return c;
}

/* |a - b|, scaled by the largest difference so that no square underflows:
 * a segment of 1e-162 m measures 1e-162 m, not 0. */
static double segment_length(const fg_node *a, const fg_node *b)
{
    double d[3] = {a->x - b->x, a->y - b->y, a->z - b->z};
    double m = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
    if (m == 0)
        return 0;
    double x = d[0] / m, y = d[1] / m, z = d[2] / m;
    return m * sqrt(x * x + y * y + z * z);
}

fg_result fg_tree_check(const fg_node *nodes, size_t count, fg_tree_fault *out)
{
    if (out)
        *out = (fg_tree_fault){FG_TREE_FAULT_NONE, 0, 0, 0};
    if (!nodes)
        return FG_ERR_NULL;
    if (count < 2)
        return fault(out, FG_TREE_FAULT_TOO_FEW_NODES, count, -1, 0);
    for (size_t i = 0; i < count; i++) {
        const fg_node *n = &nodes[i];
        if (!isfinite(n->x) || !isfinite(n->y) || !isfinite(n->z))
            return fault(out, FG_TREE_FAULT_NOT_FINITE, i, n->parent, 0);
        double far = farthest_coordinate(n);
        if (fabs(far) > FG_TREE_MAX_COORDINATE_M)
            return fault(out, FG_TREE_FAULT_TOO_FAR, i, n->parent, far);
        if (i == 0) {
            if (n->parent != -1)
                return fault(out, FG_TREE_FAULT_ROOT, i, n->parent, 0);
            continue;
        }
        if (n->parent < 0 && n->parent != -1)
            return fault(out, FG_TREE_FAULT_PARENT_ORDER, i, n->parent, 0);
        if (n->parent == -1)
            return fault(out, FG_TREE_FAULT_ROOT, i, n->parent, 0);
        if ((size_t)n->parent >= i)
            return fault(out, FG_TREE_FAULT_PARENT_ORDER, i, n->parent, 0);
        const fg_node *p = &nodes[n->parent];
        if (p->x == n->x && p->y == n->y && p->z == n->z)
            return fault(out, FG_TREE_FAULT_ZERO_LENGTH, i, n->parent, 0);
        double len = segment_length(n, p);
        if (len < FG_TREE_MIN_SEGMENT_M)
            return fault(out, FG_TREE_FAULT_TOO_SHORT, i, n->parent, len);
    }
    return FG_OK;
}

void fg_tree_fault_describe(const fg_tree_fault *f, char *buf, size_t size)
{
    FG_REQUIRE(buf || size == 0);
    if (size == 0)
        return;
    if (!f) {
        snprintf(buf, size, "no fault");
        return;
    }
    switch (f->kind) {
    case FG_TREE_FAULT_NONE:
        snprintf(buf, size, "no fault");
        break;
    case FG_TREE_FAULT_TOO_FEW_NODES:
        snprintf(buf, size, "%zu node(s): a tree needs at least 2 (one segment)", f->node);
        break;
    case FG_TREE_FAULT_ROOT:
        if (f->node == 0)
            snprintf(buf, size, "node 0 must be the root (parent -1), not have parent %d",
                     (int)f->parent);
        else
            snprintf(buf, size, "node %zu has no parent; only node 0 may be the root", f->node);
        break;
    case FG_TREE_FAULT_PARENT_ORDER:
        snprintf(buf, size, "parent %d is not before node %zu", (int)f->parent, f->node);
        break;
    case FG_TREE_FAULT_NOT_FINITE:
        snprintf(buf, size, "node %zu has a coordinate that is not a finite number", f->node);
        break;
    case FG_TREE_FAULT_ZERO_LENGTH:
        snprintf(buf, size, "node %zu lies on its parent %d (zero-length segment)", f->node,
                 (int)f->parent);
        break;
    case FG_TREE_FAULT_TOO_FAR:
        snprintf(buf, size, "node %zu has a coordinate of %.6g m, beyond +-%.0e m", f->node,
                 f->value, FG_TREE_MAX_COORDINATE_M);
        break;
    case FG_TREE_FAULT_TOO_SHORT:
        snprintf(buf, size, "node %zu is %.3g m from its parent %d, closer than %.0e m",
                 f->node, f->value, (int)f->parent, FG_TREE_MIN_SEGMENT_M);
        break;
    default:
        snprintf(buf, size, "unknown fault");
        break;
    }
}

void fg_tree_translate(fg_node *nodes, size_t count, const double offset_m[3])
{
    FG_REQUIRE((nodes || count == 0) && offset_m);
    for (size_t i = 0; i < count; i++) {
        nodes[i].x += offset_m[0];
        nodes[i].y += offset_m[1];
        nodes[i].z += offset_m[2];
    }
}

fg_result fg_tree_create(size_t capacity_hint, fg_tree **out)
{
    if (!out)
        return FG_ERR_NULL;
    *out = NULL;
    fg_tree *t = calloc(1, sizeof *t);
    if (!t)
        return FG_ERR_NO_MEMORY;
    if (capacity_hint < 16)
        capacity_hint = 16;
    t->nodes = malloc(capacity_hint * sizeof *t->nodes);
    if (!t->nodes) {
        free(t);
        return FG_ERR_NO_MEMORY;
    }
    t->capacity = capacity_hint;
    *out = t;
    return FG_OK;
}

void fg_tree_destroy(fg_tree *tree)
{
    if (!tree)
        return;
    free(tree->nodes);
    free(tree);
}

fg_result fg_tree_add(fg_tree *t, double x, double y, double z, int32_t parent, uint32_t flags,
                      size_t *index)
{
    if (!t)
        return FG_ERR_NULL;
    if (!isfinite(x) || !isfinite(y) || !isfinite(z))
        return FG_ERR_NOT_FINITE;
    if (t->count == 0 ? parent != -1 : (parent < 0 || (size_t)parent >= t->count))
        return FG_ERR_TREE;
    fg_node *grown = fg_array_grow(t->nodes, &t->capacity, t->count + 1, sizeof *grown, 16);
    if (!grown)
        return FG_ERR_NO_MEMORY;
    t->nodes = grown;
    t->nodes[t->count] = (fg_node){x, y, z, parent, flags};
    if (index)
        *index = t->count;
    t->count++;
    return FG_OK;
}

void fg_tree_clear(fg_tree *t)
{
    FG_REQUIRE(t);
    t->count = 0;
}

fg_node *fg_tree_nodes(fg_tree *t)
{
    FG_REQUIRE_OR(t, NULL);
    return t->nodes;
}

size_t fg_tree_count(const fg_tree *t)
{
    FG_REQUIRE_OR(t, 0);
    return t->count;
}

size_t fg_nodes_mark_main(fg_node *nodes, size_t node)
{
    size_t n = 0;
    for (int32_t i = (int32_t)node; i >= 0; i = nodes[i].parent, n++)
        nodes[i].flags |= FG_NODE_MAIN;
    return n;
}
