/* From a recorded force to a seamless loop of g = dF/dt.
 *
 * The shedding period comes from the lift's upward crossings of its mean
 * (with hysteresis, so ripple does not count). The loop holds a whole number
 * of periods; its length is refined to the lag, within a quarter period,
 * at which the signal best repeats itself, and the period after the loop's
 * end is cross-faded into its start, so that sample frames - 1 runs on into
 * sample 0 as the recorded signal ran on. The derivative is taken of the
 * finished loop, with wrap-around, so g is seamless too. */
#include <math.h>

#include "aero_internal.h"
#include "vec3_internal.h" /* FG_PI */

#define HYSTERESIS 0.1 /* of the rms */

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

double fg_aero_mean_period(const double *x, size_t n, double rate_hz)
{
    if (n < 4)
        return 0.0;
    double m, rms;
    mean_rms(x, n, &m, &rms);
    if (!(rms > 0.0))
        return 0.0;
    double low = m - HYSTERESIS * rms, first = -1.0, last = -1.0;
    int armed = 0;
    size_t count = 0;
    for (size_t i = 1; i < n; i++) {
        if (x[i] < low)
            armed = 1;
        if (armed && x[i - 1] < m && x[i] >= m) {
            double t = (double)(i - 1) + (m - x[i - 1]) / (x[i] - x[i - 1]);
            if (count == 0)
                first = t;
            last = t;
            count++;
            armed = 0;
        }
    }
    if (count < 3)
        return 0.0;
    return (last - first) / (double)(count - 1) / rate_hz;
}

int fg_aero_loop_plan(const double *lift, size_t n, double rate_hz, uint32_t want,
                      fg_aero_loop *loop)
{
    double period = fg_aero_mean_period(lift, n, rate_hz);
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
