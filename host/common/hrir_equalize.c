/* The diffuse-field equalization of an HRIR set: see hrir_equalize.h. */
#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hrir_equalize.h"

/* FFTW's planner is not thread-safe by itself: scenes may be loaded on
 * threads at once (the Python package), and the LV2 plugin's worker plans
 * while other plugins in the same host may. FFTW's own lock
 * (fftw_make_planner_thread_safe, FFTW 3.3.5, libfftw3_threads) guards
 * every planner call in the process once it is installed, ours and
 * theirs. */
static pthread_once_t planner_lock = PTHREAD_ONCE_INIT;

#define PI 3.14159265358979323846

/* The onset threshold, of the response's peak (-10 dB), and the share of
 * the response faded out at its end. */
#define ONSET_OF_PEAK 0.316
#define FADE_SHARE 0.05

typedef struct eq_work {
    size_t n, bins;
    double *time;
    fftw_complex *freq;
    fftw_plan forward, inverse;
} eq_work;

static void work_free(eq_work *w)
{
    if (w->forward)
        fftw_destroy_plan(w->forward);
    if (w->inverse)
        fftw_destroy_plan(w->inverse);
    fftw_free(w->time);
    fftw_free(w->freq);
}

static int work_init(eq_work *w, size_t length)
{
    *w = (eq_work){.n = 1024};
    while (w->n < 8 * length)
        w->n <<= 1;
    w->bins = w->n / 2 + 1;
    w->time = fftw_alloc_real(w->n);
    w->freq = fftw_alloc_complex(w->bins);
    if (!w->time || !w->freq)
        return -1;
    pthread_once(&planner_lock, fftw_make_planner_thread_safe);
    w->forward = fftw_plan_dft_r2c_1d((int)w->n, w->time, w->freq, FFTW_ESTIMATE);
    w->inverse = fftw_plan_dft_c2r_1d((int)w->n, w->freq, w->time, FFTW_ESTIMATE);
    return w->forward && w->inverse ? 0 : -1;
}

/* The spectrum of taps[0..length), zero-padded, into w->freq. */
static void spectrum(eq_work *w, const float *taps, size_t length)
{
    for (size_t t = 0; t < w->n; t++)
        w->time[t] = t < length ? taps[t] : 0.0;
    fftw_execute(w->forward);
}

/* The minimum-phase filter whose magnitude is 1 / sqrt(power[b]), by the
 * folded cepstrum, into filter[0..bins). */
static void inverse_min_phase(eq_work *w, const double *power, double complex *filter)
{
    for (size_t b = 0; b < w->bins; b++)
        w->freq[b] = -0.5 * log(power[b]);
    fftw_execute(w->inverse); /* the real cepstrum, times n */
    for (size_t t = 0; t < w->n; t++) {
        double fold = t == 0 || t == w->n / 2 ? 1.0 : t < w->n / 2 ? 2.0 : 0.0;
        w->time[t] *= fold / (double)w->n;
    }
    fftw_execute(w->forward);
    for (size_t b = 0; b < w->bins; b++)
        filter[b] = cexp(w->freq[b]);
}

/* The first tap within ONSET_OF_PEAK of the response's peak. */
static size_t onset(const float *taps, size_t length)
{
    double peak = 0.0;
    for (size_t t = 0; t < length; t++)
        peak = fmax(peak, fabs(taps[t]));
    size_t t = 0;
    while (t + 1 < length && fabs(taps[t]) < ONSET_OF_PEAK * peak)
        t++;
    return t;
}

/* A fourth-order Linkwitz-Riley crossover at fc, bin by bin: the
 * response above it goes through high[], the flat delayed one below
 * through low[]; low + high is one all-pass, the same for every response,
 * so interaural differences are kept. */
static void crossover(const eq_work *w, size_t bc, double fs, double complex *low,
                      double complex *high)
{
    double fc = (double)bc * fs / (double)w->n;
    for (size_t b = 0; b < w->bins; b++) {
        double f = (double)b * fs / (double)w->n;
        double complex s = I * f / fc, butter = 1.0 / (s * s + sqrt(2.0) * s + 1.0);
        low[b] = butter * butter;
        high[b] = s * s * s * s * butter * butter;
    }
}

/* One response: times the equalizer, and below the crossover bin bc a
 * unit impulse delayed to the response's phase there (the head
 * transparent), back to its length with its end faded. */
static void equalize(eq_work *w, float *taps, size_t length, const double complex *filter,
                     const double complex *low, const double complex *high, size_t bc,
                     double fs)
{
    double tau0 = (double)onset(taps, length) / fs;
    spectrum(w, taps, length);
    for (size_t b = 0; b < w->bins; b++)
        w->freq[b] *= filter[b];
    double fc = (double)bc * fs / (double)w->n;
    double phase = carg(w->freq[bc]);
    /* the delay whose phase at fc is the response's, nearest the onset */
    double k = round((2.0 * PI * fc * tau0 + phase) / (2.0 * PI));
    double tau = (2.0 * PI * k - phase) / (2.0 * PI * fc);
    if (tau < 0.0)
        tau += 1.0 / fc;
    for (size_t b = 0; b < w->bins; b++) {
        double f = (double)b * fs / (double)w->n;
        w->freq[b] = high[b] * w->freq[b] + low[b] * cexp(-2.0 * PI * I * f * tau);
    }
    fftw_execute(w->inverse);
    size_t fade_from = (size_t)((1.0 - FADE_SHARE) * (double)length);
    for (size_t t = 0; t < length; t++) {
        double g = 1.0 / (double)w->n;
        if (t >= fade_from)
            g *= 0.5 + 0.5 * cos(PI * (double)(t - fade_from) / (double)(length - fade_from));
        taps[t] = (float)(w->time[t] * g);
    }
}

int hrir_equalize(const fg_hrir_set *set, float *left, float *right, double file_rate_hz,
                  char *why, size_t why_size)
{
    const size_t length = set->length, count = set->count;
    const double fs = set->sample_rate_hz;
    eq_work w;
    double *power = NULL;
    double complex *filter = NULL, *low = NULL, *high = NULL;
    int rc = -1;
    if (work_init(&w, length) != 0 || !(power = calloc(w.bins, sizeof *power)) ||
        !(filter = malloc(w.bins * sizeof *filter)) || !(low = malloc(w.bins * sizeof *low)) ||
        !(high = malloc(w.bins * sizeof *high))) {
        snprintf(why, why_size, "equalizing the responses: out of memory");
        goto done;
    }
    for (size_t s = 0; s < 2 * count; s++) {
        spectrum(&w, (s < count ? left : right) + (s % count) * length, length);
        for (size_t b = 0; b < w.bins; b++)
            power[b] += creal(w.freq[b] * conj(w.freq[b])) / (double)(2 * count);
    }
    size_t bc = (size_t)lround(HRIR_EQ_CROSSOVER_HZ * (double)w.n / fs);
    size_t bh = (size_t)lround(0.45 * fmin(file_rate_hz, fs) * (double)w.n / fs);
    if (bh >= w.bins)
        bh = w.bins - 1;
    if (bc < 2 || bc >= bh || !(power[bc] > 0.0) || !(power[bh] > 0.0)) {
        snprintf(why, why_size, "the responses have no energy at %g Hz to equalize",
                 !(power[bc] > 0.0) ? HRIR_EQ_CROSSOVER_HZ : 0.45 * fmin(file_rate_hz, fs));
        goto done;
    }
    for (size_t b = 0; b < w.bins; b++) {
        power[b] = b < bc ? power[bc] : b > bh ? power[bh] : power[b];
        if (!(power[b] > 0.0))
            power[b] = power[bc]; /* a notch shared by every response: left as it is */
    }
    inverse_min_phase(&w, power, filter);
    crossover(&w, bc, fs, low, high);
    for (size_t s = 0; s < count; s++) {
        equalize(&w, left + s * length, length, filter, low, high, bc, fs);
        equalize(&w, right + s * length, length, filter, low, high, bc, fs);
    }
    rc = 0;
done:
    work_free(&w);
    free(power);
    free(filter);
    free(low);
    free(high);
    return rc;
}
