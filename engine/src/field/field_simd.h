/* The field solver's vector helpers beyond util/fg_simd.h (the types,
 * loads and stores): selects by mask, the masks of free nodes and
 * colours, the moves between rows of doubles and split rows of floats,
 * and the AVX2 build's way back to the portable code. A mask is nonzero (all ones in a vector lane) where a select
 * takes its first operand; a build with FG_SIMD_SCALAR defined gets one
 * lane, the same kernels on scalars. */
#ifndef FULGUR_FIELD_SIMD_H
#define FULGUR_FIELD_SIMD_H

#include <stdint.h>

#include "fg_simd.h"

#if defined(FG_SIMD_WIDE) && !defined(FG_SIMD_SCALAR)
#include <immintrin.h>
#endif

/* Where a kernel of the AVX2 build (kernels_avx2.h) returns to the
 * portable code: clears the upper halves of the vector registers, which
 * left in use make every SSE instruction after them wait on those halves
 * (SOR's sweeps ran five times slower). The compiler does this itself at
 * the end of a function that uses them, but not for a static one called
 * from a function that does not (laplace.c's rows). */
static inline void fg_simd_leave(void)
{
#if defined(FG_SIMD_WIDE) && !defined(FG_SIMD_SCALAR)
    _mm256_zeroupper();
#endif
}

#if FG_VF_LANES > 1

/* Lanes where mask is all ones take a, the others b. */
static inline fg_vf fg_vf_select(fg_vi mask, fg_vf a, fg_vf b)
{
    return (fg_vf)((mask & (fg_vi)a) | (~mask & (fg_vi)b));
}

/* All ones in the lanes l where (l + parity) is even: the nodes of one
 * colour in a block starting at an index of the given parity. */
static inline fg_vi fg_vi_colour(int parity)
{
    fg_vi v = {0};
    for (int l = 0; l < FG_VF_LANES; l++)
        v[l] = ((l + parity) & 1) - 1;
    return v;
}

static inline fg_vd fg_vd_select(fg_vl mask, fg_vd a, fg_vd b)
{
    return (fg_vd)((mask & (fg_vl)a) | (~mask & (fg_vl)b));
}

/* All ones in the lanes whose byte of m[0..FG_VD_LANES) is zero (a free
 * node). */
static inline fg_vl fg_vl_zero_bytes(const uint8_t *m)
{
    fg_vl v = {0};
    for (int l = 0; l < FG_VD_LANES; l++)
        v[l] = m[l];
    return v == 0;
}

static inline double fg_vd_lane(fg_vd v, int l)
{
    return v[l];
}

#if defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector) && __has_builtin(__builtin_convertvector)
/* Lane shuffles (Clang, GCC 12 and later): rows of doubles to split rows
 * of floats and back. */
#define FG_FIELD_SPLIT_VECTORS 1

/* FG_VD_LANES floats. */
typedef float fg_field_vfd __attribute__((vector_size(FG_VD_LANES * sizeof(float))));

/* Two blocks of a row from a node i, nodes i.. in v0 and the next
 * FG_VD_LANES in v1, as floats into split rows: the nodes of i's parity
 * at same[0..FG_VD_LANES), the others at other[0..FG_VD_LANES). */
static inline void fg_vd_store_split(float *same, float *other, fg_vd v0, fg_vd v1)
{
#ifdef FG_SIMD_WIDE
    fg_vd s = __builtin_shufflevector(v0, v1, 0, 2, 4, 6);
    fg_vd o = __builtin_shufflevector(v0, v1, 1, 3, 5, 7);
#else
    fg_vd s = __builtin_shufflevector(v0, v1, 0, 2);
    fg_vd o = __builtin_shufflevector(v0, v1, 1, 3);
#endif
    fg_field_vfd a = __builtin_convertvector(s, fg_field_vfd);
    fg_field_vfd b = __builtin_convertvector(o, fg_field_vfd);
    memcpy(same, &a, sizeof a);
    memcpy(other, &b, sizeof b);
}

/* x[0..2 FG_VF_LANES) += even[0], odd[0], even[1], odd[1], ... */
static inline void fg_vd_add_interleaved(double *x, const float *even, const float *odd)
{
    fg_vf e = fg_vf_load(even), o = fg_vf_load(odd);
#ifdef FG_SIMD_WIDE
    fg_vf lo = __builtin_shufflevector(e, o, 0, 8, 1, 9, 2, 10, 3, 11);
    fg_vf hi = __builtin_shufflevector(e, o, 4, 12, 5, 13, 6, 14, 7, 15);
    fg_vd d[4] = {__builtin_convertvector(__builtin_shufflevector(lo, lo, 0, 1, 2, 3), fg_vd),
                  __builtin_convertvector(__builtin_shufflevector(lo, lo, 4, 5, 6, 7), fg_vd),
                  __builtin_convertvector(__builtin_shufflevector(hi, hi, 0, 1, 2, 3), fg_vd),
                  __builtin_convertvector(__builtin_shufflevector(hi, hi, 4, 5, 6, 7), fg_vd)};
#else
    fg_vf lo = __builtin_shufflevector(e, o, 0, 4, 1, 5);
    fg_vf hi = __builtin_shufflevector(e, o, 2, 6, 3, 7);
    fg_vd d[4] = {__builtin_convertvector(__builtin_shufflevector(lo, lo, 0, 1), fg_vd),
                  __builtin_convertvector(__builtin_shufflevector(lo, lo, 2, 3), fg_vd),
                  __builtin_convertvector(__builtin_shufflevector(hi, hi, 0, 1), fg_vd),
                  __builtin_convertvector(__builtin_shufflevector(hi, hi, 2, 3), fg_vd)};
#endif
    for (int q = 0; q < 4; q++) {
        fg_vd v = fg_vd_load(x + q * FG_VD_LANES) + d[q];
        memcpy(x + q * FG_VD_LANES, &v, sizeof v);
    }
}
#endif
#endif

#else

static inline fg_vf fg_vf_select(fg_vi mask, fg_vf a, fg_vf b)
{
    return mask ? a : b;
}

static inline fg_vi fg_vi_colour(int parity)
{
    return (parity & 1) == 0;
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
