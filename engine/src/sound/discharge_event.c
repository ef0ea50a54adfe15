/* Per-ear state of one event for the current pose: distance, travel time
 * (straight or refracted), shadow-zone fade, the filter bus and the
 * head-shadow share; the model's wave from them. */
#include <math.h>

#include "air/head_shadow_internal.h"
#include "air/refraction_internal.h"
#include "discharge_internal.h"

static unsigned bus_of(const fg_bus_set *buses, const fg_propagation_config *p, double r)
{
    switch (p->absorption) {
    case FG_ABSORPTION_ISO9613:
        return fg_bus_for_distance(buses, r);
    case FG_ABSORPTION_ABE_FIR:
        return r > p->abe_fir_distance_m ? FG_BUS_FIR : FG_BUS_DRY;
    case FG_ABSORPTION_OFF:
        break;
    }
    return FG_BUS_DRY;
}

void fg_event_geometry(const fg_discharge_voice *v, fg_event *ev, const fg_ears *ears, int k,
                       double c_m_s, const fg_bus_set *buses)
{
    const double *ear = ears->pos[k];
    const fg_propagation_config *pr = &v->propagation;
    double c = c_m_s;
    fg_ear_path path = {.ear = ear, .c_m_s = c};
    double *d = path.d;
    d[0] = ear[0] - ev->mid[0];
    d[1] = ear[1] - ev->mid[1];
    d[2] = ear[2] - ev->mid[2];
    double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    path.r_m = r;

    /* eqs. 3-4 clamp r to r0; the wave still travels the true distance */
    double travel = r / c, gain = ev->gain;
    if (pr->refraction_radius_m > 0) {
        travel = fg_refraction_travel_s(ev->mid, ear, pr->refraction_radius_m, c);
        /* an image's fade is its source's: the height above ground */
        gain *= fg_shadow_gain(fabs(ev->mid[2]), hypot(d[0], d[1]), pr->refraction_radius_m);
    }
    path.gain = gain;
    ev->center_s[k] = ev->emit_s + travel;
    v->model->wave(&v->sound, ev, &path, k);
    ev->bus[k] = (uint8_t)bus_of(buses, pr, r);
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
