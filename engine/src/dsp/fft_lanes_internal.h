/* FG_VF_LANES real FFTs at once, in float: the same power-of-two length
 * for one signal per vector lane (util/fg_simd.h), so every butterfly is
 * one vector operation on all the signals and the transform vectorises
 * whatever its length and the optimisation level. The partitioned
 * convolver's transform (dsp/convolver_internal.h); fg_fft (fft_internal.h)
 * stays the double one for everything else.
 *
 * Layouts, per lane (array element [k * FG_VF_LANES + lane]):
 *  - a real signal x[0 .. N) is held as the N/2 complex values
 *    z[k] = x[2k] + i x[2k+1], split: element k < N/2 is x[2k] (re) and
 *    element N/2 + k is x[2k+1] (im);
 *  - a spectrum X[k] = sum_n x[n] e^{-2 pi i k n / N}, k = 0 .. N/2, is
 *    packed into N elements: k < N/2 is Re X[k], N/2 + k (k >= 1) is
 *    Im X[k], and element N/2 holds X[N/2], real like X[0].
 * inverse(forward(x)) = x (the inverse carries the 1/N).
 *
 * The complex N/2-point transform is a Stockham autosort (no
 * bit-reversal pass: each stage writes its outputs in the order the next
 * reads them) of radix 4, with one radix-2 stage first when log2(N/2) is
 * odd, ping-ponging with a caller's work array; the twiddles of each stage
 * are stored contiguously, computed directly in double (cos, sin of each
 * angle) and rounded, and the first butterfly of a stage (twiddles 1) is
 * not multiplied. Then the usual split of a real transform into its even
 * and odd halves; the inverse runs the forward stages on the conjugate.
 *
 * One signal alone (the _one functions, where the plan says `one`: N/2 at
 * least 4 FG_VF_LANES) is transformed with its neighbouring elements
 * across the lanes instead, for the callers that have fewer signals than
 * lanes: bit for bit the same floats as its lane would hold (the same
 * operations on each element; tests/test_fft_lanes.c), for a quarter of
 * the butterflies and no transposes into and out of the lanes (at 128
 * points, 2.3 thousand instructions forward against 5.7 for the lane
 * transform, plus its transposes). Its layouts are those above for a
 * single lane (element k at index k).
 *
 * [main-thread] init allocates; forward and inverse never allocate, and
 * one plan may serve several threads at once (it is read-only). */
#ifndef FULGUR_DSP_FFT_LANES_INTERNAL_H
#define FULGUR_DSP_FFT_LANES_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

#include "fg_simd.h"

typedef struct fg_fft_lanes {
    size_t n;       /* real length N */
    bool radix2;    /* log2(N/2) is odd: a radix-2 stage comes first */
    size_t stages;  /* radix-2 and radix-4 stages in all */
    float *twiddle; /* per stage of length L (N/2, then down by its radix): the
                       radix-2 one cos then sin of 2 pi j / L, j < L/2; a radix-4
                       one cos then sin of 2 pi j k / L, j < L/4, for k = 1, 2, 3 */
    float *split;   /* cos, sin of 2 pi k / N, k <= N/4: the real split */
    bool one;       /* the single-signal path is available */
    float *spread;  /* its twiddles: each stage's runs spread to one value per
                       butterfly (spread_stages floats), then the split's cos
                       and sin runs (k < N/4) */
    size_t spread_stages; /* the floats of spread before the split's runs */
} fg_fft_lanes;

/* Prepares a plan for length n (a power of two in FG_FFT_MIN_SIZE ..
 * FG_FFT_MAX_SIZE, fft_internal.h). Returns false, leaving *f zeroed, for
 * another n or when out of memory. */
bool fg_fft_lanes_init(fg_fft_lanes *f, size_t n);
/* Frees the plan; a zeroed plan is a no-op. */
void fg_fft_lanes_deinit(fg_fft_lanes *f);

/* x[0 .. n * FG_VF_LANES): a split signal per lane in, its packed
 * spectrum out. work: as many floats, overwritten. */
void fg_fft_lanes_forward(const fg_fft_lanes *f, float *x, float *work);
/* x: a packed spectrum per lane in, the split signal out; work as above. */
void fg_fft_lanes_inverse(const fg_fft_lanes *f, float *x, float *work);

/* The same for one signal: x[0 .. n) a split signal in, its packed
 * spectrum out (work: n floats, overwritten); only where f->one. */
void fg_fft_lanes_forward_one(const fg_fft_lanes *f, float *x, float *work);
/* x[0 .. n): a packed spectrum in, the split signal out; only where
 * f->one. */
void fg_fft_lanes_inverse_one(const fg_fft_lanes *f, float *x, float *work);

#endif
