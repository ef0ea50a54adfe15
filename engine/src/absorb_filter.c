#include <math.h>
#include <string.h>

#include "absorb_filter_internal.h"
#include "fg_math_internal.h"

#define NP (4 * FG_IIR_MAX_SECTIONS) /* u1, u2 for numerator and denominator */
#define U_MAX 12.0
#define ITERATIONS 300
#define STEP 1e-6

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

/* The stability triangle of x^2 + c1 x + c2 scaled to the disc of radius
 * FG_ABSORB_MAX_RADIUS: any u gives roots inside it. */
static void triangle(const double *u, double *c1, double *c2)
{
    const double rho = FG_ABSORB_MAX_RADIUS;
    double t2 = tanh(u[1]);
    *c2 = rho * rho * t2;
    *c1 = rho * (1.0 + t2) * tanh(u[0]);
}

static void to_filter(const double *u, fg_iir *f)
{
    f->sections = FG_IIR_MAX_SECTIONS;
    for (unsigned k = 0; k < FG_IIR_MAX_SECTIONS; k++) {
        double n1, n2, d1, d2;
        triangle(u + 4 * k, &n1, &n2);
        triangle(u + 4 * k + 2, &d1, &d2);
        double b0 = (1.0 + d1 + d2) / (1.0 + n1 + n2);
        f->sec[k] = (fg_biquad){b0, b0 * n1, b0 * n2, d1, d2};
    }
}

typedef struct problem {
    double w[FG_ABSORB_GRID];
    fg_phasor e[FG_ABSORB_GRID];
    double target[FG_ABSORB_GRID];
} problem;

static double residuals(const problem *pb, const double *u, double *r)
{
    fg_iir f;
    to_filter(u, &f);
    double cost = 0.0;
    for (int i = 0; i < FG_ABSORB_GRID; i++) {
        double m2 = 1.0;
        for (unsigned k = 0; k < f.sections; k++)
            m2 *= fg_biquad_mag2(&f.sec[k], &pb->e[i]);
        r[i] = residual(10.0 * log10(m2), pb->target[i]);
        cost += r[i] * r[i];
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

static void jacobian(const problem *pb, double *u, double jac[FG_ABSORB_GRID][NP])
{
    double rp[FG_ABSORB_GRID], rm[FG_ABSORB_GRID];
    for (int k = 0; k < NP; k++) {
        double keep = u[k];
        u[k] = keep + STEP;
        residuals(pb, u, rp);
        u[k] = keep - STEP;
        residuals(pb, u, rm);
        u[k] = keep;
        for (int i = 0; i < FG_ABSORB_GRID; i++)
            jac[i][k] = (rp[i] - rm[i]) / (2.0 * STEP);
    }
}

/* One Levenberg-Marquardt run from u; returns the final cost. */
static double levenberg_marquardt(const problem *pb, double *u)
{
    static const double lambda_max = 1e12;
    double r[FG_ABSORB_GRID], jac[FG_ABSORB_GRID][NP];
    double cost = residuals(pb, u, r), lambda = 1e-2;
    for (int it = 0; it < ITERATIONS && lambda < lambda_max; it++) {
        jacobian(pb, u, jac);
        double jtj[NP][NP], g[NP];
        for (int a = 0; a < NP; a++) {
            g[a] = 0.0;
            for (int i = 0; i < FG_ABSORB_GRID; i++)
                g[a] -= jac[i][a] * r[i];
            for (int b = 0; b < NP; b++) {
                double s = 0.0;
                for (int i = 0; i < FG_ABSORB_GRID; i++)
                    s += jac[i][a] * jac[i][b];
                jtj[a][b] = s;
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
            double c = residuals(pb, trial, rt);
            if (c < cost) {
                memcpy(u, trial, sizeof trial);
                memcpy(r, rt, sizeof rt);
                double gain = cost - c;
                cost = c;
                lambda = fmax(lambda / 3.0, 1e-9);
                if (gain < 1e-12 * (1.0 + cost))
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
        const double rho = FG_ABSORB_MAX_RADIUS;
        u[4 * k + 2] = atanh(c1 / (rho * (1.0 + c2 / (rho * rho))));
        u[4 * k + 3] = atanh(c2 / (rho * rho));
    }
}

double fg_absorb_design(fg_iir *f, const fg_air *air, double distance_m, double fs_hz)
{
    problem pb;
    double lo = log(FG_ABSORB_LO_HZ), hi = log(fg_absorb_hi_hz(fs_hz));
    for (int i = 0; i < FG_ABSORB_GRID; i++) {
        double hz = exp(lo + (hi - lo) * i / (FG_ABSORB_GRID - 1));
        pb.w[i] = 2.0 * FG_PI * hz / fs_hz;
        pb.e[i] = fg_phasor_at(pb.w[i]);
        pb.target[i] = fg_absorb_target_db(air, distance_m, hz);
    }
    /* Local minima are common: keep the best of a few starts. */
    static const double spreads[] = {1.5, 2.0, 3.0};
    double u[NP], best = INFINITY;
    for (size_t s = 0; s < sizeof spreads / sizeof spreads[0]; s++) {
        double v[NP];
        initial_guess(&pb, spreads[s], v);
        double cost = levenberg_marquardt(&pb, v);
        if (cost < best) {
            best = cost;
            memcpy(u, v, sizeof v);
        }
    }
    to_filter(u, f);
    fg_iir_reset(f);
    double r[FG_ABSORB_GRID], worst = 0.0;
    residuals(&pb, u, r);
    for (int i = 0; i < FG_ABSORB_GRID; i++)
        worst = fmax(worst, fabs(r[i]));
    return worst;
}
