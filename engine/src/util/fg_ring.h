/* A single-producer single-consumer ring of fixed-size items: pointers
 * (item_bytes = sizeof(void *)) or small structs, copied in and out.
 *
 * The producer owns head, the consumer owns tail; each reads the other's
 * index with acquire and publishes its own with release, so a slot's
 * contents are visible before the index that hands it over. The indices sit
 * on separate cache lines. Capacity is a power of two; indices run freely
 * and wrap by masking. Push and pop are wait-free and never allocate
 * ([audio-thread] safe on either side); init and deinit allocate and free
 * ([main-thread]). */
#ifndef FG_RING_H
#define FG_RING_H

#include <stdalign.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define FG_CACHE_LINE 64

typedef struct fg_ring {
    alignas(FG_CACHE_LINE) atomic_size_t head; /* next slot to write: producer */
    alignas(FG_CACHE_LINE) atomic_size_t tail; /* next slot to read: consumer */
    alignas(FG_CACHE_LINE) unsigned char *slots;
    size_t mask;
    size_t item_bytes;
} fg_ring;

/* Allocates room for at least min_capacity items of item_bytes each
 * (rounded up to a power of two). Returns false when out of memory, or
 * when min_capacity or item_bytes is 0 or the ring would be too big. */
static inline bool fg_ring_init(fg_ring *ring, size_t min_capacity, size_t item_bytes)
{
    if (min_capacity == 0 || item_bytes == 0 || min_capacity > (SIZE_MAX >> 2) / item_bytes)
        return false;
    size_t cap = 1;
    while (cap < min_capacity)
        cap <<= 1;
    ring->slots = calloc(cap, item_bytes);
    if (!ring->slots)
        return false;
    ring->mask = cap - 1;
    ring->item_bytes = item_bytes;
    atomic_init(&ring->head, 0);
    atomic_init(&ring->tail, 0);
    return true;
}

static inline void fg_ring_deinit(fg_ring *ring)
{
    free(ring->slots);
    ring->slots = NULL;
}

static inline size_t fg_ring_capacity(const fg_ring *ring)
{
    return ring->mask + 1;
}

/* Producer side: free slots now (a lower bound while the consumer runs). */
static inline size_t fg_ring_space(fg_ring *ring)
{
    size_t head = atomic_load_explicit(&ring->head, memory_order_relaxed);
    size_t tail = atomic_load_explicit(&ring->tail, memory_order_acquire);
    return ring->mask + 1 - (head - tail);
}

/* Producer side: copies item_bytes from *item into the ring. Returns
 * false, changing nothing, when full. */
static inline bool fg_ring_push(fg_ring *ring, const void *item)
{
    size_t head = atomic_load_explicit(&ring->head, memory_order_relaxed);
    size_t tail = atomic_load_explicit(&ring->tail, memory_order_acquire);
    if (head - tail > ring->mask)
        return false;
    memcpy(ring->slots + (head & ring->mask) * ring->item_bytes, item, ring->item_bytes);
    atomic_store_explicit(&ring->head, head + 1, memory_order_release);
    return true;
}

/* Consumer side: copies the oldest item into *item. Returns false when
 * empty. */
static inline bool fg_ring_pop(fg_ring *ring, void *item)
{
    size_t tail = atomic_load_explicit(&ring->tail, memory_order_relaxed);
    size_t head = atomic_load_explicit(&ring->head, memory_order_acquire);
    if (tail == head)
        return false;
    memcpy(item, ring->slots + (tail & ring->mask) * ring->item_bytes, ring->item_bytes);
    atomic_store_explicit(&ring->tail, tail + 1, memory_order_release);
    return true;
}

#endif
