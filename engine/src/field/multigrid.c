/* The multigrid cycle: one symmetric V(2,2) cycle in single precision.
 *
 * Pre-smoothing is red-black Gauss-Seidel, post-smoothing black-red, the
 * restriction (full weighting) is the transpose of the trilinear
 * prolongation, and the levels below the grid carry the rediscretised
 * operators of coarse_operator.c, symmetric too: so the cycle is a
 * symmetric positive operator, a stationary iteration that converges on
 * its own where the coarse operators see the boundary, and a
 * preconditioner conjugate gradient may use where they do not. */
#include <stdlib.h>

#include "field_internal.h"

#define COARSEST_SWEEPS 16

static int coarsenable(const int n[3])
{
    for (int a = 0; a < 3; a++)
        if ((n[a] - 1) % 2 != 0 || n[a] < 9)
            return 0;
    return 1;
}

/* A coarse level's floats: e and the three weights padded, rhs, tmp, diag
 * and inv_diag not. */
static size_t level_floats(const fg_level *L)
{
    return 4 * (L->count + 2 * fg_level_pad(L)) + 4 * L->count;
}

size_t fg_multigrid_bytes(const int n0[3])
{
    fg_level L = {.n = {n0[0], n0[1], n0[2]}};
    /* level 0's inv_diag */
    size_t bytes = (size_t)n0[0] * (size_t)n0[1] * (size_t)n0[2] * sizeof(float);
    for (int l = 1; l < FG_FIELD_MAX_LEVELS && coarsenable(L.n); l++) {
        for (int a = 0; a < 3; a++)
            L.n[a] = (L.n[a] - 1) / 2 + 1;
        L.count = (size_t)L.n[0] * (size_t)L.n[1] * (size_t)L.n[2];
        bytes += level_floats(&L) * sizeof(float) + L.count;
    }
    return bytes;
}

/* Points the arrays of coarse level L into its block. */
static void carve(fg_level *L)
{
    size_t pad = fg_level_pad(L), padded = L->count + 2 * pad;
    float *p = L->block;
    L->e = p + pad;
    for (int a = 0; a < 3; a++)
        L->w[a] = p + (size_t)(a + 1) * padded + pad;
    p += 4 * padded;
    L->rhs = p;
    L->tmp = p + L->count;
    L->diag = p + 2 * L->count;
    L->inv_diag = p + 3 * L->count;
}

fg_result fg_multigrid_init(fg_field *f)
{
    fg_level *L0 = &f->level[0];
    for (int a = 0; a < 3; a++)
        L0->n[a] = f->config.size[a];
    L0->count = (size_t)L0->n[0] * (size_t)L0->n[1] * (size_t)L0->n[2];
    L0->mask = f->label;
    L0->split = 1;
    f->kernels = fg_field_kernels_pick();
    L0->inv_diag = calloc(L0->count, sizeof(float));
    if (!L0->inv_diag)
        return FG_ERR_NO_MEMORY;
    double h[3] = {f->h[0], f->h[1], f->h[2]};
    f->levels = 1;
    for (int l = 0;; l++) {
        fg_level *L = &f->level[l];
        L->c[0] = h[1] * h[2] / h[0];
        L->c[1] = h[0] * h[2] / h[1];
        L->c[2] = h[0] * h[1] / h[2];
        if (l + 1 >= FG_FIELD_MAX_LEVELS || !coarsenable(L->n))
            break;
        fg_level *C = &f->level[l + 1];
        for (int a = 0; a < 3; a++) {
            C->n[a] = (L->n[a] - 1) / 2 + 1;
            h[a] *= 2.0;
        }
        C->count = (size_t)C->n[0] * (size_t)C->n[1] * (size_t)C->n[2];
        C->mask = calloc(C->count, 1);
        C->block = calloc(level_floats(C), sizeof(float));
        f->levels = l + 2;
        if (!C->mask || !C->block)
            return FG_ERR_NO_MEMORY;
        carve(C);
    }
    f->operators_dirty = 1;
    return FG_OK;
}

void fg_multigrid_deinit(fg_field *f)
{
    free(f->level[0].inv_diag);
    for (int l = 1; l < f->levels; l++) {
        free(f->level[l].mask);
        free(f->level[l].block);
    }
    f->levels = 0;
}

const fg_field_kernels fg_field_kernels_portable = {
    fg_lap_residual,   fg_lap_correct_residual,   fg_fine_smooth,
    fg_fine_residual,  fg_coarse_sweep_from_zero, fg_coarse_sweep,
    fg_coarse_residual, fg_restrict,              fg_prolong_add,
};

const fg_field_kernels *fg_field_kernels_pick(void)
{
#ifdef FG_FIELD_AVX2
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2"))
        return &fg_field_kernels_avx2;
#endif
    return &fg_field_kernels_portable;
}

/* count half-sweeps on level l, of colour color first and then
 * alternating; from_zero (color 0): the first from e = 0. */
static void smooth(const fg_field_kernels *k, const fg_level *L, int l, int color, int count,
                   int from_zero)
{
    if (l == 0) {
        k->fine_smooth(L, L->e, L->rhs, color, count, from_zero);
        return;
    }
    for (int t = 0; t < count; t++) {
        if (t == 0 && from_zero)
            k->coarse_sweep_from_zero(L);
        else
            k->coarse_sweep(L, (color + t) & 1);
    }
}

/* e = M rhs on level l, from e = 0: red-black sweeps down, black-red up. */
static void cycle(fg_field *f, int l)
{
    const fg_field_kernels *k = f->kernels;
    const fg_level *L = &f->level[l];
    if (l == f->levels - 1) {
        smooth(k, L, l, 0, 2 * COARSEST_SWEEPS, 1);
        smooth(k, L, l, 1, 2 * COARSEST_SWEEPS, 0);
        return;
    }
    fg_level *C = &f->level[l + 1];
    smooth(k, L, l, 0, 4, 1);
    if (l == 0)
        k->fine_residual(L, L->e, L->rhs, L->tmp);
    else
        k->coarse_residual(L);
    k->restrict_down(L, L->tmp, C);
    cycle(f, l + 1);
    k->prolong_add(C, L, L->e);
    smooth(k, L, l, 1, 4, 0);
}

void fg_multigrid_cycle(fg_field *f, float *rhs, float *e)
{
    if (f->operators_dirty)
        fg_multigrid_assemble(f);
    fg_level *L0 = &f->level[0];
    L0->rhs = rhs;
    L0->e = e;
    L0->tmp = f->q;
    cycle(f, 0);
}
