#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "iir_internal.h"

#define SNAP 1e-30

void fg_iir_reset(fg_iir *f)
{
    for (unsigned k = 0; k < FG_IIR_MAX_SECTIONS; k++)
        f->z[k][0] = f->z[k][1] = 0.0;
}

static double snap(double v)
{
    return fabs(v) < SNAP ? 0.0 : v;
}

void fg_iir_process(fg_iir *f, float *buf, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        double x = buf[i];
        for (unsigned k = 0; k < f->sections; k++) {
            const fg_biquad *s = &f->sec[k];
            double *z = f->z[k];
            double y = s->b0 * x + z[0];
            z[0] = snap(s->b1 * x - s->a1 * y + z[1]);
            z[1] = snap(s->b2 * x - s->a2 * y);
            x = y;
        }
        buf[i] = (float)x;
    }
}

/* count (1..FG_IIR_LANES) lanes as scalars side by side, every section
 * per sample; the state and coefficients in local arrays, lanes
 * innermost. */
static inline __attribute__((always_inline)) void process_scalars(fg_iir *const *f,
                                                                  float *const *buf,
                                                                  unsigned count,
                                                                  unsigned sections, size_t n)
{
    double b0[FG_IIR_MAX_SECTIONS][FG_IIR_LANES], b1[FG_IIR_MAX_SECTIONS][FG_IIR_LANES],
        b2[FG_IIR_MAX_SECTIONS][FG_IIR_LANES], a1[FG_IIR_MAX_SECTIONS][FG_IIR_LANES],
        a2[FG_IIR_MAX_SECTIONS][FG_IIR_LANES], z0[FG_IIR_MAX_SECTIONS][FG_IIR_LANES],
        z1[FG_IIR_MAX_SECTIONS][FG_IIR_LANES];
    for (unsigned k = 0; k < sections; k++) {
        for (unsigned j = 0; j < count; j++) {
            const fg_biquad *s = &f[j]->sec[k];
            b0[k][j] = s->b0;
            b1[k][j] = s->b1;
            b2[k][j] = s->b2;
            a1[k][j] = s->a1;
            a2[k][j] = s->a2;
            z0[k][j] = f[j]->z[k][0];
            z1[k][j] = f[j]->z[k][1];
        }
    }
    for (size_t i = 0; i < n; i++) {
        double x[FG_IIR_LANES];
        for (unsigned j = 0; j < count; j++)
            x[j] = buf[j][i];
        for (unsigned k = 0; k < sections; k++) {
            for (unsigned j = 0; j < count; j++) {
                double y = b0[k][j] * x[j] + z0[k][j];
                z0[k][j] = snap(b1[k][j] * x[j] - a1[k][j] * y + z1[k][j]);
                z1[k][j] = snap(b2[k][j] * x[j] - a2[k][j] * y);
                x[j] = y;
            }
        }
        for (unsigned j = 0; j < count; j++)
            buf[j][i] = (float)x[j];
    }
    for (unsigned k = 0; k < sections; k++) {
        for (unsigned j = 0; j < count; j++) {
            f[j]->z[k][0] = z0[k][j];
            f[j]->z[k][1] = z1[k][j];
        }
    }
}

/* process_scalars with its lane count constant (the compiler unrolls and
 * interleaves the lanes). */
static inline __attribute__((always_inline)) void scalars_counted(fg_iir *const *f,
                                                                  float *const *buf,
                                                                  unsigned count, size_t n)
{
    const unsigned sections = f[0]->sections;
    switch (count) {
    case 1: process_scalars(f, buf, 1, sections, n); break;
    case 2: process_scalars(f, buf, 2, sections, n); break;
    case 3: process_scalars(f, buf, 3, sections, n); break;
    default: process_scalars(f, buf, FG_IIR_LANES, sections, n); break;
    }
}

static void process_portable(fg_iir *const *f, float *const *buf, unsigned count, size_t n)
{
    scalars_counted(f, buf, count, n);
}

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>

/* The helpers of process_avx2, built for AVX2 (a 256-bit vector passed
 * between functions of another target would change the ABI). */
#define AVX2_INLINE static inline __attribute__((always_inline, target("avx2")))

/* Four lanes side by side, one double each (GCC and clang vector
 * extensions, used where the code is built for AVX: every operation is per
 * lane, so a lane gets the roundings a scalar cascade gives it). */
typedef double lanes_v __attribute__((vector_size(4 * sizeof(double))));
typedef long long lanes_mask __attribute__((vector_size(4 * sizeof(long long))));

/* snap() on each lane: fabs(v), the sign bit cleared, below SNAP (false
 * for NaN) gives +0 */
AVX2_INLINE lanes_v snap_lanes(lanes_v v)
{
    const lanes_mask magnitude = {INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX};
    lanes_mask tiny = (lanes_v)((lanes_mask)v & magnitude) < SNAP;
    return (lanes_v)((lanes_mask)v & ~tiny);
}

typedef struct lanes_section {
    lanes_v b0, b1, b2, a1, a2, z0, z1;
} lanes_section;

AVX2_INLINE lanes_v section_step(lanes_section *s, lanes_v x)
{
    lanes_v y = s->b0 * x + s->z0;
    s->z0 = snap_lanes(s->b1 * x - s->a1 * y + s->z1);
    s->z1 = snap_lanes(s->b2 * x - s->a2 * y);
    return y;
}

/* Runs section s over x[0..m) in place. */
AVX2_INLINE void run_section(lanes_section *s, lanes_v *x,
                                                              size_t m)
{
    lanes_section t = *s;
    for (size_t i = 0; i < m; i++)
        x[i] = section_step(&t, x[i]);
    *s = t;
}

/* Runs sections s and its successor u over x[0..m) in place, skewed by a
 * sample: u takes sample i - 1 while s takes sample i, two recurrences
 * that do not wait for each other. */
AVX2_INLINE void run_section_pair(lanes_section *s,
                                                                   lanes_section *u,
                                                                   lanes_v *x, size_t m)
{
    lanes_section t = *s, v = *u;
    x[0] = section_step(&t, x[0]);
    for (size_t i = 1; i < m; i++) {
        x[i - 1] = section_step(&v, x[i - 1]);
        x[i] = section_step(&t, x[i]);
    }
    x[m - 1] = section_step(&v, x[m - 1]);
    *s = t;
    *u = v;
}

/* Runs sections s[0..4) over x[0..m) in place, each a sample behind the
 * one before it: four recurrences that do not wait for each other. */
AVX2_INLINE void run_section_quad(lanes_section *s, lanes_v *x, size_t m)
{
    lanes_section a = s[0], b = s[1], c = s[2], d = s[3];
    for (size_t i = 0; i < m + 3; i++) {
        if (i >= 3 && i - 3 < m)
            x[i - 3] = section_step(&d, x[i - 3]);
        if (i >= 2 && i - 2 < m)
            x[i - 2] = section_step(&c, x[i - 2]);
        if (i >= 1 && i - 1 < m)
            x[i - 1] = section_step(&b, x[i - 1]);
        if (i < m)
            x[i] = section_step(&a, x[i]);
    }
    s[0] = a;
    s[1] = b;
    s[2] = c;
    s[3] = d;
}

#define CHUNK 64 /* frames per pass through the sections */

/* Zeros for the lanes past count to read. */
static const float silence[CHUNK];

/* x[t], t < 4: frame i + t of the four planes in[0..4), as doubles (a
 * 4 x 4 transpose of floats, then exact conversions). */
AVX2_INLINE void planes_to_lanes(const float *const *in, size_t i, lanes_v *x)
{
    __m128 r0 = _mm_loadu_ps(in[0] + i), r1 = _mm_loadu_ps(in[1] + i);
    __m128 r2 = _mm_loadu_ps(in[2] + i), r3 = _mm_loadu_ps(in[3] + i);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    x[0] = (lanes_v)_mm256_cvtps_pd(r0);
    x[1] = (lanes_v)_mm256_cvtps_pd(r1);
    x[2] = (lanes_v)_mm256_cvtps_pd(r2);
    x[3] = (lanes_v)_mm256_cvtps_pd(r3);
}

/* The reverse: x[0..4) rounded to float (as a scalar cast rounds) into
 * frames at .. at + 4 of the planes buf[0..count). */
AVX2_INLINE void lanes_to_planes(const lanes_v *x, float *const *buf, size_t at, unsigned count)
{
    __m128 r0 = _mm256_cvtpd_ps((__m256d)x[0]), r1 = _mm256_cvtpd_ps((__m256d)x[1]);
    __m128 r2 = _mm256_cvtpd_ps((__m256d)x[2]), r3 = _mm256_cvtpd_ps((__m256d)x[3]);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    const __m128 r[FG_IIR_LANES] = {r0, r1, r2, r3};
    for (unsigned j = 0; j < count; j++)
        _mm_storeu_ps(buf[j] + at, r[j]);
}

/* count (1..FG_IIR_LANES) lanes: the cascade runs section by section over
 * chunks of CHUNK frames held in double (as the scalar cascade holds its
 * value between sections), so each section's state stays in registers.
 * Four sections run at once, else two at a time. Lanes past count run
 * zero filters on zeros and are not written. */
AVX2_INLINE void process_lanes(fg_iir *const *f,
                                                                float *const *buf,
                                                                unsigned count, size_t n)
{
    const unsigned sections = f[0]->sections;
    lanes_section sec[FG_IIR_MAX_SECTIONS];
    memset(sec, 0, sizeof sec);
    for (unsigned k = 0; k < sections; k++) {
        for (unsigned j = 0; j < count; j++) {
            const fg_biquad *b = &f[j]->sec[k];
            sec[k].b0[j] = b->b0;
            sec[k].b1[j] = b->b1;
            sec[k].b2[j] = b->b2;
            sec[k].a1[j] = b->a1;
            sec[k].a2[j] = b->a2;
            sec[k].z0[j] = f[j]->z[k][0];
            sec[k].z1[j] = f[j]->z[k][1];
        }
    }
    lanes_v x[CHUNK];
    for (size_t start = 0; start < n; start += CHUNK) {
        size_t m = n - start < CHUNK ? n - start : CHUNK;
        const float *in[FG_IIR_LANES];
        for (unsigned j = 0; j < FG_IIR_LANES; j++)
            in[j] = j < count ? buf[j] + start : silence;
        size_t i = 0;
        for (; i + 4 <= m; i += 4) /* four frames of four lanes: a transpose */
            planes_to_lanes(in, i, x + i);
        for (; i < m; i++) {
            lanes_v v = {0.0, 0.0, 0.0, 0.0};
            for (unsigned j = 0; j < count; j++)
                v[j] = in[j][i];
            x[i] = v;
        }
        unsigned k = 0;
        if (sections == 4) {
            run_section_quad(sec, x, m);
            k = 4;
        }
        for (; k + 1 < sections; k += 2)
            run_section_pair(&sec[k], &sec[k + 1], x, m);
        for (; k < sections; k++)
            run_section(&sec[k], x, m);
        for (i = 0; i + 4 <= m; i += 4)
            lanes_to_planes(x + i, buf, start + i, count);
        for (; i < m; i++)
            for (unsigned j = 0; j < count; j++)
                buf[j][start + i] = (float)x[i][j];
    }
    for (unsigned k = 0; k < sections; k++) {
        for (unsigned j = 0; j < count; j++) {
            f[j]->z[k][0] = sec[k].z0[j];
            f[j]->z[k][1] = sec[k].z1[j];
        }
    }
}

/* AVX's four-double registers: three or four lanes run as vectors, fewer
 * as scalars (the vectors' moves between planes and lanes cost more than
 * they save there). Without FMA
 * (and with ISO C's contraction off) each lane gets the portable code's
 * roundings in the same order. */
__attribute__((target("avx2"))) static void process_avx2(fg_iir *const *f, float *const *buf,
                                                         unsigned count, size_t n)
{
    if (count >= 4)
        process_lanes(f, buf, FG_IIR_LANES, n);
    else if (count == 3)
        process_lanes(f, buf, 3, n);
    else
        scalars_counted(f, buf, count, n);
}
#endif

void fg_iir_process_lanes(fg_iir *const *f, float *const *buf, unsigned count, size_t n)
{
    if (count == 0 || n == 0)
        return;
#if defined(__x86_64__) || defined(__i386__)
    if (__builtin_cpu_supports("avx2")) {
        process_avx2(f, buf, count, n);
        return;
    }
#endif
    process_portable(f, buf, count, n);
}

fg_phasor fg_phasor_at(double w)
{
    return (fg_phasor){cos(w), sin(w), cos(2.0 * w), sin(2.0 * w)};
}

/* |c0 + c1 e^{-jw} + c2 e^{-2jw}|^2 */
static double poly_mag2(double c0, double c1, double c2, const fg_phasor *e)
{
    double re = c0 + c1 * e->c1 + c2 * e->c2;
    double im = c1 * e->s1 + c2 * e->s2;
    return re * re + im * im;
}

static double biquad_mag2(const fg_biquad *s, const fg_phasor *e)
{
    return poly_mag2(s->b0, s->b1, s->b2, e) / poly_mag2(1.0, s->a1, s->a2, e);
}

double fg_iir_db(const fg_iir *f, double w)
{
    fg_phasor e = fg_phasor_at(w);
    double m2 = 1.0;
    for (unsigned k = 0; k < f->sections; k++)
        m2 *= biquad_mag2(&f->sec[k], &e);
    return 10.0 * log10(m2);
}
