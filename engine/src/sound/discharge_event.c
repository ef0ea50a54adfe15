/* Per-ear state of one segment for the current pose: distance, angle,
 * travel time (straight or refracted), shadow-zone fade, the WM-wave's
 * shape or Abe's wave, the filter bus and the head-shadow share. */
#include <math.h>

#include "core/engine_internal.h"
#include "air/head_shadow_internal.h"
#include "air/refraction_internal.h"

static unsigned bus_of(const fg_engine *e, const fg_propagation *p, double r)
{
    switch (p->absorption) {
    case FG_ABSORPTION_ISO9613:
        return fg_bus_for_distance(&e->buses, r);
    case FG_ABSORPTION_ABE_FIR: {
        double far = p->abe_fir_distance_m > 0 ? p->abe_fir_distance_m : FG_ABE_FIR_DEFAULT_DISTANCE_M;
        return r > far ? FG_BUS_FIR : FG_BUS_DRY;
    }
    case FG_ABSORPTION_OFF:
        break;
    }
    return FG_BUS_DRY;
}

void fg_event_geometry(const fg_engine *e, const fg_voice *v, fg_event *ev, const fg_ears *ears,
                       int k)
{
    const double *ear = ears->pos[k];
    const fg_propagation *pr = &v->propagation;
    const fg_sound_params *p = &v->sound;
    double c = e->cfg.speed_of_sound_m_s;
    double d[3] = {ear[0] - ev->mid[0], ear[1] - ev->mid[1], ear[2] - ev->mid[2]};
    double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);

    /* eqs. 3-4 clamp r to r0; the wave still travels the true distance */
    double travel = r / c, gain = ev->gain;
    if (pr->refraction_radius_m > 0) {
        travel = fg_refraction_travel_s(ev->mid, ear, pr->refraction_radius_m, c);
        /* an image's fade is its source's: the height above ground */
        gain *= fg_shadow_gain(fabs(ev->mid[2]), hypot(d[0], d[1]), pr->refraction_radius_m);
    }
    ev->center_s[k] = ev->emit_s + travel;
    if (v->model == FG_MODEL_ABE) {
        fg_abe_wave_init(&ev->abe[k], &e->abe, ev->mid, ear, 0.0, c);
        ev->abe[k].arrival_s = ev->center_s[k];
        ev->abe[k].peak_pa *= gain;
    } else {
        /* sin(theta), theta from the segment's normal: |cos| of the angle
         * to the segment's axis */
        double s = r > 0 ? fabs(d[0] * ev->dir[0] + d[1] * ev->dir[1] + d[2] * ev->dir[2]) / r : 0;
        ev->shape[k] = fg_wm_shape_at(p, ev->t0_s, r, s > 1.0 ? 1.0 : s, ev->half_len_m, c, NULL);
        ev->shape[k].b *= gain;
    }
    ev->bus[k] = (uint8_t)bus_of(e, pr, r);
    ev->shadow[k] = 0.0f;
    if (pr->head_shadow && ears->count == 2) {
        double axis[3], to_source[3];
        for (int j = 0; j < 3; j++) {
            axis[j] = k == 0 ? -ears->right[j] : ears->right[j];
            to_source[j] = -d[j];
        }
        ev->shadow[k] = (float)(fg_head_shadow_db(axis, to_source) / FG_HEAD_SHADOW_DB);
    }
}

double fg_event_start_s(const fg_engine *e, const fg_voice *v, const fg_event *ev, int k)
{
    if (v->model == FG_MODEL_ABE)
        return ev->abe[k].arrival_s;
    double half = (ev->shape[k].psi + ev->shape[k].s) * ev->half_len_m / e->cfg.speed_of_sound_m_s;
    return ev->center_s[k] - half;
}
