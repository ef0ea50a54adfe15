/* The WM-wave model (Matsuyama): one WM-wave per segment, added to the
 * buses' difference-domain accumulators. */
#include <math.h>

#include "discharge_schedule.h"

static size_t wm_stride(size_t segments)
{
    (void)segments;
    return 1;
}

static void wm_wave(const fg_sound_config *p, const fg_event *ev, const fg_ear_path *path,
                    fg_event_ear *ear)
{
    const double *d = path->d;
    double r = path->r_m;
    /* sin(theta), theta from the segment's normal: |cos| of the angle to
     * the segment's axis */
    double s = r > 0 ? fabs(d[0] * ev->dir[0] + d[1] * ev->dir[1] + d[2] * ev->dir[2]) / r : 0;
    ear->wm = fg_wm_shape_at(p, ev->t0_s, r, s > 1.0 ? 1.0 : s, ev->half_len_m, path->c_m_s, NULL);
    /* the line integral: the segment's share of the line, in reference
     * segments (fg_sound_config.ref_half_len_m) */
    double share = p->ref_half_len_m > 0 ? ev->half_len_m / p->ref_half_len_m : 1.0;
    ear->wm.b *= path->gain * share;
}

static double wm_start_s(const fg_event *ev, const fg_event_ear *ear, double c_m_s)
{
    double half = (ear->wm.psi + ear->wm.s) * ev->half_len_m / c_m_s * ear->rate;
    return ear->center_s - half;
}

static bool wm_finite(const fg_event *ev, const fg_event_ear *ear, double fs_hz, double c_m_s)
{
    fg_wm_event we = {.shape = ear->wm, .center = ear->center_s * fs_hz,
                      .width = fs_hz * ev->half_len_m / c_m_s * ear->rate};
    return fg_wm_event_in_range(&we);
}

/* A moving ear hears the wave stretched by its rate: tau advances
 * (c - dr/dt) / l per second, so a unit of tau lasts rate l / c. */
static fg_wave_status wm_place(const fg_event *ev, const fg_event_ear *ear,
                               const fg_event_play *play, fg_wave_place *at)
{
    const double fs = play->fs_hz;
    at->wm = (fg_wm_event){
        .shape = ear->wm,
        .center = play->origin_frame + (play->offset_s + ear->center_s) * fs,
        .width = fs * ev->half_len_m / play->c_m_s * ear->rate,
    };
    if (!fg_wm_event_in_range(&at->wm))
        return FG_WAVE_NON_FINITE;
    fg_wm_event_span(&at->wm, &at->first, &at->last);
    return fg_wm_event_ended(at->last) ? FG_WAVE_DONE : FG_WAVE_SOUNDING;
}

/* A wave sounding through the rest of the chunk, which adds its state
 * alone: the state's edges, placed once, give each bus's three values. */
static fg_wave_status add_through(const fg_event_ear *ear, const fg_event_play *play,
                                  const fg_wave_place *at, const fg_wm_state_edges *edges)
{
    fg_wm_shape w = ear->wm;
    fg_wave_status status = FG_WAVE_DONE;
    for (int k = 0; k < FG_PLAY_BUSES; k++) {
        if (play->share[k] == 0.0)
            continue;
        w.b = ear->wm.b * play->share[k];
        double y[3];
        if (!fg_wm_state_values(edges, &w, y))
            return FG_WAVE_NON_FINITE;
        status = FG_WAVE_SOUNDING;
        for (unsigned c = 0; c < play->channels; c++) {
            fg_accum *a = fg_bus_accum(play->buses, play->bus[k], play->ch[c]);
            fg_wm_state_add(a, y, play->gain[c]);
            fg_accum_hold(a, at->last + 4);
        }
    }
    return status;
}

/* Each bus's wave is evaluated once and added to every channel at its
 * gain: a layout of many channels (binaural's loudspeakers, ambisonics)
 * costs an evaluation per bus and an add per channel. */
static fg_wave_status wm_add(const fg_event_ear *ear, const fg_event_play *play,
                             const fg_wave_place *at)
{
    fg_wm_state_edges edges;
    if (fg_wm_through(&at->wm, at->first, at->last, (long)play->ahead, &edges))
        return add_through(ear, play, at, &edges);
    fg_wm_event we = at->wm;
    fg_wave_status status = FG_WAVE_DONE;
    for (int k = 0; k < FG_PLAY_BUSES; k++) {
        if (play->share[k] == 0.0)
            continue;
        we.shape.b = ear->wm.b * play->share[k];
        fg_wm_taps taps;
        status = fg_wm_taps_eval(&we, at->first, at->last, (long)play->ahead, &taps);
        if (status == FG_WAVE_NON_FINITE)
            break;
        if (status != FG_WAVE_SOUNDING)
            continue;
        for (unsigned c = 0; c < play->channels; c++)
            fg_wm_taps_add(fg_bus_accum(play->buses, play->bus[k], play->ch[c]), &taps,
                           play->gain[c]);
    }
    return status;
}

static bool wm_render(void *voice, bool stopping, const fg_block_context *block)
{
    return fg_discharge_render_with(voice, stopping, block, wm_place, wm_add);
}

static const fg_discharge_model wm_model = {
    .stride = wm_stride,
    .wave = wm_wave,
    .start_s = wm_start_s,
    .finite = wm_finite,
    .path_units = NULL, /* a few closed-form terms, whatever its length */
    .writes_ahead = true,
};

const fg_source_ops fg_source_wm = {
    .name = "wm",
    .kind = &fg_discharge_kind,
    .model = &wm_model,
    .prepare = fg_discharge_prepare,
    .adopt = fg_discharge_adopt,
    .render = wm_render,
    .release = fg_discharge_release,
};
