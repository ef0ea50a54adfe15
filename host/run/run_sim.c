/* The sim thread: builds each discharge's tree ahead of its time (the
 * generators run here), posts it when the engine clock reaches its time
 * with that time as its emit time, and collects finished voices.
 *
 * A discharge's tree is built as soon as the previous one is posted, so the
 * path between the event and its sound is the poll, fg_engine_post and the
 * wait for the next block: "late" sound is what a source closer than that
 * path times c loses. A post refused for a full pool or queue is retried
 * after the next block's collect, for RUN_RETRY_LIMIT_S, then dropped; both
 * are counted in the report.
 *
 * The fires (posted by run.c) are fed here too: each pass publishes the
 * moving ones' poses up to a tick past the coming block and pushes every
 * stream as far as its ring takes; the sim thread is done once every
 * discharge is posted or dropped and every fire's voice is over. */
#include <stdio.h>

#include "run_gate.h"

static bool refused_for_room(fg_result r)
{
    return r == FG_ERR_POOL_FULL || r == FG_ERR_QUEUE_FULL;
}

/* Posts the discharges due at engine frame now; *next is the first of
 * run->order not yet posted or dropped. Returns -1 on an error that ends the
 * run (message in run->sim_error). */
static int post_due(run_ctx *run, uint64_t now, size_t *next)
{
    scene *s = run->s;
    for (; *next < s->discharge_count; ++*next) {
        size_t i = run->order[*next];
        if (scene_build_discharge(s, i, run->sim_error, sizeof run->sim_error) != 0) {
            run->sim_error_in_scene = true;
            return -1;
        }
        const scene_discharge *d = &s->discharges[i];
        /* at the run's end nothing more is rendered: posting would only
         * race the audio thread's stop */
        if ((double)now < d->post.emit_time_s * run->rate_hz || now >= run->limit_frames)
            return 0;
        run_wait_pose(run, now);
        uint64_t t0 = monotonic_now_ns();
        fg_result r = fg_engine_post(run->engine, &d->post, NULL);
        run_hist_add(&run->post_call, (double)(monotonic_now_ns() - t0) * 1e-9);
        if (r == FG_OK) {
            size_t k = run->posts++;
            run->post_frame[k] = now;
            run->post_ns[k] = t0;
            run->post_event_s[k] = d->post.emit_time_s;
        } else if (refused_for_room(r)) {
            run->refused++;
            if ((double)now / run->rate_hz - d->post.emit_time_s <= RUN_RETRY_LIMIT_S)
                return 0; /* after the next block's collect */
            run->dropped++;
        } else {
            snprintf(run->sim_error, sizeof run->sim_error,
                     "discharges[%zu]: the engine refused it: %s", i, fg_result_str(r));
            return -1;
        }
    }
    return 0;
}

/* Publishes the fires' poses at the 90 Hz ticks up to RUN_POSE_LEAD_TICKS
 * past the block starting at engine frame now, then pushes their sound.
 * Returns -1 on an error that ends the run (message in run->sim_error). */
static int feed_fires(run_ctx *run, uint64_t now)
{
    double period = 1.0 / run->opt.frame_hz;
    double until = (double)(now + run->block_frames) / run->rate_hz + RUN_POSE_LEAD_TICKS * period;
    return scene_fire_job_follow(&run->fires, run->engine, until, period, &run->fire_pose_tick,
                                 run->sim_error, sizeof run->sim_error) == FG_OK
               ? 0
               : -1;
}

void *run_sim_thread(void *arg)
{
    run_ctx *run = arg;
    size_t next = 0;
    bool done = false;
    while (!run_stopping(run)) {
        uint64_t now = fg_engine_frames(run->engine);
        fg_engine_collect(run->engine);
        if (!done) {
            if (post_due(run, now, &next) != 0 || feed_fires(run, now) != 0) {
                run_stop(run);
                break;
            }
            done = next == run->s->discharge_count && scene_fire_job_over(&run->fires);
            if (done)
                atomic_store(&run->sim_done, true);
            run_publish_sim(run, done ? UINT64_MAX : now);
        }
        run_wait_engine_past(run, now);
    }
    fg_engine_collect(run->engine); /* what the last blocks finished */
    return NULL;
}
