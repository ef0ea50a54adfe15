/* The node buffer a tree is grown in before it is handed out. */
#include <stdlib.h>

#include "fg_array.h"
#include "growth_internal.h"

fg_result fg_nodebuf_push(fg_nodebuf *b, const double x[3], int32_t parent, size_t *index)
{
    fg_node *v = fg_array_grow(b->v, &b->cap, b->count + 1, sizeof *v, 256);
    if (!v)
        return FG_ERR_NO_MEMORY;
    b->v = v;
    b->v[b->count] = (fg_node){x[0], x[1], x[2], parent, 0};
    if (index)
        *index = b->count;
    b->count++;
    return FG_OK;
}

void fg_nodebuf_free(fg_nodebuf *b)
{
    free(b->v);
    *b = (fg_nodebuf){0};
}

fg_result fg_nodebuf_emit(const fg_nodebuf *b, fg_tree *out)
{
    fg_tree_clear(out);
    for (size_t i = 0; i < b->count; i++) {
        const fg_node *n = &b->v[i];
        fg_result r = fg_tree_add(out, n->x, n->y, n->z, n->parent, n->flags, NULL);
        if (r != FG_OK)
            return r;
    }
    return FG_OK;
}
