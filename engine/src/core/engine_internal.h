/* The engine object, shared by the files that implement its calls. */
#ifndef FULGUR_ENGINE_INTERNAL_H
#define FULGUR_ENGINE_INTERNAL_H

#include <stdatomic.h>
#include <stdint.h>

#include "sound/abe_voice_internal.h"
#include "core/arena_internal.h"
#include "core/bus_internal.h"
#include "fulgur/engine.h"
#include "core/listener_internal.h"
#include "fg_ring.h"
#include "core/sort_internal.h"
#include "core/voice_internal.h"

typedef struct fg_counters {
    atomic_uint_least64_t posted, dropped_posts, adopted, finished, collected;
    atomic_uint_least64_t late_events, late_samples, skipped_repeats, blocks, blocks_over_budget;
} fg_counters;

/* Scratch for preparing one tree, preallocated for the largest. */
typedef struct fg_prep_scratch {
    double *path_m;        /* path length from the root */
    uint32_t *junction;    /* deepest main-channel ancestor (or self) */
    uint8_t *main;         /* node lies on the main channel */
    fg_sort_pair *order;   /* the arrival sort, and its scratch */
    fg_sort_pair *order_tmp;
} fg_prep_scratch;

struct fg_engine {
    fg_engine_config cfg;

    /* sim thread */
    fg_voice *voices;
    uint32_t *free_slots;
    uint32_t free_count;
    uint8_t *live;            /* posted and not yet collected, by slot */
    fg_arena arena;
    fg_prep_scratch scratch;

    /* segment storage shared by all voices through the arena */
    fg_event *events;
    uint32_t *main_index;

    fg_ring inbox;            /* sim -> audio: fg_voice * */
    fg_ring garbage;          /* audio -> sim: fg_voice * */
    fg_listener_cell listener;

    /* filter buses: set up at create, band filters designed by the sim
     * thread before the first voice that needs them */
    fg_bus_set buses;
    fg_abe_params abe;        /* FG_MODEL_ABE's wave parameters */

    /* audio thread */
    fg_voice **active;
    uint32_t active_count;
    fg_listener pose;         /* last pose read */
    unsigned pose_serial;

    atomic_uint_least64_t frames;
    fg_counters counters;
};

/* Abe's model: source points per discharge at most, evenly along the tree. */
#define FG_ABE_MAX_SOURCES 512

/* Fills voice v (slot and storage already assigned) from a checked
 * discharge, reading the current listener pose. [sim-thread] */
void fg_prepare_voice(fg_engine *e, fg_voice *v, const fg_discharge *d);

/* How many events a checked discharge becomes. */
size_t fg_discharge_events(const fg_discharge *d);

/* Validates a discharge's parameters other than the tree. */
fg_result fg_discharge_check(const fg_discharge *d);

/* Renders voice v into the blocks; returns true when it has finished.
 * [audio-thread] */
typedef struct fg_block_context {
    double start_frame;       /* engine clock at the block's first sample */
    uint32_t frames;
    const fg_ears *ears;
    const double *position;   /* listener centre */
    unsigned serial;
    fg_bus_set *buses;
} fg_block_context;

void fg_voice_adopt(fg_engine *e, fg_voice *v, double start_frame);
bool fg_voice_render(fg_engine *e, fg_voice *v, const fg_block_context *ctx);

/* Event ev of voice v as heard by ear k of ears, into ev's slot k. */
void fg_event_geometry(const fg_engine *e, const fg_voice *v, fg_event *ev, const fg_ears *ears,
                       int k);

/* When ear k's slot of ev starts sounding, seconds after the emission. */
double fg_event_start_s(const fg_engine *e, const fg_voice *v, const fg_event *ev, int k);

#endif
