/* The audio thread: a device pulling fg_engine_render one block at a time,
 * or the live device's callback doing the same on the server's thread.
 * Paced (null device): block k starts at the absolute deadline
 * start + k * period, as a sound card's interrupt would; a block that ends
 * after the next deadline makes the next one start at once (catching up,
 * as a device with a deeper buffer would). This path takes no lock and
 * never allocates or prints. Lock-step (wav, raw): each block waits for its
 * inputs (run_gate.h), then goes to the driver. */
#include "run_gate.h"

/* Notes the discharges adopted by the block that started at frames at
 * wall time t_ns: adoption is in post order (one ring), the aero objects
 * and fires (posted before the threads started) first, so the k-th
 * discharge adopted is the k-th posted. */
static void note_adoptions(run_ctx *run, uint64_t frames, uint64_t t_ns)
{
    fg_engine_report stats;
    fg_engine_get_report(run->engine, &stats);
    const uint64_t first = run->s->aero_count + run->s->fire_count;
    uint64_t discharges = stats.adopted > first ? stats.adopted - first : 0;
    for (; run->adopted < discharges; run->adopted++) {
        if (run->adopted >= run->s->discharge_count)
            continue; /* cannot happen: one post per discharge */
        run->adopt_frame[run->adopted] = frames;
        run->adopt_ns[run->adopted] = t_ns;
    }
}

static bool all_sounded(run_ctx *run)
{
    if (!atomic_load(&run->sim_done))
        return false;
    fg_engine_report stats;
    fg_engine_get_report(run->engine, &stats);
    return stats.finished == stats.posted;
}

/* One block: render, measure, note adoptions, publish the clock. Returns
 * false when the render failed (run->render_result says why). */
static bool render_block(run_ctx *run, float *const *planes, uint32_t n)
{
    uint64_t t0 = monotonic_now_ns();
    fg_result r = fg_engine_render(run->engine, planes, n);
    double took_s = (double)(monotonic_now_ns() - t0) * 1e-9, budget_s = n / run->rate_hz;
    if (r != FG_OK) {
        run->render_result = r; /* reported by the main thread */
        return false;
    }
    run_hist_add(&run->callback, took_s);
    run->over_budget += took_s > budget_s;
    run->over_half_budget += took_s > 0.5 * budget_s;
    note_adoptions(run, run->frames_out, t0);
    run->frames_out += n;
    run_publish_engine(run, run->frames_out);
    return true;
}

void *run_audio_thread(void *arg)
{
    run_ctx *run = arg;
    double period_s = run->block_frames / run->rate_hz;
    for (uint64_t block = 0; run->frames_out < run->limit_frames; block++) {
        uint64_t left = run->limit_frames - run->frames_out;
        uint32_t n = left < run->block_frames ? (uint32_t)left : run->block_frames;
        if (run->paced)
            monotonic_sleep_until_ns(monotonic_deadline_ns(run->start_ns, block, period_s));
        else if (!run_wait_inputs(run, run->frames_out))
            break;
        if (run_stopping(run))
            break;
        if (!render_block(run, run->planes, n))
            break;
        if (audio_driver_write(&run->driver, run->planes, n, run->audio_error,
                               sizeof run->audio_error) != 0)
            break;
        if (run->until_done && all_sounded(run))
            break;
    }
    run_stop(run);
    return NULL;
}

void run_live_process(void *user, float *const *planes, uint32_t frames)
{
    run_ctx *run = user;
    uint32_t n = 0;
    if (!run_stopping(run) && run->frames_out < run->limit_frames) {
        uint64_t left = run->limit_frames - run->frames_out;
        n = left < frames ? (uint32_t)left : frames;
        float gain = (float)run->s->gain;
        if (render_block(run, planes, n)) {
            for (uint32_t ch = 0; ch < run->s->channels; ch++)
                for (uint32_t i = 0; i < n; i++)
                    planes[ch][i] *= gain;
        } else {
            n = 0;
        }
        /* the main thread sees it and stops the rest (run_stop locks) */
        if (n == 0 || run->frames_out >= run->limit_frames || (run->until_done && all_sounded(run)))
            atomic_store(&run->stop, true);
    }
    for (uint32_t ch = 0; ch < run->s->channels; ch++)
        for (uint32_t i = n; i < frames; i++)
            planes[ch][i] = 0;
}
