/* Air absorption over a fixed distance as a minimum-phase IIR: three
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
 * spreads) then minimises the squared decibel error. Below
 * FG_ABSORB_FLOOR_DB the target is a ceiling, not a value: there the error
 * counts only where the filter is louder than the floor, so the fit spends
 * no effort on attenuation nobody hears. Deterministic; no allocation.
 *
 * Accuracy, checked on a grid about 15 times finer than the fit's at
 * 100 m - 20 km and 44.1 / 48 / 96 kHz: within 0.25 dB wherever the target
 * is above -40 dB and within 1 dB down to the floor (20 C, 70 % RH); 0.5 dB
 * and 1 dB for the other weather tested. */
#ifndef FULGUR_ABSORB_FILTER_INTERNAL_H
#define FULGUR_ABSORB_FILTER_INTERNAL_H

#include "air_absorption_internal.h"
#include "iir_internal.h"

#define FG_ABSORB_FLOOR_DB (-60.0)
#define FG_ABSORB_LO_HZ 20.0
#define FG_ABSORB_GRID 96
#define FG_ABSORB_MAX_RADIUS 0.999

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
 * Returns the largest |error| over the fitting grid, dB. [main-thread] or
 * [sim-thread]: about 30 ms, no allocation. */
double fg_absorb_design(fg_iir *f, const fg_air *air, double distance_m, double fs_hz);

#endif
