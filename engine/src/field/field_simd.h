/* The field solver's vector helpers beyond util/fg_simd.h (the types,
 * loads and stores): selects by mask and the masks of free nodes and
 * colours. A mask is nonzero (all ones in a vector lane) where a select
 * takes its first operand; a build with FG_SIMD_SCALAR defined gets one
 * lane, the same kernels on scalars. */
#ifndef FULGUR_FIELD_SIMD_H
#define FULGUR_FIELD_SIMD_H

#include <stdint.h>

#include "fg_simd.h"

#if FG_VF_LANES > 1

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
