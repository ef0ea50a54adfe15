#include "spectrum_mac_internal.h"
#include "fg_simd.h"

#define V FG_VF_LANES

/* The real bins: elements 0 (X[0]) and B (X[B]), which the vector loops
 * took for one complex value, summed again from their values before
 * (was[0..4): acc0[0], acc0[B], acc1[0], acc1[B]). */
static void real_bins(float *restrict acc0, float *restrict acc1, const float *was,
                      const float *const *x, const float *const *h, size_t off0, size_t off1,
                      size_t count, size_t B)
{
    float dc0 = was[0], ny0 = was[1], dc1 = was[2], ny1 = was[3];
    for (size_t j = 0; j < count; j++) {
        const float *h0 = h[j] + off0, *h1 = h[j] + off1;
        dc0 += x[j][0] * h0[0];
        ny0 += x[j][B] * h0[B];
        dc1 += x[j][0] * h1[0];
        ny1 += x[j][B] * h1[B];
    }
    acc0[0] = dc0;
    acc0[B] = ny0;
    acc1[0] = dc1;
    acc1[B] = ny1;
}

void fg_spectrum_mac_plain(float *restrict acc0, float *restrict acc1, const float *const *x,
                           const float *const *h, size_t off0, size_t off1, size_t count,
                           size_t B)
{
    const float was[4] = {acc0[0], acc0[B], acc1[0], acc1[B]};
    size_t k = 0;
    for (; k + V <= B; k += V) {
        fg_vf a0r = fg_vf_load(acc0 + k), a0i = fg_vf_load(acc0 + B + k);
        fg_vf a1r = fg_vf_load(acc1 + k), a1i = fg_vf_load(acc1 + B + k);
        for (size_t j = 0; j < count; j++) {
            const float *h0 = h[j] + off0, *h1 = h[j] + off1;
            fg_vf xr = fg_vf_load(x[j] + k), xi = fg_vf_load(x[j] + B + k);
            fg_vf hr = fg_vf_load(h0 + k), hi = fg_vf_load(h0 + B + k);
            a0r += xr * hr - xi * hi;
            a0i += xr * hi + xi * hr;
            hr = fg_vf_load(h1 + k);
            hi = fg_vf_load(h1 + B + k);
            a1r += xr * hr - xi * hi;
            a1i += xr * hi + xi * hr;
        }
        fg_vf_store(acc0 + k, a0r);
        fg_vf_store(acc0 + B + k, a0i);
        fg_vf_store(acc1 + k, a1r);
        fg_vf_store(acc1 + B + k, a1i);
    }
    for (; k < B; k++)
        for (size_t j = 0; j < count; j++) {
            const float *h0 = h[j] + off0, *h1 = h[j] + off1;
            float xr = x[j][k], xi = x[j][B + k];
            acc0[k] += xr * h0[k] - xi * h0[B + k];
            acc0[B + k] += xr * h0[B + k] + xi * h0[k];
            acc1[k] += xr * h1[k] - xi * h1[B + k];
            acc1[B + k] += xr * h1[B + k] + xi * h1[k];
        }
    real_bins(acc0, acc1, was, x, h, off0, off1, count, B);
}

#ifdef FG_SPECTRUM_MAC_AVX2

#include <immintrin.h>

/* Each sum in two registers (the products with the real parts of x, and
 * with the imaginary ones), added at the end: eight chains of one fused
 * multiply-add per pair, so the pairs are not held up by the FMA's
 * latency. */
__attribute__((target("avx2,fma"))) void
fg_spectrum_mac_avx2(float *restrict acc0, float *restrict acc1, const float *const *x,
                     const float *const *h, size_t off0, size_t off1, size_t count, size_t B)
{
    const float was[4] = {acc0[0], acc0[B], acc1[0], acc1[B]};
    for (size_t k = 0; k < B; k += 8) {
        __m256 a0r = _mm256_loadu_ps(acc0 + k), a0i = _mm256_loadu_ps(acc0 + B + k);
        __m256 a1r = _mm256_loadu_ps(acc1 + k), a1i = _mm256_loadu_ps(acc1 + B + k);
        __m256 b0r = _mm256_setzero_ps(), b0i = b0r, b1r = b0r, b1i = b0r;
        for (size_t j = 0; j < count; j++) {
            const float *h0 = h[j] + off0, *h1 = h[j] + off1;
            __m256 xr = _mm256_loadu_ps(x[j] + k), xi = _mm256_loadu_ps(x[j] + B + k);
            __m256 hr = _mm256_loadu_ps(h0 + k), hi = _mm256_loadu_ps(h0 + B + k);
            a0r = _mm256_fmadd_ps(xr, hr, a0r);
            b0r = _mm256_fnmadd_ps(xi, hi, b0r);
            a0i = _mm256_fmadd_ps(xr, hi, a0i);
            b0i = _mm256_fmadd_ps(xi, hr, b0i);
            hr = _mm256_loadu_ps(h1 + k);
            hi = _mm256_loadu_ps(h1 + B + k);
            a1r = _mm256_fmadd_ps(xr, hr, a1r);
            b1r = _mm256_fnmadd_ps(xi, hi, b1r);
            a1i = _mm256_fmadd_ps(xr, hi, a1i);
            b1i = _mm256_fmadd_ps(xi, hr, b1i);
        }
        _mm256_storeu_ps(acc0 + k, _mm256_add_ps(a0r, b0r));
        _mm256_storeu_ps(acc0 + B + k, _mm256_add_ps(a0i, b0i));
        _mm256_storeu_ps(acc1 + k, _mm256_add_ps(a1r, b1r));
        _mm256_storeu_ps(acc1 + B + k, _mm256_add_ps(a1i, b1i));
    }
    real_bins(acc0, acc1, was, x, h, off0, off1, count, B);
}

fg_spectrum_mac_fn fg_spectrum_mac_pick(size_t B)
{
    __builtin_cpu_init();
    if (B % 8 == 0 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return fg_spectrum_mac_avx2;
    return fg_spectrum_mac_plain;
}

#else

fg_spectrum_mac_fn fg_spectrum_mac_pick(size_t B)
{
    (void)B;
    return fg_spectrum_mac_plain;
}

#endif
