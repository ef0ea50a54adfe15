/* The difference-domain accumulators' integration four at once, one per
 * lane of an AVX vector of doubles (core/accum_internal.h). Each lane runs
 * end_one's three sums in its order, so every accumulator gives the same
 * floats as alone; four chains in one vector also run four times as many
 * sums per add's latency as one. */
#include "accum_internal.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))

#include <immintrin.h>

/* target "avx2" without "fma": nothing here may be fused, as nothing in
 * the portable end is */
#define AVX2 __attribute__((target("avx2")))

AVX2 uint32_t fg_accum_end_four_avx2(fg_accum *const b[4], float *const out[4], double sum[3][4],
                                     uint32_t frames)
{
    const uint32_t end = frames & ~(uint32_t)3;
    const __m256d zero = _mm256_setzero_pd();
    __m256d d2 = _mm256_loadu_pd(sum[0]), d1 = _mm256_loadu_pd(sum[1]), y = _mm256_loadu_pd(sum[2]);
    for (uint32_t k = 0; k < end; k += 4) {
        /* r[c]: b[c]'s samples k .. k + 3, transposed to v[j]: sample
         * k + j of the four */
        __m256d r[4];
        for (int c = 0; c < 4; c++) {
            r[c] = _mm256_loadu_pd(b[c]->d3 + k);
            _mm256_storeu_pd(b[c]->d3 + k, zero);
        }
        __m256d t0 = _mm256_unpacklo_pd(r[0], r[1]), t1 = _mm256_unpackhi_pd(r[0], r[1]);
        __m256d t2 = _mm256_unpacklo_pd(r[2], r[3]), t3 = _mm256_unpackhi_pd(r[2], r[3]);
        __m256d v[4] = {_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
                        _mm256_permute2f128_pd(t0, t2, 0x31), _mm256_permute2f128_pd(t1, t3, 0x31)};
        __m128 f[4];
        for (int j = 0; j < 4; j++) {
            d2 = _mm256_add_pd(d2, v[j]);
            d1 = _mm256_add_pd(d1, d2);
            y = _mm256_add_pd(y, d1);
            f[j] = _mm256_cvtpd_ps(y);
        }
        _MM_TRANSPOSE4_PS(f[0], f[1], f[2], f[3]);
        for (int c = 0; c < 4; c++)
            _mm_storeu_ps(out[c] + k, _mm_add_ps(_mm_loadu_ps(out[c] + k), f[c]));
    }
    _mm256_storeu_pd(sum[0], d2);
    _mm256_storeu_pd(sum[1], d1);
    _mm256_storeu_pd(sum[2], y);
    return end;
}

bool fg_accum_avx2_available(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
}

#else

uint32_t fg_accum_end_four_avx2(fg_accum *const b[4], float *const out[4], double sum[3][4],
                                uint32_t frames)
{
    (void)b;
    (void)out;
    (void)sum;
    (void)frames;
    return 0; /* never chosen: fg_accum_avx2_available says no */
}

bool fg_accum_avx2_available(void)
{
    return false;
}

#endif
