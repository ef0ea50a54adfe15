/* A real FFT of power-of-two length: the engine's one Fourier transform
 * (the engine core may not use FFTW).
 *
 * Forward: X[k] = sum_n x[n] e^{-2 pi i k n / N}, k = 0 .. N/2, returned as
 * N/2 + 1 complex values interleaved (re, im), N + 2 doubles; X[0] and
 * X[N/2] have zero imaginary parts. Inverse: x[n] = (1/N) sum_k X[k]
 * e^{+2 pi i k n / N} over the full Hermitian spectrum, so
 * inverse(forward(x)) = x. An N-point real transform is one N/2-point
 * complex radix-2 transform and a split; twiddles are computed directly
 * (cos, sin of each angle), not by recurrence, for accuracy near 1e-16.
 *
 * [sim-thread]: init allocates; forward and inverse never allocate, and
 * one plan may serve several threads at once (it is read-only). */
#ifndef FULGUR_UTIL_FFT_INTERNAL_H
#define FULGUR_UTIL_FFT_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

#define FG_FFT_MIN_SIZE 4
#define FG_FFT_MAX_SIZE ((size_t)1 << 24)

typedef struct fg_fft {
    size_t n;          /* real length N */
    double *twiddle;   /* e^{-2 pi i k / N}, k < N/2: (cos, sin) pairs */
    size_t *reverse;   /* bit-reversal permutation of the N/2-point transform */
} fg_fft;

/* Prepares a plan for length n (a power of two in FG_FFT_MIN_SIZE ..
 * FG_FFT_MAX_SIZE). Returns false, leaving *f zeroed, for another n or when
 * out of memory. */
bool fg_fft_init(fg_fft *f, size_t n);
/* Frees the plan; a zeroed plan is a no-op. */
void fg_fft_deinit(fg_fft *f);

/* spectrum[0 .. n + 2) = the forward transform of x[0 .. n). x and
 * spectrum may be the same array (of n + 2 doubles). */
void fg_fft_forward(const fg_fft *f, const double *x, double *spectrum);

/* x[0 .. n) = the inverse transform of spectrum[0 .. n + 2) (which it
 * overwrites). x and spectrum may be the same array. */
void fg_fft_inverse(const fg_fft *f, double *spectrum, double *x);

#endif
