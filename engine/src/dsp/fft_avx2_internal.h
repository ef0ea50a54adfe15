/* The real FFTs of the binaural layout's convolver (dsp/convolver_internal.h)
 * of 128 and 256 points, one signal in the eight floats of AVX2 vectors.
 * 128 points: the 64-point complex transform of z[k] = x[2k] + i x[2k+1]
 * by four steps (eight-point DFTs down the columns of an 8 x 8 matrix held
 * in registers, a twiddle multiply, a transpose, eight more: Bailey 1990,
 * "FFTs in external or hierarchical memory"), then the usual split of a
 * real transform. 256 points: the 128-point complex transform as two of
 * those 64-point ones joined by one radix-2 step (decimation in time
 * forward, in frequency inverse), then the split. In the layouts of
 * dsp/fft_lanes_internal.h for a single signal of n points: the forward
 * transform takes the n frames in their order (and splits them itself)
 * and writes the packed spectrum (Re X[k], k < n/2, then Im X[k] with the
 * real X[n/2] in the place of Im X[0]); the inverse takes a packed
 * spectrum back to the split signal (x[2k] as element k, x[2k+1] as
 * element n/2 + k) and carries the 1/n. In float, the products fused:
 * against the double transform each bin is off by a few units of float
 * rounding of the spectrum's largest (tests/test_fft_avx2.c).
 *
 * Only on x86-64 with GCC or Clang, chosen where the CPU has AVX2 and FMA
 * (fg_fft_avx2_available: __builtin_cpu_supports, asked once per
 * convolver at init); elsewhere the convolver keeps fft_lanes.c's
 * transform. [audio-thread]: the transforms never allocate. */
#ifndef FULGUR_DSP_FFT_AVX2_INTERNAL_H
#define FULGUR_DSP_FFT_AVX2_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

typedef struct fg_fft_avx2 {
    size_t n;                             /* 128 or 256 real points */
    float twiddle_re[64], twiddle_im[64]; /* e^{-2 pi i n2 k1 / 64}: [8 k1 + n2] */
    float join_re[64], join_im[64];       /* e^{-2 pi i k / 128}, k < 64: the radix-2 step */
    float split_re[128], split_im[128];   /* e^{-2 pi i k / n}, k < n / 2 */
} fg_fft_avx2;

/* Fills the tables for n points; false (and nothing to undo) for an n
 * other than 128 and 256. [main-thread] */
bool fg_fft_avx2_init(fg_fft_avx2 *f, size_t n);

/* Whether this CPU runs the transforms below. [main-thread] */
bool fg_fft_avx2_available(void);

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define FG_FFT_AVX2 1
/* window[0 .. n): frames in; x[0 .. n): their packed spectrum out. */
void fg_fft_avx2_forward(const fg_fft_avx2 *f, const float *window, float *x);
/* x[0 .. n): a packed spectrum in, the split signal out. */
void fg_fft_avx2_inverse(const fg_fft_avx2 *f, float *x);
#endif

#endif
