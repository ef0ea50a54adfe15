#include <math.h>

#include "fft_avx2_internal.h"
#include "fg_math.h"

/* Twiddles in double, rounded once: W = e^{-2 pi i / 64} raised to n2 k1
 * for the four-step's middle multiply (lane n2 of vector k1), e^{-2 pi i
 * k / 128}, k < 64, for the 256-point transform's radix-2 step, and e^{-2
 * pi i k / n}, k < n/2, for the real split. */
bool fg_fft_avx2_init(fg_fft_avx2 *f, size_t n)
{
    if (n != 128 && n != 256)
        return false;
    f->n = n;
    for (int k1 = 0; k1 < 8; k1++)
        for (int n2 = 0; n2 < 8; n2++) {
            double a = -2.0 * FG_PI * (double)(n2 * k1) / 64.0;
            f->twiddle_re[8 * k1 + n2] = (float)cos(a);
            f->twiddle_im[8 * k1 + n2] = (float)sin(a);
        }
    for (int k = 0; k < 64; k++) {
        double a = -2.0 * FG_PI * (double)k / 128.0;
        f->join_re[k] = (float)cos(a);
        f->join_im[k] = (float)sin(a);
    }
    for (size_t k = 0; k < 128; k++) {
        double a = -2.0 * FG_PI * (double)k / (double)n;
        f->split_re[k] = k < n / 2 ? (float)cos(a) : 0.0f;
        f->split_im[k] = k < n / 2 ? (float)sin(a) : 0.0f;
    }
    return true;
}

#ifdef FG_FFT_AVX2

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
INLINE_AVX2 void dft64(const fg_fft_avx2 *f, cv z[8])
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

/* The real spectrum X[0 .. M] of n = 2M points from the complex one of
 * z[k] = x[2k] + i x[2k+1], Z[0 .. M] in re and im (Z[M] = Z[0]), packed
 * into x: X[k] = E + W^k O, E = (Z[k] + conj Z[M - k]) / 2,
 * O = (Z[k] - conj Z[M - k]) / 2i. */
INLINE_AVX2 void split_forward(const fg_fft_avx2 *f, const float *re, const float *im, int M,
                               float *x)
{
    const __m256 half = _mm256_set1_ps(0.5f);
    for (int j = 0; j < M / 8; j++) {
        __m256 ar = _mm256_loadu_ps(re + 8 * j), ai = _mm256_loadu_ps(im + 8 * j);
        __m256 br = load_reversed(re + M - 8 * j), bi = load_reversed(im + M - 8 * j);
        cv e = {_mm256_mul_ps(half, _mm256_add_ps(ar, br)),
                _mm256_mul_ps(half, _mm256_sub_ps(ai, bi))};
        cv o = {_mm256_mul_ps(half, _mm256_add_ps(ai, bi)),
                _mm256_mul_ps(half, _mm256_sub_ps(br, ar))};
        cv w = {_mm256_loadu_ps(f->split_re + 8 * j), _mm256_loadu_ps(f->split_im + 8 * j)};
        cv X = add(e, mul(o, w));
        _mm256_storeu_ps(x + 8 * j, X.re);
        _mm256_storeu_ps(x + M + 8 * j, X.im);
    }
    x[0] = re[0] + im[0];
    x[M] = re[0] - im[0];
}

/* Vector j of the complex values the inverse transforms, from the packed
 * spectrum x of n = 2M points: E = (X[k] + conj X[M - k]) / 2,
 * O = (X[k] - conj X[M - k]) W^-k / 2, Z[k] = E + i O, conjugated and
 * scaled by 1/n so that the forward DFT serves: z = conj(DFT(conj Z)). */
INLINE_AVX2 cv unsplit(const fg_fft_avx2 *f, const float *x, int M, int j)
{
    const __m256 scale = _mm256_set1_ps(1.0f / (float)(2 * M));
    const __m256 zero = _mm256_setzero_ps();
    __m256 ar = _mm256_loadu_ps(x + 8 * j), ai = _mm256_loadu_ps(x + M + 8 * j);
    __m256 br = load_reversed(x + M - 8 * j), bi;
    if (j == 0) {
        /* lane 0: X[0] and X[M] are real (x[M] holds X[M]); lanes 1..7
         * take Im X[M - 1 .. M - 7] */
        const __m256 first = _mm256_castsi256_ps(_mm256_setr_epi32(0, -1, -1, -1, -1, -1, -1, -1));
        ai = _mm256_and_ps(ai, first);
        __m256 tail = _mm256_loadu_ps(x + 2 * M - 8); /* Im X[M - 8 .. M - 1] */
        bi = _mm256_and_ps(
            _mm256_permutevar8x32_ps(tail, _mm256_setr_epi32(0, 7, 6, 5, 4, 3, 2, 1)), first);
    } else {
        bi = load_reversed(x + 2 * M - 8 * j);
    }
    cv e = {_mm256_add_ps(ar, br), _mm256_sub_ps(ai, bi)};
    cv d = {_mm256_sub_ps(ar, br), _mm256_add_ps(ai, bi)};
    cv w = {_mm256_loadu_ps(f->split_re + 8 * j),
            _mm256_sub_ps(zero, _mm256_loadu_ps(f->split_im + 8 * j))};
    cv o = mul(d, w);
    return (cv){_mm256_mul_ps(scale, _mm256_sub_ps(e.re, o.im)),
                _mm256_mul_ps(scale, _mm256_sub_ps(zero, _mm256_add_ps(e.im, o.re)))};
}

/* 128 points: the 64 values z[k] in the eight vectors, one DFT64. */
INLINE_AVX2 void forward128(const fg_fft_avx2 *f, const float *window, float *x)
{
    /* the even and the odd floats of sixteen, whose 128-bit halves the
     * shuffles leave in the order 0 2 1 3 */
    cv z[8];
    for (int j = 0; j < 8; j++) {
        __m256 a = _mm256_loadu_ps(window + 16 * j), b = _mm256_loadu_ps(window + 16 * j + 8);
        __m256 even = _mm256_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0));
        __m256 odd = _mm256_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1));
        z[j] = (cv){_mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(even), 0xD8)),
                    _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(odd), 0xD8))};
    }
    dft64(f, z);
    float re[72], im[72]; /* Z[0 .. 64] with Z[64] = Z[0], for the reversed loads */
    for (int j = 0; j < 8; j++) {
        _mm256_storeu_ps(re + 8 * j, z[j].re);
        _mm256_storeu_ps(im + 8 * j, z[j].im);
    }
    re[64] = re[0];
    im[64] = im[0];
    split_forward(f, re, im, 64, x);
}

/* 256 points: the 128 values z[k] by decimation in time, Z[k] = E[k] +
 * W^k O[k] and Z[k + 64] = E[k] - W^k O[k] (W = e^{-2 pi i / 128}), E
 * the DFT64 of z[2m] = x[4m] + i x[4m+1] and O that of z[2m+1]. */
INLINE_AVX2 void forward256(const fg_fft_avx2 *f, const float *window, float *x)
{
    /* the four floats of each m apart: the 128-bit halves of the four
     * loads regrouped (m, m + 4) and each half's 4 x 4 transposed */
    float even_re[64], even_im[64], odd_re[64], odd_im[64];
    for (int j = 0; j < 8; j++) {
        const float *w = window + 32 * j;
        __m256 a0 = _mm256_loadu_ps(w), a1 = _mm256_loadu_ps(w + 8);
        __m256 a2 = _mm256_loadu_ps(w + 16), a3 = _mm256_loadu_ps(w + 24);
        __m256 b0 = _mm256_permute2f128_ps(a0, a2, 0x20), b1 = _mm256_permute2f128_ps(a0, a2, 0x31);
        __m256 b2 = _mm256_permute2f128_ps(a1, a3, 0x20), b3 = _mm256_permute2f128_ps(a1, a3, 0x31);
        __m256 t0 = _mm256_unpacklo_ps(b0, b1), t1 = _mm256_unpackhi_ps(b0, b1);
        __m256 t2 = _mm256_unpacklo_ps(b2, b3), t3 = _mm256_unpackhi_ps(b2, b3);
        _mm256_storeu_ps(even_re + 8 * j, _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)));
        _mm256_storeu_ps(even_im + 8 * j, _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)));
        _mm256_storeu_ps(odd_re + 8 * j, _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)));
        _mm256_storeu_ps(odd_im + 8 * j, _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2)));
    }
    float re[136], im[136]; /* E, then Z[0 .. 128] with Z[128] = Z[0] */
    cv z[8];
    for (int j = 0; j < 8; j++)
        z[j] = (cv){_mm256_loadu_ps(even_re + 8 * j), _mm256_loadu_ps(even_im + 8 * j)};
    dft64(f, z);
    for (int j = 0; j < 8; j++) {
        _mm256_storeu_ps(re + 8 * j, z[j].re);
        _mm256_storeu_ps(im + 8 * j, z[j].im);
    }
    for (int j = 0; j < 8; j++)
        z[j] = (cv){_mm256_loadu_ps(odd_re + 8 * j), _mm256_loadu_ps(odd_im + 8 * j)};
    dft64(f, z);
    for (int j = 0; j < 8; j++) {
        cv e = {_mm256_loadu_ps(re + 8 * j), _mm256_loadu_ps(im + 8 * j)};
        cv t = mul(z[j],
                   (cv){_mm256_loadu_ps(f->join_re + 8 * j), _mm256_loadu_ps(f->join_im + 8 * j)});
        cv lo = add(e, t), hi = sub(e, t);
        _mm256_storeu_ps(re + 8 * j, lo.re);
        _mm256_storeu_ps(im + 8 * j, lo.im);
        _mm256_storeu_ps(re + 64 + 8 * j, hi.re);
        _mm256_storeu_ps(im + 64 + 8 * j, hi.im);
    }
    re[128] = re[0];
    im[128] = im[0];
    split_forward(f, re, im, 128, x);
}

AVX2 void fg_fft_avx2_forward(const fg_fft_avx2 *f, const float *window, float *x)
{
    if (f->n == 128)
        forward128(f, window, x);
    else
        forward256(f, window, x);
}

INLINE_AVX2 void inverse128(const fg_fft_avx2 *f, float *x)
{
    const __m256 zero = _mm256_setzero_ps();
    cv z[8];
    for (int j = 0; j < 8; j++)
        z[j] = unsplit(f, x, 64, j);
    dft64(f, z);
    for (int j = 0; j < 8; j++) {
        _mm256_storeu_ps(x + 8 * j, z[j].re);
        _mm256_storeu_ps(x + 64 + 8 * j, _mm256_sub_ps(zero, z[j].im));
    }
}

/* a[0 .. 8) and b[0 .. 8) interleaved into out[0 .. 16): a0 b0 a1 b1 ... */
INLINE_AVX2 void store_interleaved(float *out, __m256 a, __m256 b)
{
    __m256 lo = _mm256_unpacklo_ps(a, b), hi = _mm256_unpackhi_ps(a, b);
    _mm256_storeu_ps(out, _mm256_permute2f128_ps(lo, hi, 0x20));
    _mm256_storeu_ps(out + 8, _mm256_permute2f128_ps(lo, hi, 0x31));
}

/* 256 points by decimation in frequency: with y the 128 values to
 * transform, Y[2k] is the DFT64 of y[m] + y[m + 64] and Y[2k + 1] that of
 * (y[m] - y[m + 64]) W^m (W = e^{-2 pi i / 128}). */
INLINE_AVX2 void inverse256(const fg_fft_avx2 *f, float *x)
{
    const __m256 zero = _mm256_setzero_ps();
    float yr[128], yi[128];
    for (int j = 0; j < 16; j++) {
        cv y = unsplit(f, x, 128, j);
        _mm256_storeu_ps(yr + 8 * j, y.re);
        _mm256_storeu_ps(yi + 8 * j, y.im);
    }
    /* the sums into z, the twiddled differences where y[0 .. 64) was */
    cv z[8];
    for (int j = 0; j < 8; j++) {
        cv a = {_mm256_loadu_ps(yr + 8 * j), _mm256_loadu_ps(yi + 8 * j)};
        cv b = {_mm256_loadu_ps(yr + 64 + 8 * j), _mm256_loadu_ps(yi + 64 + 8 * j)};
        z[j] = add(a, b);
        cv d = mul(sub(a, b),
                   (cv){_mm256_loadu_ps(f->join_re + 8 * j), _mm256_loadu_ps(f->join_im + 8 * j)});
        _mm256_storeu_ps(yr + 8 * j, d.re);
        _mm256_storeu_ps(yi + 8 * j, d.im);
    }
    dft64(f, z); /* Y[2k] */
    for (int j = 0; j < 8; j++) {
        _mm256_storeu_ps(yr + 64 + 8 * j, z[j].re);
        _mm256_storeu_ps(yi + 64 + 8 * j, z[j].im);
    }
    for (int j = 0; j < 8; j++)
        z[j] = (cv){_mm256_loadu_ps(yr + 8 * j), _mm256_loadu_ps(yi + 8 * j)};
    dft64(f, z); /* Y[2k + 1] */
    /* z[t] = conj Y[t]: Re z[t] as element t, Im z[t] as element 128 + t */
    for (int j = 0; j < 8; j++) {
        store_interleaved(x + 16 * j, _mm256_loadu_ps(yr + 64 + 8 * j), z[j].re);
        store_interleaved(x + 128 + 16 * j, _mm256_sub_ps(zero, _mm256_loadu_ps(yi + 64 + 8 * j)),
                          _mm256_sub_ps(zero, z[j].im));
    }
}

AVX2 void fg_fft_avx2_inverse(const fg_fft_avx2 *f, float *x)
{
    if (f->n == 128)
        inverse128(f, x);
    else
        inverse256(f, x);
}

bool fg_fft_avx2_available(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

#else

bool fg_fft_avx2_available(void)
{
    return false;
}

#endif
