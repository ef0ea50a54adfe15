/* Turbulence (Glassner): a small travel-time offset that varies slowly
 * along the channel, from seeded 3-D value noise.
 *
 * Noise: values uniform in [-1, 1] at the integer lattice, hashed from the
 * lattice point and the seed (splitmix64 finaliser), blended by trilinear
 * interpolation with the quintic fade 6t^5 - 15t^4 + 10t^3. The result is
 * a convex combination of lattice values, so |n| <= 1; it is C2-smooth,
 * and its slope along an axis is at most 2 * 15/8 = 3.75 per lattice unit,
 * so two points differ by at most 3.75 (|dx| + |dy| + |dz|) lattice units.
 * Offset: amplitude_s * n(p / correlation_m). */
#ifndef FULGUR_TURBULENCE_INTERNAL_H
#define FULGUR_TURBULENCE_INTERNAL_H

#include <stdint.h>

#define FG_NOISE_MAX_SLOPE 3.75

typedef struct fg_turbulence {
    uint64_t seed;
    double amplitude_s;    /* largest offset, seconds (>= 0) */
    double correlation_m;  /* lattice spacing, metres (> 0) */
} fg_turbulence;

/* Value noise at (x, y, z) in lattice units: in [-1, 1]. */
double fg_value_noise3(uint64_t seed, double x, double y, double z);

/* The travel-time offset for a source at p (metres), seconds, in
 * [-amplitude_s, amplitude_s]. Pure and allocation-free. */
double fg_turbulence_offset_s(const fg_turbulence *t, const double p[3]);

#endif
