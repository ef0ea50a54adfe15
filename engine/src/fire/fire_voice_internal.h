/* The fire voice as a source model (core/source_internal.h): its kind,
 * its voice state and its model.
 *
 * The kind's storage holds FG_FIRE_VOICE_MAX sample rings, each allocated
 * at the first post that needs it (or a larger one) and kept for the next
 * fire until the engine is destroyed; a voice takes one at prepare and
 * gives it back at release. The frame thread publishes the fire's poses
 * into the voice's pose queue (fg_listener records: forward and up fixed)
 * and the audio thread absorbs them into the voice's own trajectory, the
 * listener's interpolation. Each block, for every ear, the emission time
 * of the block's end is solved from the two trajectories; the samples
 * between interpolate it (and the gain 1/r and the layout's gains)
 * linearly from the block's start and read the ring there
 * (fire_voice_render.c). */
#ifndef FULGUR_FIRE_VOICE_INTERNAL_H
#define FULGUR_FIRE_VOICE_INTERNAL_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "core/listener_internal.h"
#include "core/source_internal.h"
#include "core/trajectory_internal.h"
#include "fg_sample_ring.h"
#include "fulgur/fire_voice.h"
#include "spatial/layout_internal.h"

/* One ear at a control frame (FG_CONTROL_FRAMES): the end of one
 * interpolation and the start of the next. */
typedef struct fg_fire_end {
    double tau_s;                    /* emission time heard there */
    double gain;                     /* g / r */
    double layout[FG_LAYOUT_CHANNELS_MAX]; /* the output channels' gains */
    unsigned first, count;           /* the channels they reach: first .. first + count */
} fg_fire_end;

typedef struct fg_fire_storage {
    fg_sample_ring ring[FG_FIRE_VOICE_MAX];
    bool allocated[FG_FIRE_VOICE_MAX];
    bool in_use[FG_FIRE_VOICE_MAX];
} fg_fire_storage;

typedef struct fg_fire_voice_state {
    fg_pose_queue queue;       /* the frame thread's poses */
    fg_trajectory path;        /* audio thread: the poses absorbed */
    uint64_t poses_seen;
    fg_sample_ring *ring;
    unsigned ring_index;
    double gain;
    unsigned bus;              /* its distance band (or the dry bus) */
    double next_share;         /* the share of the next band */
    double emit_s;             /* engine clock of stream frame 0 */
    unsigned ears;
    /* audio thread: each ear at control_frame (at or before the adoption's
     * block), and at the control frame after it once next_ready */
    uint64_t control_frame;
    fg_fire_end end[2], next[2];
    bool next_ready;
    double envelope;           /* the fade, 0 .. 1, at the last frame played */
    bool dry;                  /* audio thread: faded out for want of samples */
    uint64_t covered;          /* audio thread: stream frames whose time has passed */
    uint64_t released;         /* audio thread: the ring's frames before it let go */
    atomic_bool closed;        /* the producer's: no more frames */
    /* read by other threads */
    atomic_int_least64_t read_frame;
    atomic_uint_least64_t underrun_frames, underruns, blocks;
} fg_fire_voice_state;

/* The fire kind and its one model. */
extern const fg_source_kind fg_fire_kind;
extern const fg_source_ops fg_fire_ops;

/* The model's prepare and release (fire_voice.c). [sim-thread] */
fg_result fg_fire_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                          const fg_post_context *post);
void fg_fire_release(void *voice, void *storage);

/* The fg_listener record the trajectory keeps for a fire's pose. */
void fg_fire_pose_record(const fg_fire_pose *pose, fg_listener *out);

#endif
