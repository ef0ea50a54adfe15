/* The WM-wave of one segment (wmwave.c) against things computed another way:
 * a brute-force sum of point N-waves along the segment, numeric integrals,
 * Glassner's chain identity, and the direct per-sample reference for the
 * difference-domain block accumulator. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "fg_math.h"
#include "fg_rng.h"
#include "sound/wmwave_internal.h"
#include "wm_reference.h"

#define C_M_S 343.0
#define FS_HZ 48000.0

#define CHECK(cond, ...)            \
    do {                            \
        if (!(cond))                \
            fail_msg(__VA_ARGS__);  \
    } while (0)

/* A shape with broadside peak ps: B = ps / (4 psi). */
static fg_wm_shape shape_of(double ps, double s, double psi)
{
    return (fg_wm_shape){.b = ps / (4.0 * psi), .s = s, .psi = psi};
}

/* ---------------------------------------------------------------------------
 * 1. Against point sources. The segment of half-length l lies along x; the
 * ear is at distance r from its midpoint, at angle theta from the normal
 * (the y axis). Each of M points on the segment radiates the point N-wave
 *   N(t) = -ps t / T on |t| < T,
 * delayed by its own exact 3-D path length; the segment's wave is their
 * mean. Nothing here uses eq. 5, tau, psi or B. */

typedef struct brute_segment {
    double l, t_half, ps, r, theta;
    int m;
    double *delay; /* m entries, seconds, relative to r / c */
} brute_segment;

static void brute_init(brute_segment *g)
{
    g->delay = malloc((size_t)g->m * sizeof *g->delay);
    assert_non_null(g->delay);
    double ex = g->r * sin(g->theta), ey = g->r * cos(g->theta);
    for (int i = 0; i < g->m; i++) {
        double x = g->l * (-1.0 + (2.0 * i + 1.0) / g->m);
        double d = sqrt((ex - x) * (ex - x) + ey * ey);
        g->delay[i] = (d - g->r) / C_M_S;
    }
}

static double brute_pressure(const brute_segment *g, double t)
{
    double sum = 0.0;
    for (int i = 0; i < g->m; i++) {
        double u = t - g->delay[i];
        if (fabs(u) < g->t_half)
            sum += -g->ps * u / g->t_half;
    }
    return sum / g->m;
}

typedef struct point_case {
    const char *name;
    double l, t_half; /* psi = c T / l */
    double theta_deg; /* < 0: put s exactly at psi * (1 + boundary_rel) */
    double boundary_rel;
} point_case;

static const point_case point_cases[] = {
    /* l = 2 cm, T = 30 us: psi = 0.5145, so 0-30 deg are s < psi and
     * 45-90 deg the split case */
    {"psi0.51 theta0", 0.02, 30e-6, 0.0, 0},
    {"psi0.51 theta15", 0.02, 30e-6, 15.0, 0},
    {"psi0.51 theta30", 0.02, 30e-6, 30.0, 0},
    {"psi0.51 theta45", 0.02, 30e-6, 45.0, 0},
    {"psi0.51 theta60", 0.02, 30e-6, 60.0, 0},
    {"psi0.51 theta90", 0.02, 30e-6, 90.0, 0},
    {"psi0.51 s=psi", 0.02, 30e-6, -1.0, 0.0},
    {"psi0.51 s=psi(1-1e-9)", 0.02, 30e-6, -1.0, -1e-9},
    {"psi0.51 s=psi(1+1e-9)", 0.02, 30e-6, -1.0, 1e-9},
    {"psi0.51 s=psi(1-2e-2)", 0.02, 30e-6, -1.0, -2e-2},
    {"psi0.51 s=psi(1+2e-2)", 0.02, 30e-6, -1.0, 2e-2},
    /* spark-ball segment: l = 1 mm, psi = 10.3, never split */
    {"psi10 theta0", 0.001, 30e-6, 0.0, 0},
    {"psi10 theta45", 0.001, 30e-6, 45.0, 0},
    {"psi10 theta90", 0.001, 30e-6, 90.0, 0},
    /* lightning segment: l = 1.5 m, T = 500 us, psi = 0.114 */
    {"psi0.11 theta15", 1.5, 500e-6, 15.0, 0},
    {"psi0.11 s=psi", 1.5, 500e-6, -1.0, 0.0},
    {"psi0.11 theta60", 1.5, 500e-6, 60.0, 0},
};

static void test_against_point_sources(void **state)
{
    (void)state;
    enum { M = 4000, K = 2000 };
    for (size_t ci = 0; ci < sizeof point_cases / sizeof point_cases[0]; ci++) {
        const point_case *pc = &point_cases[ci];
        double psi = C_M_S * pc->t_half / pc->l;
        double s, theta;
        if (pc->theta_deg < 0) {
            s = psi * (1.0 + pc->boundary_rel);
            theta = asin(s);
        } else {
            theta = pc->theta_deg * FG_PI / 180.0;
            s = fabs(sin(theta));
        }
        /* far field: r = 10^4 l makes the wavefront curvature over the
         * segment l^2 / 2r = 5e-5 l, far below what is measured */
        brute_segment g = {.l = pc->l, .t_half = pc->t_half, .ps = 2.5, .r = 1e4 * pc->l,
                           .theta = theta, .m = M};
        brute_init(&g);
        fg_wm_shape w = shape_of(g.ps, s, psi);

        double span_s = 1.2 * (pc->t_half + pc->l * s / C_M_S);
        double sab = 0, saa = 0, sbb = 0, peak_a = 0, peak_b = 0;
        for (int k = 0; k < K; k++) {
            double t = span_s * (-1.0 + (2.0 * k + 1.0) / K);
            double a = brute_pressure(&g, t);
            double b = fg_wm_pressure(&w, C_M_S * t / pc->l);
            CHECK(isfinite(b), "%s: p not finite at t=%g", pc->name, t);
            sab += a * b;
            saa += a * a;
            sbb += b * b;
            if (fabs(a) > peak_a)
                peak_a = fabs(a);
            if (fabs(b) > peak_b)
                peak_b = fabs(b);
        }
        double corr = sab / sqrt(saa * sbb);
        CHECK(corr >= 0.999, "%s: correlation %.6f < 0.999", pc->name, corr);
        CHECK(fabs(peak_b - peak_a) <= 0.01 * peak_a, "%s: peak %.6g vs point sources %.6g",
              pc->name, peak_b, peak_a);
        free(g.delay);
    }
}

/* ---------------------------------------------------------------------------
 * 2. Shape invariants over a table of (s, psi). */

typedef struct shape_case {
    const char *name;
    double s, psi;
} shape_case;

static const shape_case shape_cases[] = {
    {"s<psi", 0.3, 0.8},      {"s<<psi", 0.01, 5.0},   {"s=psi", 0.5, 0.5},
    {"s>psi", 0.9, 0.2},      {"s>>psi", 1.0, 0.01},   {"end-on psi>1", 1.0, 3.0},
    {"s=psi small", 0.05, 0.05},
};
#define N_SHAPES (sizeof shape_cases / sizeof shape_cases[0])

/* p is continuous at every breakpoint +-(psi - s), +-(psi + s), and so is P.
 * The step eps is small enough that the slope (at most ps / 2s per unit of
 * tau) moves p by far less than the tolerance. */
static void test_continuity(void **state)
{
    (void)state;
    const double eps = 1e-10;
    for (size_t ci = 0; ci < N_SHAPES; ci++) {
        const shape_case *sc = &shape_cases[ci];
        fg_wm_shape w = shape_of(1.0, sc->s, sc->psi);
        double bps[4] = {-(sc->psi + sc->s), -(sc->psi - sc->s), sc->psi - sc->s, sc->psi + sc->s};
        double pmax = 0, qmax = 0;
        for (int k = -1000; k <= 1000; k++) {
            double tau = (sc->psi + sc->s) * k / 1000.0;
            pmax = fmax(pmax, fabs(fg_wm_pressure(&w, tau)));
            qmax = fmax(qmax, fabs(fg_wm_integral(&w, tau)));
        }
        for (int i = 0; i < 4; i++) {
            double lo = bps[i] - eps, hi = bps[i] + eps;
            double dp = fabs(fg_wm_pressure(&w, hi) - fg_wm_pressure(&w, lo));
            double dq = fabs(fg_wm_integral(&w, hi) - fg_wm_integral(&w, lo));
            double at = fg_wm_pressure(&w, bps[i]);
            CHECK(dp <= 1e-7 * pmax, "%s: p jumps by %.3g (peak %.3g) at tau=%.6g", sc->name,
                  dp, pmax, bps[i]);
            CHECK(fabs(at - fg_wm_pressure(&w, lo)) <= 1e-7 * pmax,
                  "%s: p at breakpoint %.6g differs from the left limit", sc->name, bps[i]);
            CHECK(dq <= 1e-7 * qmax, "%s: P jumps by %.3g at tau=%.6g", sc->name, dq, bps[i]);
        }
        /* outside the support both vanish exactly */
        double out = sc->psi + sc->s;
        CHECK(fg_wm_pressure(&w, out * 1.0001) == 0.0 && fg_wm_pressure(&w, -out * 1.0001) == 0.0,
              "%s: p outside the support", sc->name);
        CHECK(fg_wm_integral(&w, out * 1.0001) == 0.0 && fg_wm_integral(&w, -out * 1.0001) == 0.0,
              "%s: P outside the support", sc->name);
    }
}

/* P is the running integral of p: compare with a composite Simpson rule on
 * a grid that knows nothing of the breakpoints. */
static void test_integral_matches_quadrature(void **state)
{
    (void)state;
    enum { N = 200000 }; /* even */
    for (size_t ci = 0; ci < N_SHAPES; ci++) {
        const shape_case *sc = &shape_cases[ci];
        fg_wm_shape w = shape_of(1.0, sc->s, sc->psi);
        double a = -1.1 * (sc->psi + sc->s), h = -2.0 * a / N;
        double acc = 0.0, qmax = 0.0, worst = 0.0;
        for (int k = 0; k + 2 <= N; k += 2) {
            double t0 = a + k * h;
            acc += h / 3.0 *
                   (fg_wm_pressure(&w, t0) + 4.0 * fg_wm_pressure(&w, t0 + h) +
                    fg_wm_pressure(&w, t0 + 2 * h));
            double q = fg_wm_integral(&w, t0 + 2 * h);
            qmax = fmax(qmax, fabs(q));
            worst = fmax(worst, fabs(q - acc));
        }
        CHECK(qmax > 0, "%s: P identically zero", sc->name);
        CHECK(worst <= 1e-6 * qmax, "%s: P differs from quadrature by %.3g (max P %.3g)",
              sc->name, worst, qmax);
        /* and the whole wave integrates to zero */
        CHECK(fabs(acc) <= 1e-6 * qmax, "%s: integral of p is %.3g", sc->name, acc);
    }
}

/* Zero DC of the sampled wave: the per-sample averages of an event sum to
 * zero up to rounding, relative to sqrt(sample count * energy). The centre
 * sits just past a sample edge so that even the narrowest wave straddles it
 * (one lying wholly inside a sample averages to exactly 0 there). */
static void test_zero_dc(void **state)
{
    (void)state;
    enum { N = 4096 };
    static double y[N];
    const double widths[] = {1e-3, 0.05, 0.7, 3.0, 40.0, 300.0};
    for (size_t ci = 0; ci < N_SHAPES; ci++) {
        for (size_t wi = 0; wi < sizeof widths / sizeof widths[0]; wi++) {
            fg_wm_event e = {.shape = shape_of(1.0, shape_cases[ci].s, shape_cases[ci].psi),
                          .center = N / 2 + 0.5 + 1e-5, .width = widths[wi]};
            memset(y, 0, sizeof y);
            ref_wm_add_direct(&e, y, N);
            double sum = 0, energy = 0;
            for (int n = 0; n < N; n++) {
                sum += y[n];
                energy += y[n] * y[n];
            }
            CHECK(energy > 0, "%s width %g: silent", shape_cases[ci].name, widths[wi]);
            CHECK(fabs(sum) <= 1e-12 * sqrt(N * energy), "%s width %g: DC %.3g, energy %.3g",
                  shape_cases[ci].name, widths[wi], sum, energy);
        }
    }
}

/* ---------------------------------------------------------------------------
 * 3. A spark shorter than a sample.
 *
 * Sample n of an event arriving at offset d (in samples) is the average
 *   y_n(d) = q(n - d),  q(x) = int_{x-1/2}^{x+1/2} p,
 * i.e. the box-filtered wave q read at the sample points. Averaged over a
 * uniform d in [0, 1),
 *   E[sum_n y_n(d)^2] = sum_n int_0^1 q(n - d)^2 dd = int q(x)^2 dx,
 * because the shifted unit intervals n - [0, 1) tile the line. So the mean
 * over arrival offsets of sum y^2 / fs is exactly the energy of the
 * box-filtered continuous wave; with a midpoint rule over K offsets it is
 * matched to the rule's accuracy. The same argument for point sampling gives
 * the unfiltered energy int p^2: point sampling keeps the energy on average
 * but spreads it wildly over the offsets.
 *
 * Each offset's own energy, though, is bounded away from zero only when the
 * wave cannot hide inside one sample interval: a zero-mean wave lying wholly
 * inside [n - 1/2, n + 1/2) averages to exactly 0 there. That happens for
 * 2(T + s l / c) < 1/fs, e.g. T = 10 us at 48 kHz; the band below is asserted
 * only where 2T exceeds a sample. */

typedef struct spark_case {
    const char *name;
    double t_half, s;
    double band_lo, band_hi; /* per-offset energy / mean; lo < 0: not asserted */
    double point_lo_max;     /* point sampling's worst offset keeps at most this; < 0: not asserted */
} spark_case;

static const spark_case spark_cases[] = {
    {"T=10us broadside", 10e-6, 0.0, -1, 2.0, -1},
    {"T=10us s=0.5", 10e-6, 0.5, -1, 2.0, -1},
    {"T=10us end-on", 10e-6, 1.0, -1, 2.0, -1},
    {"T=16us broadside", 16e-6, 0.0, 0.4, 1.5, 0.05},
    {"T=16us s=0.5", 16e-6, 0.5, 0.4, 1.5, 0.05},
    {"T=16us end-on", 16e-6, 1.0, 0.4, 1.5, 0.05},
    {"T=20us s=0.7", 20e-6, 0.7, 0.6, 1.45, 0.3},
};

static void test_short_spark_energy(void **state)
{
    (void)state;
    enum { K = 1024, N = 64, SUB = 4096 };
    const double l = 0.001; /* spark-ball segment */
    const double width = FS_HZ * l / C_M_S;
    static double e_box[K], e_point[K];
    for (size_t ci = 0; ci < sizeof spark_cases / sizeof spark_cases[0]; ci++) {
        const spark_case *sc = &spark_cases[ci];
        fg_wm_shape w = shape_of(1.0, sc->s, C_M_S * sc->t_half / l);
        double mean_box = 0, mean_point = 0;
        for (int k = 0; k < K; k++) {
            double y[N] = {0};
            fg_wm_event e = {.shape = w, .center = N / 2 + (k + 0.5) / K, .width = width};
            ref_wm_add_direct(&e, y, N);
            double eb = 0, ep = 0;
            for (int n = 0; n < N; n++) {
                double p = fg_wm_pressure(&w, (n - e.center) / width);
                eb += y[n] * y[n] / FS_HZ;
                ep += p * p / FS_HZ;
            }
            e_box[k] = eb;
            e_point[k] = ep;
            mean_box += eb / K;
            mean_point += ep / K;
        }

        /* the box-filtered energy, from p alone: q by a running sum of p on a
         * fine grid (SUB points per sample), then int q^2 */
        double half = (w.psi + w.s) * width; /* support half-width, samples */
        int len = (int)ceil((2 * half + 2) * SUB);
        double *pf = malloc((size_t)len * sizeof *pf);
        assert_non_null(pf);
        double x0 = -half - 1.0, h = 1.0 / SUB;
        for (int i = 0; i < len; i++)
            pf[i] = fg_wm_pressure(&w, (x0 + (i + 0.5) * h) / width);
        double run = 0, q2 = 0, p2 = 0;
        for (int i = 0; i < len; i++) {
            run += pf[i] * h;
            if (i >= SUB)
                run -= pf[i - SUB] * h;
            q2 += run * run * h;
            p2 += pf[i] * pf[i] * h;
        }
        free(pf);
        double box_energy = q2 / FS_HZ, cont_energy = p2 / FS_HZ;

        /* exact but for the quadratures: with s > 0 p is continuous and
         * both rules agree to ~1e-7; the broadside N-wave jumps, and the
         * fine grid's running sum then errs by ~1/SUB */
        double tol = sc->s > 0 ? 1e-6 : 1e-3;
        CHECK(fabs(mean_box - box_energy) <= tol * box_energy,
              "%s: offset-mean energy %.6g vs box-filtered %.6g", sc->name, mean_box, box_energy);
        /* point sampling jumps with the offset: the midpoint rule is coarser */
        CHECK(fabs(mean_point - cont_energy) <= 1e-2 * cont_energy,
              "%s: point-sampled mean %.6g vs continuous %.6g", sc->name, mean_point,
              cont_energy);

        double lo = INFINITY, hi = 0, lo_point = INFINITY;
        for (int k = 0; k < K; k++) {
            lo = fmin(lo, e_box[k] / mean_box);
            hi = fmax(hi, e_box[k] / mean_box);
            lo_point = fmin(lo_point, e_point[k] / mean_point);
        }
        CHECK(hi <= sc->band_hi, "%s: an offset holds %.3f x the mean", sc->name, hi);
        if (sc->band_lo > 0)
            CHECK(lo >= sc->band_lo, "%s: an offset keeps only %.3f of the mean", sc->name, lo);
        /* point sampling at the same offsets can lose most of it */
        if (sc->point_lo_max > 0)
            CHECK(lo_point <= sc->point_lo_max, "%s: point sampling kept %.3f at worst",
                  sc->name, lo_point);
    }
}

/* ---------------------------------------------------------------------------
 * 4. Glassner fig. 3: n equal colinear segments of half-length l, centres 2l
 * apart, arrivals 2 l s / c apart, with the same T and ps, sum to n times one
 * segment of half-length n l.
 *
 * Each WM-wave is the segment average (1/2l) int_{x-l}^{x+l} N(t - u s / c) du
 * of the point N-wave N, so the chain's sum is (1/2l) int_{-nl}^{nl} N du =
 * n (1/2nl) int_{-nl}^{nl} N du: n times the long segment's WM-wave, whose
 * psi is c T / (n l) and whose B is ps / (4 psi). */

typedef struct chain_case {
    const char *name;
    int n;
    double l, t_half, s;
} chain_case;

static const chain_case chain_cases[] = {
    {"2 x spark, s=0.3", 2, 0.001, 30e-6, 0.3},
    {"3 x spark, end-on", 3, 0.001, 30e-6, 1.0},
    {"8 x plasma, s=0.6", 8, 0.01, 40e-6, 0.6},
    {"5 x lightning, s=0.2", 5, 1.5, 500e-6, 0.2},
    {"12 x lightning, s=0.97", 12, 1.5, 500e-6, 0.97},
    {"4 x broadside", 4, 0.01, 40e-6, 0.0},
};

static void test_chain_is_one_segment(void **state)
{
    (void)state;
    enum { N = 12000 };
    static double chain[N], longseg[N];
    for (size_t ci = 0; ci < sizeof chain_cases / sizeof chain_cases[0]; ci++) {
        const chain_case *cc = &chain_cases[ci];
        const double ps = 1.7, center = N / 2 + 0.137;
        memset(chain, 0, sizeof chain);
        memset(longseg, 0, sizeof longseg);
        for (int j = 0; j < cc->n; j++) {
            double x = (2 * j - (cc->n - 1)) * cc->l; /* centre along the chain */
            fg_wm_event e = {.shape = shape_of(ps, cc->s, C_M_S * cc->t_half / cc->l),
                          .center = center + FS_HZ * x * cc->s / C_M_S,
                          .width = FS_HZ * cc->l / C_M_S};
            ref_wm_add_direct(&e, chain, N);
        }
        double big_l = cc->n * cc->l;
        fg_wm_event one = {.shape = shape_of(ps, cc->s, C_M_S * cc->t_half / big_l),
                        .center = center, .width = FS_HZ * big_l / C_M_S};
        ref_wm_add_direct(&one, longseg, N);
        double peak = 0, worst = 0;
        for (int k = 0; k < N; k++) {
            peak = fmax(peak, fabs(chain[k]));
            worst = fmax(worst, fabs(chain[k] - cc->n * longseg[k]));
        }
        CHECK(peak > 0.01 * ps, "%s: chain is silent (peak %.3g)", cc->name, peak);
        CHECK(worst <= 1e-9 * peak, "%s: chain - n x long = %.3g (peak %.3g)", cc->name, worst,
              peak);
    }
}

/* ---------------------------------------------------------------------------
 * 5. The block accumulator equals the direct per-sample sum. The test
 * rebuilds each block in double from the state and third differences as the
 * header defines them, so the comparison is not limited by float output;
 * fg_accum_end_all is then checked against the same values to float rounding. */

static fg_wm_event random_event(fg_rng *rng, double lo, double hi)
{
    double u = fg_rng_uniform(rng);
    double psi = exp(fg_rng_range(rng, log(0.01), log(20.0)));
    double s;
    if (u < 0.15)
        s = 0.0;
    else if (u < 0.3 && psi <= 1.0)
        s = psi;
    else
        s = fg_rng_uniform(rng);
    double v = fg_rng_uniform(rng);
    double width;
    if (v < 0.1)
        width = 1e-7; /* far shorter than a sample */
    else if (v < 0.15)
        width = 4096.0 / (psi + s); /* as long as the largest block */
    else
        width = exp(fg_rng_range(rng, log(1e-3), log(300.0)));
    double ps = fg_rng_range(rng, -1.0, 1.0);
    return (fg_wm_event){.shape = shape_of(ps, s, psi), .center = fg_rng_range(rng, lo, hi),
                      .width = width};
}

static void rebuild(const fg_accum *b, double *y)
{
    double y1 = b->state[0], y2 = b->state[1], y3 = b->state[2];
    for (size_t k = 0; k < b->n; k++) {
        y[k] = b->d3[k] + 3.0 * y1 - 3.0 * y2 + y3;
        y3 = y2;
        y2 = y1;
        y1 = y[k];
    }
}

typedef struct block_case {
    const char *name;
    size_t total;       /* samples rendered */
    size_t block;       /* block size; 0 = random 1..4096 per block */
    int events;
    double tol;         /* max error / peak */
} block_case;

/* Error model: the block is rebuilt by integrating third differences three
 * times, so a rounding error made where an event's breakpoint lands grows
 * like k^2 / 2 over the k samples after it in the block: about
 * eps * n^2 / 2 of the peak at the end of an n-sample block (eps = 2^-52),
 * adding up over the breakpoints in the block. That is ~1e-9 at n = 1000 and
 * ~1e-8 per breakpoint at n = 4096: there the bound is the resolution of the
 * engine's float output, 2^-24 = 6e-8, instead. */
static const block_case block_cases[] = {
    {"block 1", 1500, 1, 60, 1e-9},          {"block 2", 1500, 2, 60, 1e-9},
    {"block 3", 3000, 3, 80, 1e-9},          {"block 4", 3000, 4, 80, 1e-9},
    {"block 7", 6000, 7, 100, 1e-9},         {"block 64", 20000, 64, 300, 1e-9},
    {"block 100", 20000, 100, 300, 1e-9},    {"block 700", 40000, 700, 400, 1e-9},
    {"block 4096", 60000, 4096, 400, 0x1p-24}, {"random blocks", 60000, 0, 400, 0x1p-24},
};

/* copies of each block ended together with others: a pair, then five */
#define COPIES 7

static double run_blocks(const block_case *bc, uint64_t seed)
{
    fg_rng rng;
    fg_rng_seed(&rng, seed);
    size_t total = bc->total;
    fg_wm_event *ev = malloc((size_t)bc->events * sizeof *ev);
    double *ref = calloc(total, sizeof *ref);
    double *d3 = malloc((COPIES + 1) * 4096 * sizeof *d3);
    double *y = malloc(4096 * sizeof *y);
    float *out = malloc((COPIES + 1) * 4096 * sizeof *out);
    assert_true(ev && ref && d3 && y && out);
    /* centres from before the first block to after the last */
    for (int i = 0; i < bc->events; i++) {
        ev[i] = random_event(&rng, -300.0, (double)total + 300.0);
        ref_wm_add_direct(&ev[i], ref, total);
    }
    double peak = 0;
    for (size_t k = 0; k < total; k++)
        peak = fmax(peak, fabs(ref[k]));
    CHECK(peak > 0, "%s: silent reference", bc->name);

    double worst = 0;
    size_t start = 0;
    while (start < total) {
        size_t n = bc->block ? bc->block : 1 + (size_t)(fg_rng_next(&rng) % 4096);
        if (n > total - start)
            n = total - start;
        fg_accum blk;
        memset(d3, 0, n * sizeof *d3);
        fg_accum_restart(&blk, d3, n);
        for (int i = 0; i < bc->events; i++) {
            fg_wm_event rel = ev[i];
            rel.center -= (double)start;
            long first, last;
            fg_wm_event_span(&rel, &first, &last);
            fg_wave_status st = fg_wm_accum_add(&blk, &rel);
            if (st == FG_WAVE_DONE)
                CHECK(last < 0, "%s: event %d DONE but reaches sample %ld", bc->name, i, last);
            if (st == FG_WAVE_PENDING)
                CHECK(first >= (long)n, "%s: event %d PENDING but starts at %ld", bc->name, i,
                      first);
        }
        rebuild(&blk, y);
        /* alone, two copies of it as a pair and five copies at once (four
         * in AVX2 where the CPU has it, and one): every output as alone,
         * bit for bit; each end leaves its third differences zero */
        fg_accum copy[COPIES];
        float *copy_out[COPIES];
        for (size_t c = 0; c < COPIES; c++) {
            memcpy(d3 + (c + 1) * 4096, d3, n * sizeof *d3);
            copy[c] = blk;
            copy[c].d3 = d3 + (c + 1) * 4096;
            copy_out[c] = out + (c + 1) * n;
        }
        memset(out, 0, (COPIES + 1) * n * sizeof *out);
        fg_accum *alone[1] = {&blk}, *many[COPIES];
        for (size_t c = 0; c < COPIES; c++)
            many[c] = &copy[c];
        fg_accum_end_all(alone, (float *[]){out}, 1, n, false);
        fg_accum_end_all(many, copy_out, 2, n, false);
        fg_accum_end_all(many + 2, copy_out + 2, COPIES - 2, n, fg_accum_avx2_available());
        for (size_t c = 0; c < COPIES; c++)
            CHECK(memcmp(out, copy_out[c], n * sizeof *out) == 0,
                  "%s: copy %zu of a block, ended with others, differs from the block ended "
                  "alone",
                  bc->name, c);
        bool cleared = true;
        for (size_t c = 0; c <= COPIES; c++)
            for (size_t k = 0; k < n; k++)
                cleared = cleared && d3[c * 4096 + k] == 0.0;
        CHECK(cleared, "%s: an end left third differences in its block", bc->name);
        for (size_t k = 0; k < n; k++) {
            worst = fmax(worst, fabs(y[k] - ref[start + k]));
            CHECK(fabs(out[k] - y[k]) <= 1e-7 * peak, "%s: fg_accum_end_all wrote %.9g for %.9g",
                  bc->name, out[k], y[k]);
        }
        start += n;
    }
    free(ev);
    free(ref);
    free(d3);
    free(y);
    free(out);
    return worst / peak;
}

static void test_block_matches_direct(void **state)
{
    (void)state;
    for (size_t ci = 0; ci < sizeof block_cases / sizeof block_cases[0]; ci++) {
        double rel = run_blocks(&block_cases[ci], 1000 + ci);
        print_message("%-14s max error %.2e of the peak\n", block_cases[ci].name, rel);
        CHECK(rel <= block_cases[ci].tol, "%s: max error %.3g of the peak (bound %.3g)",
              block_cases[ci].name, rel, block_cases[ci].tol);
    }
}

/* Many blocks, events everywhere: the error of the last blocks is no worse
 * than that of the first (each block starts from exact values). */
static void test_block_no_drift(void **state)
{
    (void)state;
    enum { BLOCK = 256, BLOCKS = 1200, EVENTS = 2400 };
    const size_t total = (size_t)BLOCK * BLOCKS;
    fg_rng rng;
    fg_rng_seed(&rng, 77);
    fg_wm_event *ev = malloc(EVENTS * sizeof *ev);
    double *ref = calloc(total, sizeof *ref);
    assert_true(ev && ref);
    for (int i = 0; i < EVENTS; i++) {
        ev[i] = random_event(&rng, 0.0, (double)total);
        ev[i].width = fmin(ev[i].width, 50.0);
        ref_wm_add_direct(&ev[i], ref, total);
    }
    double peak = 0;
    for (size_t k = 0; k < total; k++)
        peak = fmax(peak, fabs(ref[k]));
    double d3[BLOCK], y[BLOCK];
    double first_err = 0, last_err = 0;
    for (size_t b = 0; b < BLOCKS; b++) {
        fg_accum blk;
        memset(d3, 0, BLOCK * sizeof *d3);
        fg_accum_restart(&blk, d3, BLOCK);
        for (int i = 0; i < EVENTS; i++) {
            fg_wm_event rel = ev[i];
            rel.center -= (double)(b * BLOCK);
            (void)fg_wm_accum_add(&blk, &rel);
        }
        rebuild(&blk, y);
        double err = 0;
        for (size_t k = 0; k < BLOCK; k++)
            err = fmax(err, fabs(y[k] - ref[b * BLOCK + k]));
        if (b < BLOCKS / 10)
            first_err = fmax(first_err, err);
        if (b >= BLOCKS - BLOCKS / 10)
            last_err = fmax(last_err, err);
    }
    CHECK(first_err <= 1e-9 * peak && last_err <= 1e-9 * peak,
          "error first %.3g last %.3g (peak %.3g)", first_err, last_err, peak);
    CHECK(last_err <= 10 * first_err + 1e-14 * peak, "drift: first %.3g, last %.3g", first_err,
          last_err);
    free(ev);
    free(ref);
}

/* ---------------------------------------------------------------------------
 * 6. s -> 0: the pure N-wave, no NaN or infinity. */
static void test_tiny_s(void **state)
{
    (void)state;
    const double tiny[] = {1e-300, 1e-12, 0.0};
    const double psis[] = {0.05, 1.0, 10.0};
    for (size_t pi = 0; pi < 3; pi++) {
        double psi = psis[pi];
        fg_wm_shape n_wave = shape_of(1.0, 0.0, psi);
        for (size_t si = 0; si < 3; si++) {
            fg_wm_shape w = shape_of(1.0, tiny[si], psi);
            for (int k = -2000; k <= 2000; k++) {
                double tau = 1.2 * psi * k / 2000.0 + 1e-7 * psi;
                double p = fg_wm_pressure(&w, tau), q = fg_wm_integral(&w, tau);
                CHECK(isfinite(p) && isfinite(q), "s=%g psi=%g: p=%g P=%g at %g", tiny[si], psi,
                      p, q, tau);
                /* away from the jumps at +-psi, exactly the N-wave -ps tau/psi */
                if (fabs(fabs(tau) - psi) > 1e-6 * psi) {
                    double want = fabs(tau) < psi ? -tau / psi : 0.0;
                    CHECK(fabs(p - want) <= 1e-9, "s=%g psi=%g: p(%g)=%.12g, N-wave %.12g",
                          tiny[si], psi, tau, p, want);
                }
                CHECK(fabs(q - fg_wm_integral(&n_wave, tau)) <= 1e-9 * psi,
                      "s=%g psi=%g: P(%g) differs from the N-wave's", tiny[si], psi, tau);
            }
            /* sample averages as well */
            double y[64] = {0}, y0[64] = {0};
            fg_wm_event e = {.shape = w, .center = 31.7, .width = 7.0 / psi};
            fg_wm_event e0 = {.shape = n_wave, .center = 31.7, .width = 7.0 / psi};
            ref_wm_add_direct(&e, y, 64);
            ref_wm_add_direct(&e0, y0, 64);
            for (int n = 0; n < 64; n++)
                CHECK(isfinite(y[n]) && fabs(y[n] - y0[n]) <= 1e-9,
                      "s=%g psi=%g: sample %d = %.12g vs %.12g", tiny[si], psi, n, y[n], y0[n]);
        }
    }
}

/* ---------------------------------------------------------------------------
 * 7. A wave whose breakpoint taps overflow is refused in every block it
 * sounds in, a block with none of its breakpoints in it too (where the
 * accumulator skips breakpoints of moderate waves): its state there is
 * finite, its taps are not. A moderate twin sounds in the same block and
 * matches the direct sum. */
static void test_overflowing_taps_refused_mid_wave(void **state)
{
    (void)state;
    enum { N = 64 };
    double d3[N], y[N];
    /* closed form (s width = 50); breakpoints near samples +-950 and
     * +-1050, none in the block; the state's samples lie in the linear
     * middle piece near tau = 0, where -4 B tau stays finite */
    fg_wm_event e = {.shape = shape_of(1.0, 0.5, 10.0), .center = 1.5, .width = 100.0};
    e.shape.b = 1e307; /* 2 B psi / s overflows */
    fg_accum blk;
    memset(d3, 0, N * sizeof *d3);
    fg_accum_restart(&blk, d3, N);
    CHECK(fg_wm_event_in_range(&e), "the wave is in range");
    CHECK(fg_wm_accum_add(&blk, &e) == FG_WAVE_NON_FINITE, "overflowing taps were accepted");
    CHECK(!fg_accum_sounds(&blk), "a refused wave touched the block");

    e.shape.b = 1.0;
    double ref[N] = {0};
    ref_wm_add_direct(&e, ref, N);
    CHECK(fg_wm_accum_add(&blk, &e) == FG_WAVE_SOUNDING, "the moderate twin does not sound");
    rebuild(&blk, y);
    double peak = 0;
    for (int k = 0; k < N; k++)
        peak = fmax(peak, fabs(ref[k]));
    CHECK(peak > 0, "a silent reference");
    for (int k = 0; k < N; k++)
        CHECK(fabs(y[k] - ref[k]) <= 1e-10 * peak, "sample %d: %.15g, direct %.15g", k, y[k],
              ref[k]);
}

/* ---------------------------------------------------------------------------
 * 8. The state of a wave in its middle piece (what a long wave adds in
 * every block it sounds through) is the sample averages the exact ranges
 * give, bit for bit: fg_wm_pressure at each sample's midpoint, + 0. Both
 * ways a wave is added (closed form, exact ranges), a middle piece of 0
 * (s >= psi), and s below psi's rounding (inner = outer = 2^53), where the
 * state's last two midpoints fall on the outer breakpoint: 0 there. */
typedef struct state_case {
    const char *name;
    fg_wm_event e;
    bool closed_form;
} state_case;

/* Evaluates e, in range and sounding, for a block of 64 frames. */
static void eval_sounding(const char *name, const fg_wm_event *e, fg_wm_taps *t)
{
    long first, last;
    CHECK(fg_wm_event_in_range(e), "%s: out of range", name);
    fg_wm_event_span(e, &first, &last);
    CHECK(fg_wm_taps_eval(e, first, last, 64, t) == FG_WAVE_SOUNDING, "%s: not sounding", name);
}

static void test_state_in_the_middle(void **state)
{
    (void)state;
    const state_case cases[] = {
        {"closed form", {shape_of(1.0, 0.5, 10.0), 1.5, 100.0}, true},
        {"s >= psi", {shape_of(1.0, 0.9, 0.3), 1.5, 100.0}, true},
        {"exact ranges", {shape_of(1.0, 0.01, 10.0), 1.5, 100.0}, false},
        {"s below rounding", {shape_of(1.0, 0.5, 0x1p53), -0x1p55, 4.0}, true},
    };
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
        const state_case *c = &cases[ci];
        const fg_wm_shape *w = &c->e.shape;
        fg_wm_taps t;
        eval_sounding(c->name, &c->e, &t);
        CHECK(t.closed_form == c->closed_form, "%s: added the other way", c->name);
        CHECK(c->closed_form ? t.state : t.lo[0] == -3 && t.hi[0] == -1,
              "%s: no state of its own", c->name);
        for (long k = -3; k <= -1; k++) {
            double a = ((double)k - 0.5 - c->e.center) / c->e.width;
            double z = ((double)k + 0.5 - c->e.center) / c->e.width;
            CHECK(a > -fabs(w->psi - w->s) && z <= fabs(w->psi - w->s),
                  "%s: sample %ld outside the middle piece", c->name, k);
            double want = fg_wm_pressure(w, 0.5 * (a + z)) + 0.0;
            CHECK(memcmp(&t.y[0][k + 3], &want, sizeof want) == 0,
                  "%s: sample %ld is %.17g, the exact range's %.17g", c->name, k,
                  t.y[0][k + 3], want);
        }
    }
}

/* ---------------------------------------------------------------------------
 * 9. The state of a wave inside one shell (a quadratic piece) is the
 * sample averages the exact ranges give, bit for bit: fg_wm_pressure at
 * each sample's midpoint plus the curvature term p'' h^2 / 24, p'' = -+2 B
 * / s on the rising / falling shell; and, independently, the average of p
 * over the sample from the closed-form integral, width (P(z) - P(a)), to
 * 1e-9 of the peak. Both shells of a wave added in closed form (one
 * added by exact ranges has a shell under 4 samples wide, whose state
 * merges with its breakpoints' ranges). */
typedef struct shell_case {
    const char *name;
    fg_wm_event e;
    double p2; /* the shell's p'', per tau^2, over B / s */
} shell_case;

static void test_state_in_a_shell(void **state)
{
    (void)state;
    const shell_case cases[] = {
        {"rising", {shape_of(1.0, 0.5, 10.0), 998.0, 100.0}, -2.0},
        {"falling", {shape_of(1.0, 0.5, 10.0), -1002.0, 100.0}, 2.0},
    };
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
        const shell_case *c = &cases[ci];
        const fg_wm_shape *w = &c->e.shape;
        const double inner = fabs(w->psi - w->s), outer = w->psi + w->s;
        fg_wm_taps t;
        eval_sounding(c->name, &c->e, &t);
        CHECK(t.closed_form && t.state, "%s: not in closed form with a state", c->name);
        const double curvature = c->p2 * w->b / w->s;
        for (long k = -3; k <= -1; k++) {
            double a = ((double)k - 0.5 - c->e.center) / c->e.width;
            double z = ((double)k + 0.5 - c->e.center) / c->e.width;
            CHECK(fabs(a) > inner && fabs(z) > inner && fabs(a) <= outer && fabs(z) <= outer &&
                      (a < 0) == (z < 0),
                  "%s: sample %ld outside one shell", c->name, k);
            double h = z - a;
            double want = fg_wm_pressure(w, 0.5 * (a + z)) + curvature * h * h / 24.0;
            CHECK(memcmp(&t.y[0][k + 3], &want, sizeof want) == 0,
                  "%s: sample %ld is %.17g, the exact range's %.17g", c->name, k,
                  t.y[0][k + 3], want);
            double integral = c->e.width * (fg_wm_integral(w, z) - fg_wm_integral(w, a));
            double peak = 4.0 * w->b * w->psi;
            CHECK(fabs(want - integral) <= 1e-9 * peak,
                  "%s: sample %ld averages %.17g, the integral %.17g", c->name, k, want,
                  integral);
        }
    }
}

/* ---------------------------------------------------------------------------
 * 10. A wave sounding through a block with none of its breakpoints in it
 * adds its state alone; fg_wm_through finds exactly those waves, and the
 * edges it places once give each bus's B (a share in [-1, 1] of the ear's)
 * the state fg_wm_taps_eval gives, bit for bit. Over waves at random
 * places around a block of 64, long and short, middle pieces of either
 * sign and of 0 (s >= psi), both shells, and waves out of closed form. */
static void test_through_is_the_state_alone(void **state)
{
    (void)state;
    enum { N = 64, WAVES = 20000 };
    fg_rng rng;
    fg_rng_seed(&rng, 17);
    int through = 0, other = 0, pieces[4] = {0};
    static const double shares[] = {1.0, -0.37, 0.8125, 1.0 / 3.0};
    for (int i = 0; i < WAVES; i++) {
        double psi = fg_rng_range(&rng, 0.05, 12.0), s = fg_rng_range(&rng, 0.0, 1.0);
        double width = fg_rng_range(&rng, 0.5, 300.0);
        double reach = (psi + s) * width;
        fg_wm_event e = {shape_of(fg_rng_range(&rng, -3.0, 3.0), s, psi),
                         fg_rng_range(&rng, -reach - 8.0, N + reach + 8.0), width};
        long first, last;
        CHECK(fg_wm_event_in_range(&e), "wave %d: out of range", i);
        fg_wm_event_span(&e, &first, &last);
        fg_wm_state_edges edges;
        const bool alone = fg_wm_through(&e, first, last, N, &edges);
        for (size_t k = 0; k < sizeof shares / sizeof shares[0]; k++) {
            fg_wm_event bus = e;
            bus.shape.b = e.shape.b * shares[k];
            fg_wm_taps t;
            fg_wave_status st = fg_wm_taps_eval(&bus, first, last, N, &t);
            bool state_alone = st == FG_WAVE_SOUNDING && t.closed_form && t.state && t.count == 0;
            CHECK(alone == state_alone,
                  "wave %d (psi %.17g, s %.17g, width %.17g, centre %.17g): "
                  "through %d, the evaluation's state alone %d",
                  i, psi, s, width, e.center, alone, state_alone);
            if (!alone)
                continue;
            double y[3];
            CHECK(fg_wm_state_values(&edges, &bus.shape, y), "wave %d: not finite", i);
            CHECK(memcmp(y, t.y[0], sizeof y) == 0,
                  "wave %d, share %g: state %.17g %.17g %.17g, the evaluation's %.17g %.17g %.17g",
                  i, shares[k], y[0], y[1], y[2], t.y[0][0], t.y[0][1], t.y[0][2]);
        }
        if (alone) {
            through++;
            pieces[edges.piece]++;
        } else {
            other++;
        }
    }
    CHECK(through > 1000 && other > 1000, "%d waves through the block, %d not", through, other);
    CHECK(pieces[1] > 100 && pieces[2] > 100 && pieces[3] > 100,
          "through in the rising shell %d, the middle %d, the falling shell %d", pieces[1],
          pieces[2], pieces[3]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_point_sources),
        cmocka_unit_test(test_continuity),
        cmocka_unit_test(test_integral_matches_quadrature),
        cmocka_unit_test(test_zero_dc),
        cmocka_unit_test(test_short_spark_energy),
        cmocka_unit_test(test_chain_is_one_segment),
        cmocka_unit_test(test_block_matches_direct),
        cmocka_unit_test(test_block_no_drift),
        cmocka_unit_test(test_tiny_s),
        cmocka_unit_test(test_overflowing_taps_refused_mid_wave),
        cmocka_unit_test(test_state_in_the_middle),
        cmocka_unit_test(test_state_in_a_shell),
        cmocka_unit_test(test_through_is_the_state_alone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
