/* The monotonic clock, and sleeping to absolute deadlines on it: how the
 * paced threads of fulgur run and fulgur view keep time, one period after
 * another like a sound card's interrupt, without drifting. [any-thread] */
#ifndef HOST_COMMON_CLOCK_H
#define HOST_COMMON_CLOCK_H

#include <stdint.h>

/* CLOCK_MONOTONIC in nanoseconds. */
uint64_t monotonic_now_ns(void);

/* Sleeps until the monotonic clock reads deadline_ns (clock_nanosleep,
 * TIMER_ABSTIME); returns at once when it has passed. */
void monotonic_sleep_until_ns(uint64_t deadline_ns);

/* The deadline of period `tick` of a loop started at start_ns:
 * start_ns + tick * period_s, rounded to the nanosecond (no drift). */
uint64_t monotonic_deadline_ns(uint64_t start_ns, uint64_t tick, double period_s);

#endif
