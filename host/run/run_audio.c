/* The audio thread: a device pulling fg_engine_render one block at a time.
 * Paced (null device): block k starts at the absolute deadline
 * start + k * period, as a sound card's interrupt would; a block that ends
 * after the next deadline makes the next one start at once (catching up,
 * as a device with a deeper buffer would). This path takes no lock and
 * never allocates or prints. Lock-step (wav, raw): each block waits for its
 * inputs (run_gate.h), then goes to the driver. */
#include "run_gate.h"

/* Notes the voices adopted by the block that started at frames at wall
 * time t_ns: adoption is in post order (one ring), so the k-th adopted is
 * the k-th posted. */
static void note_adoptions(run_ctx *run, uint64_t frames, uint64_t t_ns)
{
    fg_engine_report stats;
    fg_engine_get_report(run->engine, &stats);
    for (; run->adopted < stats.adopted; run->adopted++) {
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

void *run_audio_thread(void *arg)
{
    run_ctx *run = arg;
    double period_s = run->block_frames / run->rate_hz;
    uint64_t frames = 0;
    for (uint64_t block = 0; frames < run->limit_frames; block++) {
        uint64_t left = run->limit_frames - frames;
        uint32_t n = left < run->block_frames ? (uint32_t)left : run->block_frames;
        if (run->paced)
            monotonic_sleep_until_ns(monotonic_deadline_ns(run->start_ns, block, period_s));
        else if (!run_wait_inputs(run, frames))
            break;
        if (run_stopping(run))
            break;
        uint64_t t0 = monotonic_now_ns();
        fg_result r = fg_engine_render(run->engine, run->planes, n);
        double took_s = (double)(monotonic_now_ns() - t0) * 1e-9, budget_s = n / run->rate_hz;
        if (r != FG_OK) {
            run->render_result = r; /* reported by the main thread */
            break;
        }
        run_hist_add(&run->callback, took_s);
        run->over_budget += took_s > budget_s;
        run->over_half_budget += took_s > 0.5 * budget_s;
        note_adoptions(run, frames, t0);
        frames += n;
        run->frames_out = frames;
        run_publish_engine(run, frames);
        if (audio_driver_write(&run->driver, run->planes, n, run->audio_error,
                               sizeof run->audio_error) != 0)
            break;
        if (run->until_done && all_sounded(run))
            break;
    }
    run_stop(run);
    return NULL;
}
