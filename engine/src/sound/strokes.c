#include <math.h>

#include "fg_rules.h"
#include "fulgur/engine.h"
#include "strokes_internal.h"

static double logseries_weight(uint32_t k)
{
    return pow(FG_STROKE_LOGSERIES_P, k) / k;
}

static double poisson_weight(uint32_t k)
{
    double lambda = FG_STROKE_INTERVAL_POISSON_MEAN;
    return exp(k * log(lambda) - lambda - lgamma(k + 1.0));
}

/* Inversion over a law cut at kmax; weights need not be normalised. */
static uint32_t draw(fg_rng *rng, double (*weight)(uint32_t), uint32_t kmin, uint32_t kmax)
{
    double total = 0;
    for (uint32_t k = kmin; k <= kmax; k++)
        total += weight(k);
    double u = fg_rng_uniform(rng) * total;
    for (uint32_t k = kmin; k < kmax; k++) {
        u -= weight(k);
        if (u < 0)
            return k;
    }
    return kmax;
}

uint32_t fg_strokes_draw_count(fg_rng *rng)
{
    return draw(rng, logseries_weight, 1, FG_MAX_STROKES);
}

double fg_strokes_draw_interval_s(fg_rng *rng)
{
    uint32_t k = draw(rng, poisson_weight, 0, FG_STROKE_INTERVAL_MAX_K);
    return FG_STROKE_INTERVAL_UNIT_S * (1.0 + k + fg_rng_uniform(rng));
}

/* The strokes take a stream of their own from the seed, so that they depend
 * on the seed alone and a picture can flash with the sound before (or
 * without) the tree being posted. */
#define STROKE_STREAM FG_SPLITMIX64_GAMMA

uint32_t fg_discharge_stroke_offsets(const fg_discharge *d, double *offsets_s, uint32_t max)
{
    FG_REQUIRE_OR(d, 0);
    if (d->strokes > FG_MAX_STROKES)
        return 0;
    fg_rng rng;
    fg_rng_seed(&rng, d->seed ^ STROKE_STREAM);
    uint32_t count = d->strokes ? d->strokes : d->continuous ? 1 : fg_strokes_draw_count(&rng);
    double t = 0.0;
    for (uint32_t k = 0; k < count; k++) {
        if (k > 0)
            t += fg_strokes_draw_interval_s(&rng);
        if (offsets_s && k < max)
            offsets_s[k] = t;
    }
    return count;
}
