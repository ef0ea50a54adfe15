/* Several floats (or doubles) at a time for the solver's row kernels.
 *
 * With GCC or Clang: their vector extensions, plain C that compiles to
 * SSE2 on x86-64 (and NEON on ARM) at any optimisation level, without a
 * target-specific intrinsic or flag. Any other C11 compiler, or a build
 * with FG_FIELD_SCALAR defined (to test this path), gets one lane: the
 * same kernels on scalars. Loads and stores go through memcpy, so rows
 * need no alignment. The arithmetic is lane by lane, in the order
 * written: a vector kernel gives the same floats as the same expression on
 * scalars (no reassociation; nothing is contracted into FMAs unless the
 * compiler is told to). A mask is nonzero (all ones in a vector lane) where
 * a select takes its first operand. */
#ifndef FULGUR_FIELD_SIMD_H
#define FULGUR_FIELD_SIMD_H

#include <stdint.h>
#include <string.h>

#if (defined(__GNUC__) || defined(__clang__)) && !defined(FG_FIELD_SCALAR)

#define FG_VF_LANES 4
#define FG_VD_LANES 2

typedef float fg_vf __attribute__((vector_size(16)));
typedef int32_t fg_vi __attribute__((vector_size(16)));
typedef double fg_vd __attribute__((vector_size(16)));
typedef int64_t fg_vl __attribute__((vector_size(16)));

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

static inline fg_vf fg_vf_set(float x)
{
    return (fg_vf){x, x, x, x};
}

/* Lanes where mask is all ones take a, the others b. */
static inline fg_vf fg_vf_select(fg_vi mask, fg_vf a, fg_vf b)
{
    return (fg_vf)((mask & (fg_vi)a) | (~mask & (fg_vi)b));
}

/* All ones in the lanes whose byte of m[0..3] is zero (a free node). */
static inline fg_vi fg_vi_zero_bytes(const uint8_t *m)
{
    fg_vi v = {m[0], m[1], m[2], m[3]};
    return v == 0;
}

/* All ones in the lanes l where (l + parity) is even: the nodes of one
 * colour in a block starting at an index of the given parity. */
static inline fg_vi fg_vi_colour(int parity)
{
    return parity & 1 ? (fg_vi){0, -1, 0, -1} : (fg_vi){-1, 0, -1, 0};
}

static inline fg_vd fg_vd_load(const double *p)
{
    fg_vd v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline fg_vd fg_vd_set(double x)
{
    return (fg_vd){x, x};
}

static inline fg_vd fg_vd_select(fg_vl mask, fg_vd a, fg_vd b)
{
    return (fg_vd)((mask & (fg_vl)a) | (~mask & (fg_vl)b));
}

/* All ones in the lanes whose byte of m[0..1] is zero. */
static inline fg_vl fg_vl_zero_bytes(const uint8_t *m)
{
    fg_vl v = {m[0], m[1]};
    return v == 0;
}

static inline double fg_vd_lane(fg_vd v, int l)
{
    return v[l];
}

#else

#define FG_VF_LANES 1
#define FG_VD_LANES 1

typedef float fg_vf;
typedef int fg_vi;
typedef double fg_vd;
typedef int fg_vl;

static inline fg_vf fg_vf_load(const float *p)
{
    return *p;
}

static inline void fg_vf_store(float *p, fg_vf v)
{
    *p = v;
}

static inline fg_vf fg_vf_set(float x)
{
    return x;
}

static inline fg_vf fg_vf_select(fg_vi mask, fg_vf a, fg_vf b)
{
    return mask ? a : b;
}

static inline fg_vi fg_vi_zero_bytes(const uint8_t *m)
{
    return m[0] == 0;
}

static inline fg_vi fg_vi_colour(int parity)
{
    return (parity & 1) == 0;
}

static inline fg_vd fg_vd_load(const double *p)
{
    return *p;
}

static inline fg_vd fg_vd_set(double x)
{
    return x;
}

static inline fg_vd fg_vd_select(fg_vl mask, fg_vd a, fg_vd b)
{
    return mask ? a : b;
}

static inline fg_vl fg_vl_zero_bytes(const uint8_t *m)
{
    return m[0] == 0;
}

static inline double fg_vd_lane(fg_vd v, int l)
{
    (void)l;
    return v;
}

#endif

#endif
