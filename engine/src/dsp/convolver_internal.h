/* A multichannel, uniformly partitioned FFT convolution (overlap-save with
 * a frequency-domain delay line): each of `inputs` signals is filtered by
 * its own impulse response to each of `outputs` signals, and every output
 * is the sum over the inputs,
 *   y_o = sum_i h_{i,o} * x_i.
 * The responses are cut into partitions of B taps; each block of B input
 * frames is transformed once per input (a 2B-point real FFT), multiplied
 * with every partition's spectrum against the spectra of the B-frame blocks
 * before it, summed per output in the frequency domain and transformed back
 * once per output. Output lags input by exactly B frames (whatever the
 * render call sizes: frames are buffered to the partition). Cost per B
 * frames: a forward FFT per input with sound in its last two blocks,
 * outputs multiply-adds of B + 1 bins per history slot whose block had
 * sound (at most inputs * outputs * P, P = ceil(length / B)), `outputs`
 * inverse FFTs; an input silent for P blocks costs nothing, and a short
 * burst costs only the partitions its blocks have reached.
 * (Uniformly partitioned convolution: Wefers 2015, "Partitioned
 * convolution algorithms for real-time auralization", ch. 5.)
 *
 * Everything runs in float, in util/fg_simd.h's vectors: the spectra are
 * packed split-complex runs (dsp/fft_lanes_internal.h: B real parts, then
 * B imaginary parts with X[B] in the place of Im X[0]), so the
 * multiply-add is FG_VF_LANES bins per operation at any optimisation
 * level, or eight bins with fused products where the CPU has AVX2 and FMA
 * (dsp/spectrum_mac_internal.h, the kernel chosen at init); the
 * transforms take FG_VF_LANES inputs (or outputs) at once, one per lane,
 * but for 64- and 128-frame partitions (the binaural layout's) on a CPU
 * with AVX2 and FMA, where each signal takes dsp/fft_avx2_internal.h's
 * transform, a quarter of the instructions of the lanes' per signal.
 * The responses' spectra are computed in double (fg_fft) and rounded
 * once. Against the exact sum the output is off by float rounding, 1-2e-7
 * of its peak (tests/test_convolver.c), and the binaural renders of the
 * examples moved by under 5e-7 of their peaks from the double convolver
 * this replaced.
 *
 * [main-thread] init allocates every buffer; [audio-thread] process never
 * allocates, locks or loops beyond its frames. */
#ifndef FULGUR_DSP_CONVOLVER_INTERNAL_H
#define FULGUR_DSP_CONVOLVER_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "fft_avx2_internal.h"
#include "fft_internal.h"
#include "fft_lanes_internal.h"
#include "spectrum_mac_internal.h"

typedef struct fg_convolver {
    unsigned inputs, outputs;
    size_t block;         /* B, a power of two >= 2 */
    size_t partitions;    /* P */
    fg_fft_lanes fft;     /* 2B points */
    bool fft_avx2;        /* 2B = 128 or 256 on a CPU with AVX2 and FMA: each transform
                             is fg_fft_avx2's, one signal at a time */
    fg_fft_avx2 fft_avx2_plan;
    fg_spectrum_mac_fn mac; /* the multiply-add kernel for this CPU */
    float *filter;        /* [input][partition][output][2B]: packed spectra */
    float *history;       /* [input][slot][2B]: the inputs' last P block spectra */
    unsigned char *live;  /* [input][slot]: the slot's block had sound (else its spectrum is
                             stale and counts as zero) */
    size_t newest;        /* the slot of the newest block spectrum in history */
    size_t *quiet;        /* [input]: blocks since the input was last non-zero */
    unsigned char *fed;   /* [input]: frames of the block being filled were given (not
                             NULL): else the block is known to be zero */
    size_t words;         /* 64-bit words of the input masks below */
    uint64_t *awake;      /* [words]: bit i: input i has a history that is not all zero
                             or was given frames (quiet[i] < P + 2, or fed); only these
                             are visited, in the order of their indices */
    uint64_t *given;      /* [words]: the inputs the current process call was given */
    float *in;            /* [input][2B]: the previous block and the one being filled */
    float *out;           /* [output][B]: the block being played */
    float *acc;           /* [output + 1][2B]: the outputs' spectra, and a spare */
    const float **pairs;  /* 2P: an input's live history slots, then their filters */
    float *lanes, *work;  /* 2B * FG_VF_LANES each: the signals being transformed */
    float *zeros;         /* 2B zeros: the window of a lane no input fills */
    size_t fill;          /* frames of the current block taken so far */
} fg_convolver;

/* Prepares a convolver for responses of `length` taps, filter[(i * outputs
 * + o) * length + k] tap k from input i to output o (copied), partitions of
 * `block` frames (a power of two in 2 .. 65536). Returns false, leaving *c
 * zeroed, for a zero count or length, another block, or out of memory. */
bool fg_convolver_init(fg_convolver *c, unsigned inputs, unsigned outputs, size_t length,
                       size_t block, const double *filter);
/* Frees it; a zeroed convolver is a no-op. */
void fg_convolver_deinit(fg_convolver *c);

/* Takes n frames of each input (in[i][0..n); a NULL in[i]: n zeros, which
 * cost nothing once the input's window is silent) and writes n frames of
 * each output (out[o][0..n)), B frames late. [audio-thread] */
void fg_convolver_process(fg_convolver *c, const float *const *in, float *const *out, size_t n);

#endif
