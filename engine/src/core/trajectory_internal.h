/* The listener's trajectory: where the head, and so each ear, is at any
 * time t on the engine clock. The one place that answers it; every source
 * model asks here (fg_trajectory_head, fg_head_ears).
 *
 * The audio thread absorbs the timestamped poses the host publishes
 * (core/listener_internal.h) into a history of the last
 * FG_TRAJECTORY_POSES, ascending in time. A pose whose time is not after
 * the newest one's replaces every pose from its time on: the latest value
 * wins. Poses older than FG_TRAJECTORY_MEMORY_S before the block being
 * rendered are forgotten, keeping the one in force then.
 *
 * Between two poses the position is the cubic Hermite curve through both
 * positions with both velocities as tangents, so position and velocity are
 * continuous; a pose published without a velocity (all three zero) while
 * it moved takes the chord from the pose before it (exact for straight
 * motion at a constant speed). The orientation is a pose's orthonormal
 * frame (ahead = forward, right = forward x up, above = right x ahead)
 * turned: between poses a and b it is exp(phi(t)) applied to a's frame,
 * phi the cubic Hermite from 0 to the rotation vector taking a's frame
 * onto b's (util/fg_rotation.h) with tangents h w_a and h J^-1 w_b, so the
 * angular velocity J(phi) dphi/dt is w_a at a and w_b at b and continuous
 * between. A pose published without an angular velocity (all zero) while
 * it turned takes the rotation from the pose before over the time
 * between: for a steady turn both ends' rates are the turn's, phi is
 * linear and the path is the turn exactly, at its exact rate. A pose
 * with velocity_given keeps its velocities as given (zeros: at rest, so
 * the body stops at it). After the
 * newest pose the head continues along its velocity and turns at its
 * angular velocity for at most FG_EXTRAPOLATE_MAX_S, then holds; before
 * the oldest it holds the oldest.
 *
 * A trajectory is still when it holds one pose at rest (velocity and
 * angular velocity all zero): then every time
 * sees that pose exactly as published (no normalisation), and the sound of
 * a still listener does not change with this module.
 *
 * fg_pose_queue_push (core/listener.c) mirrors the replacing and chord
 * rules above to tell when a pose at rest sent again changes nothing:
 * change them together. */
#ifndef FULGUR_TRAJECTORY_INTERNAL_H
#define FULGUR_TRAJECTORY_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "fulgur/engine.h"

#define FG_TRAJECTORY_POSES 128
#define FG_TRAJECTORY_MEMORY_S 1.0
#define FG_EXTRAPOLATE_MAX_S 0.1

/* The head at one time. */
typedef struct fg_head {
    double position[3];
    double velocity[3];   /* m/s */
    double forward[3], up[3]; /* unit and perpendicular but in a still
                               * trajectory (the pose as published) */
    double right[3];      /* unit: forward x up, normalised */
    double right_rate[3]; /* d right / dt, 1/s: the ears' share of a turn */
} fg_head;

/* Where the ears are: channel 0 is the left ear, 1 the right, at the ends
 * of the head's diameter (spatial/spherical_head_internal.h). */
typedef struct fg_ears {
    double pos[2][3];
    double vel[2][3];     /* m/s */
    double right[3];      /* unit vector from the left ear to the right */
    double right_rate[3]; /* d right / dt, 1/s */
    double ahead[3], above[3]; /* unit, with right the head's orthonormal frame:
                                * ahead along forward, above = right x ahead */
    double centre[3];     /* the head's centre */
    double centre_vel[3]; /* m/s */
    double radius_m;      /* the head's: half the ear spacing; 0 with one ear */
    unsigned count;
} fg_ears;

/* A pose the trajectory holds, and its span from the pose before. */
typedef struct fg_trajectory_pose {
    fg_listener pose;     /* as published, the velocities not known filled in */
    double turn[3];       /* the rotation vector from the pose before's frame
                           * to this one's, |turn| <= pi */
    double turn_end[3];   /* J(turn)^-1 w: the span's end tangent, rad/s */
} fg_trajectory_pose;

typedef struct fg_trajectory {
    fg_trajectory_pose pose[FG_TRAJECTORY_POSES]; /* a ring: pose[(first + i) % N], times ascending */
    unsigned first, count;
    uint64_t number;      /* the publication number of the newest pose absorbed */
    bool still;           /* one pose, at rest */
} fg_trajectory;

/* A trajectory holding pose alone, pose number `number` of the queue. */
void fg_trajectory_init(fg_trajectory *t, const fg_listener *pose, uint64_t number);

/* Absorbs pose number `number` (increasing). [audio-thread] */
void fg_trajectory_push(fg_trajectory *t, const fg_listener *pose, uint64_t number);

/* A value that changes whenever what the trajectory says changes: twice
 * the newest pose's number, plus one while still. A voice prepared with
 * pose n as the listener at rest caches geometry under 2 n + 1. */
static inline uint64_t fg_trajectory_serial(const fg_trajectory *t)
{
    return 2 * t->number + (t->still ? 1 : 0);
}

/* Forgets the poses no longer needed for times after now_s minus
 * FG_TRAJECTORY_MEMORY_S. [audio-thread] */
void fg_trajectory_forget(fg_trajectory *t, double now_s);

/* The head at time t_s. */
void fg_trajectory_head(const fg_trajectory *t, double t_s, fg_head *out);

/* The head of a single pose, at rest, exactly as published. */
void fg_head_of_pose(const fg_listener *pose, fg_head *out);

/* The ears of a head: one at its centre (channels 1) or two, spacing_m
 * apart along its right axis (the diameter of its sphere). */
void fg_head_ears(const fg_head *head, unsigned channels, double spacing_m, fg_ears *out);

/* The largest distance the head comes from point p between times a_s and
 * b_s, bounded from above (the poses and the ends of the span). */
double fg_trajectory_reach_m(const fg_trajectory *t, const double p[3], double a_s, double b_s);

#endif
