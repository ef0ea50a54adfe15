#include <stdint.h>
#include <stdlib.h>

#include "ring_internal.h"

bool fg_ring_init(fg_ring *r, size_t min_capacity)
{
    if (min_capacity == 0 || min_capacity > (SIZE_MAX >> 2) / sizeof(void *))
        return false;
    size_t cap = 1;
    while (cap < min_capacity)
        cap <<= 1;
    r->slots = calloc(cap, sizeof *r->slots);
    if (!r->slots)
        return false;
    r->mask = cap - 1;
    atomic_init(&r->head, 0);
    atomic_init(&r->tail, 0);
    return true;
}

void fg_ring_deinit(fg_ring *r)
{
    free(r->slots);
    r->slots = NULL;
}

size_t fg_ring_capacity(const fg_ring *r)
{
    return r->mask + 1;
}

size_t fg_ring_space(fg_ring *r)
{
    size_t head = atomic_load_explicit(&r->head, memory_order_relaxed);
    size_t tail = atomic_load_explicit(&r->tail, memory_order_acquire);
    return r->mask + 1 - (head - tail);
}

bool fg_ring_push(fg_ring *r, void *item)
{
    size_t head = atomic_load_explicit(&r->head, memory_order_relaxed);
    size_t tail = atomic_load_explicit(&r->tail, memory_order_acquire);
    if (head - tail > r->mask)
        return false;
    r->slots[head & r->mask] = item;
    atomic_store_explicit(&r->head, head + 1, memory_order_release);
    return true;
}

bool fg_ring_pop(fg_ring *r, void **item)
{
    size_t tail = atomic_load_explicit(&r->tail, memory_order_relaxed);
    size_t head = atomic_load_explicit(&r->head, memory_order_acquire);
    if (tail == head)
        return false;
    *item = r->slots[tail & r->mask];
    atomic_store_explicit(&r->tail, tail + 1, memory_order_release);
    return true;
}
