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

/* Writes cos and sin of 2 pi j k / len, j < count, as two runs. */
static float *angles(float *t, size_t count, size_t k, size_t len)
{
    for (size_t j = 0; j < count; j++) {
        double a = 2.0 * FG_PI * (double)(j * k) / (double)len;
        t[j] = (float)cos(a);
        t[count + j] = (float)sin(a);
    }
    return t + 2 * count;
}

bool fg_fft_lanes_init(fg_fft_lanes *f, size_t n)
{
    memset(f, 0, sizeof *f);
    if (n < FG_FFT_MIN_SIZE || n > FG_FFT_MAX_SIZE || (n & (n - 1)) != 0)
        return false;
    size_t m = n / 2, bits = 0;
    while (((size_t)1 << bits) < m)
        bits++;
    f->twiddle = malloc(sizeof(float) * 3 * m);
    f->split = malloc(sizeof(float) * 2 * (m / 2 + 1));
    if (!f->twiddle || !f->split) {
        fg_fft_lanes_deinit(f);
        return false;
    }
    f->n = n;
    f->radix2 = bits % 2 == 1;
    f->stages = bits % 2 + bits / 2;
    float *t = f->twiddle;
    size_t len = m;
    if (f->radix2) {
        t = angles(t, len / 2, 1, len);
        len /= 2;
    }
    for (; len >= 4; len /= 4)
        for (size_t k = 1; k <= 3; k++)
            t = angles(t, len / 4, k, len);
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

/* u e^{-i a}, given cos a and sin a */
static inline void rotate(fg_vf *ur, fg_vf *ui, fg_vf c, fg_vf s)
{
    fg_vf r = *ur * c + *ui * s;
    *ui = *ui * c - *ur * s;
    *ur = r;
}

/* The butterflies of index p of a radix-2 Stockham stage: the m / len
 * interleaved len-point transforms of x (stride st = m / len) split into
 * the sum of their halves and the difference turned by e^{-2 pi i p / len}
 * (skipped for p = 0), written to y at stride 2 st. */
static inline void radix2(const float *x, float *y, size_t m, size_t st, size_t half, size_t p,
                          const float *tw, bool turn)
{
    fg_vf c = fg_vf_set(turn ? tw[p] : 1.0f), s = fg_vf_set(turn ? tw[half + p] : 0.0f);
    for (size_t q = 0; q < st; q++) {
        size_t a = q + st * p, b = a + st * half, ya = q + 2 * st * p, yb = ya + st;
        fg_vf ar = get(x, a), ai = get(x, m + a), br = get(x, b), bi = get(x, m + b);
        fg_vf dr = ar - br, di = ai - bi;
        put(y, ya, ar + br);
        put(y, m + ya, ai + bi);
        if (turn)
            rotate(&dr, &di, c, s);
        put(y, yb, dr);
        put(y, m + yb, di);
    }
}

/* The same for radix 4: the quarters a, b, c, d of each len-point
 * transform give a + b + c + d and, turned by e^{-2 pi i k p / len},
 * a - ib - c + id (k = 1), a - b + c - d (k = 2), a + ib - c - id (k = 3),
 * written to y at stride 4 st. tw: the stage's cos and sin runs for
 * k = 1, 2, 3. */
static inline void radix4(const float *x, float *y, size_t m, size_t st, size_t quarter, size_t p,
                          const float *tw, bool turn)
{
    fg_vf c1 = fg_vf_set(1.0f), s1 = fg_vf_set(0.0f), c2 = c1, s2 = s1, c3 = c1, s3 = s1;
    if (turn) {
        c1 = fg_vf_set(tw[p]);
        s1 = fg_vf_set(tw[quarter + p]);
        c2 = fg_vf_set(tw[2 * quarter + p]);
        s2 = fg_vf_set(tw[3 * quarter + p]);
        c3 = fg_vf_set(tw[4 * quarter + p]);
        s3 = fg_vf_set(tw[5 * quarter + p]);
    }
    const size_t gap = st * quarter;
    for (size_t q = 0; q < st; q++) {
        size_t a = q + st * p, y0 = q + 4 * st * p;
        fg_vf ar = get(x, a), ai = get(x, m + a);
        fg_vf br = get(x, a + gap), bi = get(x, m + a + gap);
        fg_vf cr = get(x, a + 2 * gap), ci = get(x, m + a + 2 * gap);
        fg_vf dr = get(x, a + 3 * gap), di = get(x, m + a + 3 * gap);
        fg_vf t0r = ar + cr, t0i = ai + ci, t1r = ar - cr, t1i = ai - ci;
        fg_vf t2r = br + dr, t2i = bi + di, er = br - dr, ei = bi - di; /* -i e = (ei, -er) */
        fg_vf u1r = t1r + ei, u1i = t1i - er;
        fg_vf u2r = t0r - t2r, u2i = t0i - t2i;
        fg_vf u3r = t1r - ei, u3i = t1i + er;
        if (turn) {
            rotate(&u1r, &u1i, c1, s1);
            rotate(&u2r, &u2i, c2, s2);
            rotate(&u3r, &u3i, c3, s3);
        }
        put(y, y0, t0r + t2r);
        put(y, m + y0, t0i + t2i);
        put(y, y0 + st, u1r);
        put(y, m + y0 + st, u1i);
        put(y, y0 + 2 * st, u2r);
        put(y, m + y0 + 2 * st, u2i);
        put(y, y0 + 3 * st, u3r);
        put(y, m + y0 + 3 * st, u3i);
    }
}

/* The forward m = N/2-point complex transform of the split array x,
 * ping-ponging with other; returns the one that holds it (x after an even
 * number of stages). */
static float *complex_fft(const fg_fft_lanes *f, float *x, float *other)
{
    const size_t m = f->n / 2;
    const float *tw = f->twiddle;
    float *src = x, *dst = other;
    size_t len = m;
    if (f->radix2) {
        for (size_t p = 0; p < len / 2; p++)
            radix2(src, dst, m, 1, len / 2, p, tw, p > 0);
        tw += len;
        dst = src;
        src = other;
        len /= 2;
    }
    for (; len >= 4; len /= 4) {
        size_t st = m / len, quarter = len / 4;
        for (size_t p = 0; p < quarter; p++)
            radix4(src, dst, m, st, quarter, p, tw, p > 0);
        tw += 6 * quarter;
        float *t = src;
        src = dst;
        dst = t;
    }
    return src;
}

void fg_fft_lanes_forward(const fg_fft_lanes *f, float *x, float *work)
{
    const size_t m = f->n / 2;
    const float *z = complex_fft(f, x, work);
    /* X[k] = E[k] + W^k O[k], W = e^{-2 pi i / N}, from Z[k] and conj
     * Z[m-k]; the pair k, m - k at once, from z into x */
    const fg_vf half = fg_vf_set(0.5f);
    fg_vf z0r = get(z, 0), z0i = get(z, m);
    for (size_t k = 1; k < m / 2; k++) {
        size_t j = m - k;
        fg_vf ar = get(z, k), ai = get(z, m + k), br = get(z, j), bi = get(z, m + j);
        fg_vf er = half * (ar + br), ei = half * (ai - bi);
        fg_vf tr = half * (ai + bi), ti = half * (br - ar); /* O */
        rotate(&tr, &ti, fg_vf_set(f->split[2 * k]), fg_vf_set(f->split[2 * k + 1]));
        put(x, k, er + tr);
        put(x, m + k, ei + ti);
        put(x, j, er - tr);
        put(x, m + j, ti - ei);
    }
    /* X[m/2] = conj Z[m/2] */
    put(x, m / 2, get(z, m / 2));
    put(x, m + m / 2, -get(z, m + m / 2));
    put(x, 0, z0r + z0i);
    put(x, m, z0r - z0i); /* X[N/2], in the place of Im X[0] = 0 */
}

void fg_fft_lanes_inverse(const fg_fft_lanes *f, float *x, float *work)
{
    const size_t m = f->n / 2;
    /* Z[k] = E + i O, E = (X[k] + conj X[m-k]) / 2, O = W^{-k} (X[k] -
     * conj X[m-k]) / 2, with the transform's 1/N carried here; written
     * conjugated, since the inverse transform of Z is the conjugate of
     * the forward one of conj Z, and where the stages end in x. */
    float *y = f->stages % 2 ? work : x;
    const fg_vf h = fg_vf_set(1.0f / (float)f->n), h2 = h + h;
    fg_vf x0 = get(x, 0), xm = get(x, m);
    for (size_t k = 1; k < m / 2; k++) {
        size_t j = m - k;
        fg_vf ar = get(x, k), ai = get(x, m + k), br = get(x, j), bi = get(x, m + j);
        fg_vf er = h * (ar + br), ei = h * (ai - bi);
        fg_vf or_ = h * (ar - br), oi = h * (ai + bi);
        rotate(&or_, &oi, fg_vf_set(f->split[2 * k]), fg_vf_set(-f->split[2 * k + 1]));
        put(y, k, er - oi);
        put(y, m + k, -(ei + or_));
        put(y, j, er + oi);
        put(y, m + j, ei - or_);
    }
    put(y, m / 2, h2 * get(x, m / 2));
    put(y, m + m / 2, h2 * get(x, m + m / 2));
    put(y, 0, h * (x0 + xm));
    put(y, m, h * (xm - x0));
    complex_fft(f, y, y == x ? work : x);
    for (size_t k = 0; k < m; k++)
        put(x, m + k, -get(x, m + k));
}
