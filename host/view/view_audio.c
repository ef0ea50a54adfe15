/* The viewer's audio thread: fg_engine_render one block at a time into
 * the audio drivers (common/audio_driver.h), each call's duration kept for
 * the overlay (view_overlay.c). Window: paced by the monotonic clock to
 * absolute deadlines one block period apart, as run paces its null device,
 * whatever the driver (a player reading raw:- wants real time).
 * Headless: lock-step, rendering up to the frame thread's audio_target.
 * Paced, the loop takes no lock; headless, the gate's lock (view_gate.c)
 * is taken between blocks to wait for the target and to announce progress. */
#include "common/clock.h"
#include "view.h"

static bool headless(const view *v)
{
    return v->opt.backend != FGG_BACKEND_WINDOW;
}

void *view_audio_thread(void *arg)
{
    view *v = arg;
    double period_s = v->block_frames / v->rate_hz;
    uint64_t frames = 0, start_ns = monotonic_now_ns();
    for (uint64_t block = 0; !atomic_load(&v->stop); block++) {
        uint32_t n = v->block_frames;
        if (headless(v)) {
            n = view_wait_target(v, frames, n);
            if (n == 0)
                break;
        } else {
            monotonic_sleep_until_ns(monotonic_deadline_ns(start_ns, block, period_s));
        }
        uint64_t t0 = monotonic_now_ns();
        fg_result r = fg_engine_render(v->engine, v->planes, n);
        uint64_t took_us = (monotonic_now_ns() - t0) / 1000;
        uint64_t k = atomic_load_explicit(&v->callbacks, memory_order_relaxed);
        atomic_store_explicit(&v->recent_us[k % VIEW_RECENT_CALLBACKS],
                              took_us > UINT32_MAX ? UINT32_MAX : (uint32_t)took_us,
                              memory_order_relaxed);
        atomic_store_explicit(&v->callbacks, k + 1, memory_order_release);
        if (r != FG_OK) {
            v->render_result = r; /* read by the frame thread after the join */
            break;
        }
        if (audio_driver_write(&v->driver, v->planes, n, v->audio_error, sizeof v->audio_error))
            break;
        frames += n;
        if (headless(v)) /* the frame thread may wait for the end */
            view_announce_audio(v, frames);
        else
            atomic_store(&v->audio_done, frames);
    }
    view_stop(v);
    return NULL;
}
