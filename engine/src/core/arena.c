#include <stdlib.h>
#include <string.h>

#include "arena_internal.h"

bool fg_arena_init(fg_arena *a, size_t capacity, size_t max_allocations)
{
    /* n live allocations split the storage into at most n + 1 free ranges */
    a->max_ranges = max_allocations + 1;
    a->free = calloc(a->max_ranges, sizeof *a->free);
    if (!a->free)
        return false;
    a->free[0] = (fg_extent){0, capacity};
    a->count = capacity > 0;
    return true;
}

void fg_arena_deinit(fg_arena *a)
{
    free(a->free);
    a->free = NULL;
    a->count = 0;
}

bool fg_arena_alloc(fg_arena *a, size_t length, size_t *offset)
{
    for (size_t i = 0; i < a->count; i++) {
        fg_extent *e = &a->free[i];
        if (e->length < length)
            continue;
        *offset = e->offset;
        e->offset += length;
        e->length -= length;
        if (e->length == 0) {
            memmove(e, e + 1, (a->count - i - 1) * sizeof *e);
            a->count--;
        }
        return true;
    }
    return false;
}

void fg_arena_free(fg_arena *a, size_t offset, size_t length)
{
    size_t i = 0;
    while (i < a->count && a->free[i].offset < offset)
        i++;
    bool joins_prev = i > 0 && a->free[i - 1].offset + a->free[i - 1].length == offset;
    bool joins_next = i < a->count && offset + length == a->free[i].offset;
    if (joins_prev && joins_next) {
        a->free[i - 1].length += length + a->free[i].length;
        memmove(&a->free[i], &a->free[i + 1], (a->count - i - 1) * sizeof a->free[0]);
        a->count--;
    } else if (joins_prev) {
        a->free[i - 1].length += length;
    } else if (joins_next) {
        a->free[i].offset = offset;
        a->free[i].length += length;
    } else {
        memmove(&a->free[i + 1], &a->free[i], (a->count - i) * sizeof a->free[0]);
        a->free[i] = (fg_extent){offset, length};
        a->count++;
    }
}
