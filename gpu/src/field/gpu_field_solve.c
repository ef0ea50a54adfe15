/* Solving on the GPU: warm-started multigrid V-cycles on phi (the
 * correction scheme: level 0 relaxes phi itself, the coarse levels a
 * correction), and when a cycle fails to shrink the residual enough — a
 * thin Dirichlet tree the coarse levels cannot see makes plain cycles stall
 * or diverge — multigrid-preconditioned conjugate gradient from where the
 * cycles left phi, as the engine's CPU solver always does. Every vector is
 * single precision on the GPU; dot products are summed in double there,
 * and only the scalars come back. */
#include <math.h>

#include "gpu_field_internal.h"

#define DEFAULT_TOLERANCE 1e-5
#define DEFAULT_CYCLES 100
/* A healthy V(2,2) cycle divides the residual by about ten; one that does
 * not halve it is stalling (or diverging), and CG takes over. */
#define STALL_RATIO 0.5

double fgg_field_b_norm(fgg_field *f)
{
    if (f->b_norm >= 0.0)
        return f->b_norm;
    const fgg_level *L = &f->level[0];
    fgg_k_residual(f, L, f->phi, 0, L->tmp, 1);
    double b = sqrt(fgg_dot(f, L->tmp, L->tmp));
    f->b_norm = b > 0.0 ? b : 1.0;
    return f->b_norm;
}

/* ||-A phi|| / ||b||, leaving -A phi in r. */
static double relative_residual(fgg_field *f)
{
    const fgg_level *L = &f->level[0];
    fgg_k_residual(f, L, f->phi, 0, L->rhs, 0);
    return sqrt(fgg_dot(f, L->rhs, L->rhs)) / fgg_field_b_norm(f);
}

/* z = M r, p = z; returns r . z. */
static double restart(fgg_field *f)
{
    const fgg_level *L = &f->level[0];
    fgg_k_vector(f, L, FGG_VEC_ZERO, L->e, 0, 0.0f);
    fgg_vcycle(f, L->e, L->rhs);
    fgg_k_vector(f, L, FGG_VEC_XPAY, f->p, L->e, 0.0f); /* p = z */
    return fgg_dot(f, L->rhs, L->e);
}

/* CG on the free nodes from the current phi; r = -A phi on entry. In
 * single precision the recurrence for r drifts from the true residual:
 * when it claims convergence the true residual is computed, and if that is
 * not yet there CG restarts from it (residual replacement). */
static int mgpcg(fgg_field *f, double tol, int max_it, fgg_solve_report *rep)
{
    const fgg_level *L = &f->level[0];
    GLuint r = L->rhs, z = L->e, q = L->tmp;
    double bn = fgg_field_b_norm(f);
    double rz = restart(f);
    for (int it = 1; it <= max_it; it++) {
        fgg_k_residual(f, L, f->p, 0, q, 0); /* q = -A p */
        double pq = -fgg_dot(f, f->p, q);
        if (!(pq > 0.0))
            break;
        float alpha = (float)(rz / pq);
        fgg_k_vector(f, L, FGG_VEC_AXPY, f->phi, f->p, alpha);
        fgg_k_vector(f, L, FGG_VEC_AXPY, r, q, alpha);
        rep->cg_iterations = it;
        rep->residual = sqrt(fgg_dot(f, r, r)) / bn;
        if (rep->residual <= tol) {
            rep->residual = relative_residual(f); /* r = -A phi again */
            if (rep->residual <= tol)
                return 1;
            rz = restart(f);
            continue;
        }
        fgg_k_vector(f, L, FGG_VEC_ZERO, z, 0, 0.0f);
        fgg_vcycle(f, z, r);
        double rz_new = fgg_dot(f, r, z);
        float beta = (float)(rz_new / rz);
        rz = rz_new;
        fgg_k_vector(f, L, FGG_VEC_XPAY, f->p, z, beta); /* p = z + beta p */
    }
    rep->residual = relative_residual(f);
    return rep->residual <= tol;
}

fg_result fgg_field_solve(fgg_field *f, const fgg_solve_config *config, fgg_solve_report *report)
{
    fgg_solve_config c = {0};
    fgg_solve_report dummy;
    if (!f)
        return fgg_fail(FG_ERR_NULL, "fgg_field_solve: NULL field");
    if (config)
        c = *config;
    if (!report)
        report = &dummy;
    if (!(c.tolerance >= 0.0) || !(c.tolerance < 1.0) || c.max_cycles < 0)
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_field_solve: tolerance %g not in [0, 1) or "
                        "max_cycles %d negative", c.tolerance, c.max_cycles);
    double tol = c.tolerance > 0.0 ? c.tolerance : DEFAULT_TOLERANCE;
    int max = c.max_cycles ? c.max_cycles : DEFAULT_CYCLES;
    const fgg_level *L = &f->level[0];
    *report = (fgg_solve_report){0};
    if (c.cold)
        fgg_k_vector(f, L, FGG_VEC_ZERO_FREE, f->phi, 0, 0.0f);
    double res = relative_residual(f);
    report->initial_residual = report->residual = res;
    int converged = res <= tol;
    while (!converged && report->cycles < max) {
        fgg_vcycle(f, f->phi, 0);
        report->cycles++;
        double next = relative_residual(f);
        report->residual = next;
        converged = next <= tol;
        if (!converged && !c.vcycles_only && !(next < STALL_RATIO * res)) {
            converged = mgpcg(f, tol, max, report);
            break;
        }
        res = next;
    }
    fg_result r = fgg_gl_check("solving the field");
    if (r != FG_OK)
        return r;
    if (!converged)
        return fgg_fail(FG_ERR_NOT_CONVERGED,
                        "fgg_field_solve: relative residual %.2e after %d cycles and %d CG "
                        "iterations (tolerance %.1e)",
                        report->residual, report->cycles, report->cg_iterations, tol);
    return FG_OK;
}
