/* lv2_host — a small LV2 host on liblilv for the plugin's tests.
 *
 * Discovers plugins through LV2_PATH (CTest points it at the build's
 * bundle), instantiates fulgur.lv2, owns every port buffer, and provides
 * urid:map and worker:schedule itself. Work scheduled from run() is queued;
 * lv2_host_work runs the queue on a separate worker thread and joins it; the
 * responses are delivered at the start of the next lv2_host_run, on the
 * calling (audio) thread, before run(). The real-time guard is armed on the
 * audio thread around the responses and run(). */
#ifndef FULGUR_TESTS_LV2_HOST_H
#define FULGUR_TESTS_LV2_HOST_H

#include <stdint.h>

#include <lilv/lilv.h>

#include "rt_guard.h"

typedef struct lv2_host lv2_host;

/* Loads and instantiates the plugin at rate_hz; NULL on any failure (a
 * message on stderr says which). */
lv2_host *lv2_host_create(double rate_hz);
void lv2_host_destroy(lv2_host *host);

/* An input control's value by its symbol; an output control's value. */
void lv2_host_set(lv2_host *host, const char *symbol, float value);
float lv2_host_get(const lv2_host *host, const char *symbol);

/* Queues a 3-byte MIDI message at frame of the next run. */
void lv2_host_midi(lv2_host *host, uint32_t frame, uint8_t status, uint8_t data1, uint8_t data2);

/* Delivers pending responses, runs the plugin for frames (<= 4096) into
 * left/right, and returns what the guard counted during both. */
rt_guard_counts lv2_host_run(lv2_host *host, uint32_t frames, float *left, float *right);

/* Runs every queued request on a worker thread, joined before it returns.
 * Returns how many it ran. */
unsigned lv2_host_work(lv2_host *host);

/* Totals so far: work() calls, and responses handed to the plugin. */
unsigned lv2_host_work_calls(const lv2_host *host);
unsigned lv2_host_responses(const lv2_host *host);

/* The plugin's allocations counted by the guard on the worker thread, so a
 * test can show the guard sees calls made inside the loaded module. */
unsigned long lv2_host_worker_allocs(const lv2_host *host);

/* A snapshot of the instance (its state and control values), and its
 * restoration into another instance; the caller frees with lilv_state_free. */
LilvState *lv2_host_save(lv2_host *host);
void lv2_host_restore(lv2_host *host, const LilvState *state);

#endif
