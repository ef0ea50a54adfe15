/* Playing a discharge voice's instances (strokes, repeats) in one block:
 * the window of events that can sound, lateness, and each event added to
 * the buses by the model's add function.
 *
 * Events are sorted by their earliest start at the pose of the post. A
 * moving listener shifts any start by at most (displacement + ear spacing)
 * / c, so an event joins an instance's window once its post-time start,
 * less that look-ahead, falls before the block's end. Events leave the
 * window in order once their waveform has ended for every ear; one that
 * has ended behind a longer one still sounding stays in the window, where
 * each ear costs the model's placing of its span (fg_discharge_place_fn),
 * not an add, and the unit of the work bound it always cost. A model that
 * writes ahead (the WM-wave's accumulators) adds a wave to the end of the
 * chunk (core/bus_internal.h) and visits it again only in the next chunk's
 * first block: a long wave costs about what a short one does.
 *
 * One implementation for both models, written once here and instantiated
 * by each model's render with its own add function (wm_model.c,
 * abe_model.c): the add is then a direct call the compiler can inline in
 * the per-event loop, the hottest of the audio thread. [audio-thread] */
#ifndef FULGUR_DISCHARGE_SCHEDULE_H
#define FULGUR_DISCHARGE_SCHEDULE_H

#include <math.h>

#include "discharge_internal.h"

/* Places an ear's wave of ev in the block as play's instance hears it:
 * writes *at and returns FG_WAVE_NON_FINITE when the wave is out of range
 * (at->first and last unspecified), FG_WAVE_DONE when it ended before the
 * block, so that its add would add nothing on any bus or channel, else
 * FG_WAVE_SOUNDING (the add tells a pending wave from a sounding one). An
 * ear that has ended then costs the few terms of its span, not the
 * layout's gains and an add per channel and bus. Exact because every
 * weight an add scales a wave by (a layout gain, the head shadow's alpha -
 * 1, a band's share) lies in [-1, 1]: a wave in range stays in range on
 * every bus. The model's path_units of a wave that has ended is 0, so its
 * price is the one unit (fg_discharge_price_ended). */
typedef fg_wave_status (*fg_discharge_place_fn)(const fg_event *ev, const fg_event_ear *ear,
                                                const fg_event_play *play, fg_wave_place *at);

/* Adds an ear's wave, placed at *at (FG_WAVE_SOUNDING from the place), to
 * the buses of play's channels (fg_discharge_model's add); returns its
 * status, the same on every channel. */
typedef fg_wave_status (*fg_discharge_add_fn)(const fg_event_ear *ear, const fg_event_play *play,
                                              const fg_wave_place *at);

/* One block of one voice, as its instances see it. */
typedef struct fg_discharge_block {
    const fg_block_context *ctx;
    double origin_frame;   /* voice emission relative to the block's first sample */
    double end_s;          /* block end, seconds after the voice's emission */
    double margin_s;       /* the motion look-ahead */
    bool moving;           /* the listener moves: each wave's ear is evaluated where it arrives */
} fg_discharge_block;

/* discharge_schedule.c: the block's start for the voice: the look-ahead,
 * a stop (emissions not yet begun are dropped), continuous repeats. */
void fg_discharge_begin_block(fg_discharge_voice *v, bool stopping, const fg_block_context *ctx,
                              fg_discharge_block *vb);

static inline fg_event *fg_instance_event(fg_discharge_voice *v, const fg_instance *in,
                                          uint32_t k)
{
    return &v->events[in->main_only ? v->main_index[k] : k];
}

/* Adds ear ch of an event, as that ear hears it, placed at *at (placed:
 * the place's status, not FG_WAVE_DONE), to the buses through play (the
 * instance's), on each output channel the layout sends it to with the
 * layout's gain (spatial/layout_internal.h), split between its two
 * distance bands: whole to each band's plain bus, and alpha - 1 of it to
 * the head-shadowed twin (spatial/spherical_head_internal.h). Its price
 * (one unit and the model's path_units for each bus and channel) is spent
 * from the block's work first: when it does not fit, nothing is added and
 * FG_WAVE_SKIPPED returned with the price in *units. Returns its status. */
static inline fg_wave_status fg_discharge_add_event(const fg_event_ear *ear, fg_event_play *play,
                                                    unsigned ch, const fg_block_context *ctx,
                                                    const fg_discharge_model *m,
                                                    fg_discharge_add_fn add,
                                                    fg_wave_status placed,
                                                    const fg_wave_place *at, uint64_t *units)
{
    const double dir[3] = {ear->dir[0], ear->dir[1], ear->dir[2]};
    double gain[FG_LAYOUT_CHANNELS_MAX];
    unsigned index[FG_LAYOUT_CHANNELS_MAX];
    const unsigned count = fg_layout_reach(play->cfg, ch, dir, index, gain);
    const double next = ear->band_w;
    for (unsigned k = 0; k < FG_PLAY_BUSES; k++)
        play->bus[k] = ear->bus + k / 2 + (k % 2) * FG_BUS_PLAIN;
    /* a channel of gain 0 gets nothing; the wave's status is that of the
     * first channel it reaches, the same on every one (stereo's ear and
     * ambisonics' W have gain 1; binaural's loudspeaker 0 mostly 0) */
    *units = 1;
    if (m->path_units) {
        uint64_t paths = 0;
        for (unsigned c = 0; c < count; c++)
            if (gain[c] != 0.0)
                paths += (1u + (ear->shadow != 0.0)) * (1u + (next != 0.0 && next != 1.0));
        *units += paths * m->path_units(ear, play);
    }
    if (*units > *ctx->work_left)
        return FG_WAVE_SKIPPED;
    *ctx->work_left -= *units;
    if (placed == FG_WAVE_NON_FINITE)
        return FG_WAVE_NON_FINITE;
    play->channels = 0;
    for (unsigned c = 0; c < count; c++) {
        if (gain[c] == 0.0)
            continue;
        play->ch[play->channels] = index[c];
        play->gain[play->channels++] = gain[c];
    }
    if (play->channels == 0)
        return FG_WAVE_DONE;
    for (unsigned k = 0; k < FG_PLAY_BUSES; k++)
        play->share[k] = (k % 2 ? ear->shadow : 1.0) * (k / 2 ? next : 1.0 - next);
    return add(ear, play, at);
}

/* The price of an ear that has ended (fg_discharge_place_fn): its one
 * unit, spent from the block's work as fg_discharge_add_event would, or
 * FG_WAVE_SKIPPED when it does not fit. */
static inline fg_wave_status fg_discharge_price_ended(const fg_block_context *ctx,
                                                      uint64_t *units)
{
    *units = 1;
    if (*ctx->work_left < 1)
        return FG_WAVE_SKIPPED;
    *ctx->work_left -= 1;
    return FG_WAVE_DONE;
}

/* Renders one instance; returns true once all its events are done. Stops
 * at the first ear whose price does not fit the block's work (it and the
 * unit of each ear after it are counted skipped) or a wave that is not
 * finite (v->non_finite).
 *
 * A model that writes ahead visits, in a chunk's first block, every event
 * of the window and, in a later one, only those not yet written in the
 * chunk (those that joined the window, or that a skip left): a wave is
 * then placed, evaluated and added once a chunk, whatever its length. The
 * events written to their end in one chunk are not visited in the next
 * when it follows whole. The instance is done once every event is written
 * and has ended. */
static inline bool fg_discharge_render_instance(fg_discharge_voice *v, fg_instance *in,
                                                const fg_discharge_block *vb,
                                                fg_discharge_place_fn place,
                                                fg_discharge_add_fn add)
{
    const fg_block_context *ctx = vb->ctx;
    const uint32_t n = in->main_only ? v->main_count : v->event_count;
    const uint32_t first_new = in->hi;
    while (in->hi < n &&
           fg_instance_event(v, in, in->hi)->start_s + in->offset_s - vb->margin_s <= vb->end_s)
        in->hi++;
    const bool writes_ahead = v->model->writes_ahead;
    const bool whole = !writes_ahead || ctx->chunk_start;
    if (whole) {
        if (ctx->chunk_follows && in->settled > in->lo)
            in->lo = in->settled;
        in->ahead = in->settled = in->lo;
        in->ahead_ear = 0;
        in->last_frame = -INFINITY;
    } else if (in->ahead == n && !fg_instance_sounds_ahead(in, ctx->start_frame)) {
        in->lo = n;
        return true;
    }

    fg_event_play play = {
        .cfg = ctx->cfg,
        .buses = ctx->buses,
        .origin_frame = vb->origin_frame,
        .offset_s = in->offset_s,
        .fs_hz = ctx->cfg->sample_rate_hz,
        .c_m_s = ctx->cfg->speed_of_sound_m_s,
        .frames = ctx->frames,
        .ahead = writes_ahead ? ctx->ahead : ctx->frames,
    };
    /* the instance's emission on the engine clock, seconds */
    const double emission_s = (v->emit_frame / play.fs_hz) + in->offset_s;
    uint64_t late = 0, lost = 0;
    const unsigned ears = ctx->ears->count;
    for (uint32_t k = in->ahead; k < in->hi; k++) {
        uint64_t skipped = 0;
        fg_event *ev = fg_instance_event(v, in, k);
        if (!vb->moving && ev->serial != ctx->serial) {
            for (unsigned ch = 0; ch < ears; ch++)
                fg_event_geometry(v, ev, ctx->ears, (int)ch, ctx->cfg->speed_of_sound_m_s,
                                  ctx->buses);
            ev->serial = ctx->serial;
        }
        bool done = true;
        long lost_here = 0;
        const unsigned first_ear = k == in->ahead ? in->ahead_ear : 0;
        /* written to its end in the chunk, every ear (the ears before
         * first_ear were written in an earlier block, perhaps not whole) */
        bool settled = first_ear == 0;
        for (unsigned ch = first_ear; ch < ears; ch++) {
            const fg_event_ear *ear = &ev->ear[ch];
            fg_event_ear heard;
            if (vb->moving) {
                fg_event_ear_at(v, ev, ctx->trajectory, ctx->cfg, emission_s, (int)ch,
                                ctx->buses, &heard);
                ear = &heard;
            }
            fg_wave_place at;
            const fg_wave_status placed = place(ev, ear, &play, &at);
            uint64_t units;
            fg_wave_status st = placed == FG_WAVE_DONE
                                    ? fg_discharge_price_ended(ctx, &units)
                                    : fg_discharge_add_event(ear, &play, ch, ctx, v->model, add,
                                                             placed, &at, &units);
            if (st == FG_WAVE_NON_FINITE) {
                v->non_finite = true;
                return false;
            }
            if (st == FG_WAVE_SKIPPED) {
                skipped = units + (ears - ch - 1) + (uint64_t)(in->hi - k - 1) * ears;
                in->ahead = k;
                in->ahead_ear = ch;
                done = settled = false;
                break;
            }
            if (st != FG_WAVE_DONE)
                done = false;
            const long a = at.first, b = at.last;
            /* its last taps, at b .. b + 3, lie in the chunk */
            settled = settled && (st == FG_WAVE_DONE || (writes_ahead && st == FG_WAVE_SOUNDING &&
                                                         b + 3 < (long)play.ahead));
            in->last_frame = fmax(in->last_frame, ctx->start_frame + (double)b);
            long missed = k >= first_new && a < 0 ? (b < 0 ? b : -1) - a + 1 : 0;
            if (missed > lost_here)
                lost_here = missed;
        }
        if (lost_here > 0) {
            late++;
            lost += (uint64_t)lost_here;
        }
        if (done && k == in->lo && whole)
            in->lo++;
        if (settled && !skipped && k == in->settled)
            in->settled++;
        if (skipped) {
            fg_count(&ctx->counters->skipped_work, skipped);
            break;
        }
        in->ahead = k + 1;
        in->ahead_ear = 0;
    }
    if (late) {
        fg_count(&ctx->counters->late_events, late);
        fg_count(&ctx->counters->late_samples, lost);
    }
    return in->lo == n;
}

/* fg_source_ops.render of a discharge model whose events add. A voice
 * whose wave turned non-finite is retired at once: what it added before
 * was finite, and it adds nothing more. */
static inline bool fg_discharge_render_with(void *voice, bool stopping,
                                            const fg_block_context *ctx,
                                            fg_discharge_place_fn place, fg_discharge_add_fn add)
{
    fg_discharge_voice *v = voice;
    fg_discharge_block vb;
    fg_discharge_begin_block(v, stopping, ctx, &vb);
    for (uint32_t i = 0; i < v->inst_count && !v->non_finite;) {
        if (fg_discharge_render_instance(v, &v->inst[i], &vb, place, add))
            v->inst[i] = v->inst[--v->inst_count];
        else
            i++;
    }
    if (v->non_finite) {
        fg_count(&ctx->counters->non_finite_voices, 1);
        /* the waves it wrote ahead end with the block */
        for (uint32_t i = 0; i < v->inst_count && v->model->writes_ahead; i++)
            if (fg_instance_sounds_ahead(&v->inst[i], ctx->start_frame))
                *ctx->restart = true;
        return true;
    }
    return v->inst_count == 0 && v->next_repeat_s < 0;
}

#endif
