/* rt_guard — proves the audio thread's rules in tests.
 *
 * Linking rt_guard.c into a test executable interposes the allocator, the
 * blocking pthread/semaphore calls, sleeps and the common I/O calls. Each
 * wrapper forwards to the real function (or to a sanitizer's interceptor
 * when the executable is built with one) and, if the calling thread is
 * armed, counts the call by kind. Only the armed thread counts: other
 * threads allocate and lock freely while it renders.
 *
 * Usage, on the thread that calls the render function:
 *   rt_guard_arm();
 *   fg_engine_render(...);
 *   rt_guard_counts c = rt_guard_disarm();   // c.alloc == 0 && ...
 */
#ifndef FULGUR_TESTS_RT_GUARD_H
#define FULGUR_TESTS_RT_GUARD_H

typedef struct rt_guard_counts {
    unsigned long alloc;  /* malloc, calloc, realloc, reallocarray, free, memalign family */
    unsigned long lock;   /* mutex/rwlock/spin lock, condition and semaphore waits */
    unsigned long io;     /* read/write/open and stdio */
    unsigned long sleep;  /* nanosleep, clock_nanosleep, usleep, sleep, sched_yield */
    const char *first;    /* name of the first function counted, or NULL */
} rt_guard_counts;

/* Starts counting on the calling thread, from zero. */
void rt_guard_arm(void);

/* As rt_guard_arm, but a call counts only when a frame of its stack lies in
 * the loaded object (shared library or executable) that holds code: what
 * that library does, directly or through libc, and not what its caller
 * does around it. For a library driven from an interpreter (the Python
 * package's test, with this file built as an LD_PRELOAD module), whose own
 * allocations are not the library's. A code address in no object arms
 * nothing and returns -1; else 0. */
int rt_guard_arm_within(const void *code);

/* Stops counting on the calling thread and returns what it counted since
 * rt_guard_arm. */
rt_guard_counts rt_guard_disarm(void);

/* alloc + lock + io + sleep. */
unsigned long rt_guard_total(const rt_guard_counts *counts);

#endif
