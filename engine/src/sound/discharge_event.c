/* What one ear hears of one event: distance, travel time (straight or
 * refracted, and around the head to an ear on its far side), shadow-zone
 * fade, the filter bus and the head-shadow weight;
 * the model's wave from them. For a still listener at the pose the voice
 * caches; for a moving one at the moment the wave arrives on the
 * listener's trajectory, with the Doppler rate there. */
#include <math.h>

#include "air/refraction_internal.h"
#include "discharge_internal.h"
#include "spatial/layout_internal.h"
#include "spatial/spherical_head_internal.h"

/* Newton steps on the arrival time at most, and when to stop. */
#define ARRIVAL_ITERATIONS 6
#define ARRIVAL_TOLERANCE_S 1e-9
/* 1 - d travel/dt at least: the listener well below the speed of sound */
#define MIN_CLOSING 0.1

/* The bus for a source r away, and the share of the next one. */
static unsigned bus_of(const fg_bus_set *buses, const fg_propagation_config *p, double r,
                       double *w_next)
{
    *w_next = 0.0;
    switch (p->absorption) {
    case FG_ABSORPTION_ISO9613:
        return fg_bus_for_distance(buses, r, w_next);
    case FG_ABSORPTION_ABE_FIR:
        return r > p->abe_fir_distance_m ? FG_BUS_FIR : FG_BUS_DRY;
    case FG_ABSORPTION_OFF:
        break;
    }
    return FG_BUS_DRY;
}

/* The path from ev to ear k; returns the travel time, sets *slope to
 * d(path length)/d(distance) and *excess_rate to the time derivative of
 * the way around the head (spatial/spherical_head_internal.h), m/s. */
static double path_to(const fg_discharge_voice *v, const fg_event *ev, const fg_ears *ears, int k,
                      double c, fg_ear_path *path, double *slope, double *excess_rate)
{
    const fg_propagation_config *pr = &v->propagation;
    const double *ear = ears->pos[k];
    *path = (fg_ear_path){.ear = ear, .c_m_s = c};
    double *d = path->d;
    d[0] = ear[0] - ev->mid[0];
    d[1] = ear[1] - ev->mid[1];
    d[2] = ear[2] - ev->mid[2];
    double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    path->r_m = r;
    /* eqs. 3-4 clamp r to r0; the wave still travels the true distance */
    double travel = r / c, gain = ev->image ? pr->ground_reflection : 1.0;
    *slope = 1.0;
    if (pr->refraction_radius_m > 0) {
        travel = fg_refraction_travel_s(ev->mid, ear, pr->refraction_radius_m, c);
        *slope = fg_refraction_path_slope(r, pr->refraction_radius_m);
        /* an image's shadow is its source's: the height above ground */
        gain *= fg_shadow_gain(fabs(ev->mid[2]), ear[2], hypot(d[0], d[1]),
                               pr->refraction_radius_m, c);
    }
    path->gain = gain;
    double u[3], u_rate[3];
    for (int j = 0; j < 3; j++) {
        u[j] = k == 0 ? -ears->right[j] : ears->right[j];
        u_rate[j] = k == 0 ? -ears->right_rate[j] : ears->right_rate[j];
    }
    double excess = fg_head_excess_m(ev->mid, ears->centre, u, ears->radius_m, ears->centre_vel,
                                     u_rate, excess_rate);
    return travel + excess / c;
}

/* The ear's state from its path: the wave, the bus, the head shadow, the
 * direction it comes from. */
static void hear(const fg_discharge_voice *v, const fg_event *ev, const fg_ear_path *path,
                 const fg_ears *ears, int k, const fg_bus_set *buses, fg_event_ear *out)
{
    const fg_propagation_config *pr = &v->propagation;
    v->model->wave(&v->sound, ev, path, out);
    double w_next;
    out->bus = (uint8_t)bus_of(buses, pr, path->r_m, &w_next);
    out->band_w = (float)w_next;
    double from[3], len = 0.0;
    for (int j = 0; j < 3; j++) {
        from[j] = ev->mid[j] - ears->centre[j];
        len += from[j] * from[j];
    }
    len = len > 0.0 ? 1.0 / sqrt(len) : 0.0;
    double x = 0.0, y = 0.0, z = 0.0;
    for (int j = 0; j < 3; j++) {
        x += from[j] * ears->ahead[j];
        y -= from[j] * ears->right[j];
        z += from[j] * ears->above[j];
    }
    /* a source at the centre is heard from ahead */
    out->dir[0] = len > 0.0 ? (float)(x * len) : 1.0f;
    out->dir[1] = (float)(y * len);
    out->dir[2] = (float)(z * len);
    out->shadow = 0.0f;
    if (pr->head_shadow && ears->count == 2 && ears->radius_m > 0.0) {
        double axis[3];
        for (int j = 0; j < 3; j++)
            axis[j] = k == 0 ? -ears->right[j] : ears->right[j];
        out->shadow = (float)(fg_head_alpha(axis, from) - 1.0);
    }
}

void fg_event_geometry(const fg_discharge_voice *v, fg_event *ev, const fg_ears *ears, int k,
                       double c_m_s, const fg_bus_set *buses)
{
    fg_ear_path path;
    double slope, excess_rate;
    double travel = path_to(v, ev, ears, k, c_m_s, &path, &slope, &excess_rate);
    fg_event_ear *out = &ev->ear[k];
    out->center_s = ev->emit_s + travel;
    out->rate = 1.0;
    hear(v, ev, &path, ears, k, buses, out);
}

/* d travel / dt for an ear moving at vel along path. */
static double travel_rate(const fg_ear_path *path, const double vel[3], double slope)
{
    if (path->r_m == 0.0)
        return 0.0;
    const double *d = path->d;
    double closing = (d[0] * vel[0] + d[1] * vel[1] + d[2] * vel[2]) / path->r_m;
    return slope * closing / path->c_m_s;
}

void fg_event_ear_at(const fg_discharge_voice *v, const fg_event *ev, const fg_trajectory *traj,
                     const fg_engine_config *cfg, double emission_s, int k,
                     const fg_bus_set *buses, fg_event_ear *out)
{
    const double c = cfg->speed_of_sound_m_s;
    /* the arrival t solves t = emission + emit + travel(ear(t)); Newton
     * from the arrival at the voice's cached pose */
    double t = emission_s + ev->ear[k].center_s;
    fg_head head;
    fg_ears ears;
    fg_ear_path path;
    double travel = 0.0, slope = 1.0, dtravel = 0.0, excess_rate = 0.0;
    for (int it = 0; it < ARRIVAL_ITERATIONS; it++) {
        fg_trajectory_head(traj, t, &head);
        fg_head_ears(&head, fg_layout_ears(cfg), cfg->ear_spacing_m, &ears);
        travel = path_to(v, ev, &ears, k, c, &path, &slope, &excess_rate);
        dtravel = travel_rate(&path, ears.vel[k], slope) + excess_rate / c;
        double closing = fmax(1.0 - dtravel, MIN_CLOSING);
        double step = (t - emission_s - ev->emit_s - travel) / closing;
        if (fabs(step) < ARRIVAL_TOLERANCE_S)
            break;
        t -= step;
    }
    out->center_s = ev->emit_s + travel;
    out->rate = 1.0 / fmax(1.0 - dtravel, MIN_CLOSING);
    hear(v, ev, &path, &ears, k, buses, out);
}
