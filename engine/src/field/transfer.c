/* Between two levels: full weighting down, trilinear interpolation up.
 *
 * The restriction is the transpose of the prolongation (weight 1/2 per
 * axis offset, only nodes inside the box), so the cycle stays symmetric.
 * Both are separable and go a row at a time: the restriction reduces each
 * fine plane to a coarse-sized one once (along x, then y) and adds three
 * of those per coarse plane; the prolongation sums the four coarse rows
 * around a fine row once and spreads the sums along it. A fine row's
 * vectors are split (level 0) or not: its even nodes are at even[I s],
 * its odd ones at odd[I s]. */
#include "field_internal.h"
#include "field_simd.h"

/* Coarse rows are at most this long. */
#define MAX_COARSE_ROW (FG_FIELD_MAX_SIZE / 2 + 1)

typedef struct halves {
    ptrdiff_t odd, stride; /* offset of the first odd node, and the step */
} halves;

static halves halves_of(const fg_level *F)
{
    return F->split ? (halves){(F->n[0] + 1) / 2, 1} : (halves){1, 2};
}

/* out[I] = r[2I] + (r[2I - 1] + r[2I + 1]) / 2 over a fine row of 2 nc - 1
 * nodes (a level is coarsened only when its sizes are odd). */
static void reduce_row(const float *r, halves h, int nc, float *out)
{
    const float *even = r, *odd = r + h.odd;
    const ptrdiff_t s = h.stride;
    out[0] = even[0] + 0.5f * odd[0];
    int I = 1;
    if (s == 1) { /* split: both halves contiguous */
        const fg_vf half = fg_vf_set(0.5f);
        for (; I + FG_VF_LANES <= nc - 1; I += FG_VF_LANES)
            fg_vf_store(out + I, fg_vf_load(even + I) +
                                     half * (fg_vf_load(odd + I - 1) + fg_vf_load(odd + I)));
    }
    for (; I < nc - 1; I++)
        out[I] = even[I * s] + 0.5f * (odd[(I - 1) * s] + odd[I * s]);
    out[nc - 1] = even[(nc - 1) * s] + 0.5f * odd[(nc - 2) * s];
}

static void add_scaled(float *acc, const float *v, float s, int n)
{
    int i = 0;
    const fg_vf vs = fg_vf_set(s);
    for (; i + FG_VF_LANES <= n; i += FG_VF_LANES)
        fg_vf_store(acc + i, fg_vf_load(acc + i) + vs * fg_vf_load(v + i));
    for (; i < n; i++)
        acc[i] += s * v[i];
}

/* plane (coarse-sized, nc[0] x nc[1]) = fine plane k reduced along x and y. */
static void reduce_plane(const fg_level *F, const float *r, int k, const int nc[2], float *plane)
{
    float row[MAX_COARSE_ROW];
    const halves h = halves_of(F);
    memset(plane, 0, (size_t)nc[0] * (size_t)nc[1] * sizeof *plane);
    for (int j = 0; j < F->n[1]; j++) {
        reduce_row(r + fg_level_index(F, 0, j, k), h, nc[0], row);
        if (j % 2 == 0) {
            add_scaled(plane + (size_t)(j / 2) * (size_t)nc[0], row, 1.0f, nc[0]);
        } else {
            add_scaled(plane + (size_t)(j / 2) * (size_t)nc[0], row, 0.5f, nc[0]);
            add_scaled(plane + (size_t)(j / 2 + 1) * (size_t)nc[0], row, 0.5f, nc[0]);
        }
    }
}

void fg_restrict(const fg_level *F, const float *r, fg_level *C)
{
    const int nc[2] = {C->n[0], C->n[1]};
    const size_t plane = (size_t)nc[0] * (size_t)nc[1];
    /* C->tmp is free until C's own residual: two reduced planes, the one
     * below and the one above the coarse plane's fine plane. */
    float *below = C->tmp, *above = C->tmp + plane;
    for (int K = 0; K < C->n[2]; K++) {
        float *out = C->rhs + (size_t)K * plane;
        reduce_plane(F, r, 2 * K, nc, out);
        if (K > 0)
            add_scaled(out, below, 0.5f, (int)plane);
        if (2 * K + 1 < F->n[2]) {
            reduce_plane(F, r, 2 * K + 1, nc, above);
            add_scaled(out, above, 0.5f, (int)plane);
            float *t = below;
            below = above;
            above = t;
        }
        const uint8_t *m = C->mask + (size_t)K * plane;
        for (size_t i = 0; i < plane; i++)
            if (m[i])
                out[i] = 0.0f;
    }
}

/* A fine row of a level in the natural order (m its mask) += the coarse row
 * interpolated along x from its sums: 1/4 of a sum at an even node, 1/8 of
 * the two around an odd one. */
static void spread(const float *sum, int nc, const uint8_t *m, float *e)
{
    for (int I = 0; I < nc; I++)
        e[2 * I] += m[2 * I] ? 0.0f : 0.25f * sum[I];
    for (int I = 0; I < nc - 1; I++)
        e[2 * I + 1] += m[2 * I + 1] ? 0.0f : 0.125f * (sum[I] + sum[I + 1]);
}

/* The same on a split row of level 0, whose inv_diag (split too) is 0
 * exactly on its Dirichlet nodes: a block of lanes at a time. */
static void spread_split(const float *sum, int nc, const float *inv, float *even, float *odd)
{
    const fg_vf zero = fg_vf_set(0.0f), quarter = fg_vf_set(0.25f), eighth = fg_vf_set(0.125f);
    const float *inv_odd = inv + (odd - even);
    int I = 0;
    for (; I + FG_VF_LANES <= nc; I += FG_VF_LANES)
        fg_vf_store(even + I, fg_vf_load(even + I) +
                                  fg_vf_select(fg_vf_load(inv + I) != zero,
                                               quarter * fg_vf_load(sum + I), zero));
    for (; I < nc; I++)
        even[I] += inv[I] != 0.0f ? 0.25f * sum[I] : 0.0f;
    for (I = 0; I + FG_VF_LANES <= nc - 1; I += FG_VF_LANES)
        fg_vf_store(odd + I,
                    fg_vf_load(odd + I) +
                        fg_vf_select(fg_vf_load(inv_odd + I) != zero,
                                     eighth * (fg_vf_load(sum + I) + fg_vf_load(sum + I + 1)),
                                     zero));
    for (; I < nc - 1; I++)
        odd[I] += inv_odd[I] != 0.0f ? 0.125f * (sum[I] + sum[I + 1]) : 0.0f;
}

void fg_prolong_add(const fg_level *C, const fg_level *F, float *e)
{
    float sum[MAX_COARSE_ROW];
    const int nc = C->n[0];
    const halves h = halves_of(F);
    for (int k = 0; k < F->n[2]; k++) {
        int k0 = k >> 1, k1 = (k + 1) >> 1;
        for (int j = 0; j < F->n[1]; j++) {
            int j0 = j >> 1, j1 = (j + 1) >> 1;
            const float *r00 = C->e + fg_level_index(C, 0, j0, k0);
            const float *r01 = C->e + fg_level_index(C, 0, j1, k0);
            const float *r10 = C->e + fg_level_index(C, 0, j0, k1);
            const float *r11 = C->e + fg_level_index(C, 0, j1, k1);
            int I = 0;
            for (; I + FG_VF_LANES <= nc; I += FG_VF_LANES)
                fg_vf_store(sum + I, (fg_vf_load(r00 + I) + fg_vf_load(r01 + I)) +
                                         (fg_vf_load(r10 + I) + fg_vf_load(r11 + I)));
            for (; I < nc; I++)
                sum[I] = (r00[I] + r01[I]) + (r10[I] + r11[I]);
            size_t row = fg_level_index(F, 0, j, k);
            if (F->split)
                spread_split(sum, nc, F->inv_diag + row, e + row, e + row + h.odd);
            else
                spread(sum, nc, F->mask + row, e + row);
        }
    }
}
