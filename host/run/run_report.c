/* fulgur run's JSON report, built with cJSON after the threads are joined.
 * Times are microseconds (callback, post call) or milliseconds (latency,
 * jitter), named in each key. */
#include <math.h>
#include <stdlib.h>

#include <cjson/cJSON.h>

#include "run.h"

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The q-quantile of v[0..n) by rank (sorts v); 0 when empty. */
static double quantile(double *v, size_t n, double q)
{
    if (n == 0)
        return 0;
    qsort(v, n, sizeof *v, by_value);
    size_t rank = (size_t)ceil(q * (double)n);
    return v[rank ? rank - 1 : 0];
}

static cJSON *spread(cJSON *parent, const char *key, double p50, double p99, double max)
{
    cJSON *o = cJSON_AddObjectToObject(parent, key);
    cJSON_AddNumberToObject(o, "p50", p50);
    cJSON_AddNumberToObject(o, "p99", p99);
    cJSON_AddNumberToObject(o, "max", max);
    return o;
}

/* p50/p99/max of a histogram, scaled (1e6: microseconds, 1e3: ms). */
static cJSON *hist_spread(cJSON *parent, const char *key, const run_hist *h, double scale)
{
    return spread(parent, key, run_hist_quantile(h, 0.5) * scale,
                  run_hist_quantile(h, 0.99) * scale, h->max_s * scale);
}

static void add_callback(cJSON *root, const run_ctx *run)
{
    const run_hist *h = &run->callback;
    cJSON *cb = cJSON_AddObjectToObject(root, "callback");
    double budget_s = run->block_frames / run->rate_hz;
    cJSON_AddNumberToObject(cb, "budget_us", budget_s * 1e6);
    cJSON_AddNumberToObject(cb, "blocks", (double)h->count);
    hist_spread(cb, "time_us", h, 1e6);
    cJSON_AddNumberToObject(cb, "mean_us", h->count ? h->sum_s / (double)h->count * 1e6 : 0);
    cJSON_AddNumberToObject(cb, "over_budget", (double)run->over_budget);
    cJSON_AddNumberToObject(cb, "over_half_budget", (double)run->over_half_budget);
    /* octave bins in microseconds: [0, 1), [1, 2), [2, 4), ... the last open */
    cJSON *bins = cJSON_AddArrayToObject(cb, "histogram");
    double lo = 0, hi = 1;
    for (;;) {
        bool last = hi * 1e-6 > h->max_s;
        cJSON *bin = cJSON_CreateObject();
        cJSON_AddNumberToObject(bin, "from_us", lo);
        if (last)
            cJSON_AddNullToObject(bin, "to_us");
        else
            cJSON_AddNumberToObject(bin, "to_us", hi);
        cJSON_AddNumberToObject(bin, "count",
                                (double)run_hist_count_between(h, lo * 1e-6,
                                                               last ? INFINITY : hi * 1e-6));
        cJSON_AddItemToArray(bins, bin);
        if (last)
            break;
        lo = hi;
        hi *= 2;
    }
}

/* Post to adoption, per discharge posted and adopted: blocks between the
 * engine clock the sim thread read and the adopting block's start; wall
 * time from the post call to that block's render call; and the lag of the
 * adopting block behind the discharge's own time, which sets the distance
 * inside which its first sound is late. */
static void add_adoption(cJSON *root, const run_ctx *run)
{
    size_t n = run->posts < run->adopted ? run->posts : (size_t)run->adopted;
    double *blocks = malloc((n ? n : 1) * sizeof *blocks);
    double *ms = malloc((n ? n : 1) * sizeof *ms);
    double max_lag_s = 0;
    for (size_t k = 0; blocks && ms && k < n; k++) {
        blocks[k] = (double)((run->adopt_frame[k] - run->post_frame[k]) / run->block_frames);
        ms[k] = (double)(int64_t)(run->adopt_ns[k] - run->post_ns[k]) * 1e-6;
        double lag_s = (double)run->adopt_frame[k] / run->rate_hz - run->post_event_s[k];
        max_lag_s = fmax(max_lag_s, lag_s);
    }
    cJSON *a = cJSON_AddObjectToObject(root, "adoption");
    cJSON_AddNumberToObject(a, "count", (double)n);
    if (blocks && ms) {
        /* quantile sorts: the maximum is read after */
        double b50 = quantile(blocks, n, 0.5), b99 = quantile(blocks, n, 0.99);
        double m50 = quantile(ms, n, 0.5), m99 = quantile(ms, n, 0.99);
        spread(a, "latency_blocks", b50, b99, n ? blocks[n - 1] : 0);
        spread(a, "latency_ms", m50, m99, n ? ms[n - 1] : 0);
    }
    free(blocks);
    free(ms);
    fg_engine_config cfg;
    fg_engine_get_config(run->engine, &cfg);
    cJSON_AddNumberToObject(a, "event_lag_max_ms", max_lag_s * 1e3);
    /* the ear farthest from the head's centre, the head's own sway */
    double head_m = cfg.ear_spacing_m / 2 + (run->s->pose_count == 1 ? RUN_SWAY_M : 0);
    cJSON_AddNumberToObject(a, "safe_distance_m", max_lag_s * cfg.speed_of_sound_m_s + head_m);
}

char *run_report_json(const run_ctx *run, double wall_s)
{
    cJSON *root = cJSON_CreateObject();
    if (!root)
        return NULL;
    fg_engine_report st;
    fg_engine_get_report(run->engine, &st);
    cJSON_AddStringToObject(root, "scene", run->opt.scene_path);
    cJSON_AddStringToObject(root, "audio", audio_driver_name(run->opt.audio.kind));
    if (run->live_description[0]) {
        cJSON *live = cJSON_AddObjectToObject(root, "live");
        cJSON_AddStringToObject(live, "device", run->live_description);
        cJSON_AddNumberToObject(live, "xruns", (double)run->live_xruns);
    }
    cJSON_AddBoolToObject(root, "paced", run->paced);
    cJSON_AddNumberToObject(root, "sample_rate_hz", run->rate_hz);
    cJSON_AddNumberToObject(root, "block_frames", run->block_frames);
    cJSON *lo = cJSON_AddObjectToObject(root, "layout");
    cJSON_AddStringToObject(lo, "type", scene_layout_name(run->s->layout));
    if (run->s->layout == FG_LAYOUT_AMBISONICS)
        cJSON_AddNumberToObject(lo, "order", run->s->ambisonic_order);
    cJSON_AddNumberToObject(lo, "channels", run->s->channels);
    cJSON_AddNumberToObject(root, "seconds", (double)run->frames_out / run->rate_hz);
    cJSON_AddNumberToObject(root, "wall_s", wall_s);
    add_callback(root, run);
    hist_spread(root, "post_call_us", &run->post_call, 1e6);
    add_adoption(root, run);
    cJSON *late = cJSON_AddObjectToObject(root, "late");
    cJSON_AddNumberToObject(late, "events", (double)st.late_events);
    cJSON_AddNumberToObject(late, "samples", (double)st.late_samples);
    cJSON *fl = cJSON_AddObjectToObject(root, "frame_loop");
    cJSON_AddNumberToObject(fl, "rate_hz", run->opt.frame_hz);
    cJSON_AddNumberToObject(fl, "frames", (double)run->frames_set);
    if (run->paced)
        hist_spread(fl, "jitter_ms", &run->jitter, 1e3);
    else
        cJSON_AddNullToObject(fl, "jitter_ms"); /* ticks follow the engine clock */
    /* the aero objects and fires were posted (and adopted) first, all of them */
    const double aeros = (double)run->s->aero_count;
    const double fires = (double)run->s->fire_count;
    cJSON *d = cJSON_AddObjectToObject(root, "discharges");
    cJSON_AddNumberToObject(d, "scheduled", (double)run->s->discharge_count);
    cJSON_AddNumberToObject(d, "posted", (double)st.posted - aeros - fires);
    cJSON_AddNumberToObject(d, "refused_posts", (double)run->refused);
    cJSON_AddNumberToObject(d, "dropped", (double)run->dropped);
    cJSON_AddNumberToObject(d, "adopted", (double)run->adopted);
    cJSON_AddNumberToObject(d, "rendered", (double)st.finished);
    cJSON_AddNumberToObject(d, "collected", (double)st.collected);
    cJSON_AddNumberToObject(d, "skipped_repeats", (double)st.skipped_repeats);
    cJSON *ao = cJSON_AddObjectToObject(root, "aero_objects");
    cJSON_AddNumberToObject(ao, "count", aeros);
    cJSON_AddNumberToObject(ao, "poses_set", (double)run->aero_poses_set);
    cJSON *fi = cJSON_AddObjectToObject(root, "fires");
    cJSON_AddNumberToObject(fi, "count", fires);
    cJSON_AddNumberToObject(fi, "underrun_frames", (double)run->fires.underrun_frames);
    cJSON *e = cJSON_AddObjectToObject(root, "engine");
    cJSON_AddNumberToObject(e, "blocks", (double)st.blocks);
    cJSON_AddNumberToObject(e, "blocks_over_budget", (double)st.blocks_over_budget);
    cJSON_AddNumberToObject(e, "dropped_posts", (double)st.dropped_posts);
    cJSON *work = cJSON_AddObjectToObject(e, "work");
    cJSON_AddNumberToObject(work, "units", (double)st.work_units);
    cJSON_AddNumberToObject(work, "peak_block_units", (double)st.peak_block_work);
    cJSON_AddNumberToObject(work, "skipped_units", (double)st.skipped_work);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}
