/* Playing a voice on the audio thread: its instances (strokes, repeats),
 * the window of events that can sound in this block, and lateness.
 *
 * Events are sorted by their earliest start at the pose of the post. A
 * moving listener shifts any start by at most (displacement + ear spacing)
 * / c, so an event joins an instance's window once its post-time start,
 * less that look-ahead, falls before the block's end. Events leave the
 * window in order once their waveform has ended for every ear. */
#include <math.h>

#include "core/engine_internal.h"

void fg_voice_adopt(fg_engine *e, fg_voice *v, double start_frame)
{
    v->emit_frame =
        v->emit_time_s == FG_EMIT_NOW ? start_frame : v->emit_time_s * e->cfg.sample_rate_hz;
    v->inst_count = 0;
    for (uint32_t k = 0; k < v->strokes; k++)
        v->inst[v->inst_count++] = (fg_instance){v->stroke_offset_s[k], 0, 0, k > 0};
    v->next_repeat_s =
        v->continuous ? fg_rng_range(&v->rng, v->repeat_min_s, v->repeat_max_s) : -1.0;
}

static double look_ahead_s(const fg_engine *e, const fg_voice *v, const double position[3])
{
    double d2 = 0;
    for (int k = 0; k < 3; k++)
        d2 += (position[k] - v->post_position[k]) * (position[k] - v->post_position[k]);
    double ears = e->cfg.channels == 2 ? e->cfg.ear_spacing_m : 0.0;
    /* 1 % for the growth of T with distance, two samples for rounding */
    double m = 1.01 * (sqrt(d2) + ears) / e->cfg.speed_of_sound_m_s + 2.0 / e->cfg.sample_rate_hz;
    return m < e->cfg.max_lookahead_s ? m : e->cfg.max_lookahead_s;
}

static fg_event *instance_event(fg_voice *v, const fg_instance *in, uint32_t k)
{
    return &v->events[in->main_only ? v->main_index[k] : k];
}

typedef struct voice_block {
    const fg_block_context *ctx;
    double origin_frame;   /* voice emission relative to the block's first sample */
    double end_s;          /* block end, seconds after the voice's emission */
    double margin_s;
} voice_block;

/* Adds ear ch of event ev, played by instance in, to the buses, splitting
 * it with the head-shadowed twin bus. Returns its status and its first and
 * last sample relative to the block. */
static fg_wave_status add_event(fg_engine *e, const fg_voice *v, const fg_event *ev,
                           const fg_instance *in, const voice_block *vb, unsigned ch, long *first,
                           long *last)
{
    const fg_block_context *ctx = vb->ctx;
    const double fs = e->cfg.sample_rate_hz;
    const unsigned n = ctx->frames;
    unsigned bus = ev->bus[ch];
    double shadow = ev->shadow[ch];
    /* shares below 2 % go whole to one side */
    double share[2] = {shadow < 0.02 ? 1.0 : shadow > 0.98 ? 0.0 : 1.0 - shadow,
                       shadow < 0.02 ? 0.0 : shadow > 0.98 ? 1.0 : shadow};
    if (v->model == FG_MODEL_ABE) {
        fg_abe_wave w = ev->abe[ch];
        w.arrival_s += in->offset_s + vb->origin_frame / fs;
        int64_t a, b;
        fg_abe_wave_span(&w, fs, &a, &b);
        *first = (long)a;
        *last = (long)b;
        if (b < 0)
            return FG_WAVE_DONE;
        if (a >= (int64_t)n)
            return FG_WAVE_PENDING;
        double peak = w.peak_pa;
        for (int k = 0; k < 2; k++) {
            if (share[k] == 0.0)
                continue;
            w.peak_pa = peak * share[k];
            fg_abe_wave_render(&w, fs, 0, fg_bus_pre(ctx->buses, bus + k * FG_BUS_PLAIN, ch), n);
        }
        return FG_WAVE_SOUNDING;
    }
    fg_wm_event we = {
        .shape = ev->shape[ch],
        .center = vb->origin_frame + (in->offset_s + ev->center_s[ch]) * fs,
        .width = fs * ev->half_len_m / e->cfg.speed_of_sound_m_s,
    };
    fg_wm_event_span(&we, first, last);
    fg_wave_status status = FG_WAVE_DONE;
    for (int k = 0; k < 2; k++) {
        if (share[k] == 0.0)
            continue;
        we.shape.b = ev->shape[ch].b * share[k];
        status = fg_wm_accum_add(&ctx->buses->bus[bus + k * FG_BUS_PLAIN].accum[ch], &we);
    }
    return status;
}

/* Renders one instance; returns true once all its events are done. */
static bool render_instance(fg_engine *e, fg_voice *v, fg_instance *in, const voice_block *vb)
{
    const fg_block_context *ctx = vb->ctx;
    const uint32_t n = in->main_only ? v->main_count : v->event_count;
    const uint32_t first_new = in->hi;
    while (in->hi < n &&
           instance_event(v, in, in->hi)->start_s + in->offset_s - vb->margin_s <= vb->end_s)
        in->hi++;

    uint64_t late = 0, lost = 0;
    for (uint32_t k = in->lo; k < in->hi; k++) {
        fg_event *ev = instance_event(v, in, k);
        if (ev->serial != ctx->serial) {
            for (unsigned ch = 0; ch < ctx->ears->count; ch++)
                fg_event_geometry(e, v, ev, ctx->ears, (int)ch);
            ev->serial = ctx->serial;
        }
        bool done = true;
        long lost_here = 0;
        for (unsigned ch = 0; ch < ctx->ears->count; ch++) {
            long a, b;
            if (add_event(e, v, ev, in, vb, ch, &a, &b) != FG_WAVE_DONE)
                done = false;
            long missed = k >= first_new && a < 0 ? (b < 0 ? b : -1) - a + 1 : 0;
            if (missed > lost_here)
                lost_here = missed;
        }
        if (lost_here > 0) {
            late++;
            lost += (uint64_t)lost_here;
        }
        if (done && k == in->lo)
            in->lo++;
    }
    if (late) {
        atomic_fetch_add_explicit(&e->counters.late_events, late, memory_order_relaxed);
        atomic_fetch_add_explicit(&e->counters.late_samples, lost, memory_order_relaxed);
    }
    return in->lo == n;
}

static void spawn_repeats(fg_engine *e, fg_voice *v, const voice_block *vb)
{
    double first_start = v->events[0].start_s;
    while (v->next_repeat_s >= 0 && v->next_repeat_s + first_start - vb->margin_s <= vb->end_s) {
        if (v->duration_s > 0 && v->next_repeat_s >= v->duration_s) {
            v->next_repeat_s = -1.0;
            break;
        }
        if (v->inst_count < FG_MAX_INSTANCES)
            v->inst[v->inst_count++] = (fg_instance){v->next_repeat_s, 0, 0, false};
        else
            atomic_fetch_add_explicit(&e->counters.skipped_repeats, 1, memory_order_relaxed);
        v->next_repeat_s += fg_rng_range(&v->rng, v->repeat_min_s, v->repeat_max_s);
    }
}

bool fg_voice_render(fg_engine *e, fg_voice *v, const fg_block_context *ctx)
{
    const double fs = e->cfg.sample_rate_hz;
    voice_block vb = {
        .ctx = ctx,
        .origin_frame = v->emit_frame - ctx->start_frame,
        .end_s = (ctx->start_frame + ctx->frames - v->emit_frame) / fs,
        .margin_s = look_ahead_s(e, v, ctx->position),
    };
    if (atomic_load_explicit(&v->stop, memory_order_acquire)) {
        /* emissions that have not begun by this block's start never will */
        double start_s = vb.end_s - ctx->frames / fs;
        for (uint32_t i = 0; i < v->inst_count;) {
            if (v->inst[i].offset_s > start_s)
                v->inst[i] = v->inst[--v->inst_count];
            else
                i++;
        }
        v->next_repeat_s = -1.0;
    }
    if (v->continuous)
        spawn_repeats(e, v, &vb);
    for (uint32_t i = 0; i < v->inst_count;) {
        if (render_instance(e, v, &v->inst[i], &vb))
            v->inst[i] = v->inst[--v->inst_count];
        else
            i++;
    }
    return v->inst_count == 0 && v->next_repeat_s < 0;
}
