/* A growable array's storage: capacity doubles, so n appends cost O(n). */
#ifndef FG_ARRAY_H
#define FG_ARRAY_H

#include <stdint.h>
#include <stdlib.h>

/* The capacity that holds need items of item_bytes: doubled from
 * capacity, or from first_capacity (> 0) when capacity is 0, until need
 * fits; 0 when the size would overflow. */
static inline size_t fg_array_capacity(size_t capacity, size_t need, size_t item_bytes,
                                       size_t first_capacity)
{
    size_t cap = capacity ? capacity : first_capacity;
    while (cap < need) {
        if (cap > SIZE_MAX / 2)
            return 0;
        cap *= 2;
    }
    return cap > SIZE_MAX / item_bytes ? 0 : cap;
}

/* Returns items reallocated to hold at least need (> 0) items of
 * item_bytes, *capacity updated (fg_array_capacity). Returns items itself
 * when need already fits, and NULL (items and *capacity untouched, items
 * still owned by the caller) when memory runs out or the size would
 * overflow. [any thread; the caller owns items] */
static inline void *fg_array_grow(void *items, size_t *capacity, size_t need, size_t item_bytes,
                                  size_t first_capacity)
{
    if (need <= *capacity)
        return items;
    size_t cap = fg_array_capacity(*capacity, need, item_bytes, first_capacity);
    if (cap == 0)
        return NULL;
    void *grown = realloc(items, cap * item_bytes);
    if (grown)
        *capacity = cap;
    return grown;
}

#endif
