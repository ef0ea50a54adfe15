#include "ear_measure.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* X[k] = sum x[i] e^{-2 pi j k i / n} for bins k in [k0, k1). */
static void dft(const float *x, size_t n, size_t k0, size_t k1, double *re, double *im)
{
    for (size_t k = k0; k < k1; k++) {
        double w = 2.0 * PI * (double)k / (double)n, sr = 0.0, si = 0.0;
        /* the phasor by recurrence, renormalised every 1024 steps */
        double cr = 1.0, ci = 0.0, dr = cos(w), di = -sin(w);
        for (size_t i = 0; i < n; i++) {
            sr += x[i] * cr;
            si += x[i] * ci;
            double t = cr * dr - ci * di;
            ci = cr * di + ci * dr;
            cr = t;
            if ((i & 1023) == 1023) {
                cr = cos(w * (double)(i + 1));
                ci = -sin(w * (double)(i + 1));
            }
        }
        re[k - k0] = sr;
        im[k - k0] = si;
    }
}

double em_itd_s(const float *left, const float *right, size_t n, double fs_hz, double f_max_hz,
                double max_lag_s)
{
    size_t k1 = (size_t)(f_max_hz * (double)n / fs_hz) + 1;
    size_t m = k1 - 1;
    double *lr = malloc(4 * m * sizeof *lr);
    double *li = lr + m, *rr = lr + 2 * m, *ri = lr + 3 * m;
    dft(left, n, 1, k1, lr, li);
    dft(right, n, 1, k1, rr, ri);
    /* L conj(R): its phase falls as w tau for left = right delayed by tau */
    for (size_t k = 0; k < m; k++) {
        double a = lr[k] * rr[k] + li[k] * ri[k], b = li[k] * rr[k] - lr[k] * ri[k];
        lr[k] = a;
        li[k] = b;
    }
    double best = -INFINITY, best_tau = 0.0;
    for (double step = 1e-6, lo = -max_lag_s, hi = max_lag_s; step >= 0.99e-7; step /= 10.0) {
        double found = best_tau;
        for (double tau = lo; tau <= hi; tau += step) {
            double s = 0.0;
            for (size_t k = 0; k < m; k++) {
                double w = 2.0 * PI * (double)(k + 1) * fs_hz / (double)n;
                s += lr[k] * cos(w * tau) - li[k] * sin(w * tau);
            }
            if (s > best) {
                best = s;
                found = tau;
            }
        }
        best_tau = found;
        lo = found - step;
        hi = found + step;
    }
    free(lr);
    return best_tau;
}

double em_band_energy(const float *x, size_t n, double fs_hz, double f_lo_hz, double f_hi_hz)
{
    size_t k0 = (size_t)ceil(f_lo_hz * (double)n / fs_hz);
    size_t k1 = (size_t)ceil(f_hi_hz * (double)n / fs_hz);
    if (k1 <= k0)
        return 0.0;
    double *re = malloc(2 * (k1 - k0) * sizeof *re), *im = re + (k1 - k0), e = 0.0;
    dft(x, n, k0, k1, re, im);
    for (size_t k = 0; k < k1 - k0; k++)
        e += re[k] * re[k] + im[k] * im[k];
    free(re);
    return e;
}
