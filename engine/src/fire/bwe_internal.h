/* Spectral bandwidth extension (section 4, Algorithm 1), streaming.
 *
 * Window i has centre c_i = i w_H and the triangle w_i(n) = 1 - |n - c_i| / w_H
 * (Algorithm 1's, divided by w_H so the windows sum to exactly one). For
 * each window:
 *   p_W = w_i p,   N_W = |w_i p| N          (figure 4: the noise follows
 *                                            the low band's envelope)
 *   P = FFT(p_W),  Q = FFT(N_W)             (M points, the window centred,
 *                                            zero-padded: M >= 7 w_H)
 *   beta >= 0 from eq. 13 (fg_bwe_beta), on the same signals windowed by
 *            a triangle of half-width A >= w_H centred at c_i
 *   y = IFFT(F_low P + beta F_high Q)       (eq. 12)
 * and the M samples of y are overlap-added into the output. N is one
 * continuous noise signal (fg_noise) of magnitude f^(-alpha/2) F_high(f):
 * the paper high-passes the noise's spectrum before the transform, and
 * F_high again blends it. F_low is 1 below blend_low, 0 above blend_high,
 * linear between; F_high = 1 - F_low; the weight of eq. 13 is g(f)^2 with
 * g = exp(-(f - f_cut)^2 / (2 sigma_cut^2)).
 *
 * The zero padding matters: at w_H = 500 a window is 22.7 ms long, its
 * FFT's bins 44 Hz apart, coarser than the 30 Hz blend range and the
 * 10 Hz Gaussian; padded to M = 4096 (44.1 kHz) the bins are 10.8 Hz
 * apart and F_low's impulse response (about 1/30 Hz long) fits in the
 * frame instead of wrapping around.
 *
 * The analysis window for beta. Eq. 13 weights the power by g^2, a
 * Gaussian of sigma_cut = 10 Hz; a window of half-width T seconds smears
 * the spectrum over +-1/T (+-88 Hz for table 1's w_H = 500 at 44.1 kHz),
 * so on the w_H window eq. 13 balances band powers smeared over 90-270 Hz
 * where the input's spectrum falls steeply (the interpolation's roll-off
 * at the simulation's Nyquist frequency): measured, the output's power
 * under g^2 then misses the input's by -0.5 .. +2 dB. With A = fs /
 * sigma_cut (T = 1/sigma_cut, 100 ms) the window resolves g and the
 * balance holds to +-0.25 dB; A = w_H is the paper's own choice, offered
 * for its lower latency. The analysis transform has Ma >= 2A + 1 points.
 *
 * Latency: window i is made once the input reaches c_i + A - 1 and
 * completes the output up to c_{i+1} - M/2 - 1, so output sample n is
 * final once the input reaches n + M/2 + A - 1 at most. [sim-thread];
 * init allocates, push never does. */
#ifndef FULGUR_FIRE_BWE_INTERNAL_H
#define FULGUR_FIRE_BWE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "noise_internal.h"
#include "dsp/fft_internal.h"

typedef struct fg_bwe_params {
    double sample_rate_hz;
    double alpha;
    double f_cut_hz, sigma_cut_hz;
    double blend_low_hz, blend_high_hz;
    int half_window;     /* w_H, samples */
    int beta_half_window; /* A >= w_H, samples: the analysis window of eq. 13 */
    uint64_t seed;
} fg_bwe_params;

typedef enum fg_beta_case {
    FG_BETA_ROOT = 0,       /* the non-negative root of eq. 13 */
    FG_BETA_DEGENERATE = 1, /* the noise has no power under g: beta = 0 */
    FG_BETA_NO_ROOT = 2     /* no real root >= 0: beta minimises the residual */
} fg_beta_case;

/* The per-bin weights of one FFT length. */
typedef struct fg_bwe_weights {
    size_t bins;         /* M/2 + 1 */
    double *f_low, *f_high, *g2;
} fg_bwe_weights;

typedef struct fg_bwe_stats {
    uint64_t windows, degenerate, no_root;
    double last_beta;
} fg_bwe_stats;

typedef struct fg_bwe {
    fg_bwe_params params;
    size_t m;            /* FFT length M */
    fg_fft fft;
    fg_bwe_weights weights;
    size_t ma;           /* the analysis FFT length, 0 when A = w_H (P, Q serve) */
    fg_fft fft_beta;
    fg_bwe_weights weights_beta;
    double *pa, *na;     /* Ma + 2 each */
    fg_noise noise;
    double *p_ring, *n_ring; /* input and noise history, ring_mask + 1 long */
    size_t ring_mask;
    double *acc;         /* output accumulator, M long, indexed by time mod M */
    double *pw, *nw;     /* M + 2 each */
    uint64_t taken;      /* input samples taken */
    uint64_t next_window;
    uint64_t released;   /* output samples handed out */
    fg_bwe_stats stats;
} fg_bwe;

/* The FFT length for a half-window: the smallest power of two >= 7 w_H. */
size_t fg_bwe_fft_length(int half_window);

/* Fills the per-bin weights for an M-point FFT at the given parameters.
 * Returns false when out of memory. */
bool fg_bwe_weights_init(fg_bwe_weights *w, const fg_bwe_params *p, size_t m);
void fg_bwe_weights_deinit(fg_bwe_weights *w);

/* Eq. 13 for the spectra P and Q (interleaved complex, w->bins values):
 * sum g2 |F_low P + beta F_high Q|^2 = sum g2 |P|^2, the quadratic
 * a beta^2 + b beta + c = 0 with a = sum g2 F_high^2 |Q|^2,
 * b = 2 sum g2 F_low F_high Re(P conj Q), c = sum g2 (F_low^2 - 1) |P|^2.
 * Since F_low <= 1, c <= 0 and the discriminant is >= b^2: for a > 0 there
 * is always exactly one non-negative root (the larger), computed without
 * cancellation. a = 0 (no noise under g) is degenerate: beta = 0. No
 * real root, or no non-negative one, cannot arise from these sums (it
 * needs c > 0); were it to, beta is max(0, -b / 2a), where the residual
 * is least. */
double fg_bwe_beta(const fg_bwe_weights *w, const double *P, const double *Q, fg_beta_case *how);

/* Eq. 12: y[0 .. M) = IFFT(F_low P + beta F_high Q) for the spectra P and
 * Q (M + 2 doubles each, as fg_fft_forward makes them; P is overwritten). */
void fg_bwe_blend(const fg_bwe *b, double *P, const double *Q, double beta, double *y);

/* Validates nothing (the public layer does); false when out of memory. */
bool fg_bwe_init(fg_bwe *b, const fg_bwe_params *p);
void fg_bwe_deinit(fg_bwe *b);
void fg_bwe_reset(fg_bwe *b);

/* Output samples released per input sample, at most, in a call of n. */
size_t fg_bwe_max_frames(const fg_bwe *b, size_t n);
/* The latency bound, samples: M/2 + A - 1. */
size_t fg_bwe_latency(const fg_bwe *b);

/* Takes p[0 .. n) and writes the output samples they complete to out,
 * returning how many (at most fg_bwe_max_frames(n)). */
size_t fg_bwe_push(fg_bwe *b, const float *p, size_t n, float *out);

#endif
