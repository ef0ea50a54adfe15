/* The LV2 tests' way of driving host/lv2/lilv_host: the audio thread's
 * calls under the real-time guard, the worker on a thread of its own. */
#ifndef FULGUR_TESTS_LV2_FIXTURE_H
#define FULGUR_TESTS_LV2_FIXTURE_H

#include "lilv_host.h"
#include "rt_guard.h"

/* lv2_host_run with the guard armed around it (responses and run()); returns
 * the calls the guard counted. */
unsigned long lv2_run_guarded(lv2_host *host, uint32_t frames, float *left, float *right);

/* lv2_host_work on a new thread, joined before it returns; adds the
 * allocations the guard counted on that thread to *allocs (may be NULL).
 * Returns how many requests it ran. */
unsigned lv2_work_on_thread(lv2_host *host, unsigned long *allocs);

#endif
