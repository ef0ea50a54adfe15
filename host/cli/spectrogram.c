/* STFT with band grouping for a log-frequency axis.
 *
 * Level of a band: the mean-square pressure it carries in the frame,
 * sum over its bins of c|X_k|^2 / (N^2 mean(w^2)) with c = 2 for the bins
 * that stand for a negative frequency too (Parseval, corrected for the
 * window's power), as dB re (20 uPa)^2. A sinusoid thus reads its own
 * level in the band that holds it. */
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

#include "spectrogram.h"
#include "fg_math.h"

#define MAX_SLICES 400
#define MAX_WINDOW 65536
#define BAND_RATIO 1.0293022366434921 /* 2^(1/24): bands at least 1/24 octave wide */
#define P_REF_PA 20e-6
#define FLOOR_DB (-20.0)

/* Window length: the power of two at or above 1/12 s (4096 at 48 kHz,
 * ~12 Hz bins: thunder's 20-50 Hz is resolved), at most MAX_WINDOW (what
 * 768 kHz needs): the rate comes from a file's header. */
static size_t window_length(double rate_hz)
{
    size_t n = 256;
    while ((double)n < rate_hz / 12 && n < MAX_WINDOW)
        n *= 2;
    return n;
}

static void write_slice(FILE *out, const fftw_complex *X, size_t n, double rate_hz,
                        double t_s)
{
    double norm = (double)n * (double)n * 0.375; /* N^2 mean(w^2), Hann: 3/8 */
    double floor_ms = P_REF_PA * P_REF_PA * pow(10, FLOOR_DB / 10);
    size_t half = n / 2;
    for (size_t lo = 1; lo <= half;) {
        size_t hi = (size_t)ceil((double)lo * BAND_RATIO);
        if (hi <= lo)
            hi = lo + 1;
        if (hi > half + 1)
            hi = half + 1;
        double power = 0;
        for (size_t k = lo; k < hi; k++)
            power += (k == half ? 1.0 : 2.0) * (X[k][0] * X[k][0] + X[k][1] * X[k][1]) / norm;
        double freq = rate_hz / (double)n * sqrt((double)lo * (double)(hi - 1));
        double db = 10 * log10(fmax(power, floor_ms) / (P_REF_PA * P_REF_PA));
        fprintf(out, "%.6f %.3f %.2f\n", t_s, freq, db);
        lo = hi;
    }
    fprintf(out, "\n");
}

int spectrogram_write(FILE *out, const float *samples, size_t frames, int channels, int channel,
                      double rate_hz)
{
    size_t n = window_length(rate_hz);
    size_t hop = (frames + MAX_SLICES - 1) / MAX_SLICES;
    if (hop < n / 8)
        hop = n / 8;
    double *in = fftw_malloc(n * sizeof *in);
    double *window = malloc(n * sizeof *window);
    fftw_complex *X = fftw_malloc((n / 2 + 1) * sizeof *X);
    fftw_plan plan = in && X ? fftw_plan_dft_r2c_1d((int)n, in, X, FFTW_ESTIMATE) : NULL;
    int rc = -1;
    if (!plan || !window)
        goto done;
    for (size_t i = 0; i < n; i++)
        window[i] = 0.5 - 0.5 * cos(2 * FG_PI * (double)i / (double)n);
    fprintf(out, "# time_s freq_hz level_db_re_20uPa (window %zu, hop %zu, channel %d)\n", n,
            hop, channel);
    for (size_t centre = 0; centre <= frames; centre += hop) {
        for (size_t i = 0; i < n; i++) {
            /* frame i covers sample centre - n/2 + i; zero outside the file */
            size_t f = centre + i;
            in[i] = f >= n / 2 && f - n / 2 < frames
                        ? window[i] * samples[(f - n / 2) * (size_t)channels + (size_t)channel]
                        : 0.0;
        }
        fftw_execute(plan);
        write_slice(out, X, n, rate_hz, (double)centre / rate_hz);
    }
    rc = ferror(out) ? -1 : 0;
done:
    if (plan)
        fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(X);
    free(window);
    return rc;
}
