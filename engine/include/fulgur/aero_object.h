/* fulgur — aerodynamic objects in the engine (Dobashi, Yamamoto & Nishita
 * 2003): a stick or blade, or a compact body, moving through the air or
 * standing in a wind, sounding its sound texture (fulgur/aero.h).
 *
 *   sim thread                          frame thread (any but audio)
 *   fg_aero_object_post(e, &object) --> fg_aero_object_set_pose(e, id, &pose)
 *   fg_engine_stop(e, id)                  each frame, timestamped
 *   fg_engine_collect(e)                fg_aero_object_set_wind(e, id, &wind)
 *
 * The object is split into sources one correlation length apart (3 D, D
 * the texture's reference_m); each source l at o_l moves at
 * v_l = v + w x r_l (its point's velocity on the pose path) through an air
 * moving at the wind; the air's speed across the object, u_l, plays the
 * texture with texture time advancing at u_l / v0 (eq. 3) and its samples
 * scaled by fg_aero_pressure_scale (the corrected (v/v0)^3 law), and each
 * ear hears p = (q - o_l) . g_l(t - r_l / c) / (4 pi c r_l^2) (eq. 4), the
 * emission time solved for every sample, so Doppler and the interaural
 * delay fall out of the changing r_l. Method, validation and limits:
 * docs/aero-objects.md.
 *
 * Frames. A pose gives the object's origin, its axis and a normal fixing
 * the cross-section: in the texture's frame (fulgur/aero.h) x is the
 * normal (made perpendicular to the axis), z the axis, y = z x x. A stick
 * spans the axis from start_m to end_m past the origin (a pivot, a hilt);
 * a compact body (a 3-D texture: a sphere, a club) has its texture's z = 0
 * at the origin (the sphere's centre, the club's handle end).
 *
 * Units: SI; pressure in pascals at the ear, into the same buses as the
 * discharges. */
#ifndef FULGUR_AERO_OBJECT_H
#define FULGUR_AERO_OBJECT_H

#include <stdint.h>

#include "fulgur/aero.h"
#include "fulgur/defs.h"
#include "fulgur/engine.h"
#include "fulgur/propagation.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Sources of one object at most: a stick longer than this many correlation
 * lengths gives each source a longer span (docs/aero-objects.md). */
#define FG_AERO_OBJECT_MAX_SOURCES 64

/* The fastest a pose may move, m/s (Mach 0.29 in air at 20 degC): beyond
 * it the compact-dipole and incompressible model of the texture fails. */
#define FG_AERO_MAX_SPEED_M_S 100.0

/* The Reynolds numbers, of a source's cross-flow and the texture's
 * reference_m, over which the texture's pitch law holds: from the onset
 * of shedding to the drag crisis. A source below sheds no tone and is
 * silent; one above plays on by the same laws and is counted in
 * fg_aero_report.beyond_range_blocks. */
#define FG_AERO_RE_MIN 47.0
#define FG_AERO_RE_MAX 2e5

typedef enum fg_aero_body {
    FG_AERO_STICK = 0,  /* a 2-D texture's cross-section along the axis */
    FG_AERO_COMPACT = 1 /* a 3-D texture's body, its sources as computed */
} fg_aero_body;

/* Where the object is at one moment, as the listener's pose is. */
typedef struct fg_aero_pose {
    double position[3]; /* the origin, metres, within +-FG_TREE_MAX_COORDINATE_M */
    double axis[3];     /* any length in [1e-50, 1e50] */
    double normal[3];   /* the same, not parallel to axis */
    double velocity[3]; /* of the origin, m/s at time_s; all zero while the
                         * origin moves from the previous pose (and not
                         * velocity_given): the chord */
    double time_s;      /* engine clock (fg_engine_time_s); 0 = at the call */
    double angular_velocity[3]; /* rad/s at time_s about world axes through
                         * the origin, |w| <= FG_MAX_ANGULAR_SPEED_RAD_S;
                         * all zero while the axis or normal turns from the
                         * previous pose (and not velocity_given): the
                         * rotation between the two over the time between
                         * (fg_aero_object_set_pose) */
    int velocity_given; /* non-zero: velocity and angular_velocity are the
                         * body's, all zero meaning at rest (it stops here) */
} fg_aero_pose;

/* The air's motion around the object: a mean plus gusts, a seeded smooth
 * noise n(t) in [-1, 1] (knots every gust_period_s joined by a C1
 * curve), the wind being velocity * (1 + gust * n(t)). */
typedef struct fg_aero_wind {
    double velocity[3];  /* m/s, |v| <= FG_AERO_MAX_SPEED_M_S */
    double gust;         /* 0 (steady) .. 1 */
    double gust_period_s;/* 0: 2 s; else 0.05 .. 600 */
    uint64_t seed;
} fg_aero_wind;

typedef struct fg_aero_object {
    /* Borrowed: it must stay alive, unchanged, until fg_engine_collect has
     * reclaimed the voice (after fg_engine_stop and its fade, or after
     * duration_s). */
    const fg_aero_texture *texture;
    fg_aero_body body;          /* STICK needs a 2-D texture, COMPACT a 3-D one */
    double start_m, end_m;      /* STICK: the span along the axis, end > start */
    uint32_t sources;           /* STICK: 0 = floor((end - start) / (3 D)), at least 1;
                                 * else 1..FG_AERO_OBJECT_MAX_SOURCES */
    double gain;                /* on the pressure; 0 = 1 */
    fg_aero_pose pose;          /* the first pose */
    fg_aero_wind wind;
    fg_absorption absorption;   /* FG_ABSORPTION_OFF, or ISO9613: the distance
                                 * band bus of the first pose's distance */
    double emit_time_s;         /* engine clock >= 0, or FG_EMIT_NOW */
    double duration_s;          /* 0 = until fg_engine_stop */
} fg_aero_object;

/* The fade in at the start and out at the end of the emission, s. */
#define FG_AERO_FADE_S 0.005

/* Checks o and posts it: the object sounds from emit_time_s (faded in over
 * FG_AERO_FADE_S) until duration_s or fg_engine_stop (faded out). *id (may
 * be NULL) receives its voice id. [sim-thread]
 * Errors: FG_ERR_NULL engine, o or its texture; FG_ERR_NOT_FINITE a NaN or
 * infinite field; FG_ERR_ARGUMENT an unknown body or absorption mode
 * (ABE_FIR is for discharges), a texture for the other body, end_m not
 * above start_m (a zero-length stick), sources above
 * FG_AERO_OBJECT_MAX_SOURCES (given, or the default for a stick longer
 * than that many correlation lengths), a negative gain or duration, an
 * emit time negative and not FG_EMIT_NOW, a pose fg_aero_object_set_pose
 * refuses, a wind out of range; FG_ERR_POOL_FULL / FG_ERR_QUEUE_FULL as
 * fg_engine_post. On any error nothing changes but the dropped_posts
 * counter for the last two. */
FG_API FG_NODISCARD fg_result fg_aero_object_post(fg_engine *engine, const fg_aero_object *o,
                                                  fg_voice_id *id);

/* Publishes where object id is at pose->time_s (0: now); the pose is
 * copied. The audio thread joins the poses into a path exactly as the
 * listener's (fg_engine_set_listener): the origin on the cubic through
 * the positions and velocities, the axis and normal turned on the cubic
 * through the orientations and angular velocities, at most 0.1 s of
 * extrapolation; a source at r from the origin moves at v + w x r, w the
 * path's angular velocity: the pose's where given, else the rotation
 * from the pose before over the time between, so a steady turn (a swing
 * sampled at 90 Hz) is followed exactly. A pose at rest with
 * velocity_given stops the body there; one without it (velocity not
 * known) is stopped by its first repeat; further repeats change nothing
 * (docs/aero-objects.md, "A body at rest"). [any-thread] but not the
 * audio thread, one writer per object, from the post until the voice is
 * collected (the caller orders its last call before fg_engine_collect).
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND id is not a live aero object;
 * FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT a position beyond
 * +-FG_TREE_MAX_COORDINATE_M, an axis or normal whose length is outside
 * [1e-50, 1e50], the two parallel, a speed above FG_AERO_MAX_SPEED_M_S, an
 * angular speed above FG_MAX_ANGULAR_SPEED_RAD_S, a negative time. Nothing
 * is published on an error. */
FG_API FG_NODISCARD fg_result fg_aero_object_set_pose(fg_engine *engine, fg_voice_id id,
                                                      const fg_aero_pose *pose);

/* How long a changed wind takes to blend from the old one, s. */
#define FG_AERO_WIND_RAMP_S 0.02

/* Changes object id's wind (copied): the newest wind wins. The audio
 * thread takes it at the start of its next block, the moment the new wind
 * starts at the object (each ear hears it r / c later), and blends the old
 * wind into it over FG_AERO_WIND_RAMP_S (a C1 smoothstep: speed, pitch
 * and level change smoothly, click-free). A wind published while a blend
 * is still under way at some source waits for it to end (at most
 * FG_AERO_WIND_RAMP_S plus a block; a newer one replaces it). Lock-free
 * for the audio thread. [any-thread] but not the audio thread, one writer
 * per object (the same as fg_aero_object_set_pose's), from the post until
 * the voice is collected.
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND id is not a live aero object;
 * FG_ERR_NOT_FINITE a NaN or infinite field; FG_ERR_ARGUMENT a speed above
 * FG_AERO_MAX_SPEED_M_S, a gust outside [0, 1], a gust period neither 0
 * nor in [0.05, 600] s. Nothing is published on an error. */
FG_API FG_NODISCARD fg_result fg_aero_object_set_wind(fg_engine *engine, fg_voice_id id,
                                                      const fg_aero_wind *wind);

/* What an object's voice has done. */
typedef struct fg_aero_report {
    uint32_t sources;             /* as split at the post */
    uint64_t blocks;              /* blocks rendered */
    uint64_t beyond_range_blocks; /* blocks in which a sounding source's Reynolds
                                   * number lay above FG_AERO_RE_MAX */
    double max_speed_m_s;         /* the fastest cross-flow a source has met */
} fg_aero_report;

/* A snapshot of object id's report. [any-thread] but not the audio thread,
 * while the voice is live (not yet collected).
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND id is not a live aero object. */
FG_API FG_NODISCARD fg_result fg_aero_object_get_report(fg_engine *engine, fg_voice_id id,
                                                        fg_aero_report *out);

#ifdef __cplusplus
}
#endif

#endif
