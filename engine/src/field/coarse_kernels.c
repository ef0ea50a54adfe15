/* The levels below the grid: red-black Gauss-Seidel and the residual of
 * the assembled operator (coarse_operator.c), four nodes at a time.
 *
 * Every node runs the same arithmetic: an edge that does not exist weighs
 * 0, and a Dirichlet node has diag = inv_diag = 0 and a zero right-hand
 * side, so its correction stays 0. The padded arrays let a row read its
 * neighbours past the box (times a zero weight). As on level 0, a
 * half-sweep keeps the new value only in the lanes of its colour. */
#include "field_internal.h"
#include "field_simd.h"

typedef struct coarse_level {
    const float *wx, *wy, *wz; /* edge weights to +x, +y, +z */
    ptrdiff_t sy, sz;
} coarse_level;

static coarse_level view(const fg_level *L)
{
    coarse_level v = {L->w[0], L->w[1], L->w[2], L->n[0], (ptrdiff_t)L->n[0] * L->n[1]};
    return v;
}

/* sum_j w_ij e_j at node i. */
static inline float neighbours(const coarse_level *v, const float *e, ptrdiff_t i)
{
    return (v->wx[i] * e[i + 1] + v->wx[i - 1] * e[i - 1]) +
           (v->wy[i] * e[i + v->sy] + v->wy[i - v->sy] * e[i - v->sy]) +
           (v->wz[i] * e[i + v->sz] + v->wz[i - v->sz] * e[i - v->sz]);
}

static inline fg_vf load(const float *p, ptrdiff_t i)
{
    return fg_vf_load(p + i);
}

static inline fg_vf neighbours4(const coarse_level *v, const float *e, ptrdiff_t i)
{
    return (load(v->wx, i) * load(e, i + 1) + load(v->wx, i - 1) * load(e, i - 1)) +
           (load(v->wy, i) * load(e, i + v->sy) + load(v->wy, i - v->sy) * load(e, i - v->sy)) +
           (load(v->wz, i) * load(e, i + v->sz) + load(v->wz, i - v->sz) * load(e, i - v->sz));
}

void fg_coarse_sweep(const fg_level *L, int color)
{
    const coarse_level v = view(L);
    float *e = L->e;
    /* New values first, then the blend (see fine_kernels.c). */
    float t[FG_FIELD_MAX_SIZE / 2 + 1];
    for (int k = 0; k < L->n[2]; k++)
        for (int j = 0; j < L->n[1]; j++) {
            ptrdiff_t row = (ptrdiff_t)fg_level_index(L, 0, j, k), n = L->n[0];
            int parity = color + j + k;
            ptrdiff_t i = 0;
            for (; i + FG_VF_LANES <= n; i += FG_VF_LANES)
                fg_vf_store(t + i, load(L->inv_diag, row + i) *
                                       (load(L->rhs, row + i) + neighbours4(&v, e, row + i)));
            ptrdiff_t tail = i;
            for (i = 0; i < tail; i += FG_VF_LANES)
                fg_vf_store(e + row + i, fg_vf_select(fg_vi_colour(parity + (int)i),
                                                      fg_vf_load(t + i), load(e, row + i)));
            for (; i < n; i++)
                if (((parity + (int)i) & 1) == 0)
                    e[row + i] = L->inv_diag[row + i] *
                                 (L->rhs[row + i] + neighbours(&v, e, row + i));
        }
}

void fg_coarse_sweep_from_zero(const fg_level *L)
{
    for (int k = 0; k < L->n[2]; k++)
        for (int j = 0; j < L->n[1]; j++) {
            ptrdiff_t row = (ptrdiff_t)fg_level_index(L, 0, j, k), end = row + L->n[0];
            int parity = j + k;
            ptrdiff_t i = row;
            for (; i + FG_VF_LANES <= end; i += FG_VF_LANES)
                fg_vf_store(L->e + i,
                            fg_vf_select(fg_vi_colour(parity + (int)(i - row)),
                                         load(L->inv_diag, i) * load(L->rhs, i), fg_vf_set(0.0f)));
            for (; i < end; i++)
                L->e[i] = ((parity + (int)(i - row)) & 1) == 0 ? L->inv_diag[i] * L->rhs[i] : 0.0f;
        }
}

void fg_coarse_residual(const fg_level *L)
{
    const coarse_level v = view(L);
    const float *e = L->e;
    const ptrdiff_t n = (ptrdiff_t)L->count;
    ptrdiff_t i = 0;
    for (; i + FG_VF_LANES <= n; i += FG_VF_LANES)
        fg_vf_store(L->tmp + i, (load(L->rhs, i) + neighbours4(&v, e, i)) -
                                    load(L->diag, i) * load(e, i));
    for (; i < n; i++)
        L->tmp[i] = (L->rhs[i] + neighbours(&v, e, i)) - L->diag[i] * e[i];
}
