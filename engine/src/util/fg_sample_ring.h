/* A single-producer single-consumer ring of float samples, indexed by the
 * stream's own frame number.
 *
 * Frame n of the stream (n = 0, 1, ... as the producer wrote them) sits
 * in slot n & mask while the consumer still holds it: from the tail (the
 * oldest frame held) to the head (one past the newest written). The
 * consumer reads any frame in [tail, head) by its number, as often as it
 * likes, and lets frames go by advancing the tail; the producer writes
 * only into slots the tail has passed. Each side publishes its index with
 * release and reads the other's with acquire, so a frame's value is
 * visible before the head that covers it, and a slot is not overwritten
 * before the consumer has finished reading it. Capacity is a power of two;
 * the 64-bit indices never wrap in practice (3 million years at 192 kHz).
 * Writes and reads are wait-free and never allocate ([audio-thread] safe
 * on either side); init and deinit allocate and free ([main-thread] or
 * [sim-thread]). */
#ifndef FG_SAMPLE_RING_H
#define FG_SAMPLE_RING_H

#include <stdalign.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "fg_ring.h" /* FG_CACHE_LINE */

typedef struct fg_sample_ring {
    alignas(FG_CACHE_LINE) atomic_uint_least64_t head; /* frames written: producer */
    alignas(FG_CACHE_LINE) atomic_uint_least64_t tail; /* frames let go: consumer */
    alignas(FG_CACHE_LINE) float *slots;
    uint64_t mask;
} fg_sample_ring;

/* The capacity fg_sample_ring_init gives for min_frames: the power of two
 * at or above it, or 0 when min_frames is 0 or above 2^30. */
static inline uint64_t fg_sample_ring_capacity_for(uint64_t min_frames)
{
    if (min_frames == 0 || min_frames > ((uint64_t)1 << 30))
        return 0;
    uint64_t cap = 1;
    while (cap < min_frames)
        cap <<= 1;
    return cap;
}

/* Allocates room for at least min_frames frames, empty, at frame 0.
 * Returns false (ring unchanged) when out of memory or min_frames is 0 or
 * above 2^30. */
static inline bool fg_sample_ring_init(fg_sample_ring *ring, uint64_t min_frames)
{
    uint64_t cap = fg_sample_ring_capacity_for(min_frames);
    float *slots = cap ? calloc((size_t)cap, sizeof *slots) : NULL;
    if (!slots)
        return false;
    ring->slots = slots;
    ring->mask = cap - 1;
    atomic_init(&ring->head, 0);
    atomic_init(&ring->tail, 0);
    return true;
}

static inline void fg_sample_ring_deinit(fg_sample_ring *ring)
{
    free(ring->slots);
    ring->slots = NULL;
}

/* Empties the ring back to frame 0; neither side may be using it. */
static inline void fg_sample_ring_reset(fg_sample_ring *ring)
{
    atomic_store_explicit(&ring->head, 0, memory_order_relaxed);
    atomic_store_explicit(&ring->tail, 0, memory_order_relaxed);
}

static inline uint64_t fg_sample_ring_capacity(const fg_sample_ring *ring)
{
    return ring->mask + 1;
}

/* Producer side: writes up to n frames of x (as many as there is room for
 * now) after the newest and returns how many. */
static inline size_t fg_sample_ring_write(fg_sample_ring *ring, const float *x, size_t n)
{
    uint64_t head = atomic_load_explicit(&ring->head, memory_order_relaxed);
    uint64_t tail = atomic_load_explicit(&ring->tail, memory_order_acquire);
    uint64_t room = ring->mask + 1 - (head - tail);
    size_t k = n < room ? n : (size_t)room;
    for (size_t i = 0; i < k; i++)
        ring->slots[(head + i) & ring->mask] = x[i];
    atomic_store_explicit(&ring->head, head + k, memory_order_release);
    return k;
}

/* Producer side: frames written so far. */
static inline uint64_t fg_sample_ring_written(fg_sample_ring *ring)
{
    return atomic_load_explicit(&ring->head, memory_order_relaxed);
}

/* Consumer side: one past the newest frame the producer has published. */
static inline uint64_t fg_sample_ring_head(fg_sample_ring *ring)
{
    return atomic_load_explicit(&ring->head, memory_order_acquire);
}

/* Consumer side: frame n, which must lie in [tail, a head it has read). */
static inline float fg_sample_ring_at(const fg_sample_ring *ring, uint64_t n)
{
    return ring->slots[n & ring->mask];
}

/* Consumer side: lets every frame before n go (n at most a head it has
 * read; a tail already past n stays). */
static inline void fg_sample_ring_release_before(fg_sample_ring *ring, uint64_t n)
{
    uint64_t tail = atomic_load_explicit(&ring->tail, memory_order_relaxed);
    if (n > tail)
        atomic_store_explicit(&ring->tail, n, memory_order_release);
}

/* Any thread: frames held (written and not yet let go), a snapshot: the
 * tail is read first, so the head is never behind it, and while both
 * sides run the two may be from moments apart (at most the capacity is
 * reported). */
static inline uint64_t fg_sample_ring_held(fg_sample_ring *ring)
{
    uint64_t tail = atomic_load_explicit(&ring->tail, memory_order_acquire);
    uint64_t head = atomic_load_explicit(&ring->head, memory_order_acquire);
    uint64_t held = head - tail;
    return held > ring->mask + 1 ? ring->mask + 1 : held;
}

#endif
