/* Laplace solves: multigrid V-cycles, multigrid-preconditioned conjugate
 * gradient where the cycles stall, and red-black SOR as the oracle.
 *
 * The multigrid solves correct a double phi: the double residual
 * r = b - A phi (laplace.c; the Dirichlet values carry b), a float
 * correction e for A e = r (one V-cycle, or conjugate gradient
 * preconditioned by it), phi += e, and the residual again. So the float
 * work reaches the double solution. Conjugate gradient runs on the free
 * nodes, where A is symmetric positive definite when every free region
 * touches a Dirichlet node. */
#include <math.h>
#include <string.h>

#include "fg_math.h"
#include "fg_rules.h"
#include "field_internal.h"
#include "core/fp_env_internal.h"

#define DEFAULT_TOLERANCE 1e-5
#define DEFAULT_ITERATIONS 200
#define DEFAULT_SOR_SWEEPS 100000
/* SOR checks its residual every this many sweeps (a residual costs a sweep). */
#define SOR_CHECK_EVERY 10
/* A V-cycle that leaves more than this of the residual is too slow for a
 * stationary iteration (the spark-ball and plasma-ball cycles leave 0.1 to
 * 0.25, a one-node-thick tree's 0.45): conjugate gradient takes over. */
#define STALL_RATIO 0.3
/* Conjugate gradient in float is asked for at most this reduction at a
 * time; the double residual then says how far phi really got. */
#define CG_FLOOR 1e-5

double fg_field_b_norm(fg_field *f)
{
    if (f->b_norm < 0.0) {
        double b = sqrt(f->kernels->lap_residual(&f->level[0], f->phi, 1, NULL));
        f->b_norm = b > 0.0 ? b : 1.0;
    }
    return f->b_norm;
}

static void zero_free(fg_field *f)
{
    const fg_level *L = &f->level[0];
    for (size_t i = 0; i < L->count; i++)
        if (!L->mask[i])
            f->phi[i] = 0.0;
}

double fg_field_residual(fg_field *f)
{
    return sqrt(f->kernels->lap_residual(&f->level[0], f->phi, 0, f->r)) / fg_field_b_norm(f);
}

/* phi += e, and the new residual (as fg_field_residual). */
static double correct(fg_field *f, const float *e)
{
    return sqrt(f->kernels->lap_correct_residual(&f->level[0], f->phi, e, f->r)) /
           fg_field_b_norm(f);
}

static double dot(const float *a, const float *b, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; i++)
        s += (double)a[i] * b[i];
    return s;
}

double fg_field_vcycle(fg_field *f)
{
    fg_multigrid_cycle(f, f->r, f->z);
    return correct(f, f->z);
}

/* Conjugate gradient for A x = r from x = 0, preconditioned by the cycle,
 * until ||r|| has fallen by reduce or max_it iterations are done; r
 * follows x. Returns the iterations done. */
static int cg(fg_field *f, double reduce, int max_it)
{
    const fg_level *L = &f->level[0];
    size_t n = L->count;
    float *x = f->x, *r = f->r, *z = f->z, *p = f->p, *q = f->q;
    memset(x, 0, n * sizeof *x);
    fg_multigrid_cycle(f, r, z);
    memcpy(p, z, n * sizeof *p);
    double rz = dot(r, z, n), stop = reduce * reduce * dot(r, r, n);
    int it = 0;
    while (it < max_it) {
        f->kernels->fine_residual(L, p, NULL, q); /* q = -A p */
        double pq = -dot(p, q, n);
        if (!(pq > 0.0))
            break; /* p = 0: r is already zero to rounding */
        float alpha = (float)(rz / pq);
        double rr = 0.0;
        for (size_t i = 0; i < n; i++) {
            x[i] += alpha * p[i];
            r[i] += alpha * q[i];
            rr += (double)r[i] * r[i];
        }
        it++;
        if (rr <= stop)
            break;
        fg_multigrid_cycle(f, r, z);
        double rz_new = dot(r, z, n);
        float beta = (float)(rz_new / rz);
        rz = rz_new;
        for (size_t i = 0; i < n; i++)
            p[i] = z[i] + beta * p[i];
    }
    return it;
}

/* From the residual rr (squared) of phi, left in f->r. */
static fg_result multigrid(fg_field *f, double tol, int max_it, double rr, fg_solve_report *rep)
{
    double res = sqrt(rr) / fg_field_b_norm(f);
    rep->initial_residual = res;
    rep->iterations = 0;
    rep->cg_iterations = 0;
    int stalled = 0;
    while (res > tol && rep->iterations < max_it) {
        double next;
        if (!stalled) {
            next = fg_field_vcycle(f);
            rep->iterations++;
            stalled = !(next <= STALL_RATIO * res);
        } else {
            double reduce = fmax(0.5 * tol / res, CG_FLOOR);
            int done = cg(f, reduce, max_it - rep->iterations);
            if (done == 0)
                break;
            rep->iterations += done;
            rep->cg_iterations += done;
            next = correct(f, f->x);
        }
        res = next;
    }
    rep->residual = res;
    return res <= tol ? FG_OK : FG_ERR_NOT_CONVERGED;
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
    rep->initial_residual = rep->residual = fg_field_residual(f);
    rep->iterations = 0;
    rep->cg_iterations = 0;
    while (rep->residual > tol && rep->iterations < max_sweeps) {
        int todo = max_sweeps - rep->iterations;
        todo = todo < SOR_CHECK_EVERY ? todo : SOR_CHECK_EVERY;
        for (int s = 0; s < todo; s++) {
            fg_lap_sweep(L, f->phi, 0, omega);
            fg_lap_sweep(L, f->phi, 1, omega);
        }
        rep->iterations += todo;
        rep->residual = fg_field_residual(f);
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
    if ((c.solver != FG_SOLVER_MULTIGRID && c.solver != FG_SOLVER_SOR) ||
        !(c.tolerance >= 0.0) || !(c.tolerance < 1.0) || c.max_iterations < 0 ||
        !(c.sor_omega >= 0.0) || !(c.sor_omega < 2.0))
        return FG_ERR_ARGUMENT;
    double tol = FG_DEF(c.tolerance, DEFAULT_TOLERANCE);
    if (c.cold)
        zero_free(f);
    /* Far from the electrodes corrections decay into denormals, which
     * would slow the sweeps several-fold. */
    fg_fp_env env = fg_fp_env_flush_denormals();
    fg_result r;
    if (c.solver == FG_SOLVER_SOR) {
        r = sor(f, tol, FG_DEF(c.max_iterations, DEFAULT_SOR_SWEEPS), c.sor_omega, report);
    } else {
        double rr = f->kernels->lap_residual(&f->level[0], f->phi, 0, f->r);
        /* Cold, the residual is b itself. */
        if (c.cold && f->b_norm < 0.0)
            f->b_norm = rr > 0.0 ? sqrt(rr) : 1.0;
        r = multigrid(f, tol, FG_DEF(c.max_iterations, DEFAULT_ITERATIONS), rr, report);
    }
    fg_fp_env_restore(env);
    return r;
}
