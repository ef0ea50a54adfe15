/* The wind around an aero object: a mean velocity and gusts, a seeded
 * smooth noise as in Dobashi et al.'s wind scenes (their gusts vary the
 * wind's speed over seconds). Value noise: a uniform knot in [-1, 1] every
 * gust period, from a hash of the seed and the knot's number (so any time
 * is evaluated without state), joined by the C1 smoothstep. */
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
