/* The viewer's audio thread: fg_engine_render one block at a time into
 * the audio drivers (common/audio_driver.h). Window: paced by the monotonic
 * clock to absolute deadlines one block period apart, as run paces its null
 * device, whatever the driver (a player reading raw:- wants real time).
 * Headless: lock-step, rendering up to the frame thread's audio_target.
 * Paced, the loop takes no lock; headless, the gate's lock is taken between
 * blocks to wait for the target and to announce progress. */
#include "common/clock.h"
#include "view.h"

static bool headless(const view *v)
{
    return v->opt.backend != FGG_BACKEND_WINDOW;
}

/* Headless: waits until frames is below the target; false on stop. */
static bool wait_target(view *v, uint64_t frames)
{
    pthread_mutex_lock(&v->lock);
    while (v->audio_target <= frames && !atomic_load(&v->stop))
        pthread_cond_wait(&v->changed, &v->lock);
    bool go = !atomic_load(&v->stop);
    pthread_mutex_unlock(&v->lock);
    return go;
}

void *view_audio_thread(void *arg)
{
    view *v = arg;
    double period_s = v->block_frames / v->rate_hz;
    uint64_t frames = 0, start_ns = monotonic_now_ns();
    for (uint64_t block = 0; !atomic_load(&v->stop); block++) {
        uint32_t n = v->block_frames;
        if (headless(v)) {
            if (!wait_target(v, frames))
                break;
            pthread_mutex_lock(&v->lock);
            uint64_t left = v->audio_target - frames;
            pthread_mutex_unlock(&v->lock);
            n = left < n ? (uint32_t)left : n;
        } else {
            monotonic_sleep_until_ns(monotonic_deadline_ns(start_ns, block, period_s));
        }
        fg_result r = fg_engine_render(v->engine, v->planes, n);
        if (r != FG_OK) {
            v->render_result = r; /* read by the frame thread after the join */
            break;
        }
        if (audio_driver_write(&v->driver, v->planes, n, v->audio_error, sizeof v->audio_error))
            break;
        frames += n;
        atomic_store(&v->audio_done, frames);
        if (headless(v)) { /* the frame thread may wait for the end */
            pthread_mutex_lock(&v->lock);
            pthread_cond_broadcast(&v->changed);
            pthread_mutex_unlock(&v->lock);
        }
    }
    pthread_mutex_lock(&v->lock);
    atomic_store(&v->stop, true);
    pthread_cond_broadcast(&v->changed);
    pthread_mutex_unlock(&v->lock);
    return NULL;
}
