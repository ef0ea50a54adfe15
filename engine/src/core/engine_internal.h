/* The engine object, shared by the files that implement its calls
 * (engine.c: creation and getters; post.c: the sim thread's post, stop and
 * collect; render.c: the audio thread's loop). */
#ifndef FULGUR_ENGINE_INTERNAL_H
#define FULGUR_ENGINE_INTERNAL_H

#include <stdatomic.h>
#include <stdint.h>

#include "bus_internal.h"
#include "listener_internal.h"
#include "trajectory_internal.h"
#include "source_internal.h"
#include "spatial/binaural_internal.h"
#include "voice_internal.h"
#include "fg_ring.h"
#include "fulgur/engine.h"

/* A kind the engine holds: its shared storage and its voices' states. */
typedef struct fg_kind_slot {
    const fg_source_kind *kind;
    void *storage;
    unsigned char *pool;       /* max_voices states, each cache-line aligned */
    size_t stride;             /* bytes from one state to the next: voice_bytes rounded up */
} fg_kind_slot;

struct fg_engine {
    void *block;              /* the allocation holding it (engine.c), freed by destroy */
    fg_engine_config cfg;
    fg_kind_slot kinds[FG_MAX_SOURCE_KINDS];
    size_t kind_count;

    /* sim thread */
    fg_voice *voices;
    uint32_t *free_slots;
    uint32_t free_count;
    uint8_t *live;            /* posted and not yet collected, by slot */

    fg_ring inbox;            /* sim -> audio: fg_voice * */
    fg_ring garbage;          /* audio -> sim: fg_voice * */
    fg_pose_queue listener;   /* the frame thread's timestamped poses */

    /* filter buses: set up at create, band filters designed by the sim
     * thread before the first voice that needs them */
    fg_bus_set buses;
    /* binaural: the buses' ambisonic field, then the decoder to the ears */
    float *field_store;
    float *field[FG_BUS_MAX_CHANNELS];
    uint32_t field_frames; /* audio thread: the frames the last block wrote into them */
    fg_binaural binaural;

    /* audio thread */
    fg_voice **active;
    uint32_t active_count;
    fg_trajectory trajectory; /* the poses read so far */
    uint64_t poses_seen;      /* the number of the newest */
    uint64_t chunk_serial;    /* the trajectory's serial the chunk's waves were heard at */
    bool restart_chunk;       /* the next block starts a new chunk (fg_block_context.restart) */

    atomic_uint_least64_t frames;
    fg_counters counters;
};

#endif
