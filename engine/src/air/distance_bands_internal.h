/* Distance bands: the few buses a voice's segments are summed into before
 * air absorption, so the filtering cost does not grow with segment count.
 *
 * K band centres are log-spaced over [near_m, far_m]: centre k =
 * near (far / near)^(k / (K - 1)), ratio q = (far / near)^(1 / (K - 1))
 * between neighbours. Band k holds the distances whose log lies nearest to
 * its centre's; edges sit at the geometric means of neighbouring centres.
 * A source at r heard through band k's filter (fitted at centre c) is
 * absorbed by alpha(f) (c - r) dB too much or too little: at most
 * alpha(f) c (sqrt(q) - 1) inside the plan. Distances outside it fall in
 * the first or last band. For moving sources, fg_band_locate gives a pair
 * of neighbouring bands and a weight, linear in log distance, to split a
 * segment between them without a jump when it crosses an edge. */
#ifndef FULGUR_DISTANCE_BANDS_INTERNAL_H
#define FULGUR_DISTANCE_BANDS_INTERNAL_H

#include "fulgur/result.h"

#define FG_BANDS_MAX 16

typedef struct fg_band_plan {
    unsigned count;
    double centre_m[FG_BANDS_MAX];
    double log_near;  /* ln(centre 0) */
    double log_step;  /* ln q; 0 for a single band */
} fg_band_plan;

/* Plans count bands (1..FG_BANDS_MAX) over 0 < near_m <= far_m (finite);
 * count 1 needs near_m == far_m or takes near_m as its centre.
 * Errors: FG_ERR_NOT_FINITE for a NaN or infinite distance;
 * FG_ERR_ARGUMENT for near_m <= 0, far_m < near_m or count out of range.
 * On error *plan is unchanged. */
fg_result fg_band_plan_init(fg_band_plan *plan, double near_m, double far_m, unsigned count);

/* The band a source at r_m (> 0) belongs to. [audio-thread] safe. */
unsigned fg_band_nearest(const fg_band_plan *plan, double r_m);

/* The bands around r_m: *lo and *lo + 1 (equal at the plan's ends), and the
 * weight of *lo + 1 (0 at centre lo, 1 at centre lo + 1). [audio-thread]
 * safe. */
void fg_band_locate(const fg_band_plan *plan, double r_m, unsigned *lo, double *w_hi);

#endif
