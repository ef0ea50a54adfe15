/* The viewer's audio thread: fg_engine_render one block at a time into
 * the audio drivers (common/audio_driver.h), each call's duration kept for
 * the overlay (view_overlay.c). Window: paced by the monotonic clock to
 * absolute deadlines one block period apart, as run paces its null device,
 * whatever the driver (a player reading raw:- wants real time).
 * Headless: lock-step, rendering up to the frame thread's audio_target.
 * Paced, the loop takes no lock; headless, the gate's lock (view_gate.c)
 * is taken between blocks to wait for the target and to announce progress. */
#include <stdio.h>

#include "common/clock.h"
#include "common/commands.h"
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

void view_live_process(void *user, float *const *planes, uint32_t frames)
{
    view *v = user;
    uint32_t n = 0;
    if (!atomic_load(&v->stop)) {
        if (fg_engine_render(v->engine, planes, frames) == FG_OK) {
            n = frames;
            float gain = (float)v->s->gain;
            for (uint32_t ch = 0; ch < v->s->channels; ch++)
                for (uint32_t i = 0; i < n; i++)
                    planes[ch][i] *= gain;
            atomic_store(&v->audio_done, atomic_load(&v->audio_done) + n);
        } else {
            v->render_result = FG_ERR_BLOCK_SIZE; /* read after the device is closed */
            atomic_store(&v->stop, true);
        }
    }
    for (uint32_t ch = 0; ch < v->s->channels; ch++)
        for (uint32_t i = n; i < frames; i++)
            planes[ch][i] = 0;
}

static live_result try_open(view *v, live_kind kind, const char *target, double rate_hz,
                            char *err, size_t err_size)
{
    live_config lc = {.kind = kind, .target = target, .client_name = "fulgur-view",
                      .channels = v->s->channels, .rate_hz = rate_hz,
                      .block_frames = v->block_frames, .max_chunk_frames = v->block_frames,
                      .process = view_live_process, .user = v};
    return live_audio_open(&lc, &v->live, err, err_size);
}

int view_open_live(view *v, double *rate_hz, int *rc, char *err, size_t err_size)
{
    const audio_output *out = &v->opt.audio;
    *rc = CLI_USAGE;
    if (!audio_output_is_live(out))
        return 0;
    if (headless(v)) {
        if (out->kind == AUDIO_DRIVER_AUTO)
            return 0;
        snprintf(err, err_size, "--audio %s plays in real time: it needs --gl window (headless "
                 "runs lock-step: use --audio wav:FILE)", audio_driver_name(out->kind));
        return -1;
    }
    live_result r;
    if (out->kind != AUDIO_DRIVER_AUTO) {
        r = try_open(v, out->kind == AUDIO_DRIVER_JACK ? LIVE_JACK : LIVE_PORTAUDIO,
                     out->wav_path, *rate_hz, err, err_size);
        if (r != LIVE_OK) {
            *rc = r == LIVE_ABSENT ? CLI_USAGE : CLI_RUNTIME;
            return -1;
        }
    } else {
        char why_jack[256], why_pa[256];
        r = try_open(v, LIVE_JACK, NULL, *rate_hz, why_jack, sizeof why_jack);
        if (r != LIVE_OK)
            r = try_open(v, LIVE_PORTAUDIO, NULL, *rate_hz, why_pa, sizeof why_pa);
        if (r != LIVE_OK) {
            fprintf(stderr, "fulgur view: no live audio device, the sound goes nowhere "
                            "(--audio wav:FILE keeps it): %s; %s\n", why_jack, why_pa);
            return 0;
        }
    }
    *rate_hz = live_audio_rate_hz(v->live);
    fprintf(stderr, "fulgur view: playing to %s\n", live_audio_describe(v->live));
    return 0;
}
