/* Playing a discharge voice on the audio thread: adoption, and each
 * block's start: the motion look-ahead, a stop, continuous repeats. The
 * instances themselves are played by discharge_schedule.h. */
#include <math.h>

#include "discharge_schedule.h"

/* The repeat after one at after_s (0: the emission), or -1 when there is
 * none: the interval drawn stops advancing the clock (after 2^53 of them),
 * or it falls at or past the voice's duration, so that a voice ends with
 * its last sounding emission, not when the repeat it will never play was
 * due (an interval up to 10 s held a 0.05 s voice's slot for 5.4 s). */
static double next_repeat_s(fg_discharge_voice *v, double after_s)
{
    double next = after_s + fg_rng_range(&v->rng, v->repeat_min_s, v->repeat_max_s);
    if (!(next > after_s) || (v->duration_s > 0 && next >= v->duration_s))
        return -1.0;
    return next;
}

void fg_discharge_adopt(void *voice, const fg_block_context *block)
{
    fg_discharge_voice *v = voice;
    v->emit_frame = v->emit_time_s == FG_EMIT_NOW ? block->start_frame
                                                  : v->emit_time_s * block->cfg->sample_rate_hz;
    v->inst_count = 0;
    v->non_finite = false;
    for (uint32_t k = 0; k < v->strokes; k++)
        v->inst[v->inst_count++] = (fg_instance){
            .offset_s = v->stroke_offset_s[k], .last_frame = -INFINITY, .main_only = k > 0};
    v->next_repeat_s = v->continuous ? next_repeat_s(v, 0.0) : -1.0;
}

/* How far the listener strays from where the voice was prepared while
 * this block's waves can begin: at the block's pose when still; along the
 * trajectory from the block's start to a span after its end (a wave that
 * begins in the block arrives, at its centre, up to that much later)
 * while moving. */
#define WAVE_CENTRE_SPAN_S 0.1

static double look_ahead_s(const fg_block_context *ctx, const fg_discharge_voice *v, double end_s)
{
    const fg_engine_config *cfg = ctx->cfg;
    double moved;
    if (ctx->trajectory->still) {
        double d2 = 0;
        for (int k = 0; k < 3; k++)
            d2 += (ctx->position[k] - v->post_position[k]) * (ctx->position[k] - v->post_position[k]);
        moved = sqrt(d2);
    } else {
        moved = fg_trajectory_reach_m(ctx->trajectory, v->post_position,
                                      ctx->start_frame / cfg->sample_rate_hz,
                                      end_s + WAVE_CENTRE_SPAN_S);
    }
    /* an ear's delay from the head's centre lies in [-a, a pi / 2]: the
     * way around the head spans (1 + pi / 2) a < 1.3 spacing */
    double ears = fg_layout_ears(cfg) == 2 ? 1.3 * cfg->ear_spacing_m : 0.0;
    /* 1 % for the growth of T with distance, two samples for rounding */
    double m = 1.01 * (moved + ears) / cfg->speed_of_sound_m_s + 2.0 / cfg->sample_rate_hz;
    return m < cfg->max_lookahead_s ? m : cfg->max_lookahead_s;
}

/* The repeats due before the block's end. The loop draws at most block
 * length / FG_REPEAT_MIN_S + 1 intervals (fg_engine_post refuses shorter
 * ones), and ends where next_repeat_s ends the repeats. A repeat finds no
 * instance slot, or a block
 * whose work is already spent: it is skipped and counted. */
static void spawn_repeats(fg_discharge_voice *v, const fg_discharge_block *vb)
{
    double first_start = v->events[0].start_s;
    while (v->next_repeat_s >= 0 && v->next_repeat_s + first_start - vb->margin_s <= vb->end_s) {
        if (v->inst_count < FG_MAX_INSTANCES && *vb->ctx->work_left > 0)
            v->inst[v->inst_count++] =
                (fg_instance){.offset_s = v->next_repeat_s, .last_frame = -INFINITY};
        else
            fg_count(&vb->ctx->counters->skipped_repeats, 1);
        v->next_repeat_s = next_repeat_s(v, v->next_repeat_s);
    }
}

void fg_discharge_begin_block(fg_discharge_voice *v, bool stopping, const fg_block_context *ctx,
                              fg_discharge_block *vb)
{
    const double fs = ctx->cfg->sample_rate_hz;
    *vb = (fg_discharge_block){
        .ctx = ctx,
        .origin_frame = v->emit_frame - ctx->start_frame,
        .end_s = (ctx->start_frame + ctx->frames - v->emit_frame) / fs,
        .margin_s = look_ahead_s(ctx, v, (ctx->start_frame + ctx->frames) / fs),
        .moving = !ctx->trajectory->still,
    };
    if (stopping) {
        /* emissions that have not begun by this block's start never will;
         * the waves of one that did join (a listener within the look-ahead
         * of the source) were written ahead */
        double start_s = vb->end_s - ctx->frames / fs;
        for (uint32_t i = 0; i < v->inst_count;) {
            if (v->inst[i].offset_s > start_s) {
                if (v->model->writes_ahead &&
                    fg_instance_sounds_ahead(&v->inst[i], ctx->start_frame))
                    *ctx->restart = true;
                v->inst[i] = v->inst[--v->inst_count];
            } else {
                i++;
            }
        }
        v->next_repeat_s = -1.0;
    }
    if (v->continuous)
        spawn_repeats(v, vb);
}
