/* Interaural measures of a rendered pair, as the spatial tests take them:
 * the interaural time difference by cross-correlation band-limited below a
 * frequency, and band energies for level differences. Direct DFTs over the
 * bins needed (test code only). */
#ifndef FULGUR_TEST_EAR_MEASURE_H
#define FULGUR_TEST_EAR_MEASURE_H

#include <stddef.h>

/* The lag tau in seconds (within +-max_lag_s, to 0.1 us) maximising the
 * cross-correlation of left and right restricted to 0 < f <= f_max_hz:
 * left(t) ~ right(t - tau), so tau > 0 when the right ear leads. */
double em_itd_s(const float *left, const float *right, size_t n, double fs_hz, double f_max_hz,
                double max_lag_s);

/* The energy of x[0..n) in the DFT bins f_lo_hz <= f < f_hi_hz. */
double em_band_energy(const float *x, size_t n, double fs_hz, double f_lo_hz, double f_hi_hz);

#endif
