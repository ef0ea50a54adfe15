/* The multigrid preconditioner: one symmetric V(2,2) cycle.
 *
 * Pre-smoothing is red-black Gauss-Seidel, post-smoothing black-red, the
 * restriction (full weighting) is the transpose of the trilinear
 * prolongation, and every level's operator is the same finite-volume
 * Laplacian rediscretised: so the cycle is a symmetric positive operator and
 * conjugate gradient may use it. A coarse node is Dirichlet when the fine
 * node at the same place is (injection). Thin Dirichlet trees then vanish
 * from the coarse levels and the coarse correction is wrong next to them:
 * that is what makes plain V-cycles diverge, and what CG absorbs. Marking a
 * coarse node Dirichlet when any fine node of its stencil is keeps them
 * visible, but over-constrains the coarse problem: on the spark-ball scene
 * it took twice the iterations (12 against 6 at 65^3), and 18 against 11
 * on the thin-tree test. */
#include <stdlib.h>
#include <string.h>

#include "field_internal.h"

#define COARSEST_SWEEPS 16

static int coarsenable(const int n[3])
{
    for (int a = 0; a < 3; a++)
        if ((n[a] - 1) % 2 != 0 || n[a] < 9)
            return 0;
    return 1;
}

size_t fg_multigrid_bytes(const int n0[3])
{
    int n[3] = {n0[0], n0[1], n0[2]};
    size_t bytes = 0;
    for (int l = 1; l < FG_FIELD_MAX_LEVELS && coarsenable(n); l++) {
        for (int a = 0; a < 3; a++)
            n[a] = (n[a] - 1) / 2 + 1;
        size_t count = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
        bytes += count * (3 * sizeof(double) + 1);
    }
    return bytes;
}

fg_result fg_multigrid_init(fg_field *f)
{
    fg_level *L0 = &f->level[0];
    for (int a = 0; a < 3; a++)
        L0->n[a] = f->config.size[a];
    L0->count = (size_t)L0->n[0] * (size_t)L0->n[1] * (size_t)L0->n[2];
    L0->mask = f->label;
    L0->e = f->z;
    L0->rhs = f->r;
    L0->tmp = f->q;
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
        C->e = calloc(C->count, sizeof(double));
        C->rhs = calloc(C->count, sizeof(double));
        C->tmp = calloc(C->count, sizeof(double));
        f->levels = l + 2;
        if (!C->mask || !C->e || !C->rhs || !C->tmp)
            return FG_ERR_NO_MEMORY;
    }
    f->masks_dirty = 1;
    return FG_OK;
}

void fg_multigrid_deinit(fg_field *f)
{
    for (int l = 1; l < f->levels; l++) {
        free(f->level[l].mask);
        free(f->level[l].e);
        free(f->level[l].rhs);
        free(f->level[l].tmp);
    }
    f->levels = 0;
}

/* The fine nodes within one node of coarse node I along an axis. */
static void span(int I, int nf, int *lo, int *hi)
{
    *lo = 2 * I > 0 ? 2 * I - 1 : 0;
    *hi = 2 * I < nf - 1 ? 2 * I + 1 : nf - 1;
}

void fg_multigrid_update_masks(fg_field *f)
{
    for (int l = 1; l < f->levels; l++) {
        const fg_level *F = &f->level[l - 1];
        fg_level *C = &f->level[l];
        for (int K = 0; K < C->n[2]; K++)
            for (int J = 0; J < C->n[1]; J++)
                for (int I = 0; I < C->n[0]; I++)
                    C->mask[fg_level_index(C, I, J, K)] =
                        F->mask[fg_level_index(F, 2 * I, 2 * J, 2 * K)];
    }
    f->masks_dirty = 0;
}

/* Full weighting at one coarse node from the fine nodes that exist. */
static double restrict_edge(const fg_level *F, int I, int J, int K)
{
    int lo[3], hi[3];
    span(I, F->n[0], &lo[0], &hi[0]);
    span(J, F->n[1], &lo[1], &hi[1]);
    span(K, F->n[2], &lo[2], &hi[2]);
    double s = 0.0;
    for (int k = lo[2]; k <= hi[2]; k++) {
        double wk = k == 2 * K ? 1.0 : 0.5;
        for (int j = lo[1]; j <= hi[1]; j++) {
            double wjk = wk * (j == 2 * J ? 1.0 : 0.5);
            const double *row = &F->tmp[fg_level_index(F, 0, j, k)];
            for (int i = lo[0]; i <= hi[0]; i++)
                s += wjk * (i == 2 * I ? 1.0 : 0.5) * row[i];
        }
    }
    return s;
}

/* C->rhs = P^T F->tmp: weight 1/2 per axis offset, zero on masked nodes. */
static void restrict_residual(const fg_level *F, fg_level *C)
{
    size_t sy = (size_t)F->n[0], sz = sy * (size_t)F->n[1];
    for (int K = 0; K < C->n[2]; K++)
        for (int J = 0; J < C->n[1]; J++) {
            int edge = J == 0 || K == 0 || J == C->n[1] - 1 || K == C->n[2] - 1;
            for (int I = 0; I < C->n[0]; I++) {
                size_t id = fg_level_index(C, I, J, K);
                if (C->mask[id]) {
                    C->rhs[id] = 0.0;
                    continue;
                }
                if (edge || I == 0 || I == C->n[0] - 1) {
                    C->rhs[id] = restrict_edge(F, I, J, K);
                    continue;
                }
                /* Interior: the separable (1/2, 1, 1/2)^3 stencil. */
                const double *c = &F->tmp[fg_level_index(F, 2 * I, 2 * J, 2 * K)];
                double plane[3];
                for (int dk = -1; dk <= 1; dk++) {
                    const double *p = c + dk * (ptrdiff_t)sz;
                    double rows[3];
                    for (int dj = -1; dj <= 1; dj++) {
                        const double *r = p + dj * (ptrdiff_t)sy;
                        rows[dj + 1] = 0.5 * (r[-1] + r[1]) + r[0];
                    }
                    plane[dk + 1] = 0.5 * (rows[0] + rows[2]) + rows[1];
                }
                C->rhs[id] = 0.5 * (plane[0] + plane[2]) + plane[1];
            }
        }
}

/* F->e += P C->e on free fine nodes (trilinear). */
static void prolong_add(fg_level *F, const fg_level *C)
{
    for (int k = 0; k < F->n[2]; k++) {
        int k0 = k >> 1, k1 = (k + 1) >> 1;
        for (int j = 0; j < F->n[1]; j++) {
            int j0 = j >> 1, j1 = (j + 1) >> 1;
            const double *r00 = &C->e[fg_level_index(C, 0, j0, k0)];
            const double *r01 = &C->e[fg_level_index(C, 0, j1, k0)];
            const double *r10 = &C->e[fg_level_index(C, 0, j0, k1)];
            const double *r11 = &C->e[fg_level_index(C, 0, j1, k1)];
            size_t row = fg_level_index(F, 0, j, k);
            for (int i = 0; i < F->n[0]; i++) {
                if (F->mask[row + (size_t)i])
                    continue;
                int i0 = i >> 1, i1 = (i + 1) >> 1;
                double v = r00[i0] + r00[i1] + r01[i0] + r01[i1] + r10[i0] + r10[i1] +
                           r11[i0] + r11[i1];
                F->e[row + (size_t)i] += 0.125 * v;
            }
        }
    }
}

static void smooth(const fg_level *L, int first_color, int times)
{
    for (int t = 0; t < times; t++) {
        fg_lap_sweep(L, L->e, L->rhs, first_color, 1.0);
        fg_lap_sweep(L, L->e, L->rhs, 1 - first_color, 1.0);
    }
}

static void vcycle(fg_field *f, int l)
{
    fg_level *L = &f->level[l];
    memset(L->e, 0, L->count * sizeof(double));
    if (l == f->levels - 1) {
        smooth(L, 0, COARSEST_SWEEPS);
        smooth(L, 1, COARSEST_SWEEPS);
        return;
    }
    fg_level *C = &f->level[l + 1];
    smooth(L, 0, 2);
    fg_lap_residual(L, L->e, L->rhs, L->tmp);
    restrict_residual(L, C);
    vcycle(f, l + 1);
    prolong_add(L, C);
    smooth(L, 1, 2);
}

void fg_multigrid_precondition(fg_field *f)
{
    if (f->masks_dirty)
        fg_multigrid_update_masks(f);
    vcycle(f, 0);
}
