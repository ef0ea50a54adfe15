/* fulgur — the fire voice: a fire's sound placed in the engine, streamed
 * from the simulation (docs/fire-voice.md).
 *
 *   sim thread (the stream's one producer)    audio thread
 *   fg_fire_voice_post(e, &fire, &id)
 *   fg_fire_voice_push(e, id, p, n, &k)  -->  SPSC sample ring  -->  render:
 *     or fg_fire_feed_push(feed, e, id,         read at the emission time
 *        flux, steps, &taken)                   t - r / c of each ear
 *   fg_fire_voice_close(e, id) (no more)
 *   fg_engine_stop(e, id), fg_engine_collect(e)
 *   frame thread (any but audio): fg_fire_voice_set_pose(e, id, &pose)
 *
 * The stream is the fire's pressure at 1 m from it, pascals, one sample
 * per audio frame: frame n is emitted at emit_time_s + n / sample_rate on
 * the engine clock. The voice is a point source: each ear hears
 * p(t) = g s(tau) / r(tau), tau solving tau = t - r(tau) / c with r the
 * distance from the source (on the path of its poses) to the ear, so the
 * arrival delay, 1/r and the Doppler shift of a carried torch fall out.
 * The ring's samples are read at the fractional frame (tau - emit) fs by a
 * 4-point cubic (Catmull-Rom), through the distance bands of
 * FG_ABSORPTION_ISO9613 and the engine's output layout (stereo ears on the
 * spherical head, or ambisonics from the direction of arrival).
 *
 * Real time. The ring's memory is taken at the post (reused by later
 * fires); the audio thread never waits for the producer: a frame it needs
 * that has not been pushed is an underrun, counted in the report
 * (underrun_frames: the frames of emission time that passed without
 * their samples) and heard as silence, faded out and in again over
 * FG_FIRE_FADE_S. The voice fades out early when fewer than the
 * look-ahead (FG_FIRE_FADE_S of frames, twice, plus 6) lie ahead of what
 * it reads, so the fade itself never runs out of samples. Frames pushed
 * after their time has passed are let go unheard; the producer is told by
 * fg_fire_voice_get_report.read_frame where the voice reads.
 *
 * Latency: a sample pushed now is heard when the emission clock reaches
 * it, plus r / c. A producer keeping the ring filled to the lead L_s
 * (frames held / sample rate, at most the ring's capacity) is heard L_s
 * later than it computes; fed from flux by fg_fire_feed, the sound also
 * lags the flux by fg_fire_sound_latency_s. So the simulation runs ahead
 * of the audio by fg_fire_sound_latency_s + L_s (+ r / c to the ear). */
#ifndef FULGUR_FIRE_VOICE_H
#define FULGUR_FIRE_VOICE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/engine.h"
#include "fulgur/fire.h"
#include "fulgur/propagation.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Fire voices alive in one engine at once (posted and not yet collected). */
#define FG_FIRE_VOICE_MAX 16u

/* The ring's length, seconds of samples: the default, and the limits. The
 * capacity is rounded up to a power of two of frames. */
#define FG_FIRE_RING_DEFAULT_S 0.5
#define FG_FIRE_RING_MIN_S 0.01
#define FG_FIRE_RING_MAX_S 8.0

/* The fade at an underrun, at fg_engine_stop and at the end of a closed
 * stream, s. */
#define FG_FIRE_FADE_S 0.002

/* The fastest a fire may move, m/s (Mach 0.29 at 20 degC). */
#define FG_FIRE_MAX_SPEED_M_S 100.0

/* Stream samples beyond this magnitude are refused, Pa at 1 m (a
 * 10^4 m^2 fire front at 10 m/s changing over a millisecond gives
 * 10^7 Pa at 1 m by eq. 3; the float path's headroom is far above). */
#define FG_FIRE_MAX_PRESSURE_PA 1e9

/* Where the fire is at one moment. */
typedef struct fg_fire_pose {
    double position[3]; /* metres, within +-FG_TREE_MAX_COORDINATE_M */
    double velocity[3]; /* m/s at time_s, |v| <= FG_FIRE_MAX_SPEED_M_S; all zero while
                         * it moves from the previous pose: the chord */
    double time_s;      /* engine clock (fg_engine_time_s); 0 = at the call */
} fg_fire_pose;

typedef struct fg_fire_voice {
    fg_fire_pose pose;        /* the first pose */
    double gain;              /* on the pressure; 0 = 1; >= 0 */
    fg_absorption absorption; /* FG_ABSORPTION_OFF, or ISO9613: the distance band bus
                               * of the first pose's distance, kept while it moves */
    double emit_time_s;       /* engine clock of stream frame 0, >= 0, or FG_EMIT_NOW
                               * (the block that takes the voice up) */
    double ring_s;            /* the ring's length: 0 = FG_FIRE_RING_DEFAULT_S; else
                               * FG_FIRE_RING_MIN_S .. FG_FIRE_RING_MAX_S */
} fg_fire_voice;

/* Checks f and posts it; the stream is empty until pushed to. *id (may be
 * NULL) receives its voice id. The voice sounds until fg_engine_stop (a
 * fade of FG_FIRE_FADE_S) or, once closed, until its last frame has
 * reached every ear. [sim-thread]: allocates the ring unless a collected
 * fire's is large enough.
 * Errors: FG_ERR_NULL engine or f; FG_ERR_NOT_FINITE a NaN or infinite
 * field; FG_ERR_ARGUMENT a pose fg_fire_voice_set_pose refuses, a negative
 * gain, an unknown absorption mode (ABE_FIR is for discharges), an emit
 * time negative and not FG_EMIT_NOW, ring_s outside its limits;
 * FG_ERR_POOL_FULL FG_FIRE_VOICE_MAX fires are alive, or the engine's
 * voices are all taken; FG_ERR_QUEUE_FULL as fg_engine_post;
 * FG_ERR_NO_MEMORY. On any error nothing changes but the dropped_posts
 * counter for a full pool or queue. */
FG_API FG_NODISCARD fg_result fg_fire_voice_post(fg_engine *engine, const fg_fire_voice *f,
                                                 fg_voice_id *id);

/* Publishes where fire id is at pose->time_s (0: now); the pose is copied.
 * The audio thread joins the poses into a path as the listener's
 * (fg_engine_set_listener): a cubic through positions and velocities, at
 * most 0.1 s of extrapolation; the source moves along it within each
 * block, sample by sample. [any-thread] but not the audio thread, one
 * writer per fire, until the voice is collected.
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND id is not a live fire;
 * FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT a position beyond
 * +-FG_TREE_MAX_COORDINATE_M, a speed above FG_FIRE_MAX_SPEED_M_S, a
 * negative time. Nothing is published on an error. */
FG_API FG_NODISCARD fg_result fg_fire_voice_set_pose(fg_engine *engine, fg_voice_id id,
                                                     const fg_fire_pose *pose);

/* Appends pa_at_1m[0 .. frames) (the fire's pressure at 1 m, Pa, one per
 * audio frame) to fire id's stream: as many as the ring has room for now,
 * the oldest first; *pushed receives how many (frames when all fit; the
 * rest is the caller's to push again). Never waits. [sim-thread]: the
 * fire's one producer.
 * Errors: FG_ERR_NULL engine, pushed, or pa_at_1m with frames > 0;
 * FG_ERR_NOT_FOUND id is not a live fire; FG_ERR_NOT_FINITE a sample is
 * NaN or infinite; FG_ERR_ARGUMENT a sample beyond
 * FG_FIRE_MAX_PRESSURE_PA, or the stream was closed. On an error nothing
 * is pushed and *pushed is 0. */
FG_API FG_NODISCARD fg_result fg_fire_voice_push(fg_engine *engine, fg_voice_id id,
                                                 const float *pa_at_1m, size_t frames,
                                                 size_t *pushed);

/* Ends fire id's stream: nothing more will be pushed. The voice plays what
 * it holds, its last FG_FIRE_FADE_S faded out, and finishes once the last
 * frame has reached every ear; a closed stream has no underruns.
 * [sim-thread]: the producer.
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND id is not a live fire. Closing
 * twice is no error. */
FG_API FG_NODISCARD fg_result fg_fire_voice_close(fg_engine *engine, fg_voice_id id);

/* What a fire's voice has done. */
typedef struct fg_fire_voice_report {
    uint64_t capacity_frames;  /* the ring's */
    uint64_t pushed_frames;    /* the stream's length so far */
    uint64_t held_frames;      /* pushed and not yet let go by the audio thread */
    int64_t read_frame;        /* the stream frame the earliest ear reads now
                                * (negative before the sound leaves the fire);
                                * a producer keeps pushed_frames ahead of it */
    uint64_t underrun_frames;  /* frames of emission time that passed unpushed */
    uint64_t underruns;        /* the times the voice ran dry and faded out */
    uint64_t blocks;           /* blocks rendered */
    bool closed;
} fg_fire_voice_report;

/* A snapshot of fire id's report. [any-thread] but not the audio thread,
 * while the voice is live (not yet collected).
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND id is not a live fire. */
FG_API FG_NODISCARD fg_result fg_fire_voice_get_report(fg_engine *engine, fg_voice_id id,
                                                       fg_fire_voice_report *out);

/* ---------------------------------------------------------------------
 * Feeding a fire voice from a flux series (a game's own flame simulation,
 * or ours): fg_fire_sound on the sim thread, scaled to pascals, pushed.
 * ------------------------------------------------------------------- */

typedef struct fg_fire_feed fg_fire_feed;

/* The pressure at 1 m of a flame front whose flux changes at dI/dt
 * (m^3/s^2): a monopole of volume velocity I, p = rho0 / (4 pi) dI/dt
 * (Chadwick & James' eq. 3 with the heat release written as the
 * dilatation it causes, (gamma - 1) q / c0^2 = rho0 div u, whose volume
 * integral is I: the simple source's p = rho0 I'(t - r/c) / (4 pi r)),
 * rho0 the
 * density of dry air at the engine's air_temperature_k and
 * air_pressure_kpa. [any-thread] */
FG_API double fg_fire_pascals_per_flux_rate(const fg_engine_config *config);

/* Creates a feed: one fg_fire_sound of config (its sample_rate_hz must be
 * the engine's, checked at each push) taking at most max_steps flux
 * samples per internal call (0: 64), and the room to hold what the ring
 * could not take. *out is the caller's until fg_fire_feed_destroy.
 * [main-thread] or [sim-thread]
 * Errors: FG_ERR_NULL config or out; those of fg_fire_sound_create;
 * FG_ERR_ARGUMENT max_steps above 65536; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_fire_feed_create(const fg_fire_sound_config *config,
                                                  size_t max_steps, fg_fire_feed **out);

/* Frees the feed; NULL is a no-op. [main-thread] or [sim-thread] */
FG_API void fg_fire_feed_destroy(fg_fire_feed *feed);

/* How far its sound lags the flux: fg_fire_sound_latency_s. [any-thread] */
FG_API double fg_fire_feed_latency_s(const fg_fire_feed *feed);

/* Frames computed and not yet taken by the ring. [sim-thread] */
FG_API size_t fg_fire_feed_pending(const fg_fire_feed *feed);

/* First pushes what the feed holds into fire id's ring; then, while the
 * ring takes everything, turns flux[0 .. steps) (I, m^3/s, at the sound's
 * sim_rate_hz, following the steps already taken) into sound, scales it
 * by fg_fire_pascals_per_flux_rate and pushes it. *taken receives the
 * flux steps consumed (fewer than steps when the ring filled: the rest is
 * the caller's to give again; their sound so far is held in the feed).
 * steps = 0 only pushes what is held. [sim-thread]: the fire's producer.
 * Errors: FG_ERR_NULL feed, engine, taken, or flux with steps > 0;
 * FG_ERR_NOT_FOUND id is not a live fire; FG_ERR_SAMPLE_RATE the sound's
 * rate is not the engine's; FG_ERR_NOT_FINITE a flux value (then none of
 * these steps is taken, what was held may have been pushed);
 * FG_ERR_ARGUMENT a flux beyond FG_FIRE_MAX_FLUX_M3_S, or the stream is
 * closed. */
FG_API FG_NODISCARD fg_result fg_fire_feed_push(fg_fire_feed *feed, fg_engine *engine,
                                                fg_voice_id id, const double *flux_m3_s,
                                                size_t steps, size_t *taken);

/* Ends the flux: drains the sound (fg_fire_sound_drain) once, pushes what
 * fits, and once nothing is held closes fire id's stream; *done says
 * whether it has (call again with the ring emptier until it has).
 * [sim-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND; FG_ERR_SAMPLE_RATE as push. */
FG_API FG_NODISCARD fg_result fg_fire_feed_finish(fg_fire_feed *feed, fg_engine *engine,
                                                  fg_voice_id id, bool *done);

#ifdef __cplusplus
}
#endif

#endif
