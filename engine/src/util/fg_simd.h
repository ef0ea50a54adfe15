/* Several floats (or doubles) at a time: the vector types the engine's
 * kernels share (the field solver's rows, the convolver's spectra).
 *
 * With GCC or Clang: their vector extensions, plain C that compiles to
 * SSE2 on x86-64 (and NEON on ARM) at any optimisation level, without a
 * target-specific intrinsic or flag. Any other C11 compiler, or a build
 * with FG_SIMD_SCALAR defined (to test this path), gets one lane: the
 * same kernels on scalars. Loads and stores go through memcpy, so data
 * needs no alignment. The arithmetic is lane by lane, in the order
 * written: a vector kernel gives the same floats as the same expression on
 * scalars (no reassociation; nothing is contracted into FMAs unless the
 * compiler is told to). Where the compiler has lane shuffles,
 * FG_VF_SHUFFLE is defined with a 4 x 4 transpose, an even/odd split, a
 * reversal and an interleave.
 *
 * A file built for AVX2 (with -mavx2, chosen at run time: see
 * field/kernels_avx2.h) may define FG_SIMD_WIDE before it includes this
 * header: eight floats and four doubles, the same lane-by-lane
 * arithmetic, and no FG_VF_SHUFFLE. */
#ifndef FULGUR_UTIL_FG_SIMD_H
#define FULGUR_UTIL_FG_SIMD_H

#include <stdint.h>
#include <string.h>

#if (defined(__GNUC__) || defined(__clang__)) && !defined(FG_SIMD_SCALAR)

#ifdef FG_SIMD_WIDE

#define FG_VF_LANES 8
#define FG_VD_LANES 4

typedef float fg_vf __attribute__((vector_size(32)));
typedef int32_t fg_vi __attribute__((vector_size(32)));
typedef double fg_vd __attribute__((vector_size(32)));
typedef int64_t fg_vl __attribute__((vector_size(32)));

static inline fg_vf fg_vf_set(float x)
{
    return (fg_vf){x, x, x, x, x, x, x, x};
}

static inline fg_vd fg_vd_set(double x)
{
    return (fg_vd){x, x, x, x};
}

#else

#define FG_VF_LANES 4
#define FG_VD_LANES 2

typedef float fg_vf __attribute__((vector_size(16)));
typedef int32_t fg_vi __attribute__((vector_size(16)));
typedef double fg_vd __attribute__((vector_size(16)));
typedef int64_t fg_vl __attribute__((vector_size(16)));

static inline fg_vf fg_vf_set(float x)
{
    return (fg_vf){x, x, x, x};
}

static inline fg_vd fg_vd_set(double x)
{
    return (fg_vd){x, x};
}

#endif

#if defined(__has_builtin) && !defined(FG_SIMD_WIDE)
#if __has_builtin(__builtin_shufflevector)
/* Lane shuffles (Clang, GCC 12 and later). */
#define FG_VF_SHUFFLE 1

/* The 4 x 4 floats of r[0..4) transposed: lane l of r[j] becomes lane j
 * of r[l]. */
static inline void fg_vf_transpose(fg_vf r[4])
{
    fg_vf t0 = __builtin_shufflevector(r[0], r[1], 0, 4, 1, 5);
    fg_vf t1 = __builtin_shufflevector(r[0], r[1], 2, 6, 3, 7);
    fg_vf t2 = __builtin_shufflevector(r[2], r[3], 0, 4, 1, 5);
    fg_vf t3 = __builtin_shufflevector(r[2], r[3], 2, 6, 3, 7);
    r[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    r[1] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    r[2] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    r[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

/* The even-indexed and the odd-indexed floats of the eight in a, b. */
static inline fg_vf fg_vf_even(fg_vf a, fg_vf b)
{
    return __builtin_shufflevector(a, b, 0, 2, 4, 6);
}

static inline fg_vf fg_vf_odd(fg_vf a, fg_vf b)
{
    return __builtin_shufflevector(a, b, 1, 3, 5, 7);
}

/* The four floats of a, last first. */
static inline fg_vf fg_vf_reverse(fg_vf a)
{
    return __builtin_shufflevector(a, a, 3, 2, 1, 0);
}

/* a0 b0 a1 b1 a2 b2 a3 b3 to p[0 .. 8). */
static inline void fg_vf_interleave(fg_vf a, fg_vf b, float *p)
{
    fg_vf lo = __builtin_shufflevector(a, b, 0, 4, 1, 5),
          hi = __builtin_shufflevector(a, b, 2, 6, 3, 7);
    memcpy(p, &lo, sizeof lo);
    memcpy(p + 4, &hi, sizeof hi);
}
#endif
#endif

#else

#define FG_VF_LANES 1
#define FG_VD_LANES 1

typedef float fg_vf;
typedef int fg_vi;
typedef double fg_vd;
typedef int fg_vl;

static inline fg_vf fg_vf_set(float x)
{
    return x;
}

static inline fg_vd fg_vd_set(double x)
{
    return x;
}

#endif

static inline fg_vf fg_vf_load(const float *p)
{
    fg_vf v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void fg_vf_store(float *p, fg_vf v)
{
    memcpy(p, &v, sizeof v);
}

static inline fg_vd fg_vd_load(const double *p)
{
    fg_vd v;
    memcpy(&v, p, sizeof v);
    return v;
}

#endif
