/* The source-model seam: all the engine's loop knows of a voice.
 *
 * Every kind of sound is a source model behind one table of operations
 * (fg_source_ops), as libsamplerate's converters sit behind SRC_STATE_VT.
 * The engine adopts posted voices, renders each, retires the finished and
 * collects them without knowing which model a voice is; the model brings
 * its description (posted through its own public post function), its
 * per-voice state and its rendering into the bus set.
 *
 *   sim thread                         audio thread
 *   public post (the model's own):
 *     validate the description
 *     fg_engine_post_source(ops, desc)
 *       ops->prepare(state, desc)  -->  ops->adopt(state, block)    once
 *                                       ops->render(state, block)   each block,
 *                                         until it returns true
 *   fg_engine_collect:              <--  (retired through the garbage ring)
 *     ops->release(state, storage)
 *
 * Storage. A model belongs to a kind (fg_source_kind): the kind says how
 * many bytes of state each voice of it needs, and may keep storage shared
 * by its voices (the discharge kind: the segment events of all live voices
 * and their free list). The engine allocates both for every kind it holds
 * when it is created, one state per voice slot: prepare and render use
 * only that, and the audio thread never allocates. Several models may
 * share a kind (the WM-wave and Abe's models share the discharge kind).
 *
 * Output. A model renders through the output layout
 * (spatial/layout_internal.h) into the bus set (core/bus_internal.h): for
 * each ear the layout asks for (fg_layout_ears) it computes a wave's
 * geometry, and fg_layout_gains names the output channels the wave reaches
 * and their gains (the ear's own channel in stereo; every ambisonic
 * channel, by the direction the wave arrives from). Per bus and channel
 * there is a difference-domain accumulator (fg_bus_accum) for waves added
 * per breakpoint, and a float buffer (fg_bus_pre) for samples rendered
 * one by one. The buses then apply the air's filters, once per bus and
 * channel. docs/spatial.md shows a model doing it. */
#ifndef FULGUR_SOURCE_INTERNAL_H
#define FULGUR_SOURCE_INTERNAL_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "bus_internal.h"
#include "listener_internal.h"
#include "trajectory_internal.h"
#include "spatial/layout_internal.h"
#include "fulgur/engine.h"

/* What the audio thread reports, as atomic counters other threads read. */
typedef struct fg_counters {
    atomic_uint_least64_t posted, dropped_posts, adopted, finished, collected;
    atomic_uint_least64_t late_events, late_samples, skipped_repeats, skipped_work;
    atomic_uint_least64_t non_finite_voices, non_finite_blocks, blocks, blocks_over_budget;
    atomic_uint_least64_t work_units, peak_block_work;
} fg_counters;

/* Adds n to a counter (relaxed: the counters order nothing). */
static inline void fg_count(atomic_uint_least64_t *counter, uint64_t n)
{
    atomic_fetch_add_explicit(counter, n, memory_order_relaxed);
}

/* What a model's prepare may use besides its own state. [sim-thread] */
typedef struct fg_post_context {
    const fg_engine_config *cfg;
    const fg_listener *pose;    /* the newest listener pose at the post */
    uint64_t pose_serial;       /* the serial of a trajectory resting at it
                                 * (fg_block_context.serial) */
    fg_bus_set *buses;          /* the sim thread's part: fg_bus_set_design_bands */
    void *storage;              /* the kind's shared storage */
} fg_post_context;

/* Where a moving source is heard from (aero objects, fires) is solved at
 * every FG_CONTROL_FRAMES-th frame of the engine clock and interpolated
 * between: what such a voice plays does not depend on the host's blocks.
 * 5.3 ms at 48 kHz, in which a sword tip turning at 20 rad/s turns by 0.1
 * rad. */
#define FG_CONTROL_FRAMES 256

/* One audio block, as every voice renders it. [audio-thread] */
typedef struct fg_block_context {
    const fg_engine_config *cfg;
    double start_frame;         /* the engine clock at the block's first sample */
    uint32_t frames;
    /* Where the ears are at any time (a model evaluating its geometry at
     * the moment each wave arrives asks here), and for models content
     * with one pose a block, the ears and centre at the block's start. */
    const fg_trajectory *trajectory;
    const fg_ears *ears;
    const double *position;
    uint64_t serial;            /* fg_trajectory_serial: changes when the trajectory does */
    fg_bus_set *buses;
    /* The chunk (core/bus_internal.h): a source adding to the accumulators
     * (fg_bus_accum) writes each wave to the chunk's end, ahead frames from
     * the block's start. In its first block every sounding wave is added
     * from the block's start; in a later one only the waves not yet
     * written in it. A chunk that follows the one before whole
     * (chunk_follows) need not visit the waves that one wrote to their
     * end. A source that takes back a wave it wrote ahead (a stop, a
     * retired voice) sets *restart: the next block starts a new chunk,
     * without it. */
    uint32_t ahead;
    bool chunk_start, chunk_follows;
    bool *restart;
    fg_counters *counters;      /* late events and samples, skipped repeats and work */
    uint64_t *work_left;        /* the block's work bound: units not yet spent
                                 * (fg_engine_config.work_per_frame); a model
                                 * stops adding once it is 0 and counts the rest */
} fg_block_context;

/* A kind of source: the storage its voices need. */
typedef struct fg_source_kind {
    const char *name;
    size_t voice_bytes;         /* state per voice, allocated for every voice slot,
                                 * zeroed once, aligned to FG_CACHE_LINE */
    /* Allocates the storage shared by the kind's voices for this engine;
     * may be NULL (no shared storage). [main-thread]
     * Errors: FG_ERR_NO_MEMORY. */
    fg_result (*create)(const fg_engine_config *cfg, void **storage);
    /* Frees it; NULL storage is a no-op. May be NULL. [main-thread] */
    void (*destroy)(void *storage);
} fg_source_kind;

/* A source model: the table of operations. */
typedef struct fg_source_ops fg_source_ops;
struct fg_source_ops {
    const char *name;
    const fg_source_kind *kind;
    const void *model;          /* the model's own constants, read by its functions */
    /* Fills voice (kind->voice_bytes of zeroed-once, reused state) from the
     * model's description, which the public post function has validated.
     * Takes what it needs from post->storage; on error takes nothing and
     * leaves the engine as it was. [sim-thread]
     * Errors: FG_ERR_POOL_FULL no room in the kind's storage now;
     * FG_ERR_NOT_FINITE the description gives no finite sound. */
    fg_result (*prepare)(const fg_source_ops *ops, void *voice, const void *desc,
                         const fg_post_context *post);
    /* The block that takes the voice up, before its first render.
     * [audio-thread] */
    void (*adopt)(void *voice, const fg_block_context *block);
    /* Adds the voice's sound in this block into block->buses; returns true
     * when it has finished (nothing more to play, ever). stopping: the sim
     * thread has called fg_engine_stop on it. A value that would turn
     * non-finite is never added: the voice counts itself in
     * counters->non_finite_voices and returns true. Bounded (work_left),
     * no allocation, no lock. [audio-thread] */
    bool (*render)(void *voice, bool stopping, const fg_block_context *block);
    /* Gives back what prepare took from the storage, once the voice is
     * retired. May be NULL. [sim-thread] */
    void (*release)(void *voice, void *storage);
};

/* The kinds every engine holds (core/source_table.c). */
extern const fg_source_kind *const fg_builtin_kinds[];
extern const size_t fg_builtin_kind_count;

/* At most this many kinds per engine, built-in ones included. */
#define FG_MAX_SOURCE_KINDS 8

/* fg_engine_create with further kinds (a model outside the library, such
 * as a test's) besides the built-in ones; kinds[0..count) are borrowed
 * until fg_engine_destroy. [main-thread]
 * Errors: those of fg_engine_create; FG_ERR_ARGUMENT more than
 * FG_MAX_SOURCE_KINDS kinds in all, or a kind twice. */
fg_result fg_engine_create_with(const fg_engine_config *config,
                                const fg_source_kind *const *kinds, size_t count,
                                fg_engine **out);

/* Hands a voice of model ops, described by desc (already validated by the
 * model's public post function), to the audio thread: takes a free voice
 * slot, lets ops->prepare fill its state, and pushes it to the inbox.
 * *id (may be NULL) receives its id. [sim-thread]
 * Errors: FG_ERR_UNSUPPORTED the engine was not created with ops->kind;
 * FG_ERR_QUEUE_FULL the ring to the audio thread is full; FG_ERR_POOL_FULL
 * no free voice, or prepare's error. On any error nothing changes but the
 * dropped_posts counter, for a full pool or queue. */
fg_result fg_engine_post_source(fg_engine *engine, const fg_source_ops *ops, const void *desc,
                                fg_voice_id *id);

/* The state of live voice id if it is of kind (NULL otherwise), valid
 * until fg_engine_collect reclaims the voice: for a model's own calls on a
 * sounding voice (a pose, a stream of samples). [sim-thread] */
void *fg_engine_voice_state(fg_engine *engine, fg_voice_id id, const fg_source_kind *kind);

/* The configuration in use, valid until fg_engine_destroy. [any-thread] */
const fg_engine_config *fg_engine_config_in_use(const fg_engine *engine);

#endif
