/* The lock-step gate between fulgur run's three threads, stopping them,
 * and the 90 Hz tick on the engine clock (see run.h). The clock itself is
 * common/clock.h. */
#ifndef HOST_RUN_RUN_GATE_H
#define HOST_RUN_RUN_GATE_H

#include "common/clock.h"
#include "run.h"

/* The 90 Hz tick in force at engine frame `frames`: floor(frames * fps / rate). */
uint64_t run_tick_at(const run_ctx *run, uint64_t frames);

int run_gate_init(run_gate *g);
void run_gate_deinit(run_gate *g);

/* Asks every thread to finish and wakes the waiting ones. [any-thread] */
void run_stop(run_ctx *run);
bool run_stopping(run_ctx *run);

/* [sim-thread], frame thread: returns once the engine clock is past
 * `frames`, or on stop. Lock-step: waits on the gate; paced: polls the
 * engine clock every RUN_SIM_POLL_NS. */
void run_wait_engine_past(run_ctx *run, uint64_t frames);

/* Lock-step announcements (no-ops when paced): the sim thread has posted
 * everything due at engine frame `frames` (UINT64_MAX: all of it); the frame
 * thread has set tick's pose; the audio thread has rendered up to frames. */
void run_publish_sim(run_ctx *run, uint64_t frames);
void run_publish_tick(run_ctx *run, uint64_t tick);
void run_publish_engine(run_ctx *run, uint64_t frames);

/* Lock-step audio thread: waits until the block starting at `frames` has
 * its posts and its pose. Returns false on stop. */
bool run_wait_inputs(run_ctx *run, uint64_t frames);

/* Lock-step sim thread, before it posts at engine frame `frames`: waits
 * until the frame thread has set the pose of the tick in force there, the
 * pose fg_engine_post places the discharge from (without the wait a post on
 * a tick's first block raced the new pose). No-op when paced. */
void run_wait_pose(run_ctx *run, uint64_t frames);

#endif
