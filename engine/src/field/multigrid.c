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

/* The kernels of level l: the grid's own on level 0, the assembled
 * operator's below. */
static void sweep_from_zero(const fg_level *L, int l)
{
    if (l == 0)
        fg_fine_sweep_from_zero(L, L->e, L->rhs);
    else
        fg_coarse_sweep_from_zero(L);
}

static void sweep(const fg_level *L, int l, int color)
{
    if (l == 0)
        fg_fine_sweep(L, L->e, L->rhs, color);
    else
        fg_coarse_sweep(L, color);
}

static void residual(const fg_level *L, int l)
{
    if (l == 0)
        fg_fine_residual(L, L->e, L->rhs, L->tmp);
    else
        fg_coarse_residual(L);
}

/* times sweeps, each a half-sweep of one colour and one of the other. */
static void smooth(const fg_level *L, int l, int first_color, int times)
{
    for (int t = 0; t < times; t++) {
        sweep(L, l, first_color);
        sweep(L, l, 1 - first_color);
    }
}

/* e = M rhs on level l, from e = 0. */
static void cycle(fg_field *f, int l)
{
    const fg_level *L = &f->level[l];
    /* The first red half-sweep from e = 0, then the rest of the first
     * red-black sweep. */
    sweep_from_zero(L, l);
    sweep(L, l, 1);
    if (l == f->levels - 1) {
        smooth(L, l, 0, COARSEST_SWEEPS - 1);
        smooth(L, l, 1, COARSEST_SWEEPS);
        return;
    }
    fg_level *C = &f->level[l + 1];
    smooth(L, l, 0, 1);
    residual(L, l);
    fg_restrict(L, L->tmp, C);
    cycle(f, l + 1);
    fg_prolong_add(C, L, L->e);
    smooth(L, l, 1, 2);
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
