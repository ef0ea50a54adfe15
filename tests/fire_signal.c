#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

#include "fire_signal.h"
#include "fg_rng.h"

static double gauss(fg_rng *rng)
{
    double u1 = fg_rng_uniform(rng), u2 = fg_rng_uniform(rng);
    return sqrt(-2.0 * log(1.0 - u1)) * cos(6.283185307179586 * u2);
}

void fire_test_flux(double sim_rate_hz, size_t steps, uint64_t seed, double *flux)
{
    fg_rng rng;
    fg_rng_seed(&rng, seed);
    double a = exp(-1.0 / (0.15 * sim_rate_hz)), u = 0.0, x = 0.0;
    double u_sd = sqrt((1.0 - a) / (1.0 + a)); /* of u below, in steady state */
    for (size_t i = 0; i < steps; i++) {
        u = a * u + (1.0 - a) * gauss(&rng);
        x = 0.6 * x + gauss(&rng);
        flux[i] = 0.02 + 0.002 * exp(0.8 * u / u_sd) * x;
    }
}

void fire_welch(const float *x, size_t n, double fs, size_t seg, double *psd)
{
    double *buf = fftw_malloc(sizeof(double) * seg);
    fftw_complex *spec = fftw_malloc(sizeof(fftw_complex) * (seg / 2 + 1));
    fftw_plan plan = fftw_plan_dft_r2c_1d((int)seg, buf, spec, FFTW_ESTIMATE);
    double wsum2 = 0.0;
    for (size_t k = 0; k < seg; k++) {
        double w = 0.5 - 0.5 * cos(6.283185307179586 * (double)k / (double)seg);
        wsum2 += w * w;
    }
    for (size_t k = 0; k <= seg / 2; k++)
        psd[k] = 0.0;
    size_t segments = 0;
    for (size_t start = 0; start + seg <= n; start += seg / 2) {
        for (size_t k = 0; k < seg; k++) {
            double w = 0.5 - 0.5 * cos(6.283185307179586 * (double)k / (double)seg);
            buf[k] = w * x[start + k];
        }
        fftw_execute(plan);
        for (size_t k = 0; k <= seg / 2; k++) {
            double p = spec[k][0] * spec[k][0] + spec[k][1] * spec[k][1];
            psd[k] += (k == 0 || k == seg / 2 ? 1.0 : 2.0) * p / (fs * wsum2);
        }
        segments++;
    }
    for (size_t k = 0; k <= seg / 2; k++)
        psd[k] /= (double)segments;
    fftw_destroy_plan(plan);
    fftw_free(buf);
    fftw_free(spec);
}

double fire_band_mean(const double *psd, size_t seg, double fs, double lo, double hi)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t k = 0; k <= seg / 2; k++) {
        double f = (double)k * fs / (double)seg;
        if (f >= lo && f < hi) {
            sum += psd[k];
            count++;
        }
    }
    return count ? sum / (double)count : 0.0;
}

void fire_band_pass(const float *x, size_t n, double fs, double lo, double hi, double *out)
{
    double *buf = fftw_malloc(sizeof(double) * n);
    fftw_complex *spec = fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1));
    fftw_plan fwd = fftw_plan_dft_r2c_1d((int)n, buf, spec, FFTW_ESTIMATE);
    fftw_plan inv = fftw_plan_dft_c2r_1d((int)n, spec, buf, FFTW_ESTIMATE);
    for (size_t k = 0; k < n; k++)
        buf[k] = x[k];
    fftw_execute(fwd);
    for (size_t k = 0; k <= n / 2; k++) {
        double f = (double)k * fs / (double)n;
        if (f < lo || f >= hi)
            spec[k][0] = spec[k][1] = 0.0;
    }
    fftw_execute(inv);
    for (size_t k = 0; k < n; k++)
        out[k] = buf[k] / (double)n;
    fftw_destroy_plan(fwd);
    fftw_destroy_plan(inv);
    fftw_free(buf);
    fftw_free(spec);
}

size_t fire_frame_rms(const double *x, size_t n, size_t frame, double *rms)
{
    size_t frames = n / frame;
    for (size_t f = 0; f < frames; f++) {
        double s = 0.0;
        for (size_t k = 0; k < frame; k++)
            s += x[f * frame + k] * x[f * frame + k];
        rms[f] = sqrt(s / (double)frame);
    }
    return frames;
}

double fire_correlation(const double *a, const double *b, size_t n)
{
    double ma = 0.0, mb = 0.0;
    for (size_t i = 0; i < n; i++) {
        ma += a[i] / (double)n;
        mb += b[i] / (double)n;
    }
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (size_t i = 0; i < n; i++) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / sqrt(saa * sbb);
}

double fire_slope(const double *x, const double *y, size_t n)
{
    double mx = 0.0, my = 0.0;
    for (size_t i = 0; i < n; i++) {
        mx += x[i] / (double)n;
        my += y[i] / (double)n;
    }
    double sxy = 0.0, sxx = 0.0;
    for (size_t i = 0; i < n; i++) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
    }
    return sxy / sxx;
}
