/* The listener pose as a latest-value cell (a sequence lock).
 *
 * Writers serialise among themselves on the sequence word (odd while a
 * write is in progress): a writer preempted mid-write makes other writers
 * and retrying readers wait, never the audio thread. The audio thread makes one attempt per block and
 * keeps the pose it had if a write is in progress: wait-free. Other readers
 * retry. The payload is stored as relaxed atomics so no read is a data race.
 * The even sequence value also serves as the pose's serial number. */
#ifndef FULGUR_LISTENER_INTERNAL_H
#define FULGUR_LISTENER_INTERNAL_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "fulgur/engine.h"
#include "fg_ring.h"

#define FG_POSE_WORDS 12

typedef struct fg_listener_cell {
    alignas(FG_CACHE_LINE) atomic_uint seq;
    _Atomic uint64_t words[FG_POSE_WORDS];
} fg_listener_cell;

/* Where the ears are: channel 0 is the left ear, 1 the right. */
typedef struct fg_ears {
    double pos[2][3];
    double right[3];  /* unit vector from the left ear to the right */
    unsigned count;
} fg_ears;

void fg_listener_cell_init(fg_listener_cell *cell, const fg_listener *pose);
/* Checks the pose: finite, forward and up non-zero and not parallel. */
fg_result fg_listener_check(const fg_listener *pose);
void fg_listener_cell_write(fg_listener_cell *cell, const fg_listener *pose);
/* One attempt; returns false (leaving *pose and *serial alone) if a write
 * was in progress. [audio-thread] */
bool fg_listener_cell_try_read(const fg_listener_cell *cell, fg_listener *pose, unsigned *serial);
/* Retries until a consistent pose is read. [any-thread but audio] */
void fg_listener_cell_read(const fg_listener_cell *cell, fg_listener *pose, unsigned *serial);

void fg_listener_ears(const fg_listener *pose, unsigned channels, double spacing_m, fg_ears *out);

#endif
