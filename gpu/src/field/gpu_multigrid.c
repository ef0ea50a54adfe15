/* The multigrid V(2,2) cycle on the GPU, the same cycle as the engine's
 * multigrid.c: red-black Gauss-Seidel before the coarse correction,
 * black-red after (so that, as CG's preconditioner, it is symmetric), full
 * weighting down, trilinear up, 16 + 16 sweeps on the coarsest level. */
#include "gpu_field_internal.h"

#define COARSEST_SWEEPS 16

static void smooth(const fgg_field *f, const fgg_level *L, GLuint x, GLuint rhs, int first,
                   int times)
{
    for (int t = 0; t < times; t++) {
        fgg_k_smooth(f, L, x, rhs, first);
        fgg_k_smooth(f, L, x, rhs, 1 - first);
    }
}

/* Level l >= 1: e from zero for A e = rhs. */
static void coarse_cycle(fgg_field *f, int l)
{
    const fgg_level *L = &f->level[l];
    fgg_k_vector(f, L, FGG_VEC_ZERO, L->e, 0, 0.0f);
    if (l == f->levels - 1) {
        smooth(f, L, L->e, L->rhs, 0, COARSEST_SWEEPS);
        smooth(f, L, L->e, L->rhs, 1, COARSEST_SWEEPS);
        return;
    }
    smooth(f, L, L->e, L->rhs, 0, 2);
    fgg_k_residual(f, L, L->e, L->rhs, L->tmp, 0);
    fgg_k_restrict(f, L, &f->level[l + 1]);
    coarse_cycle(f, l + 1);
    fgg_k_prolong(f, L, L->e, &f->level[l + 1]);
    smooth(f, L, L->e, L->rhs, 1, 2);
}

void fgg_vcycle(fgg_field *f, GLuint x, GLuint rhs)
{
    const fgg_level *L = &f->level[0];
    if (f->levels == 1) {
        smooth(f, L, x, rhs, 0, COARSEST_SWEEPS);
        smooth(f, L, x, rhs, 1, COARSEST_SWEEPS);
        return;
    }
    smooth(f, L, x, rhs, 0, 2);
    fgg_k_residual(f, L, x, rhs, L->tmp, 0);
    fgg_k_restrict(f, L, &f->level[1]);
    coarse_cycle(f, 1);
    fgg_k_prolong(f, L, x, &f->level[1]);
    smooth(f, L, x, rhs, 1, 2);
}
