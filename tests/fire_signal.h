/* Signals and measurements for the fire-sound tests. The measurements use
 * FFTW, not the engine's own FFT, so they are independent of it. */
#ifndef TESTS_FIRE_SIGNAL_H
#define TESTS_FIRE_SIGNAL_H

#include <stddef.h>
#include <stdint.h>

/* A made-up simulated flame's flux at sim_rate_hz: a mean of 0.02 m^3/s
 * and fluctuations (AR(1) noise of pole 0.6) whose size follows a slow
 * log-normal envelope (bursts of a few per second), like a flickering
 * flame's front. */
void fire_test_flux(double sim_rate_hz, size_t steps, uint64_t seed, double *flux);

/* Welch's power spectral density: Hann segments of seg samples (a power
 * of two) overlapping by half; psd[0 .. seg/2] in units^2 / Hz. */
void fire_welch(const float *x, size_t n, double fs, size_t seg, double *psd);

/* The mean of psd over bins whose frequency lies in [lo, hi). */
double fire_band_mean(const double *psd, size_t seg, double fs, double lo, double hi);

/* out = x band-passed to [lo, hi) Hz with an ideal filter over the whole
 * signal (one FFT of length n). */
void fire_band_pass(const float *x, size_t n, double fs, double lo, double hi, double *out);

/* The RMS of each frame of `frame` samples of x. Returns the frame count. */
size_t fire_frame_rms(const double *x, size_t n, size_t frame, double *rms);

/* Pearson's correlation of a and b. */
double fire_correlation(const double *a, const double *b, size_t n);

/* Least-squares slope of y against x. */
double fire_slope(const double *x, const double *y, size_t n);

#endif
