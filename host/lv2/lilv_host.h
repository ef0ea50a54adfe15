/* lv2_host — a small LV2 host on liblilv for fulgur.lv2: the plugin's tests
 * and fulgur-lv2-render drive the plugin through it.
 *
 * Discovers plugins through LV2_PATH (or the standard places), instantiates
 * one of fulgur.lv2's plugins, owns every port buffer, and provides
 * urid:map, urid:unmap, worker:schedule and log:log itself. Audio outputs
 * are the planes in the order of their port indices; an atom output is
 * read as the plugin's notify port (patch:Set of a path). Work scheduled
 * from run() is queued without allocating; lv2_host_work runs the queue on whichever thread calls it
 * (never while lv2_host_run runs): a test calls it from a worker thread,
 * an offline renderer between blocks. The responses are delivered at the
 * start of the next lv2_host_run, before run(), on its thread. */
#ifndef HOST_LV2_LILV_HOST_H
#define HOST_LV2_LILV_HOST_H

#include <stddef.h>
#include <stdint.h>

#include <lilv/lilv.h>

typedef struct lv2_host lv2_host;

/* Loads and instantiates the plugin at rate_hz; NULL on any failure (a
 * message on stderr says which). lv2_host_create is the stereo plugin
 * (FULGUR_LV2_URI), lv2_host_create_plugin the one named by uri. */
lv2_host *lv2_host_create(double rate_hz);
lv2_host *lv2_host_create_plugin(const char *uri, double rate_hz);

/* The plugin's audio outputs (at most LV2_HOST_CHANNELS_MAX). */
#define LV2_HOST_CHANNELS_MAX 16
unsigned lv2_host_channels(const lv2_host *host);
void lv2_host_destroy(lv2_host *host);

/* Sets an input control by its symbol: 0, or -1 if the plugin has no
 * control port of that name. */
int lv2_host_set(lv2_host *host, const char *symbol, float value);
/* A control's value (an output's as of the last run), NaN if none. */
float lv2_host_get(const lv2_host *host, const char *symbol);

/* Queues a 3-byte MIDI message at frame of the next run: 0, or -1 if the
 * next run's sequence (4 KiB) is full. */
int lv2_host_midi(lv2_host *host, uint32_t frame, uint8_t status, uint8_t data1, uint8_t data2);

/* Queues a patch:Set of property (a URI) to an atom:Path at frame 0 of the
 * next run: 0, or -1 if the sequence is full or the path too long. */
int lv2_host_set_path(lv2_host *host, const char *property, const char *path);

/* Delivers pending responses, then runs the plugin for frames into
 * left/right (a plugin of two outputs; any other aborts), or into planes
 * (one per output).
 * [audio-thread]: no allocation or lock of its own. */
void lv2_host_run(lv2_host *host, uint32_t frames, float *left, float *right);
void lv2_host_run_planes(lv2_host *host, uint32_t frames, float *const *planes);

/* The path of the last patch:Set the plugin sent on its notify port ("" if
 * none), and the last message it logged ("" if none). */
const char *lv2_host_notified_path(const lv2_host *host);
const char *lv2_host_last_log(const lv2_host *host);

/* Runs every queued request on the calling thread. Returns how many. */
unsigned lv2_host_work(lv2_host *host);

/* Totals so far: work() calls, and responses handed to the plugin. */
unsigned lv2_host_work_calls(const lv2_host *host);
unsigned lv2_host_responses(const lv2_host *host);

/* The presets the world knows for the plugin (pset:Preset with
 * lv2:appliesTo it): up to max of their labels (rdfs:label, cut to
 * LV2_HOST_LABEL_BYTES) into labels, in no particular order. Returns how
 * many there are. [main-thread] */
#define LV2_HOST_LABEL_BYTES 64
unsigned lv2_host_presets(lv2_host *host, char (*labels)[LV2_HOST_LABEL_BYTES], unsigned max);
/* Loads the preset labelled label through liblilv and applies its control
 * values. Returns 0, or -1 when there is none or it cannot be read.
 * [main-thread] */
int lv2_host_preset_apply(lv2_host *host, const char *label);

/* A snapshot of the instance (its state and control values), and its
 * restoration into another instance; the caller frees with lilv_state_free. */
LilvState *lv2_host_save(lv2_host *host);
void lv2_host_restore(lv2_host *host, const LilvState *state);

#endif
