/* The 128-point real FFT of the binaural layout's convolver (64-frame
 * partitions: dsp/convolver_internal.h), one signal in the eight floats of
 * an AVX2 vector: the 64-point complex transform of z[k] = x[2k] + i
 * x[2k+1] by four steps (eight-point DFTs down the columns of an 8 x 8
 * matrix held in registers, a twiddle multiply, a transpose, eight more:
 * Bailey 1990, "FFTs in external or hierarchical memory"), then
 * the usual split of a real transform. In the layouts of
 * dsp/fft_lanes_internal.h for a single signal: the forward transform
 * takes the 128 frames in their order (and splits them itself) and writes
 * the packed spectrum (Re X[k], k < 64, then Im X[k] with the real X[64]
 * in the place of Im X[0]); the inverse takes a packed spectrum back to
 * the split signal (x[2k] as element k, x[2k+1] as element 64 + k) and
 * carries the 1/128. In float, the products fused where the
 * CPU has FMA: against the double transform each bin is off by a few
 * units of float rounding of the spectrum's largest (tests/test_fft128.c).
 *
 * Only on x86-64 with GCC or Clang, chosen where the CPU has AVX2 and
 * FMA (fg_fft128_avx2_available: __builtin_cpu_supports, asked once per
 * convolver at init); elsewhere the convolver keeps fft_lanes.c's
 * transform. [audio-thread]: the transforms never allocate. */
#ifndef FULGUR_DSP_FFT128_INTERNAL_H
#define FULGUR_DSP_FFT128_INTERNAL_H

#include <stdbool.h>

typedef struct fg_fft128 {
    float twiddle_re[64], twiddle_im[64]; /* e^{-2 pi i n2 k1 / 64}: [8 k1 + n2] */
    float split_re[64], split_im[64];     /* e^{-2 pi i k / 128}, k < 64 */
} fg_fft128;

/* Fills the tables. [main-thread] */
void fg_fft128_init(fg_fft128 *f);

/* Whether this CPU runs the transforms below. [main-thread] */
bool fg_fft128_avx2_available(void);

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define FG_FFT128_AVX2 1
/* window[0 .. 128): frames in; x[0 .. 128): their packed spectrum out. */
void fg_fft128_forward_avx2(const fg_fft128 *f, const float *window, float *x);
/* x[0 .. 128): a packed spectrum in, the split signal out. */
void fg_fft128_inverse_avx2(const fg_fft128 *f, float *x);
#endif

#endif
