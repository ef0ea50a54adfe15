/* From a recorded force to a seamless loop of g = dF/dt.
 *
 * The shedding frequency is the peak of the lift's spectrum (Hann window,
 * the peak refined by golden-section search on the windowed transform).
 * Counting the lift's crossings of its mean gives the same at Re 100,
 * where the lift is a clean sine, but at Re 6 700 the shear layers'
 * ripple adds crossings: 0.27 against 0.21 for the peak on the same
 * record. The loop holds a whole number
 * of periods; its length is refined to the lag, within a quarter period,
 * at which the signal best repeats itself, and the period after the loop's
 * end is cross-faded into its start, so that sample frames - 1 runs on into
 * sample 0 as the recorded signal ran on. The derivative is taken of the
 * finished loop, with wrap-around, so g is seamless too. */
#include <math.h>
#include <stdlib.h>

#include "aero_internal.h"
#include "fg_math.h"


static void mean_rms(const double *x, size_t n, double *mean, double *rms)
{
    double s = 0.0, q = 0.0;
    for (size_t i = 0; i < n; i++)
        s += x[i];
    *mean = s / (double)n;
    for (size_t i = 0; i < n; i++)
        q += (x[i] - *mean) * (x[i] - *mean);
    *rms = sqrt(q / (double)n);
}

/* |sum of v[k] e^(-2 pi i f k / rate)|^2 */
static double power(const double *v, size_t n, double rate, double f)
{
    double re = 0.0, im = 0.0, step = 2.0 * FG_PI * f / rate;
    double c = cos(step), s = sin(step), cr = 1.0, ci = 0.0; /* e^(i step k), by rotation */
    for (size_t k = 0; k < n; k++) {
        re += v[k] * cr;
        im -= v[k] * ci;
        double nr = cr * c - ci * s;
        ci = cr * s + ci * c;
        cr = nr;
    }
    return re * re + im * im;
}

double fg_aero_dominant_period(const double *x, size_t n, double rate_hz, double lo_hz,
                               double hi_hz)
{
    if (n < 16)
        return 0.0;
    double m, rms;
    mean_rms(x, n, &m, &rms);
    double *v = malloc(n * sizeof(double));
    if (!(rms > 0.0) || !v) {
        free(v);
        return 0.0;
    }
    for (size_t k = 0; k < n; k++) /* Hann-windowed, mean removed */
        v[k] = (0.5 - 0.5 * cos(2.0 * FG_PI * (double)k / (double)(n - 1))) * (x[k] - m);
    /* a grid of a quarter of the transform's resolution, from two periods
     * in the record */
    double span = (double)n / rate_hz, df = 0.25 / span;
    lo_hz = fmax(lo_hz, 2.0 / span);
    hi_hz = fmin(hi_hz, 0.25 * rate_hz);
    double best_f = 0.0, best = -1.0;
    for (double f = lo_hz; f <= hi_hz; f += df) {
        double p = power(v, n, rate_hz, f);
        if (p > best) {
            best = p;
            best_f = f;
        }
    }
    double period = 0.0;
    if (best_f > lo_hz && best_f + df <= hi_hz) { /* a peak inside the range */
        /* golden-section refinement within one grid step either side */
        double a = best_f - df, b = best_f + df, g = 0.5 * (sqrt(5.0) - 1.0);
        double c = b - g * (b - a), d = a + g * (b - a);
        double pc = power(v, n, rate_hz, c), pd = power(v, n, rate_hz, d);
        for (int it = 0; it < 40; it++) {
            if (pc > pd) {
                b = d;
                d = c;
                pd = pc;
                c = b - g * (b - a);
                pc = power(v, n, rate_hz, c);
            } else {
                a = c;
                c = d;
                pc = pd;
                d = a + g * (b - a);
                pd = power(v, n, rate_hz, d);
            }
        }
        /* no oscillation: a flat spectrum. The peak must stand 30 times
         * above the mean power (the window keeps 3/8 n rms^2 of it); noise
         * alone peaks near ln(n) times the mean, a shedding lift hundreds */
        double f = 0.5 * (a + b);
        if (power(v, n, rate_hz, f) > 30.0 * 0.375 * rms * rms * (double)n)
            period = 1.0 / f;
    }
    free(v);
    return period;
}

int fg_aero_loop_plan(const double *lift, size_t n, double rate_hz, double lo_hz, double hi_hz,
                      uint32_t want, fg_aero_loop *loop)
{
    double period = fg_aero_dominant_period(lift, n, rate_hz, lo_hz, hi_hz);
    double p = period * rate_hz; /* samples per period */
    if (!(p >= 4.0))
        return -1;
    size_t fade = (size_t)lround(p);
    double most = floor(((double)n - (double)fade) / p - 0.25);
    if (most < 2.0)
        return -1;
    uint32_t periods = want > 0 && want < most ? want : (uint32_t)most;
    long nominal = lround(periods * p), reach = lround(0.25 * p);
    long best_len = nominal;
    double best = INFINITY;
    for (long len = nominal - reach; len <= nominal + reach; len++) {
        if (len < 2 || (size_t)len + fade > n)
            continue;
        double e = 0.0;
        for (size_t i = 0; i < fade; i++) {
            double d = lift[i] - lift[i + (size_t)len];
            e += d * d;
        }
        if (e < best) {
            best = e;
            best_len = len;
        }
    }
    loop->period_s = period;
    loop->periods = periods;
    loop->frames = (uint32_t)best_len;
    loop->fade = (uint32_t)fade;
    return 0;
}

void fg_aero_loop_crossfade(const double *x, const fg_aero_loop *loop, double *out)
{
    for (uint32_t i = 0; i < loop->frames; i++) {
        if (i >= loop->fade) {
            out[i] = x[i];
            continue;
        }
        double w = 0.5 - 0.5 * cos(FG_PI * (i + 0.5) / loop->fade);
        out[i] = (1.0 - w) * x[i + loop->frames] + w * x[i];
    }
}

void fg_aero_loop_derivative(const double *f, uint32_t frames, double rate_hz, float *g,
                             size_t stride)
{
    for (uint32_t i = 0; i < frames; i++) {
        double next = f[i + 1 < frames ? i + 1 : 0], prev = f[i > 0 ? i - 1 : frames - 1];
        g[(size_t)i * stride] = (float)(0.5 * rate_hz * (next - prev));
    }
}
