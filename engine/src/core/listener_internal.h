/* The listener as the threads exchange it: a latest-value cell (a
 * sequence lock), and the queue of timestamped poses the frame thread
 * publishes and the audio thread absorbs into the trajectory
 * (core/trajectory_internal.h).
 *
 * The cell: writers serialise among themselves on the sequence word (odd
 * while a write is in progress): a writer preempted mid-write makes other
 * writers and retrying readers wait, never the audio thread. The audio
 * thread makes one attempt per block and keeps what it had if a write is
 * in progress: wait-free. Other readers retry. The payload is stored as
 * relaxed atomics so no read is a data race. The even sequence value is
 * twice the number of writes. A source model may keep one for its own pose
 * (tests/test_source_model.c does).
 *
 * The queue: FG_POSE_QUEUE such cells written in turn, and a count of the
 * poses published. The audio thread reads every pose published since its
 * last block, at most FG_POSE_QUEUE of them (a writer that laps it wins:
 * the newest poses are kept); a slot being rewritten, or already rewritten
 * for a later pose, is skipped. Bounded and wait-free. */
#ifndef FULGUR_LISTENER_INTERNAL_H
#define FULGUR_LISTENER_INTERNAL_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "fulgur/engine.h"
#include "fg_ring.h"

#define FG_POSE_DOUBLES 16 /* then the velocity_given word */
#define FG_POSE_WORDS 17
#define FG_POSE_QUEUE 64

typedef struct fg_listener_cell {
    alignas(FG_CACHE_LINE) atomic_uint seq;
    _Atomic uint64_t words[FG_POSE_WORDS];
} fg_listener_cell;

typedef struct fg_pose_queue {
    alignas(FG_CACHE_LINE) atomic_uint_least64_t published; /* poses written so far */
    atomic_uint writing;      /* writers take turns on this word */
    fg_listener_cell slot[FG_POSE_QUEUE];
    /* the writer holding the turn's: the latest repeat of the newest pose
     * at rest that was not published (resting), with its later time */
    fg_listener rest;
    bool resting;
} fg_pose_queue;

void fg_listener_cell_init(fg_listener_cell *cell, const fg_listener *pose);
/* Checks the pose: finite, forward and up non-zero and not parallel, the
 * angular speed within FG_MAX_ANGULAR_SPEED_RAD_S, the time not negative. */
fg_result fg_listener_check(const fg_listener *pose);
/* Is the pose at rest as given: its velocity and angular velocity all
 * zero (which, where it moved or turned from the pose before, means "not
 * known": core/trajectory_internal.h)? */
bool fg_listener_at_rest(const fg_listener *pose);
void fg_listener_cell_write(fg_listener_cell *cell, const fg_listener *pose);
/* One attempt; returns false (leaving *pose and *serial alone) if a write
 * was in progress. [audio-thread] */
bool fg_listener_cell_try_read(const fg_listener_cell *cell, fg_listener *pose, unsigned *serial);
/* Retries until a consistent pose is read. [any-thread but audio] */
void fg_listener_cell_read(const fg_listener_cell *cell, fg_listener *pose, unsigned *serial);

/* The queue holding one pose, published once. [main-thread] */
void fg_pose_queue_init(fg_pose_queue *q, const fg_listener *pose);
/* Publishes a pose; a pose at rest where the newest one rests is not
 * published again (returns false) once the trajectory holds the body at
 * rest there: the newest is at rest as given (velocity_given), or alone
 * (the first pose, or it replaced those before it), or the pose before it
 * in time rests in the same place.
 * Nothing the listener hears changes by it. The first repeat of a pose at
 * rest reached by moving is published: the trajectory would otherwise
 * carry the body on along the chord's velocity. The latest repeat held
 * back is published just before the next pose that is published, when
 * earlier than it: the body rests until then and moves from there, not
 * from the rest's first pose (a pose at rest at 0 s, repeated every 10 ms,
 * then moving poses from 10.01 s: the path joins 10.00 s to 10.01 s, not
 * 0 s to 10.01 s). [any-thread but audio] */
bool fg_pose_queue_push(fg_pose_queue *q, const fg_listener *pose);
/* The newest pose and its number (poses published before it and it);
 * retries while it is being written. [any-thread but audio] */
uint64_t fg_pose_queue_latest(const fg_pose_queue *q, fg_listener *pose);
/* Calls take(pose, number, arg) for each pose published after number
 * *seen, oldest first, at most FG_POSE_QUEUE; *seen becomes the number of
 * the newest. [audio-thread] */
void fg_pose_queue_drain(const fg_pose_queue *q, uint64_t *seen,
                         void (*take)(const fg_listener *pose, uint64_t number, void *arg),
                         void *arg);

#endif
