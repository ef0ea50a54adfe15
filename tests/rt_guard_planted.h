/* Render-like functions with one planted real-time violation each, built at
 * the release optimisation level, for test_rt_guard. Each fills out[0..n)
 * with a tone. */
#ifndef FULGUR_TESTS_RT_GUARD_PLANTED_H
#define FULGUR_TESTS_RT_GUARD_PLANTED_H

#include <stdint.h>
#include <stdio.h>

/* Where planted_malloc's buffer escapes to; the caller frees it. */
extern float *volatile planted_leak;
/* The stream planted_log writes to; the caller opens and closes it. */
extern FILE *planted_log_stream;

void planted_clean(float *out, uint32_t n);   /* no violation */
void planted_malloc(float *out, uint32_t n);  /* one malloc, escaping */
void planted_lock(float *out, uint32_t n);    /* one mutex lock (and unlock) */
void planted_log(float *out, uint32_t n);     /* one formatted write */
void planted_sleep(float *out, uint32_t n);   /* one nanosleep */

#endif
