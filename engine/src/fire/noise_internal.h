/* Stationary noise of a given magnitude spectrum, streamed: frames of M
 * samples, each the inverse FFT of |X_k| = magnitude[k] with uniformly
 * random phases in [-pi, pi) (section 4, "spectral noise synthesis"),
 * shaped by a sine window and overlap-added at a hop of M/2. The sine
 * window's squares sum to one at that hop, so the variance is the same at
 * every sample (no frame-rate modulation) and the power spectrum is
 * magnitude^2 smoothed by the window's (about 2 fs/M wide). Scaled to unit
 * variance. [sim-thread]; init allocates, next never does. */
#ifndef FULGUR_FIRE_NOISE_INTERNAL_H
#define FULGUR_FIRE_NOISE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "fg_rng.h"
#include "dsp/fft_internal.h"

typedef struct fg_noise {
    const fg_fft *fft;   /* borrowed plan of length M */
    double *magnitude;   /* M/2 + 1, scaled for unit variance */
    double *window;      /* M/2: the rising half of the sine window */
    double *frame;       /* M + 2 scratch */
    double *ready;       /* M/2 finished samples */
    double *tail;        /* M/2: the second half of the last frame, windowed */
    size_t pos;          /* next sample of ready to hand out */
    uint64_t seed;
    fg_rng rng;
} fg_noise;

/* magnitude[0 .. M/2 + 1) (copied; the DC and Nyquist bins are ignored).
 * Returns false when out of memory or the spectrum is all zero. */
bool fg_noise_init(fg_noise *n, const fg_fft *fft, const double *magnitude, uint64_t seed);
void fg_noise_deinit(fg_noise *n);
/* Back to the first sample of the same seed. */
void fg_noise_reset(fg_noise *n);
double fg_noise_next(fg_noise *n);

#endif
