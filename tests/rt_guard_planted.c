/* Compiled with -O2 whatever the build type (tests/CMakeLists.txt): the
 * guard must see violations that survive the optimiser. Each planted call
 * has an effect the compiler cannot remove: the allocation escapes through
 * a volatile global, the lock guards a shared gain, the log line goes to a
 * stream, the sleep is a call into libc. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <time.h>

#include "rt_guard_planted.h"

float *volatile planted_leak;
FILE *planted_log_stream;

static pthread_mutex_t gain_lock = PTHREAD_MUTEX_INITIALIZER;
static float gain = 0.5f;

void planted_clean(float *out, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++)
        out[i] = gain * sinf(0.05f * (float)i);
}

void planted_malloc(float *out, uint32_t n)
{
    float *scratch = malloc(n * sizeof *scratch);
    if (!scratch)
        return;
    planted_clean(scratch, n);
    for (uint32_t i = 0; i < n; i++)
        out[i] = scratch[i];
    planted_leak = scratch;
}

void planted_lock(float *out, uint32_t n)
{
    pthread_mutex_lock(&gain_lock);
    float g = gain;
    pthread_mutex_unlock(&gain_lock);
    for (uint32_t i = 0; i < n; i++)
        out[i] = g * sinf(0.05f * (float)i);
}

void planted_log(float *out, uint32_t n)
{
    planted_clean(out, n);
    fprintf(planted_log_stream, "rendered %u frames, last %g\n", (unsigned)n,
            n ? (double)out[n - 1] : 0.0);
}

void planted_sleep(float *out, uint32_t n)
{
    struct timespec pause = {0, 1000};
    nanosleep(&pause, NULL);
    planted_clean(out, n);
}
