/* The lock-step gate. Its mutex is taken by the audio thread only in
 * lock-step mode, where it writes a file and is no real-time thread; the
 * paced (null) device never touches it. */
#include <math.h>

#include "run_gate.h"

uint64_t run_tick_at(const run_ctx *run, uint64_t frames)
{
    return (uint64_t)floor((double)frames * run->opt.frame_hz / run->rate_hz);
}

int run_gate_init(run_gate *g)
{
    *g = (run_gate){0};
    if (pthread_mutex_init(&g->lock, NULL) != 0)
        return -1;
    if (pthread_cond_init(&g->changed, NULL) != 0) {
        pthread_mutex_destroy(&g->lock);
        return -1;
    }
    return 0;
}

void run_gate_deinit(run_gate *g)
{
    pthread_cond_destroy(&g->changed);
    pthread_mutex_destroy(&g->lock);
}

void run_stop(run_ctx *run)
{
    /* under the lock, so a waiter cannot miss it between check and wait */
    pthread_mutex_lock(&run->gate.lock);
    atomic_store(&run->stop, true);
    pthread_cond_broadcast(&run->gate.changed);
    pthread_mutex_unlock(&run->gate.lock);
}

bool run_stopping(run_ctx *run)
{
    return atomic_load(&run->stop);
}

void run_wait_engine_past(run_ctx *run, uint64_t frames)
{
    if (run->paced) {
        uint64_t t = monotonic_now_ns();
        while (fg_engine_frames(run->engine) <= frames && !run_stopping(run)) {
            t += RUN_SIM_POLL_NS;
            monotonic_sleep_until_ns(t);
        }
        return;
    }
    run_gate *g = &run->gate;
    pthread_mutex_lock(&g->lock);
    while (g->engine_frames <= frames && !atomic_load(&run->stop))
        pthread_cond_wait(&g->changed, &g->lock);
    pthread_mutex_unlock(&g->lock);
}

static void publish(run_ctx *run, uint64_t *field, uint64_t value, bool *flag)
{
    if (run->paced)
        return;
    pthread_mutex_lock(&run->gate.lock);
    *field = value;
    if (flag)
        *flag = true;
    pthread_cond_broadcast(&run->gate.changed);
    pthread_mutex_unlock(&run->gate.lock);
}

void run_publish_sim(run_ctx *run, uint64_t frames)
{
    /* stored one past, so that 0 means "nothing posted yet" */
    publish(run, &run->gate.sim_frames, frames == UINT64_MAX ? frames : frames + 1, NULL);
}

void run_publish_tick(run_ctx *run, uint64_t tick)
{
    publish(run, &run->gate.frame_tick, tick, &run->gate.frame_started);
}

void run_publish_engine(run_ctx *run, uint64_t frames)
{
    publish(run, &run->gate.engine_frames, frames, NULL);
}

void run_wait_pose(run_ctx *run, uint64_t frames)
{
    if (run->paced)
        return;
    run_gate *g = &run->gate;
    uint64_t tick = run_tick_at(run, frames);
    pthread_mutex_lock(&g->lock);
    while (!atomic_load(&run->stop) && (!g->frame_started || g->frame_tick < tick))
        pthread_cond_wait(&g->changed, &g->lock);
    pthread_mutex_unlock(&g->lock);
}

bool run_wait_inputs(run_ctx *run, uint64_t frames)
{
    run_gate *g = &run->gate;
    uint64_t tick = run_tick_at(run, frames);
    pthread_mutex_lock(&g->lock);
    while (!atomic_load(&run->stop) &&
           (g->sim_frames <= frames || !g->frame_started || g->frame_tick < tick))
        pthread_cond_wait(&g->changed, &g->lock);
    bool go = !atomic_load(&run->stop);
    pthread_mutex_unlock(&g->lock);
    return go;
}
