/* Laplace solves: multigrid-preconditioned conjugate gradient, and
 * red-black SOR as the oracle.
 *
 * CG runs on the correction of phi: A is the finite-volume Laplacian
 * restricted to the free nodes (symmetric positive definite when every free
 * region touches a Dirichlet node), the residual r = b - A phi carries the
 * Dirichlet values in b. Plain V-cycles diverge when a thin Dirichlet tree
 * sits in the grid (the coarse levels cannot represent it); as a CG
 * preconditioner the same cycle converges. */
#include <math.h>
#include <string.h>

#include "fg_math.h"
#include "fg_rules.h"
#include "field_internal.h"
#include "core/fp_env_internal.h"

#define DEFAULT_TOLERANCE 1e-5
#define DEFAULT_CG_ITERATIONS 200
#define DEFAULT_SOR_SWEEPS 100000
/* SOR checks its residual every this many sweeps (a residual costs a sweep). */
#define SOR_CHECK_EVERY 10

double fg_field_b_norm(fg_field *f)
{
    if (f->b_norm >= 0.0)
        return f->b_norm;
    const fg_level *L = &f->level[0];
    /* phi with the free nodes zeroed, into p; its residual is b. */
    for (size_t i = 0; i < L->count; i++)
        f->p[i] = L->mask[i] ? f->phi[i] : 0.0;
    fg_lap_residual(L, f->p, NULL, f->q);
    double b = sqrt(fg_dot(f->q, f->q, L->count));
    f->b_norm = b > 0.0 ? b : 1.0;
    return f->b_norm;
}

static void zero_free(fg_field *f)
{
    const fg_level *L = &f->level[0];
    for (size_t i = 0; i < L->count; i++)
        if (!L->mask[i])
            f->phi[i] = 0.0;
}

static fg_result mgpcg(fg_field *f, double tol, int max_it, fg_solve_report *rep)
{
    const fg_level *L = &f->level[0];
    size_t n = L->count;
    double bn = fg_field_b_norm(f);
    fg_lap_residual(L, f->phi, NULL, f->r);
    double res = sqrt(fg_dot(f->r, f->r, n)) / bn;
    rep->initial_residual = res;
    rep->residual = res;
    rep->iterations = 0;
    if (res <= tol)
        return FG_OK;
    fg_multigrid_precondition(f); /* z = M r */
    memcpy(f->p, f->z, n * sizeof(double));
    double rz = fg_dot(f->r, f->z, n);
    for (int it = 1; it <= max_it; it++) {
        /* q = -A p (the residual kernel with a zero right-hand side) */
        fg_lap_residual(L, f->p, NULL, f->q);
        double pq = -fg_dot(f->p, f->q, n);
        if (!(pq > 0.0))
            break; /* p = 0: r is already zero to rounding */
        double alpha = rz / pq, rr = 0.0;
        for (size_t i = 0; i < n; i++) {
            f->phi[i] += alpha * f->p[i];
            f->r[i] += alpha * f->q[i];
            rr += f->r[i] * f->r[i];
        }
        rep->iterations = it;
        rep->residual = sqrt(rr) / bn;
        if (rep->residual <= tol)
            return FG_OK;
        fg_multigrid_precondition(f);
        double rz_new = fg_dot(f->r, f->z, n);
        double beta = rz_new / rz;
        rz = rz_new;
        for (size_t i = 0; i < n; i++)
            f->p[i] = f->z[i] + beta * f->p[i];
    }
    return rep->residual <= tol ? FG_OK : FG_ERR_NOT_CONVERGED;
}

static double residual_of(fg_field *f)
{
    const fg_level *L = &f->level[0];
    fg_lap_residual(L, f->phi, NULL, f->r);
    return sqrt(fg_dot(f->r, f->r, L->count)) / fg_field_b_norm(f);
}

/* SOR's optimal factor for the model problem on the largest axis. */
static double optimal_omega(const fg_level *L)
{
    int n = L->n[0] > L->n[1] ? L->n[0] : L->n[1];
    n = n > L->n[2] ? n : L->n[2];
    return 2.0 / (1.0 + sin(FG_PI / (n - 1)));
}

static fg_result sor(fg_field *f, double tol, int max_sweeps, double omega,
                     fg_solve_report *rep)
{
    const fg_level *L = &f->level[0];
    omega = FG_DEF(omega, optimal_omega(L));
    rep->initial_residual = rep->residual = residual_of(f);
    rep->iterations = 0;
    while (rep->residual > tol && rep->iterations < max_sweeps) {
        int todo = max_sweeps - rep->iterations;
        todo = todo < SOR_CHECK_EVERY ? todo : SOR_CHECK_EVERY;
        for (int s = 0; s < todo; s++) {
            fg_lap_sweep(L, f->phi, NULL, 0, omega);
            fg_lap_sweep(L, f->phi, NULL, 1, omega);
        }
        rep->iterations += todo;
        rep->residual = residual_of(f);
    }
    return rep->residual <= tol ? FG_OK : FG_ERR_NOT_CONVERGED;
}

fg_result fg_field_solve(fg_field *f, const fg_solve_config *config, fg_solve_report *report)
{
    fg_solve_config c = {0};
    fg_solve_report dummy;
    if (!f)
        return FG_ERR_NULL;
    if (config)
        c = *config;
    if (!report)
        report = &dummy;
    if (f->shape_count == 0)
        return FG_ERR_ARGUMENT;
    if ((c.solver != FG_SOLVER_MGPCG && c.solver != FG_SOLVER_SOR) || !(c.tolerance >= 0.0) ||
        !(c.tolerance < 1.0) || c.max_iterations < 0 || !(c.sor_omega >= 0.0) ||
        !(c.sor_omega < 2.0))
        return FG_ERR_ARGUMENT;
    double tol = FG_DEF(c.tolerance, DEFAULT_TOLERANCE);
    if (c.cold)
        zero_free(f);
    /* Far from the electrodes corrections decay into denormals, which
     * would slow the sweeps several-fold. */
    fg_fp_env env = fg_fp_env_flush_denormals();
    fg_result r;
    if (c.solver == FG_SOLVER_SOR)
        r = sor(f, tol, FG_DEF(c.max_iterations, DEFAULT_SOR_SWEEPS), c.sor_omega, report);
    else
        r = mgpcg(f, tol, FG_DEF(c.max_iterations, DEFAULT_CG_ITERATIONS), report);
    fg_fp_env_restore(env);
    return r;
}
