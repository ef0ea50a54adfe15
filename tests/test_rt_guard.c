/* The interposer catches what the audio thread must never do, at the
 * release optimisation level, and counts only the armed thread. */
#define _GNU_SOURCE /* RTLD_DEFAULT */
#include <dlfcn.h>
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "rt_guard.h"
#include "rt_guard_planted.h"

#define FRAMES 256

typedef struct planted_case {
    const char *name;
    void (*render)(float *out, uint32_t n);
    rt_guard_counts expect;
} planted_case;

static const planted_case cases[] = {
    {"clean", planted_clean, {0, 0, 0, 0, NULL}},
    {"malloc", planted_malloc, {1, 0, 0, 0, "malloc"}},
    {"lock", planted_lock, {0, 1, 0, 0, "pthread_mutex_lock"}},
    {"log", planted_log, {0, 0, 1, 0, "fprintf"}},
    {"sleep", planted_sleep, {0, 0, 0, 1, "nanosleep"}},
};

static void test_planted(void **state)
{
    (void)state;
    planted_log_stream = fopen("/dev/null", "w");
    assert_non_null(planted_log_stream);
    /* stdio allocates a stream's buffer at its first write: do that here */
    assert_true(fputs("warm\n", planted_log_stream) >= 0);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const planted_case *pc = &cases[k];
        float out[FRAMES] = {0};
        rt_guard_arm();
        pc->render(out, FRAMES);
        rt_guard_counts got = rt_guard_disarm();
        print_message("%-7s alloc %lu lock %lu io %lu sleep %lu first %s\n", pc->name, got.alloc,
                      got.lock, got.io, got.sleep, got.first ? got.first : "-");
        assert_int_equal(got.alloc, pc->expect.alloc);
        assert_int_equal(got.lock, pc->expect.lock);
        assert_int_equal(got.io, pc->expect.io);
        assert_int_equal(got.sleep, pc->expect.sleep);
        if (pc->expect.first)
            assert_string_equal(got.first, pc->expect.first);
        else
            assert_null(got.first);
        /* the planted function really rendered (and was not optimised away) */
        assert_float_equal(out[20], 0.5f * sinf(1.0f), 1e-6);
    }
    free(planted_leak);
    assert_int_equal(fclose(planted_log_stream), 0);
}

/* Arming starts from zero; after disarming nothing more is counted. */
static void test_arm_window(void **state)
{
    (void)state;
    rt_guard_arm();
    void *volatile p = malloc(16);
    free(p);
    rt_guard_counts inside = rt_guard_disarm();
    p = malloc(16);
    free(p);
    rt_guard_counts after = rt_guard_disarm();
    assert_int_equal(inside.alloc, 2);
    assert_string_equal(inside.first, "malloc");
    assert_int_equal(after.alloc, 2);
    rt_guard_arm();
    rt_guard_counts fresh = rt_guard_disarm();
    assert_int_equal(rt_guard_total(&fresh), 0);
    assert_null(fresh.first);
}

/* Scoped to an object: the planted malloc counts when armed within the
 * executable that holds it, not when armed within libm, which its stack
 * does not pass through. */
static void test_arm_within(void **state)
{
    (void)state;
    float out[FRAMES] = {0};
    assert_int_equal(rt_guard_arm_within((const void *)planted_malloc), 0);
    planted_malloc(out, FRAMES);
    rt_guard_counts mine = rt_guard_disarm();
    free(planted_leak);
    assert_int_equal(mine.alloc, 1);
    assert_string_equal(mine.first, "malloc");
    const void *in_libm = dlsym(RTLD_DEFAULT, "cosf");
    assert_non_null(in_libm);
    assert_int_equal(rt_guard_arm_within(in_libm), 0);
    planted_malloc(out, FRAMES);
    rt_guard_counts libm = rt_guard_disarm();
    free(planted_leak);
    assert_int_equal(rt_guard_total(&libm), 0);
    assert_null(libm.first);
    assert_int_equal(rt_guard_arm_within(NULL), -1);
    (void)rt_guard_disarm();
}

#define OTHER_ALLOCS 1000

typedef struct other_thread {
    atomic_int go;          /* set by main once it is armed */
    atomic_int done;        /* set by the other thread */
    rt_guard_counts armed_counts;
} other_thread;

/* Allocates freely unarmed, then arms itself for one malloc and one free. */
static void *other_main(void *arg)
{
    other_thread *t = arg;
    while (!atomic_load_explicit(&t->go, memory_order_acquire))
        ;
    for (int i = 0; i < OTHER_ALLOCS; i++) {
        void *volatile p = malloc(32 + (size_t)i);
        free(p);
    }
    rt_guard_arm();
    void *volatile p = malloc(64);
    free(p);
    t->armed_counts = rt_guard_disarm();
    atomic_store_explicit(&t->done, 1, memory_order_release);
    return NULL;
}

static void test_threads_counted_apart(void **state)
{
    (void)state;
    other_thread t = {0};
    pthread_t th;
    assert_int_equal(pthread_create(&th, NULL, other_main, &t), 0);
    rt_guard_arm();
    atomic_store_explicit(&t.go, 1, memory_order_release);
    while (!atomic_load_explicit(&t.done, memory_order_acquire))
        ; /* spinning: a sleep or yield here would itself be counted */
    rt_guard_counts mine = rt_guard_disarm();
    assert_int_equal(pthread_join(th, NULL), 0);
    assert_int_equal(rt_guard_total(&mine), 0);
    assert_int_equal(t.armed_counts.alloc, 2);
    assert_int_equal(rt_guard_total(&t.armed_counts), 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_planted),
        cmocka_unit_test(test_arm_window),
        cmocka_unit_test(test_arm_within),
        cmocka_unit_test(test_threads_counted_apart),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
