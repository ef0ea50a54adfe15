/* The wind around an aero object: a mean velocity and gusts, a seeded
 * smooth noise as in Dobashi et al.'s wind scenes (their gusts vary the
 * wind's speed over seconds). Value noise: a uniform knot in [-1, 1] every
 * gust period, from a hash of the seed and the knot's number (so any time
 * is evaluated without state), joined by the C1 smoothstep.
 *
 * A wind changed after the post (fg_aero_object_set_wind) reaches the
 * audio thread through the voice's triple buffer and starts at the object
 * at the block's start, in emission time: each ear hears it r / c later.
 * From there the old wind blends into the new over FG_AERO_WIND_RAMP_S by
 * the same C1 smoothstep, so a source's speed, pitch and level change
 * smoothly (the texture position integrates the rate: no phase step). */
#include <math.h>

#include "aero_voice_internal.h"
#include "fg_rng.h"

#define DEFAULT_GUST_PERIOD_S 2.0

static double knot(uint64_t seed, int64_t k)
{
    uint64_t h = fg_splitmix64_mix(seed ^ fg_splitmix64_mix((uint64_t)k * FG_SPLITMIX64_GAMMA));
    return 2.0 * fg_unit_from_bits(h) - 1.0;
}

void fg_aero_wind_at(const fg_aero_wind *w, double t_s, double out[3])
{
    double factor = 1.0;
    if (w->gust > 0.0) {
        double period = w->gust_period_s > 0.0 ? w->gust_period_s : DEFAULT_GUST_PERIOD_S;
        double x = t_s / period, k = floor(x), u = x - k;
        double s = u * u * (3.0 - 2.0 * u);
        int64_t i = (int64_t)k;
        factor += w->gust * ((1.0 - s) * knot(w->seed, i) + s * knot(w->seed, i + 1));
    }
    for (int c = 0; c < 3; c++)
        out[c] = w->velocity[c] * factor;
}

static double smoothstep(double u)
{
    u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
    return u * u * (3.0 - 2.0 * u);
}

void fg_aero_voice_wind_at(const fg_aero_voice *v, double t_s, double out[3])
{
    double s = smoothstep((t_s - v->wind_change_s) / FG_AERO_WIND_RAMP_S);
    fg_aero_wind_at(&v->wind, t_s, out);
    if (s == 1.0)
        return;
    double from[3];
    fg_aero_wind_at(&v->wind_from, t_s, from);
    for (int c = 0; c < 3; c++)
        out[c] = from[c] + s * (out[c] - from[c]);
}

void fg_aero_wind_box_init(fg_aero_voice *v, const fg_aero_wind *w)
{
    fg_aero_wind_box *b = &v->wind_box;
    for (int i = 0; i < 3; i++)
        b->slot[i] = *w;
    b->back = 0;
    atomic_init(&b->middle, 1u);
    b->front = 2;
    v->wind_from = v->wind = v->wind_next = *w;
    v->wind_change_s = -INFINITY;
    v->wind_waiting = false;
}

void fg_aero_wind_box_push(fg_aero_voice *v, const fg_aero_wind *w)
{
    fg_aero_wind_box *b = &v->wind_box;
    b->slot[b->back] = *w;
    b->back = atomic_exchange_explicit(&b->middle, b->back | FG_AERO_WIND_FRESH,
                                       memory_order_acq_rel) & 3u;
}

void fg_aero_voice_take_wind(fg_aero_voice *v, double oldest_tau_s, double now_s)
{
    fg_aero_wind_box *b = &v->wind_box;
    if (atomic_load_explicit(&b->middle, memory_order_relaxed) & FG_AERO_WIND_FRESH) {
        b->front = atomic_exchange_explicit(&b->middle, b->front, memory_order_acq_rel) & 3u;
        v->wind_next = b->slot[b->front];
        v->wind_waiting = true;
    }
    if (v->wind_waiting && oldest_tau_s >= v->wind_change_s + FG_AERO_WIND_RAMP_S) {
        v->wind_from = v->wind;
        v->wind = v->wind_next;
        v->wind_change_s = now_s;
        v->wind_waiting = false;
    }
}
