#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fft_internal.h"
#include "fg_math.h"

bool fg_fft_init(fg_fft *f, size_t n)
{
    memset(f, 0, sizeof *f);
    if (n < FG_FFT_MIN_SIZE || n > FG_FFT_MAX_SIZE || (n & (n - 1)) != 0)
        return false;
    size_t m = n / 2;
    f->twiddle = malloc(sizeof(double) * n);
    f->reverse = malloc(sizeof(size_t) * m);
    if (!f->twiddle || !f->reverse) {
        fg_fft_deinit(f);
        return false;
    }
    f->n = n;
    for (size_t k = 0; k < m; k++) {
        double a = 2.0 * FG_PI * (double)k / (double)n;
        f->twiddle[2 * k] = cos(a);
        f->twiddle[2 * k + 1] = -sin(a);
    }
    unsigned bits = 0;
    while (((size_t)1 << bits) < m)
        bits++;
    for (size_t k = 0; k < m; k++) {
        size_t r = 0;
        for (unsigned b = 0; b < bits; b++)
            r |= ((k >> b) & 1u) << (bits - 1 - b);
        f->reverse[k] = r;
    }
    return true;
}

void fg_fft_deinit(fg_fft *f)
{
    free(f->twiddle);
    free(f->reverse);
    memset(f, 0, sizeof *f);
}

/* In-place m-point complex transform of z (interleaved), m = n / 2. The
 * twiddle of a stage of length len at index j is e^{-+2 pi i j / len}
 * = twiddle[j * (n / len)]; sign = -1 conjugates it (inverse). */
static void complex_fft(const fg_fft *f, double *z, double sign)
{
    size_t m = f->n / 2;
    for (size_t k = 0; k < m; k++) {
        size_t r = f->reverse[k];
        if (r > k) {
            double re = z[2 * k], im = z[2 * k + 1];
            z[2 * k] = z[2 * r];
            z[2 * k + 1] = z[2 * r + 1];
            z[2 * r] = re;
            z[2 * r + 1] = im;
        }
    }
    for (size_t len = 2; len <= m; len *= 2) {
        size_t half = len / 2, step = f->n / len;
        for (size_t start = 0; start < m; start += len) {
            for (size_t j = 0; j < half; j++) {
                double wr = f->twiddle[2 * j * step], wi = sign * f->twiddle[2 * j * step + 1];
                double *a = z + 2 * (start + j), *b = z + 2 * (start + j + half);
                double tr = b[0] * wr - b[1] * wi, ti = b[0] * wi + b[1] * wr;
                b[0] = a[0] - tr;
                b[1] = a[1] - ti;
                a[0] += tr;
                a[1] += ti;
            }
        }
    }
}

void fg_fft_forward(const fg_fft *f, const double *x, double *spectrum)
{
    size_t n = f->n, m = n / 2;
    if (spectrum != x)
        memcpy(spectrum, x, sizeof(double) * n);
    /* z[k] = x[2k] + i x[2k+1]: the real array read as m complex values */
    complex_fft(f, spectrum, 1.0);
    double z0r = spectrum[0], z0i = spectrum[1];
    spectrum[0] = z0r + z0i;
    spectrum[1] = 0.0;
    spectrum[n] = z0r - z0i;
    spectrum[n + 1] = 0.0;
    /* X[k] = (Z[k] + conj Z[m-k]) / 2 - i W^k (Z[k] - conj Z[m-k]) / 2,
     * W = e^{-2 pi i / n}; pairs k and m - k are done together. */
    for (size_t k = 1; k <= m / 2; k++) {
        size_t j = m - k;
        double ar = spectrum[2 * k], ai = spectrum[2 * k + 1];
        double br = spectrum[2 * j], bi = spectrum[2 * j + 1];
        double er = 0.5 * (ar + br), ei = 0.5 * (ai - bi); /* even part */
        double or_ = 0.5 * (ai + bi), oi = -0.5 * (ar - br); /* odd part */
        double wr = f->twiddle[2 * k], wi = f->twiddle[2 * k + 1];
        double tr = wr * or_ - wi * oi, ti = wr * oi + wi * or_;
        spectrum[2 * k] = er + tr;
        spectrum[2 * k + 1] = ei + ti;
        /* X[m-k] = conj(E) - conj(W^k O) * (-1): W^{m-k} = -conj(W^k) */
        spectrum[2 * j] = er - tr;
        spectrum[2 * j + 1] = -(ei - ti);
    }
}

void fg_fft_inverse(const fg_fft *f, double *spectrum, double *x)
{
    size_t n = f->n, m = n / 2;
    double x0 = spectrum[0], xm = spectrum[n];
    /* Undo the split: Z[k] = E[k] + i W^{-k} ... with E = (X[k] + conj X[m-k]) / 2,
     * O = (X[k] - conj X[m-k]) W^{-k} / 2, Z[k] = E + i O. */
    for (size_t k = 1; k <= m / 2; k++) {
        size_t j = m - k;
        double ar = spectrum[2 * k], ai = spectrum[2 * k + 1];
        double br = spectrum[2 * j], bi = spectrum[2 * j + 1];
        double er = 0.5 * (ar + br), ei = 0.5 * (ai - bi);
        double dr = 0.5 * (ar - br), di = 0.5 * (ai + bi);
        double wr = f->twiddle[2 * k], wi = -f->twiddle[2 * k + 1]; /* W^{-k} */
        double or_ = dr * wr - di * wi, oi = dr * wi + di * wr;
        /* Z[k] = E + i O; Z[m-k] = conj(E) + i conj(O) * (-1)... */
        spectrum[2 * k] = er - oi;
        spectrum[2 * k + 1] = ei + or_;
        spectrum[2 * j] = er + oi;
        spectrum[2 * j + 1] = -ei + or_;
    }
    spectrum[0] = 0.5 * (x0 + xm);
    spectrum[1] = 0.5 * (x0 - xm);
    complex_fft(f, spectrum, -1.0);
    double scale = 2.0 / (double)n;
    for (size_t k = 0; k < n; k++)
        x[k] = spectrum[k] * scale;
}
