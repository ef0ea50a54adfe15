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
    *w_hi = x - k;
    if (*lo == plan->count - 1)
        *w_hi = 0.0;
}

unsigned fg_band_nearest(const fg_band_plan *plan, double r_m)
{
    unsigned lo;
    double w;
    fg_band_locate(plan, r_m, &lo, &w);
    return w > 0.5 ? lo + 1 : lo;
}
