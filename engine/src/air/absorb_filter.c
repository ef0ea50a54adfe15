#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "absorb_filter_internal.h"
#include "fg_math.h"

#define NP FG_ABSORB_PARAMS
#define U_MAX 12.0 /* parameters stay where tanh still has a slope */
#define ITERATIONS 600
/* A run also stops once a step gains less than this share of the cost:
 * the fit has settled (in a local minimum or at what four biquads can do). */
#define SETTLED_GAIN 1e-9

double fg_absorb_hi_hz(double fs_hz)
{
    return fmin(20000.0, 0.45 * fs_hz);
}

double fg_absorb_target_db(const fg_air *air, double distance_m, double f_hz)
{
    return -fg_air_alpha_db_m(air, f_hz) * distance_m;
}

static double residual(double got_db, double target_db)
{
    if (target_db >= FG_ABSORB_FLOOR_DB)
        return got_db - target_db;
    return got_db > FG_ABSORB_FLOOR_DB ? got_db - FG_ABSORB_FLOOR_DB : 0.0;
}

double fg_absorb_error_db(const fg_iir *f, const fg_air *air, double distance_m, double fs_hz,
                          double f_hz)
{
    return residual(fg_iir_db(f, 2.0 * FG_PI * f_hz / fs_hz),
                    fg_absorb_target_db(air, distance_m, f_hz));
}

typedef struct problem {
    double w[FG_ABSORB_GRID];
    fg_phasor e[FG_ABSORB_GRID];
    double target[FG_ABSORB_GRID];
} problem;

#define POLYS (2 * FG_IIR_MAX_SECTIONS) /* numerator, denominator, ... */

/* One polynomial 1 + c1 x^-1 + c2 x^-2 and its coefficients' partial
 * derivatives with respect to its two parameters (dc2/du1 = 0). */
typedef struct poly {
    double c1, c2, dc1_du1, dc1_du2, dc2_du2;
} poly;

/* The stability triangle of x^2 + c1 x + c2 scaled to the disc of radius
 * FG_ABSORB_MAX_RADIUS: any u gives roots inside it. */
static poly triangle(const double *u)
{
    const double rho = FG_ABSORB_MAX_RADIUS;
    double t1 = tanh(u[0]), t2 = tanh(u[1]);
    return (poly){rho * (1.0 + t2) * t1, rho * rho * t2, rho * (1.0 + t2) * (1.0 - t1 * t1),
                  rho * t1 * (1.0 - t2 * t2), rho * rho * (1.0 - t2 * t2)};
}


static void to_filter(const double *u, fg_iir *f)
{
    f->sections = FG_IIR_MAX_SECTIONS;
    for (unsigned k = 0; k < FG_IIR_MAX_SECTIONS; k++) {
        poly n = triangle(u + 4 * k), d = triangle(u + 4 * k + 2);
        double b0 = (1.0 + d.c1 + d.c2) / (1.0 + n.c1 + n.c2);
        f->sec[k] = (fg_biquad){b0, b0 * n.c1, b0 * n.c2, d.c1, d.c2};
    }
}

/* Residuals r (and, unless jac is NULL, their exact Jacobian) at u;
 * returns the cost sum r^2. With b0 normalising DC, a section's response
 * in dB is 10/ln10 [ln P_num - 2 ln N_num(1) - ln P_den + 2 ln N_den(1)],
 * P = |1 + c1 e^{-jw} + c2 e^{-2jw}|^2, N(1) = 1 + c1 + c2. */
static double evaluate(const problem *pb, const double *u, double *r, double jac[][NP])
{
    const double db = 10.0 / log(10.0);
    poly p[POLYS];
    double log_dc = 0.0; /* sum of -+2 ln N(1): the same at every frequency */
    for (int k = 0; k < POLYS; k++) {
        p[k] = triangle(u + 2 * k);
        log_dc += (k % 2 == 0 ? -2.0 : 2.0) * log(1.0 + p[k].c1 + p[k].c2);
    }
    double cost = 0.0;
    for (int i = 0; i < FG_ABSORB_GRID; i++) {
        const fg_phasor *e = &pb->e[i];
        double ratio = 1.0, grad[NP];
        for (int k = 0; k < POLYS; k++) {
            double sign = k % 2 == 0 ? db : -db;
            double re = 1.0 + p[k].c1 * e->c1 + p[k].c2 * e->c2;
            double im = p[k].c1 * e->s1 + p[k].c2 * e->s2;
            double mag2 = re * re + im * im, dc = 1.0 + p[k].c1 + p[k].c2;
            ratio = k % 2 == 0 ? ratio * mag2 : ratio / mag2;
            double g1 = sign * (2.0 * (re * e->c1 + im * e->s1) / mag2 - 2.0 / dc);
            double g2 = sign * (2.0 * (re * e->c2 + im * e->s2) / mag2 - 2.0 / dc);
            grad[2 * k] = g1 * p[k].dc1_du1;
            grad[2 * k + 1] = g1 * p[k].dc1_du2 + g2 * p[k].dc2_du2;
        }
        double got = db * (log(ratio) + log_dc);
        r[i] = residual(got, pb->target[i]);
        cost += r[i] * r[i];
        if (jac) {
            bool active = pb->target[i] >= FG_ABSORB_FLOOR_DB || got > FG_ABSORB_FLOOR_DB;
            for (int a = 0; a < NP; a++)
                jac[i][a] = active ? grad[a] : 0.0;
        }
    }
    return cost;
}

/* Solves the NP x NP system a x = b in place (Gaussian elimination with
 * partial pivoting; a is symmetric positive definite after damping). */
static void solve(double a[NP][NP], double *b)
{
    for (int c = 0; c < NP; c++) {
        int p = c;
        for (int r = c + 1; r < NP; r++)
            if (fabs(a[r][c]) > fabs(a[p][c]))
                p = r;
        for (int k = 0; k < NP; k++) {
            double t = a[c][k];
            a[c][k] = a[p][k];
            a[p][k] = t;
        }
        double t = b[c];
        b[c] = b[p];
        b[p] = t;
        for (int r = c + 1; r < NP; r++) {
            double m = a[r][c] / a[c][c];
            for (int k = c; k < NP; k++)
                a[r][k] -= m * a[c][k];
            b[r] -= m * b[c];
        }
    }
    for (int c = NP - 1; c >= 0; c--) {
        for (int k = c + 1; k < NP; k++)
            b[c] -= a[c][k] * b[k];
        b[c] /= a[c][c];
    }
}

static double worst_residual(const double *r)
{
    double worst = 0.0;
    for (int i = 0; i < FG_ABSORB_GRID; i++)
        worst = fmax(worst, fabs(r[i]));
    return worst;
}

/* One Levenberg-Marquardt run from u, until every residual is within
 * FG_ABSORB_STOP_DB or the steps stop gaining; returns the final cost. */
static double levenberg_marquardt(const problem *pb, double *u)
{
    static const double lambda_max = 1e12;
    double r[FG_ABSORB_GRID], jac[FG_ABSORB_GRID][NP];
    double cost = evaluate(pb, u, r, jac), lambda = 1e-2;
    for (int it = 0; it < ITERATIONS && lambda < lambda_max; it++) {
        if (worst_residual(r) <= FG_ABSORB_STOP_DB)
            return cost;
        double jtj[NP][NP], g[NP];
        for (int a = 0; a < NP; a++) {
            g[a] = 0.0;
            for (int i = 0; i < FG_ABSORB_GRID; i++)
                g[a] -= jac[i][a] * r[i];
            for (int b = 0; b <= a; b++) {
                double s = 0.0;
                for (int i = 0; i < FG_ABSORB_GRID; i++)
                    s += jac[i][a] * jac[i][b];
                jtj[a][b] = jtj[b][a] = s;
            }
        }
        while (lambda < lambda_max) {
            double m[NP][NP], step[NP], trial[NP], rt[FG_ABSORB_GRID];
            memcpy(m, jtj, sizeof m);
            memcpy(step, g, sizeof step);
            for (int a = 0; a < NP; a++)
                m[a][a] += lambda * (jtj[a][a] + 1e-9);
            solve(m, step);
            for (int a = 0; a < NP; a++)
                trial[a] = fmax(-U_MAX, fmin(U_MAX, u[a] + step[a]));
            double c = evaluate(pb, trial, rt, NULL);
            if (c < cost) {
                memcpy(u, trial, sizeof trial);
                evaluate(pb, u, r, jac);
                double gain = cost - c;
                cost = c;
                lambda = fmax(lambda / 3.0, 1e-9);
                if (gain < SETTLED_GAIN * (1.0 + cost))
                    return cost;
                break;
            }
            lambda *= 4.0;
        }
    }
    return cost;
}

/* Start: no zeros, and each section a double real pole, at the -3 dB
 * frequency of the target and at `spread` and spread^2 times it. */
static void initial_guess(const problem *pb, double spread, double *u)
{
    const double rho = FG_ABSORB_MAX_RADIUS;
    double w3 = pb->w[FG_ABSORB_GRID - 1];
    for (int i = 0; i < FG_ABSORB_GRID; i++) {
        if (pb->target[i] < -3.0) {
            w3 = pb->w[i];
            break;
        }
    }
    for (int k = 0; k < FG_IIR_MAX_SECTIONS; k++) {
        double wk = fmin(w3 * pow(spread, k), 2.0 * FG_PI * 0.45);
        double p = exp(-wk), c2 = p * p, c1 = -2.0 * p;
        u[4 * k] = u[4 * k + 1] = 0.0;
        u[4 * k + 2] = atanh(c1 / (rho * (1.0 + c2 / (rho * rho))));
        u[4 * k + 3] = atanh(c2 / (rho * rho));
    }
}

double fg_absorb_design(fg_iir *f, const fg_air *air, double distance_m, double fs_hz,
                        fg_absorb_fit *fit)
{
    problem pb;
    double lo = log(FG_ABSORB_LO_HZ), hi = log(fg_absorb_hi_hz(fs_hz));
    for (int i = 0; i < FG_ABSORB_GRID; i++) {
        double hz = exp(lo + (hi - lo) * i / (FG_ABSORB_GRID - 1));
        pb.w[i] = 2.0 * FG_PI * hz / fs_hz;
        pb.e[i] = fg_phasor_at(pb.w[i]);
        pb.target[i] = fg_absorb_target_db(air, distance_m, hz);
    }
    double u[NP], best = INFINITY, r[FG_ABSORB_GRID];
    bool accepted = false;
    if (fit && fit->valid) {
        /* a neighbouring distance's solution is nearly this one's */
        memcpy(u, fit->u, sizeof u);
        best = levenberg_marquardt(&pb, u);
        evaluate(&pb, u, r, NULL);
        accepted = worst_residual(r) <= FG_ABSORB_WARM_ACCEPT_DB;
    }
    /* Local minima are common: keep the best of a few starts. */
    static const double spreads[] = {1.5, 2.0, 3.0};
    for (size_t s = 0; !accepted && s < sizeof spreads / sizeof spreads[0]; s++) {
        double v[NP];
        initial_guess(&pb, spreads[s], v);
        double cost = levenberg_marquardt(&pb, v);
        if (cost < best) {
            best = cost;
            memcpy(u, v, sizeof v);
            evaluate(&pb, u, r, NULL);
            accepted = worst_residual(r) <= FG_ABSORB_STOP_DB;
        }
    }
    to_filter(u, f);
    fg_iir_reset(f);
    if (fit) {
        memcpy(fit->u, u, sizeof u);
        fit->valid = true;
    }
    evaluate(&pb, u, r, NULL);
    return worst_residual(r);
}
