/* Two threads move a million items through one fg_ring: every item arrives
 * once, in order and whole, and both the full and the empty edge are
 * reached. Items are pointers (the engine's voices) or small structs (a
 * host's input events). */
#include <pthread.h>
#include <sched.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "fg_ring.h"

#define ITEMS 1000000u

/* A struct item: its fields must arrive together. */
typedef struct record {
    uint64_t seq;
    double half;      /* seq / 2 */
    uint32_t check;   /* ~seq, truncated */
} record;

typedef struct stress_case {
    const char *name;
    size_t min_capacity;
    size_t first_index;   /* where head and tail start: near SIZE_MAX wraps them */
    int records;          /* non-zero: struct items, else pointers */
} stress_case;

static const stress_case cases[] = {
    {"capacity 1", 1, 0, 0},
    {"capacity 16", 16, 0, 0},
    {"capacity 1000 (1024)", 1000, 0, 0},
    {"capacity 64, indices wrap", 64, SIZE_MAX - ITEMS / 2, 0},
    {"records, capacity 3 (4)", 3, 0, 1},
    {"records, capacity 256, wrap", 256, SIZE_MAX - ITEMS / 3, 1},
};

static bool push_item(fg_ring *ring, uint64_t seq, int records)
{
    if (records)
        return fg_ring_push(ring, &(record){seq, 0.5 * (double)seq, (uint32_t)~seq});
    void *p = (void *)(uintptr_t)seq;
    return fg_ring_push(ring, &p);
}

/* Pops one item: 0 when empty, else 1 with *seq set, or -1 for a torn or
 * wrong record. */
static int pop_item(fg_ring *ring, uint64_t *seq, int records)
{
    if (records) {
        record r;
        if (!fg_ring_pop(ring, &r))
            return 0;
        *seq = r.seq;
        return r.half == 0.5 * (double)r.seq && r.check == (uint32_t)~r.seq ? 1 : -1;
    }
    void *p;
    if (!fg_ring_pop(ring, &p))
        return 0;
    *seq = (uintptr_t)p;
    return 1;
}

typedef struct stress {
    fg_ring ring;
    int records;
    atomic_int filled;        /* the producer has seen the ring full once */
    unsigned long full_hits;  /* producer: pushes refused */
    unsigned long space_at_full;
} stress;

/* Items are 1..ITEMS (as pointers, never NULL). The producer first fills the
 * ring until a push is refused, and only then lets the consumer start, so
 * the full edge is reached in every case. */
static void *producer(void *arg)
{
    stress *s = arg;
    for (uint64_t item = 1; item <= ITEMS;) {
        if (push_item(&s->ring, item, s->records)) {
            item++;
            continue;
        }
        if (!s->full_hits)
            s->space_at_full = fg_ring_space(&s->ring);
        s->full_hits++;
        atomic_store_explicit(&s->filled, 1, memory_order_release);
        sched_yield(); /* the two threads may share a core */
    }
    atomic_store_explicit(&s->filled, 1, memory_order_release);
    return NULL;
}

static void run_case(const stress_case *sc)
{
    stress s = {.records = sc->records};
    size_t item_bytes = sc->records ? sizeof(record) : sizeof(void *);
    assert_true(fg_ring_init(&s.ring, sc->min_capacity, item_bytes));
    atomic_store(&s.ring.head, sc->first_index);
    atomic_store(&s.ring.tail, sc->first_index);
    size_t capacity = fg_ring_capacity(&s.ring);
    assert_true(capacity >= sc->min_capacity && capacity < 2 * sc->min_capacity + 1);
    assert_int_equal(capacity & (capacity - 1), 0);
    assert_int_equal(fg_ring_space(&s.ring), capacity);

    pthread_t th;
    assert_int_equal(pthread_create(&th, NULL, producer, &s), 0);
    while (!atomic_load_explicit(&s.filled, memory_order_acquire))
        sched_yield();
    uint64_t expect = 1, item;
    unsigned long empty_hits = 0, out_of_order = 0, torn = 0;
    while (expect <= ITEMS) {
        int got = pop_item(&s.ring, &item, sc->records);
        if (got == 0) {
            empty_hits++;
            sched_yield();
            continue;
        }
        if (got < 0)
            torn++;
        if (item != expect)
            out_of_order++;
        expect++;
    }
    assert_int_equal(pthread_join(th, NULL), 0);
    /* the producer is done: the ring is empty now, and stays so */
    assert_int_equal(pop_item(&s.ring, &item, sc->records), 0);
    empty_hits++;
    assert_int_equal(fg_ring_space(&s.ring), capacity);
    assert_int_equal(atomic_load(&s.ring.head) - sc->first_index, (size_t)ITEMS);
    assert_int_equal(atomic_load(&s.ring.tail) - sc->first_index, (size_t)ITEMS);

    print_message("%-28s capacity %5zu: full %lu times, empty %lu times\n", sc->name, capacity,
                  s.full_hits, empty_hits);
    assert_int_equal(out_of_order, 0);
    assert_int_equal(torn, 0);
    assert_int_equal(expect - 1, ITEMS);
    assert_true(s.full_hits > 0);
    assert_int_equal(s.space_at_full, 0);
    assert_true(empty_hits > 0);
    fg_ring_deinit(&s.ring);
}

static void test_stress(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++)
        run_case(&cases[k]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stress),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
