#include <math.h>

#include "distance_bands_internal.h"

fg_result fg_band_plan_init(fg_band_plan *plan, double near_m, double far_m, unsigned count)
{
    if (!isfinite(near_m) || !isfinite(far_m))
        return FG_ERR_NOT_FINITE;
    if (near_m <= 0.0 || far_m < near_m || count == 0 || count > FG_BANDS_MAX)
        return FG_ERR_ARGUMENT;
    plan->count = count;
    plan->log_near = log(near_m);
    plan->log_step = count > 1 ? (log(far_m) - plan->log_near) / (count - 1) : 0.0;
    plan->q = exp(plan->log_step);
    for (unsigned k = 0; k < count; k++)
        plan->centre_m[k] = near_m * exp(plan->log_step * k);
    return FG_OK;
}

/* Position of r in units of bands: k at centre k, clamped to the plan. */
static double band_coordinate(const fg_band_plan *plan, double r_m)
{
    if (plan->log_step == 0.0)
        return 0.0;
    double x = (log(r_m) - plan->log_near) / plan->log_step;
    return fmin(fmax(x, 0.0), (double)(plan->count - 1));
}

void fg_band_locate(const fg_band_plan *plan, double r_m, unsigned *lo, double *w_hi)
{
    double x = band_coordinate(plan, r_m);
    double k = floor(x);
    *lo = (unsigned)k;
    *w_hi = 0.0;
    if (*lo == plan->count - 1 || x == k)
        return;
    /* a^(q^u) = 10^(-MATCH q^u / 20) */
    const double ln_a = -FG_BAND_MATCH_DB / 20.0 * log(10.0);
    double a = exp(ln_a), a_u = exp(ln_a * pow(plan->q, x - k)), a_q = exp(ln_a * plan->q);
    *w_hi = (a - a_u) / (a - a_q);
}
