#include <math.h>

#include "fft128_internal.h"
#include "fg_math.h"

/* Twiddles in double, rounded once: W = e^{-2 pi i / 64} raised to n2 k1
 * for the four-step's middle multiply (lane n2 of vector k1), and e^{-2 pi
 * i k / 128}, k < 64, for the real split. */
void fg_fft128_init(fg_fft128 *f)
{
    for (int k1 = 0; k1 < 8; k1++)
        for (int n2 = 0; n2 < 8; n2++) {
            double a = -2.0 * FG_PI * (double)(n2 * k1) / 64.0;
            f->twiddle_re[8 * k1 + n2] = (float)cos(a);
            f->twiddle_im[8 * k1 + n2] = (float)sin(a);
        }
    for (int k = 0; k < 64; k++) {
        double a = -2.0 * FG_PI * (double)k / 128.0;
        f->split_re[k] = (float)cos(a);
        f->split_im[k] = (float)sin(a);
    }
}

#ifdef FG_FFT128_AVX2

#include <immintrin.h>

#define AVX2 __attribute__((target("avx2,fma")))
#define INLINE_AVX2 __attribute__((target("avx2,fma"), always_inline)) static inline

typedef struct cv {
    __m256 re, im;
} cv;

INLINE_AVX2 cv add(cv a, cv b)
{
    return (cv){_mm256_add_ps(a.re, b.re), _mm256_add_ps(a.im, b.im)};
}

INLINE_AVX2 cv sub(cv a, cv b)
{
    return (cv){_mm256_sub_ps(a.re, b.re), _mm256_sub_ps(a.im, b.im)};
}

/* a times -i */
INLINE_AVX2 cv times_minus_i(cv a)
{
    return (cv){a.im, _mm256_sub_ps(_mm256_setzero_ps(), a.re)};
}

INLINE_AVX2 cv mul(cv a, cv w)
{
    return (cv){_mm256_fmsub_ps(a.re, w.re, _mm256_mul_ps(a.im, w.im)),
                _mm256_fmadd_ps(a.re, w.im, _mm256_mul_ps(a.im, w.re))};
}

/* The eight-point forward DFT of a[0..8) across the vectors (each lane its
 * own transform), in place: even and odd halves, each a four-point DFT,
 * joined by e^{-2 pi i k / 8}. */
INLINE_AVX2 void dft8(cv a[8])
{
    const __m256 h = _mm256_set1_ps((float)(0.5 * sqrt(2.0)));
    cv s0 = add(a[0], a[4]), d0 = sub(a[0], a[4]);
    cv s1 = add(a[2], a[6]), d1 = times_minus_i(sub(a[2], a[6]));
    cv e0 = add(s0, s1), e2 = sub(s0, s1), e1 = add(d0, d1), e3 = sub(d0, d1);
    cv t0 = add(a[1], a[5]), u0 = sub(a[1], a[5]);
    cv t1 = add(a[3], a[7]), u1 = times_minus_i(sub(a[3], a[7]));
    cv o0 = add(t0, t1), o2 = sub(t0, t1), o1 = add(u0, u1), o3 = sub(u0, u1);
    /* o1 (1 - i) / sqrt 2, o2 (-i), o3 (-1 - i) / sqrt 2 */
    o1 = (cv){_mm256_mul_ps(h, _mm256_add_ps(o1.re, o1.im)),
              _mm256_mul_ps(h, _mm256_sub_ps(o1.im, o1.re))};
    o2 = times_minus_i(o2);
    o3 = (cv){_mm256_mul_ps(h, _mm256_sub_ps(o3.im, o3.re)),
              _mm256_mul_ps(h, _mm256_sub_ps(_mm256_setzero_ps(), _mm256_add_ps(o3.re, o3.im)))};
    a[0] = add(e0, o0);
    a[4] = sub(e0, o0);
    a[1] = add(e1, o1);
    a[5] = sub(e1, o1);
    a[2] = add(e2, o2);
    a[6] = sub(e2, o2);
    a[3] = add(e3, o3);
    a[7] = sub(e3, o3);
}

/* The 8 x 8 floats of r transposed: lane l of r[j] becomes lane j of r[l]. */
INLINE_AVX2 void transpose(__m256 r[8])
{
    __m256 t[8], u[8];
    for (int j = 0; j < 8; j += 2) {
        t[j] = _mm256_unpacklo_ps(r[j], r[j + 1]);
        t[j + 1] = _mm256_unpackhi_ps(r[j], r[j + 1]);
    }
    for (int j = 0; j < 8; j += 4) {
        u[j] = _mm256_shuffle_ps(t[j], t[j + 2], _MM_SHUFFLE(1, 0, 1, 0));
        u[j + 1] = _mm256_shuffle_ps(t[j], t[j + 2], _MM_SHUFFLE(3, 2, 3, 2));
        u[j + 2] = _mm256_shuffle_ps(t[j + 1], t[j + 3], _MM_SHUFFLE(1, 0, 1, 0));
        u[j + 3] = _mm256_shuffle_ps(t[j + 1], t[j + 3], _MM_SHUFFLE(3, 2, 3, 2));
    }
    for (int j = 0; j < 4; j++) {
        r[j] = _mm256_permute2f128_ps(u[j], u[j + 4], 0x20);
        r[j + 4] = _mm256_permute2f128_ps(u[j], u[j + 4], 0x31);
    }
}

/* The 64-point forward DFT of z (z[0..8): the complex values 8 n1 .. 8 n1
 * + 7 as vector n1), in natural order back into z, by four steps: eight
 * eight-point DFTs down the columns, the twiddles, a transpose, eight
 * more. */
INLINE_AVX2 void dft64(const fg_fft128 *f, cv z[8])
{
    dft8(z);
    for (int k1 = 1; k1 < 8; k1++)
        z[k1] = mul(z[k1], (cv){_mm256_loadu_ps(f->twiddle_re + 8 * k1),
                                _mm256_loadu_ps(f->twiddle_im + 8 * k1)});
    __m256 re[8], im[8];
    for (int j = 0; j < 8; j++) {
        re[j] = z[j].re;
        im[j] = z[j].im;
    }
    transpose(re);
    transpose(im);
    for (int j = 0; j < 8; j++)
        z[j] = (cv){re[j], im[j]};
    dft8(z);
}

/* The eight floats at p[-7 .. 0], last first. */
INLINE_AVX2 __m256 load_reversed(const float *p)
{
    return _mm256_permutevar8x32_ps(_mm256_loadu_ps(p - 7),
                                    _mm256_setr_epi32(7, 6, 5, 4, 3, 2, 1, 0));
}

AVX2 void fg_fft128_forward_avx2(const fg_fft128 *f, const float *window, float *x)
{
    /* z[k] = window[2k] + i window[2k + 1]: the even and the odd floats of
     * sixteen, whose 128-bit halves the shuffles leave in the order 0 2 1
     * 3 */
    cv z[8];
    for (int j = 0; j < 8; j++) {
        __m256 a = _mm256_loadu_ps(window + 16 * j), b = _mm256_loadu_ps(window + 16 * j + 8);
        __m256 even = _mm256_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0));
        __m256 odd = _mm256_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1));
        z[j] = (cv){_mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(even), 0xD8)),
                    _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(odd), 0xD8))};
    }
    dft64(f, z);
    /* Z[0 .. 64] with Z[64] = Z[0], for the reversed loads */
    float re[72], im[72];
    for (int j = 0; j < 8; j++) {
        _mm256_storeu_ps(re + 8 * j, z[j].re);
        _mm256_storeu_ps(im + 8 * j, z[j].im);
    }
    re[64] = re[0];
    im[64] = im[0];
    /* X[k] = E + W^k O, E = (Z[k] + conj Z[64 - k]) / 2,
     * O = (Z[k] - conj Z[64 - k]) / 2i */
    const __m256 half = _mm256_set1_ps(0.5f);
    for (int j = 0; j < 8; j++) {
        __m256 ar = z[j].re, ai = z[j].im;
        __m256 br = load_reversed(re + 64 - 8 * j), bi = load_reversed(im + 64 - 8 * j);
        cv e = {_mm256_mul_ps(half, _mm256_add_ps(ar, br)),
                _mm256_mul_ps(half, _mm256_sub_ps(ai, bi))};
        cv o = {_mm256_mul_ps(half, _mm256_add_ps(ai, bi)),
                _mm256_mul_ps(half, _mm256_sub_ps(br, ar))};
        cv w = {_mm256_loadu_ps(f->split_re + 8 * j), _mm256_loadu_ps(f->split_im + 8 * j)};
        cv X = add(e, mul(o, w));
        _mm256_storeu_ps(x + 8 * j, X.re);
        _mm256_storeu_ps(x + 64 + 8 * j, X.im);
    }
    x[0] = re[0] + im[0];
    x[64] = re[0] - im[0];
}

AVX2 void fg_fft128_inverse_avx2(const fg_fft128 *f, float *x)
{
    /* E = (X[k] + conj X[64 - k]) / 2, O = (X[k] - conj X[64 - k]) W^-k / 2,
     * Z[k] = E + i O, conjugated (and scaled by 1/64 for the inverse) so
     * that the forward DFT serves: z = conj(DFT(conj Z)) / 64. */
    const __m256 scale = _mm256_set1_ps(1.0f / 128.0f);
    const __m256 zero = _mm256_setzero_ps();
    const __m256 first = _mm256_castsi256_ps(_mm256_setr_epi32(0, -1, -1, -1, -1, -1, -1, -1));
    cv z[8];
    for (int j = 0; j < 8; j++) {
        __m256 ar = _mm256_loadu_ps(x + 8 * j), ai = _mm256_loadu_ps(x + 64 + 8 * j);
        __m256 br = load_reversed(x + 64 - 8 * j), bi;
        if (j == 0) {
            /* lane 0: X[0] and X[64] are real (x[64] holds X[64]); lanes
             * 1..7 take Im X[63 .. 57] */
            ai = _mm256_and_ps(ai, first);
            __m256 tail = _mm256_loadu_ps(x + 120); /* Im X[56 .. 63] */
            bi = _mm256_and_ps(
                _mm256_permutevar8x32_ps(tail, _mm256_setr_epi32(0, 7, 6, 5, 4, 3, 2, 1)), first);
        } else {
            bi = load_reversed(x + 128 - 8 * j);
        }
        cv e = {_mm256_add_ps(ar, br), _mm256_sub_ps(ai, bi)};
        cv d = {_mm256_sub_ps(ar, br), _mm256_add_ps(ai, bi)};
        cv w = {_mm256_loadu_ps(f->split_re + 8 * j),
                _mm256_sub_ps(zero, _mm256_loadu_ps(f->split_im + 8 * j))};
        cv o = mul(d, w);
        /* conj(E + i O) scaled */
        z[j] = (cv){_mm256_mul_ps(scale, _mm256_sub_ps(e.re, o.im)),
                    _mm256_mul_ps(scale, _mm256_sub_ps(zero, _mm256_add_ps(e.im, o.re)))};
    }
    dft64(f, z);
    for (int j = 0; j < 8; j++) {
        _mm256_storeu_ps(x + 8 * j, z[j].re);
        _mm256_storeu_ps(x + 64 + 8 * j, _mm256_sub_ps(zero, z[j].im));
    }
}

bool fg_fft128_avx2_available(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

#else

bool fg_fft128_avx2_available(void)
{
    return false;
}

#endif
