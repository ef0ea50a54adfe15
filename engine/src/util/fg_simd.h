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
 * compiler is told to). */
#ifndef FULGUR_UTIL_FG_SIMD_H
#define FULGUR_UTIL_FG_SIMD_H

#include <stdint.h>
#include <string.h>

#if (defined(__GNUC__) || defined(__clang__)) && !defined(FG_SIMD_SCALAR)

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
