/* The WM-wave model (Matsuyama): one WM-wave per segment, added to the
 * buses' difference-domain accumulators. */
#include <math.h>

#include "discharge_schedule.h"

static size_t wm_stride(size_t segments)
{
    (void)segments;
    return 1;
}

static void wm_wave(const fg_sound_config *p, fg_event *ev, const fg_ear_path *path, int k)
{
    const double *d = path->d;
    double r = path->r_m;
    /* sin(theta), theta from the segment's normal: |cos| of the angle to
     * the segment's axis */
    double s = r > 0 ? fabs(d[0] * ev->dir[0] + d[1] * ev->dir[1] + d[2] * ev->dir[2]) / r : 0;
    ev->shape[k] = fg_wm_shape_at(p, ev->t0_s, r, s > 1.0 ? 1.0 : s, ev->half_len_m, path->c_m_s,
                                  NULL);
    ev->shape[k].b *= path->gain;
}

static double wm_start_s(const fg_event *ev, int k, double c_m_s)
{
    double half = (ev->shape[k].psi + ev->shape[k].s) * ev->half_len_m / c_m_s;
    return ev->center_s[k] - half;
}

static bool wm_finite(const fg_event *ev, int k, double fs_hz, double c_m_s)
{
    fg_wm_event we = {.shape = ev->shape[k], .center = ev->center_s[k] * fs_hz,
                      .width = fs_hz * ev->half_len_m / c_m_s};
    return fg_wm_event_in_range(&we);
}

static fg_wave_status wm_add(const fg_event *ev, const fg_event_play *play, long *first,
                             long *last)
{
    const unsigned ch = play->ch;
    const double fs = play->fs_hz;
    fg_wm_event we = {
        .shape = ev->shape[ch],
        .center = play->origin_frame + (play->offset_s + ev->center_s[ch]) * fs,
        .width = fs * ev->half_len_m / play->c_m_s,
    };
    if (!fg_wm_event_in_range(&we))
        return FG_WAVE_NON_FINITE;
    fg_wm_event_span(&we, first, last);
    fg_wave_status status = FG_WAVE_DONE;
    for (int k = 0; k < 2; k++) {
        if (play->share[k] == 0.0)
            continue;
        we.shape.b = ev->shape[ch].b * play->share[k];
        status = fg_wm_accum_add(fg_bus_accum(play->buses, play->bus + k * FG_BUS_PLAIN, ch), &we);
        if (status == FG_WAVE_NON_FINITE)
            break;
    }
    return status;
}

static bool wm_render(void *voice, bool stopping, const fg_block_context *block)
{
    return fg_discharge_render_with(voice, stopping, block, wm_add);
}

static const fg_discharge_model wm_model = {
    .stride = wm_stride,
    .wave = wm_wave,
    .start_s = wm_start_s,
    .finite = wm_finite,
    .samples_per_unit = 0, /* a few closed-form terms, whatever its length */
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
