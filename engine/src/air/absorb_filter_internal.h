/* Air absorption over a fixed distance as a minimum-phase IIR: four
 * biquads fitted to the ISO 9613-1 magnitude 10^(-alpha(f) d / 20).
 *
 * Fitting: the target in decibels, T(f) = -alpha(f) d, is sampled at
 * FG_ABSORB_GRID log-spaced frequencies from 20 Hz to the band edge
 * min(20 kHz, 0.45 fs). Each biquad's numerator and denominator are
 * parametrised inside the stability triangle scaled to radius rho =
 * FG_ABSORB_MAX_RADIUS (c2 = rho^2 tanh u2, c1 = rho (1 + tanh u2) tanh u1),
 * so every pole and zero lies inside that circle whatever the parameters:
 * the filter is stable and minimum phase by construction. b0 makes each section's DC gain exactly 1 (alpha(0) = 0).
 * Levenberg-Marquardt (exact Jacobian, the best of three starting pole
 * spreads, or a neighbouring distance's fit) then minimises the squared
 * decibel error until every grid point is within FG_ABSORB_STOP_DB or the
 * steps stop gaining. Below
 * FG_ABSORB_FLOOR_DB the target is a ceiling, not a value: there the error
 * counts only where the filter is louder than the floor, so the fit spends
 * no effort on attenuation nobody hears. Deterministic; no allocation.
 *
 * Accuracy, checked on a grid about 15 times finer than the fit's at
 * 100 m - 20 km and 44.1 / 48 / 96 kHz (tests/test_absorb_filter.c):
 * within 0.25 dB wherever the target is above -40 dB and within 1 dB down
 * to -80 dB (20 C, 70 % RH; 0.5 dB and 1 dB for the other weather tested);
 * deeper, at least 80 dB down once the target is 81 dB down (the
 * deep-attenuation criterion of docs/sound-model.md).
 */
#ifndef FULGUR_ABSORB_FILTER_INTERNAL_H
#define FULGUR_ABSORB_FILTER_INTERNAL_H

#include <stdbool.h>

#include "air_absorption_internal.h"
#include "iir_internal.h"

#define FG_ABSORB_FLOOR_DB (-86.0)
#define FG_ABSORB_LO_HZ 20.0
#define FG_ABSORB_GRID 128
#define FG_ABSORB_MAX_RADIUS 0.999
/* u1, u2 for each section's numerator and denominator */
#define FG_ABSORB_PARAMS (4 * FG_IIR_MAX_SECTIONS)
/* A fit stops once it is this close to the target at every grid point. */
#define FG_ABSORB_STOP_DB 0.03
/* A warm start is kept if it fits the grid this well. */
#define FG_ABSORB_WARM_ACCEPT_DB 0.1

/* A fit's parameters, to start the next distance's fit from. */
typedef struct fg_absorb_fit {
    double u[FG_ABSORB_PARAMS];
    bool valid;
} fg_absorb_fit;

/* Upper edge of the fitted band: min(20 kHz, 0.45 fs). */
double fg_absorb_hi_hz(double fs_hz);

/* The decibel target -alpha(f) d. */
double fg_absorb_target_db(const fg_air *air, double distance_m, double f_hz);

/* The decibel error of f against the target at f_hz: the plain difference
 * where the target is above the floor, else how far f exceeds the floor
 * (0 if it does not). */
double fg_absorb_error_db(const fg_iir *f, const fg_air *air, double distance_m, double fs_hz,
                          double f_hz);

/* Designs f (state cleared) for distance_m >= 0 at sample rate fs_hz > 0.
 * fit may be NULL; if it holds a valid fit (of a nearby distance), the
 * design starts from it and keeps the result when it fits within
 * FG_ABSORB_WARM_ACCEPT_DB, else it falls back to the cold starts; fit
 * then holds this design's parameters. Returns the largest |error| over
 * the fitting grid, dB. [main-thread] or [sim-thread]: 0.05-20 ms, no
 * allocation. */
double fg_absorb_design(fg_iir *f, const fg_air *air, double distance_m, double fs_hz,
                        fg_absorb_fit *fit);

#endif
