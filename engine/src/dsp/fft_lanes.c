#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fft_internal.h"
#include "fft_lanes_internal.h"
#include "fg_math.h"

#define V FG_VF_LANES

static inline fg_vf get(const float *a, size_t e)
{
    return fg_vf_load(a + e * V);
}

static inline void put(float *a, size_t e, fg_vf v)
{
    fg_vf_store(a + e * V, v);
}

bool fg_fft_lanes_init(fg_fft_lanes *f, size_t n)
{
    memset(f, 0, sizeof *f);
    if (n < FG_FFT_MIN_SIZE || n > FG_FFT_MAX_SIZE || (n & (n - 1)) != 0)
        return false;
    size_t m = n / 2;
    f->twiddle = malloc(sizeof(float) * 2 * (m - 1));
    f->split = malloc(sizeof(float) * 2 * (m / 2 + 1));
    if (!f->twiddle || !f->split) {
        fg_fft_lanes_deinit(f);
        return false;
    }
    f->n = n;
    float *t = f->twiddle;
    for (size_t len = m; len >= 2; len /= 2) {
        for (size_t j = 0; j < len / 2; j++) {
            double a = 2.0 * FG_PI * (double)j / (double)len;
            t[j] = (float)cos(a);
            t[len / 2 + j] = (float)sin(a);
        }
        t += len;
    }
    for (size_t k = 0; k <= m / 2; k++) {
        double a = 2.0 * FG_PI * (double)k / (double)n;
        f->split[2 * k] = (float)cos(a);
        f->split[2 * k + 1] = (float)sin(a);
    }
    return true;
}

void fg_fft_lanes_deinit(fg_fft_lanes *f)
{
    free(f->twiddle);
    free(f->split);
    memset(f, 0, sizeof *f);
}

/* One Stockham stage of the m-point transform: the m / len interleaved
 * len-point transforms of x (stride s = m / len) split into their halves'
 * sum and twiddled difference, written to y at stride 2s. tw: the stage's
 * cos then sin runs; sign -1 forward (e^{-i a}), +1 inverse. */
static void stage(size_t m, size_t len, const float *tw, float sign, const float *x, float *y)
{
    size_t half = len / 2, s = m / len;
    for (size_t p = 0; p < half; p++) {
        fg_vf wr = fg_vf_set(tw[p]), wi = fg_vf_set(sign * tw[half + p]);
        for (size_t q = 0; q < s; q++) {
            size_t a = q + s * p, b = a + s * half, ya = q + 2 * s * p, yb = ya + s;
            fg_vf ar = get(x, a), ai = get(x, m + a), br = get(x, b), bi = get(x, m + b);
            fg_vf dr = ar - br, di = ai - bi;
            put(y, ya, ar + br);
            put(y, m + ya, ai + bi);
            put(y, yb, dr * wr - di * wi);
            put(y, m + yb, dr * wi + di * wr);
        }
    }
}

/* The m = N/2-point complex transform of the split array x, in place. */
static void complex_fft(const fg_fft_lanes *f, float *x, float *work, float sign)
{
    size_t m = f->n / 2;
    const float *tw = f->twiddle;
    float *src = x, *dst = work;
    for (size_t len = m; len >= 2; len /= 2) {
        stage(m, len, tw, sign, src, dst);
        tw += len;
        float *t = src;
        src = dst;
        dst = t;
    }
    if (src != x)
        memcpy(x, src, sizeof(float) * f->n * V);
}

void fg_fft_lanes_forward(const fg_fft_lanes *f, float *x, float *work)
{
    size_t m = f->n / 2;
    complex_fft(f, x, work, -1.0f);
    /* X[k] = E[k] + W^k O[k], W = e^{-2 pi i / N}, from Z[k] and conj
     * Z[m-k]; the pair k, m - k at once */
    const fg_vf half = fg_vf_set(0.5f);
    for (size_t k = 1; k < m / 2; k++) {
        size_t j = m - k;
        fg_vf ar = get(x, k), ai = get(x, m + k), br = get(x, j), bi = get(x, m + j);
        fg_vf er = half * (ar + br), ei = half * (ai - bi);
        fg_vf or_ = half * (ai + bi), oi = half * (br - ar);
        fg_vf wr = fg_vf_set(f->split[2 * k]), wi = fg_vf_set(-f->split[2 * k + 1]);
        fg_vf tr = wr * or_ - wi * oi, ti = wr * oi + wi * or_;
        put(x, k, er + tr);
        put(x, m + k, ei + ti);
        put(x, j, er - tr);
        put(x, m + j, ti - ei);
    }
    /* X[m/2] = conj Z[m/2] */
    put(x, m + m / 2, -get(x, m + m / 2));
    fg_vf z0r = get(x, 0), z0i = get(x, m);
    put(x, 0, z0r + z0i);
    put(x, m, z0r - z0i); /* X[N/2], in the place of Im X[0] = 0 */
}

void fg_fft_lanes_inverse(const fg_fft_lanes *f, float *x, float *work)
{
    size_t m = f->n / 2;
    /* Z[k] = E + i O, E = (X[k] + conj X[m-k]) / 2, O = W^{-k} (X[k] -
     * conj X[m-k]) / 2, with the transform's 1/N carried here */
    const fg_vf h = fg_vf_set(1.0f / (float)f->n);
    for (size_t k = 1; k < m / 2; k++) {
        size_t j = m - k;
        fg_vf ar = get(x, k), ai = get(x, m + k), br = get(x, j), bi = get(x, m + j);
        fg_vf er = h * (ar + br), ei = h * (ai - bi);
        fg_vf dr = h * (ar - br), di = h * (ai + bi);
        fg_vf wr = fg_vf_set(f->split[2 * k]), wi = fg_vf_set(f->split[2 * k + 1]);
        fg_vf or_ = dr * wr - di * wi, oi = dr * wi + di * wr;
        put(x, k, er - oi);
        put(x, m + k, ei + or_);
        put(x, j, er + oi);
        put(x, m + j, or_ - ei);
    }
    const fg_vf h2 = h + h;
    put(x, m / 2, h2 * get(x, m / 2));
    put(x, m + m / 2, -h2 * get(x, m + m / 2));
    fg_vf x0 = get(x, 0), xm = get(x, m);
    put(x, 0, h * (x0 + xm));
    put(x, m, h * (x0 - xm));
    complex_fft(f, x, work, 1.0f);
}
