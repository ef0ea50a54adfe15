/* The partitioned convolver's inner loop (dsp/convolver_internal.h): the
 * products of one input's history spectra with its partitions' spectra,
 * summed into two outputs' spectra, over the packed split-complex bins of
 * dsp/fft_lanes_internal.h (B real parts, then B imaginary parts with the
 * real X[B] in the place of Im X[0]):
 *   acc0 += sum_j x[j] (h[j] + off0),  acc1 += sum_j x[j] (h[j] + off1)
 * for j < count, complex products per bin but X[0] and X[B] multiplied
 * as the reals they are. The sums stay in registers across the count
 * pairs, and each x[j] is loaded once for both outputs.
 *
 * Two kernels: the portable one in util/fg_simd.h's vectors (SIMD at any
 * optimisation level, plain loops for the bins that fill no vector), and
 * on x86-64 one in AVX2 and FMA, eight bins per operation and the products
 * fused into the sums, for B a multiple of 8. fg_spectrum_mac_pick chooses
 * for the CPU it runs on (__builtin_cpu_supports, read once per convolver
 * at init: no ifunc, no global state). The two differ by float rounding
 * only (the fused products round once).
 *
 * [audio-thread]: the kernels never allocate and loop over count * B. */
#ifndef FULGUR_DSP_SPECTRUM_MAC_INTERNAL_H
#define FULGUR_DSP_SPECTRUM_MAC_INTERNAL_H

#include <stddef.h>

typedef void (*fg_spectrum_mac_fn)(float *restrict acc0, float *restrict acc1,
                                   const float *const *x, const float *const *h, size_t off0,
                                   size_t off1, size_t count, size_t B);

void fg_spectrum_mac_plain(float *restrict acc0, float *restrict acc1, const float *const *x,
                           const float *const *h, size_t off0, size_t off1, size_t count,
                           size_t B);

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define FG_SPECTRUM_MAC_AVX2 1
/* B a multiple of 8; only where the CPU has AVX2 and FMA. */
void fg_spectrum_mac_avx2(float *restrict acc0, float *restrict acc1, const float *const *x,
                          const float *const *h, size_t off0, size_t off1, size_t count,
                          size_t B);
#endif

/* The fastest kernel for this CPU and B. [main-thread] */
fg_spectrum_mac_fn fg_spectrum_mac_pick(size_t B);

#endif
