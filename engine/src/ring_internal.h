/* A single-producer single-consumer ring of pointers.
 *
 * The producer owns head, the consumer owns tail; each reads the other's
 * index with acquire and publishes its own with release, so a slot's
 * contents are visible before the index that hands it over. The indices sit
 * on separate cache lines. Capacity is a power of two; indices run freely
 * and wrap by masking. */
#ifndef FULGUR_RING_INTERNAL_H
#define FULGUR_RING_INTERNAL_H

#include <stdalign.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>

#define FG_CACHE_LINE 64

typedef struct fg_ring {
    alignas(FG_CACHE_LINE) atomic_size_t head; /* next slot to write: producer */
    alignas(FG_CACHE_LINE) atomic_size_t tail; /* next slot to read: consumer */
    alignas(FG_CACHE_LINE) void **slots;
    size_t mask;
} fg_ring;

/* Allocates room for at least min_capacity items (rounded up to a power of
 * two). Returns false when out of memory or min_capacity is 0 or too big.
 * [main-thread] */
bool fg_ring_init(fg_ring *ring, size_t min_capacity);
void fg_ring_deinit(fg_ring *ring);

size_t fg_ring_capacity(const fg_ring *ring);

/* Producer side. Returns false, changing nothing, when full. */
bool fg_ring_push(fg_ring *ring, void *item);
/* Producer side: free slots now (a lower bound while the consumer runs). */
size_t fg_ring_space(fg_ring *ring);

/* Consumer side. Returns false when empty. */
bool fg_ring_pop(fg_ring *ring, void **item);

#endif
