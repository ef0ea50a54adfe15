/* fulgur — the real-time engine: post discharges, pull sound.
 *
 *   sim thread                          audio thread (host's device)
 *   fg_engine_post(e, &discharge)  -->  fg_engine_render(e, out, nframes)
 *   fg_engine_collect(e)          <--   (finished voices)
 *   fg_engine_set_listener(e, &pose)    [any thread: timestamped poses,
 *                                        the engine follows their path]
 *
 * The engine clock is the audio clock: frames rendered so far divided by the
 * sample rate. Output is pascals at the ear, one plane per channel.
 */
#ifndef FULGUR_ENGINE_H
#define FULGUR_ENGINE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/propagation.h"
#include "fulgur/result.h"
#include "fulgur/sound.h"
#include "fulgur/tree.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fg_engine fg_engine;

/* The sample rates the engine accepts, Hz. */
#define FG_SAMPLE_RATE_MIN_HZ 8000.0
#define FG_SAMPLE_RATE_MAX_HZ 384000.0

/* The speeds of sound the engine accepts, m/s: every gas a listener
 * breathes lies inside (air: 290 m/s at -70 degC to 368 m/s at 60 degC). */
#define FG_SPEED_OF_SOUND_MIN_M_S 100.0
#define FG_SPEED_OF_SOUND_MAX_M_S 1000.0

/* The per-block work bound (docs/limits.md). A block of n frames may
 * spend at most work_per_frame * n + FG_WORK_BLOCK_FLOOR units across all
 * voices, each unit priced at about the same CPU time (bench_work_bound):
 * one unit for each ear of each event of each instance in that block
 * evaluated (a WM-wave: a few closed-form terms, whatever its length), and
 * for one of Abe's sources one more for each sample of its series it
 * renders into each bus and channel. An ear whose price does not fit what
 * is left of the block is not rendered; it and the rest of its instance
 * are counted in fg_engine_report.skipped_work, what was spent in
 * work_units and peak_block_work; a continuous repeat due once the block's
 * work is spent is skipped and counted in skipped_repeats. The default
 * keeps a block's CPU time under its duration (docs/limits.md); an offline
 * render, which has no deadline, may take FG_WORK_PER_FRAME_MAX. */
#define FG_WORK_PER_FRAME_DEFAULT 64u
#define FG_WORK_PER_FRAME_MAX 65536u
#define FG_WORK_BLOCK_FLOOR 4096u

/* The output layout: what the channels carry (docs/spatial.md). */
typedef enum fg_layout {
    /* Ears on a spherical head (radius ear_spacing_m / 2): channels 2 =
     * left, right, each with Woodworth's delay around the head and, for
     * discharges with head_shadow, Brown & Duda's head shadow; channels
     * 1 = one ear at the head's centre. */
    FG_LAYOUT_STEREO = 0,
    /* AmbiX: ambisonic_order 1..3, (order + 1)^2 channels in ACN order,
     * SN3D normalisation, the field at the head's centre in the head's
     * frame (x ahead, y left, z up), each wave encoded from where it
     * arrives at the moment it arrives, so a turning head rotates the field
     * smoothly. */
    FG_LAYOUT_AMBISONICS = 1,
    /* Two ears through measured head-related impulse responses
     * (fg_engine_config.hrirs, e.g. read from a SOFA file by the host):
     * each wave is panned, from where it arrives in the head's frame at the
     * moment it arrives, onto 50 virtual loudspeakers on rings every 30
     * degrees of elevation, each heard through the set's measured pair
     * nearest to it (docs/spatial.md). channels: 2, left and right;
     * ambisonic_order 0. The output is FG_BINAURAL_LATENCY_FRAMES late. */
    FG_LAYOUT_BINAURAL = 2
} fg_layout;

/* The binaural filters' partition: the binaural output lags the sound
 * field by this many frames. */
#define FG_BINAURAL_LATENCY_FRAMES 128u
/* HRIRs of the binaural layout: at most this many taps, at most this many
 * directions. */
#define FG_HRIR_MAX_LENGTH 8192u
#define FG_HRIR_MAX_COUNT 65536u

/* A set of measured head-related impulse responses, one pair per
 * direction, at the engine's sample rate. Borrowed for the duration of
 * fg_engine_create only. */
typedef struct fg_hrir_set {
    double sample_rate_hz;   /* must equal the engine's */
    uint32_t count;          /* directions, 16 .. FG_HRIR_MAX_COUNT */
    uint32_t length;         /* taps per response, 1..FG_HRIR_MAX_LENGTH */
    const double *direction; /* count * 3: where each pair's source lies in the head's frame
                              * (x ahead, y left, z up; any length > 0) */
    const float *left;       /* count * length: the left ear's responses, pair after pair */
    const float *right;      /* the same for the right ear */
} fg_hrir_set;

#define FG_AMBISONIC_ORDER_MIN 1u
#define FG_AMBISONIC_ORDER_MAX 3u

/* Zero in any field means "the default" given in its comment. */
typedef struct fg_engine_config {
    double sample_rate_hz;        /* 48000; must lie in [8000, 384000] */
    uint32_t max_block_frames;    /* 4096; the largest nframes render accepts, <= 65536 */
    uint32_t channels;            /* stereo: 2; 1 = one ear at the listener's centre, 2 = two
                                   * ears. Ambisonics: (order + 1)^2, the only value allowed */
    uint32_t max_voices;          /* 64; voices alive at once (posted, sounding or uncollected) */
    uint32_t segment_capacity;    /* 131072; segments held by all live discharges together */
    double speed_of_sound_m_s;    /* 343; 331.5 + 0.6 * (temperature in degC) */
    double ear_spacing_m;         /* 0.175; distance between the two ears: the diameter of
                                   * the spherical head they sit on (Woodworth's delay
                                   * around it, Brown & Duda's head shadow; radius 8.75 cm) */
    double max_lookahead_s;       /* 0.25; cap on the motion look-ahead (see fg_engine_render) */
    uint32_t max_adopt_per_block; /* 8; posted voices the audio thread takes per block */
    /* The air, for FG_ABSORPTION_ISO9613 (ISO 9613-1). */
    double air_temperature_k;     /* 293.15 (20 degC) */
    double air_humidity_pct;      /* 70; relative humidity in (0, 100] */
    double air_pressure_kpa;      /* 101.325 */
    uint32_t work_per_frame;      /* FG_WORK_PER_FRAME_DEFAULT; the work bound above, <= 65536 */
    fg_layout layout;             /* FG_LAYOUT_STEREO */
    uint32_t ambisonic_order;     /* ambisonics: 1; FG_AMBISONIC_ORDER_MIN..MAX. Stereo,
                                   * binaural: 0 */
    const fg_hrir_set *hrirs;     /* binaural only (required); borrowed by fg_engine_create,
                                   * NULL in the configuration in use */
    uint32_t chunk_frames;        /* 0 (none); <= 65536. For a render that is not paced by a
                                   * device (a file, a batch): a still listener's WM-waves
                                   * are written this many frames ahead, to the end of a
                                   * chunk of blocks, and visited once a chunk, not once a
                                   * block, so that a long wave costs about what a short one
                                   * does; the chunk's first block costs more (every wave
                                   * sounding, to the chunk's end), the others less. Longer
                                   * than max_block_frames to have an effect; cut to what the
                                   * buses' 16 MB of planes hold. fulgur render takes 1024. */
} fg_engine_config;

/* The voice model a discharge is rendered with. */
typedef enum fg_voice_model {
    FG_MODEL_WM = 0,   /* one WM-wave per segment (Matsuyama) */
    FG_MODEL_ABE = 1   /* Abe et al.: harmonic-series N-waves per node, falling in
                        * pitch and level, pitch set by height, loudness ~ 1/r^2 */
} fg_voice_model;

/* Strokes of one discharge at most (the log-series tail is cut here). */
#define FG_MAX_STROKES 32

/* An emit time meaning "the start of the block that adopts the voice". */
#define FG_EMIT_NOW (-1.0)

/* A continuous discharge's repeat interval range, s. The shortest: a
 * channel re-strikes only once the air its last spark heated has
 * recovered, and Matsuyama ties the interval to the N-wave's length; a
 * repeat sooner than 0.1 ms (2.5 plasma_ball T0s) would start inside the
 * previous emission's own wave. It also bounds the repeats one block can
 * draw: block length / FG_REPEAT_MIN_S. */
#define FG_REPEAT_MIN_S 1e-4
#define FG_REPEAT_MAX_S 10.0

typedef struct fg_discharge {
    const fg_node *nodes;   /* borrowed for the duration of fg_engine_post */
    size_t node_count;
    fg_sound_config sound;
    double emit_time_s;     /* engine clock, >= 0, or FG_EMIT_NOW */
    uint32_t strokes;       /* 0: drawn from the log-series law; else 1..FG_MAX_STROKES */
    int continuous;         /* non-zero: re-emit the pattern until stopped (plasma ball, held gap) */
    double repeat_min_s;    /* continuous: interval range, default 0.010 .. 0.050 s, within
                             * [FG_REPEAT_MIN_S, FG_REPEAT_MAX_S] */
    double repeat_max_s;
    double duration_s;      /* continuous: stop after this long; 0 = until fg_engine_stop */
    uint64_t seed;          /* T0 fluctuation, strokes, repeats, turbulence */
    fg_propagation_config propagation; /* zero: free, still air */
    fg_voice_model model;   /* FG_MODEL_WM (zero) or FG_MODEL_ABE */
} fg_discharge;

/* Identifies a posted voice until it is collected. Never 0. */
typedef uint64_t fg_voice_id;

/* Where the listener's head is at one moment. A host publishes one per
 * frame (fg_engine_set_listener); the engine joins them into a continuous
 * path and hears every wave from where the ears are when it arrives. */
typedef struct fg_listener {
    double position[3];  /* metres, each within +-FG_TREE_MAX_COORDINATE_M */
    double forward[3];   /* any length in [1e-50, 1e50] */
    double up[3];        /* the same, not parallel to forward */
    double velocity[3];  /* m/s at time_s. All zero while the position changes
                          * from the previous pose means "not known" (unless
                          * velocity_given): the engine takes the chord from
                          * that pose */
    double time_s;       /* the engine clock at which the head is here
                          * (fg_engine_time_s); 0 = when the pose is
                          * published. A VR host gives its predicted display
                          * time, or the time of the frame's tracking sample */
    double angular_velocity[3]; /* rad/s at time_s, about world axes through
                          * the head, |w| <= FG_MAX_ANGULAR_SPEED_RAD_S. All
                          * zero while forward or up changes from the
                          * previous pose means "not known" (unless
                          * velocity_given): the engine takes the rotation
                          * between the two orientations over the time
                          * between (exact for a steady turn) */
    int velocity_given;  /* non-zero: velocity and angular_velocity are the
                          * head's, all zero meaning at rest: a pose reached
                          * by moving stops the head there, and nothing is
                          * taken from the pose before */
} fg_listener;

/* The fastest turn a pose may give, rad/s (95 000 rpm). */
#define FG_MAX_ANGULAR_SPEED_RAD_S 1e4

typedef struct fg_engine_report {
    uint64_t posted;            /* voices accepted by fg_engine_post */
    uint64_t dropped_posts;     /* posts refused for a full pool or queue */
    uint64_t adopted;           /* voices taken by the audio thread */
    uint64_t finished;          /* voices the audio thread has retired */
    uint64_t collected;         /* voices reclaimed by fg_engine_collect */
    uint64_t late_events;       /* events that began before the block that could first play them */
    uint64_t late_samples;      /* per ear, the samples those events lost */
    uint64_t skipped_repeats;   /* continuous repeats dropped for lack of instance slots, or
                                 * due once their block's work was spent */
    uint64_t skipped_work;      /* work units the per-block bound left undone (above) */
    uint64_t non_finite_voices; /* voices retired because their sound turned non-finite */
    uint64_t non_finite_blocks; /* bus blocks zeroed because they held a non-finite sample */
    uint64_t blocks;            /* successful render calls of one frame or more */
    uint64_t blocks_over_budget;/* render calls that took longer than their frames last */
    uint64_t work_units;        /* work units the per-block bound let the blocks spend (above) */
    uint64_t peak_block_work;   /* the most units one block spent: at most work_per_frame * n +
                                 * FG_WORK_BLOCK_FLOOR for its n frames */
} fg_engine_report;

/* The start of each stroke of the discharge, seconds after its emit time,
 * exactly as fg_engine_post will schedule them (they depend on seed,
 * strokes and continuous only): writes min(count, max) offsets, the first
 * 0, and returns count (1 for a continuous discharge). offsets_s may be NULL
 * to ask for the count. A picture uses this to flash with the sound.
 * [any-thread]
 * Returns 0 when strokes > FG_MAX_STROKES. A NULL discharge is a programmer
 * error (fulgur/defs.h). */
FG_API uint32_t fg_discharge_stroke_offsets(const fg_discharge *discharge, double *offsets_s,
                                            uint32_t max);

/* The configuration fg_engine_create would use for config: every zero
 * field replaced by its default; config NULL gives all the defaults.
 * *out is written only on success. [any-thread]
 * Errors: FG_ERR_NULL out; the others as fg_engine_create's, but for
 * FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_engine_config_resolve(const fg_engine_config *config,
                                                       fg_engine_config *out);

/* Creates an engine; every buffer the audio thread will touch is allocated
 * here. config may be NULL (all defaults). *out is owned by the caller until
 * fg_engine_destroy. [main-thread]
 * Errors: FG_ERR_NULL out; FG_ERR_SAMPLE_RATE rate outside [8000, 384000];
 * FG_ERR_NOT_FINITE a NaN/inf field; FG_ERR_ARGUMENT an unknown layout, an
 * ambisonic order outside 1..3 (or one given for stereo or binaural), channels not 1
 * or 2 for stereo, not (order + 1)^2 for ambisonics or not 2 for binaural,
 * hrirs missing for binaural (or given for another layout), an HRIR set
 * with fewer than 16 or more than FG_HRIR_MAX_COUNT directions, a length
 * outside 1..FG_HRIR_MAX_LENGTH, a NULL array, a zero or non-finite
 * direction or a non-finite tap (FG_ERR_NOT_FINITE) or a rate that is not
 * the engine's (FG_ERR_SAMPLE_RATE), a
 * speed of sound outside [FG_SPEED_OF_SOUND_MIN_M_S, FG_SPEED_OF_SOUND_MAX_M_S],
 * a negative spacing/look-ahead, block > 65536, voices, segments or work
 * too large, air outside 200-350 K, (0, 100] %, 10-200 kPa; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_engine_create(const fg_engine_config *config, fg_engine **out);

/* Frees the engine and every voice, sounding or not. NULL is a no-op. No
 * other call may be running on it. [main-thread] */
FG_API void fg_engine_destroy(fg_engine *engine);

/* The configuration actually in use (defaults filled in). [any-thread] */
FG_API void fg_engine_get_config(const fg_engine *engine, fg_engine_config *out);

/* Validates the discharge, copies its tree into a free voice, expands its
 * strokes, prepares every segment (geometry against the listener pose now,
 * T0 fluctuation, return-stroke emit delay), sorts the events by arrival and
 * hands the voice to the audio thread. The caller keeps ownership of
 * discharge and its nodes. *id (may be NULL) receives the voice's id.
 * [sim-thread]
 * Errors: FG_ERR_NULL engine/discharge/nodes; FG_ERR_TREE the tree fails
 * fg_tree_check (its rules and limits); FG_ERR_NOT_FINITE / FG_ERR_ARGUMENT
 * a parameter (see fg_sound_config_check and fg_propagation_config_resolve,
 * strokes > FG_MAX_STROKES, negative emit time other than FG_EMIT_NOW,
 * continuous with strokes > 1, repeat range outside [FG_REPEAT_MIN_S,
 * FG_REPEAT_MAX_S] or min > max, unknown model); FG_ERR_NOT_FINITE also
 * when the sound at the listener's pose now comes out non-finite;
 * FG_ERR_CAPACITY more segments than segment_capacity (a ground image
 * counts each segment twice); FG_ERR_POOL_FULL no free voice or segment space now;
 * FG_ERR_QUEUE_FULL the ring to the audio thread is full. On any error
 * nothing changes except the dropped_posts counter for the last two. */
FG_API FG_NODISCARD fg_result fg_engine_post(fg_engine *engine, const fg_discharge *discharge,
                                             fg_voice_id *id);

/* Ends a continuous voice: no repeat starts after this; the ones sounding
 * finish. On a lightning voice, no further stroke starts. [sim-thread]
 * Errors: FG_ERR_NULL engine; FG_ERR_NOT_FOUND the id is not a live voice. */
FG_API FG_NODISCARD fg_result fg_engine_stop(fg_engine *engine, fg_voice_id id);

/* Reclaims the voices the audio thread has finished; returns how many.
 * [sim-thread] (A NULL engine here and in the getters below is a
 * programmer error: fulgur/defs.h.) */
FG_API size_t fg_engine_collect(fg_engine *engine);

/* Writes nframes of every channel into out[channel][0..nframes). Adopts up
 * to max_adopt_per_block posted voices, reads the latest listener pose,
 * renders every sounding voice through its model (a discharge: every wave
 * overlapping the block, for each ear), and retires finished voices. With
 * the WM-wave model each sample is the exact average of the continuous
 * pressure over its sample interval.
 * Moving listener: each wave is heard from where the ears are when it
 * arrives, on the path through the published poses (fg_engine_set_listener):
 * its arrival solves t = emission + travel(ear(t)), its angle, distance and
 * air are those at t, and it is stretched by the Doppler rate
 * 1 / (1 - d travel/dt) there. The output therefore does not depend on the
 * block size. A still listener (one pose at rest) is heard exactly as
 * before, each wave's geometry computed once. An event joins the block loop
 * when its waveform could start before the block's end given the
 * listener's displacement d from where the voice was posted: the look-ahead
 * is (d + 1.3 ear_spacing)/c (the way around the head to the far ear
 * included), capped at max_lookahead_s; events brought forward
 * by more than that are counted as late.
 * Chunks (chunk_frames): a still listener's wave is added to the chunk's
 * end in the block it joins and not visited again in the chunk; the
 * chunk's first block adds every sounding wave. The samples are those of
 * blocks as long as the chunk, to rounding (under 1e-7 of the peak).
 * Bounded: the block's work stops at the bound above (FG_WORK_PER_FRAME_DEFAULT),
 * at most 64 emissions (strokes, repeats) of a voice sound at once, and a voice
 * whose sound turns non-finite (a pose far out of its model's range) is
 * retired before it reaches a bus; the output is always finite.
 * Long calls: the buses' planes are bounded (16 MiB: blocks of up to 4096
 * frames in stereo, 2048 for ambisonics of order 2, 1024 of order 3, 512
 * in binaural); a call of more frames is rendered as consecutive blocks of
 * that length, each adopting up to max_adopt_per_block voices and spending
 * its own work bound (peak_block_work is of those blocks).
 * [audio-thread] Wait-free; never allocates, locks or prints.
 * Errors: FG_ERR_NULL engine/out/a plane; FG_ERR_BLOCK_SIZE nframes >
 * max_block_frames (the planes are then filled with zeros if out is valid). */
FG_API FG_NODISCARD fg_result fg_engine_render(fg_engine *engine, float *const *out,
                                               uint32_t nframes);

/* Publishes where the listener's head is at pose->time_s (0: now, the
 * engine clock at this call). The pose is copied. The audio thread takes
 * every pose published since its last block (the newest 64 if more came)
 * into the listener's path: between two poses the position follows the
 * cubic through both positions with both velocities (a pose without one
 * takes the chord from the pose before), the orientation turns by the
 * cubic through both orientations with both angular velocities (a pose
 * without one takes the rotation from the pose before over the time
 * between: a steady turn is followed exactly); after the newest pose the
 * head goes on along its velocity, turning at its angular velocity, for
 * at most 0.1 s, then stays. A pose whose time is not after the previous one's replaces the
 * path from its time on: the latest value wins. The engine keeps the last
 * 128 poses, and those of the last second.
 * For the path of a 90 Hz host to sound continuous, publish each frame's
 * pose with its time and velocity, ideally for a time ahead of the audio
 * (a VR runtime's predicted display time): then every wave a block plays
 * arrives between two known poses. A host publishing "now" poses is
 * extrapolated along its velocity between frames; a pose at rest
 * republished unchanged costs nothing, but for its first repeat after a
 * move, which stops the head where it rests (a pose at rest with
 * velocity_given stops it at once), and its latest repeat, published
 * just before the next pose that changes, so that the head rests until
 * then and moves from there.
 * [any-thread] but not the audio thread: meant for one writer (the frame
 * thread). Overlapping calls from several threads stay correct, but each
 * waits while another is writing, so it is not lock-free among writers.
 * Render never waits: a pose being written as it reads is taken in the
 * next block.
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT a position beyond
 * +-FG_TREE_MAX_COORDINATE_M, a forward or up whose length is outside
 * [1e-50, 1e50], the two parallel, an angular speed above
 * FG_MAX_ANGULAR_SPEED_RAD_S, or a negative time. */
FG_API FG_NODISCARD fg_result fg_engine_set_listener(fg_engine *engine, const fg_listener *pose);

/* Copies the latest published pose into *out (time_s as stamped); waits
 * while a write is in progress. [any-thread] but not the audio thread. */
FG_API void fg_engine_get_listener(const fg_engine *engine, fg_listener *out);

/* A snapshot of the counters. [any-thread] */
FG_API void fg_engine_get_report(const fg_engine *engine, fg_engine_report *out);

/* The engine clock: frames rendered so far, and the same in seconds.
 * [any-thread] */
FG_API uint64_t fg_engine_frames(const fg_engine *engine);
FG_API double fg_engine_time_s(const fg_engine *engine);

#ifdef __cplusplus
}
#endif

#endif
