/* Distance bands: the buses a voice's segments are summed into before air
 * absorption, so the filtering cost does not grow with segment count.
 *
 * K band centres are log-spaced over [near_m, far_m]: centre k =
 * near (far / near)^(k / (K - 1)), ratio q = (far / near)^(1 / (K - 1))
 * between neighbours. A source at r between centres c_lo and c_hi = q c_lo
 * is split between the two bands' buses, weight w on the farther one, at
 * u = log_q(r / c_lo) in [0, 1]. Its filters attenuate by A and q A dB at
 * a frequency where the source should lose q^u A; no one weight mixes
 * (1 - w) 10^(-A/20) + w 10^(-qA/20) to that at every A, so w is chosen to
 * do it exactly at A = FG_BAND_MATCH_DB:
 *     w = (a - a^(q^u)) / (a - a^q),  a = 10^(-FG_BAND_MATCH_DB / 20),
 * 0 at c_lo, 1 at c_hi, continuous and rising in r. For q = 1.2 the mix is
 * then within 0.51 dB of q^u A for every A up to 80 dB and at least 80 dB
 * down where q^u A is deeper (magnitudes alone; the two filters' phases are
 * close, and the test measures the whole). Distances outside the plan take
 * its first or last band alone. */
#ifndef FULGUR_DISTANCE_BANDS_INTERNAL_H
#define FULGUR_DISTANCE_BANDS_INTERNAL_H

#include "fulgur/result.h"

#define FG_BANDS_MAX 64
/* The attenuation at which a split source is mixed exactly, dB. */
#define FG_BAND_MATCH_DB 60.0

typedef struct fg_band_plan {
    unsigned count;
    double centre_m[FG_BANDS_MAX];
    double log_near;  /* ln(centre 0) */
    double log_step;  /* ln q; 0 for a single band */
    double q;         /* centre ratio (1 for a single band) */
} fg_band_plan;

/* Plans count bands (1..FG_BANDS_MAX) over 0 < near_m <= far_m (finite);
 * count 1 needs near_m == far_m or takes near_m as its centre.
 * Errors: FG_ERR_NOT_FINITE for a NaN or infinite distance;
 * FG_ERR_ARGUMENT for near_m <= 0, far_m < near_m or count out of range.
 * On error *plan is unchanged. */
fg_result fg_band_plan_init(fg_band_plan *plan, double near_m, double far_m, unsigned count);

/* The bands around r_m (> 0): *lo and *lo + 1, and the weight of *lo + 1
 * (above; 0 on centre lo, at or beyond the plan's ends and for a single
 * band). [audio-thread] safe. */
void fg_band_locate(const fg_band_plan *plan, double r_m, unsigned *lo, double *w_hi);

#endif
