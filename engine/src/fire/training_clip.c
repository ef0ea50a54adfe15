/* The project's procedural training clip (we may ship no recording).
 *
 * A made-up fire, in three parts, all drawn from one seeded generator:
 *   roar    noise of power spectrum f^-2.5 above 250 Hz, flat below, rolled
 *           off below 40 Hz (a 2nd-order high-pass shape), multiplied by a
 *           slow log-normal envelope e(t) = exp(0.5 u(t)), u unit-variance
 *           white noise through two one-pole low-passes (120 ms, 40 ms);
 *   crackle Poisson bursts at 25 e(t) per second (more when the roar
 *           surges), each 1-4 clicks 0.3-3 ms apart; a click is a decaying
 *           sinusoid of 1.5-7 kHz (log-uniform) and 0.06-0.4 ms decay, of
 *           Pareto-distributed amplitude (index 1.6, capped at 30x);
 *   hiss    unit white noise through a one-pole high-pass at 3 kHz,
 *           sqrt(e(t)) loud.
 * Levels: roar 0.1 (RMS before the envelope), click scale 0.08, hiss
 * 0.004; the sum is then scaled to a peak of 0.5. It sounds like a fire more than like anything
 * else, but it is not one: texture synthesis trained on it is only as
 * real as it is. */
#include <math.h>
#include <stdlib.h>

#include "noise_internal.h"
#include "fulgur/fire.h"
#include "fg_rng.h"
#include "fg_math.h"

#define ROAR_FFT 8192

static double log_uniform(fg_rng *rng, double lo, double hi)
{
    return exp(fg_rng_range(rng, log(lo), log(hi)));
}

/* The slow envelope exp(0.5 u), u normalised to unit variance. */
static void envelope(fg_rng *rng, double fs, double *e, size_t frames)
{
    double a1 = exp(-1.0 / (0.12 * fs)), a2 = exp(-1.0 / (0.04 * fs));
    double y1 = 0.0, y2 = 0.0, sum2 = 0.0;
    /* start the filters in their steady state: run them for 1 s first */
    for (size_t i = 0; i < (size_t)fs; i++) {
        y1 = a1 * y1 + (1.0 - a1) * fg_rng_gaussian(rng);
        y2 = a2 * y2 + (1.0 - a2) * y1;
    }
    for (size_t i = 0; i < frames; i++) {
        y1 = a1 * y1 + (1.0 - a1) * fg_rng_gaussian(rng);
        y2 = a2 * y2 + (1.0 - a2) * y1;
        e[i] = y2;
        sum2 += y2 * y2;
    }
    double norm = sum2 > 0.0 ? 1.0 / sqrt(sum2 / (double)frames) : 0.0;
    for (size_t i = 0; i < frames; i++)
        e[i] = exp(0.5 * norm * e[i]);
}

static void add_burst(fg_rng *rng, double fs, double *mix, size_t frames, size_t at)
{
    double amplitude = 0.08 * fmin(pow(1.0 - fg_rng_uniform(rng), -1.0 / 1.6), 30.0);
    if (fg_rng_uniform(rng) < 0.5)
        amplitude = -amplitude;
    int clicks = 1;
    while (clicks < 4 && fg_rng_uniform(rng) < 0.5)
        clicks++;
    double t0 = (double)at / fs;
    for (int c = 0; c < clicks; c++) {
        double f = log_uniform(rng, 1500.0, 7000.0), tau = log_uniform(rng, 0.06e-3, 0.4e-3);
        double phase = fg_rng_range(rng, -FG_PI, FG_PI), a = amplitude * fg_rng_range(rng, 0.5, 1.0);
        size_t start = (size_t)(t0 * fs), len = (size_t)ceil(8.0 * tau * fs);
        for (size_t k = 0; k < len && start + k < frames; k++) {
            double t = (double)k / fs;
            mix[start + k] += a * exp(-t / tau) * sin(2.0 * FG_PI * f * t + phase);
        }
        t0 += log_uniform(rng, 0.3e-3, 3e-3);
    }
}

fg_result fg_fire_training_clip(double sample_rate_hz, uint64_t seed, float *out, size_t frames)
{
    if (!out && frames > 0)
        return FG_ERR_NULL;
    if (!isfinite(sample_rate_hz) || sample_rate_hz < 8000.0 || sample_rate_hz > 384000.0)
        return FG_ERR_SAMPLE_RATE;
    if (frames == 0)
        return FG_OK;
    double fs = sample_rate_hz;
    double *mix = malloc(sizeof(double) * frames), *e = malloc(sizeof(double) * frames);
    double *shape = malloc(sizeof(double) * (ROAR_FFT / 2 + 1));
    fg_fft fft = {0};
    fg_noise roar = {0};
    fg_result r = FG_ERR_NO_MEMORY;
    if (!mix || !e || !shape || !fg_fft_init(&fft, ROAR_FFT))
        goto done;
    for (size_t k = 0; k <= ROAR_FFT / 2; k++) {
        double f = (double)k * fs / ROAR_FFT, hp = (f / 40.0) * (f / 40.0);
        shape[k] = hp / (1.0 + hp) * pow(1.0 + (f / 250.0) * (f / 250.0), -2.5 / 4.0);
    }
    if (!fg_noise_init(&roar, &fft, shape, seed ^ 0x726f6172u))
        goto done;
    fg_rng rng;
    fg_rng_seed(&rng, seed);
    envelope(&rng, fs, e, frames);
    double hiss_a = exp(-2.0 * FG_PI * 3000.0 / fs), hiss_prev_x = 0.0, hiss_y = 0.0;
    for (size_t i = 0; i < frames; i++) {
        double x = fg_rng_gaussian(&rng);
        /* one-pole high-pass: y = a (y + x - x_prev) */
        hiss_y = hiss_a * (hiss_y + x - hiss_prev_x);
        hiss_prev_x = x;
        mix[i] = 0.1 * e[i] * fg_noise_next(&roar) + 0.004 * sqrt(e[i]) * hiss_y;
    }
    for (size_t i = 0; i < frames; i++)
        if (fg_rng_uniform(&rng) < 25.0 * e[i] / fs)
            add_burst(&rng, fs, mix, frames, i);
    double peak = 0.0;
    for (size_t i = 0; i < frames; i++)
        peak = fmax(peak, fabs(mix[i]));
    double scale = peak > 0.0 ? 0.5 / peak : 0.0;
    for (size_t i = 0; i < frames; i++)
        out[i] = (float)(mix[i] * scale);
    r = FG_OK;
done:
    fg_noise_deinit(&roar);
    fg_fft_deinit(&fft);
    free(mix);
    free(e);
    free(shape);
    return r;
}
