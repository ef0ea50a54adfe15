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

/* The single-signal path's twiddles (fft_lanes_internal.h): each run of
 * `run` values of a stage of stride st spread to `count`, one per
 * butterfly a (the value of p = a / st). */
static float *spread_runs(float *s, const float *t, int runs, size_t run, size_t st, size_t count)
{
    for (int r = 0; r < runs; r++)
        for (size_t a = 0; a < count; a++)
            s[r * count + a] = t[r * run + a / st];
    return s + runs * count;
}

static bool spread_init(fg_fft_lanes *f)
{
    const size_t m = f->n / 2;
    f->spread_stages = (f->radix2 ? m : 0) + (f->stages - f->radix2) * 6 * (m / 4);
    f->spread = malloc(sizeof(float) * (f->spread_stages + m));
    if (!f->spread)
        return false;
    const float *t = f->twiddle;
    float *s = f->spread;
    size_t len = m;
    if (f->radix2) {
        s = spread_runs(s, t, 2, len / 2, 1, m / 2);
        t += len;
        len /= 2;
    }
    for (; len >= 4; len /= 4) {
        s = spread_runs(s, t, 6, len / 4, m / len, m / 4);
        t += 6 * (len / 4);
    }
    for (size_t k = 0; k < m / 2; k++) { /* the split's cos, then sin run */
        s[k] = f->split[2 * k];
        s[m / 2 + k] = f->split[2 * k + 1];
    }
    return true;
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
    f->one = m / 4 >= V;
    if (f->one && !spread_init(f)) {
        fg_fft_lanes_deinit(f);
        return false;
    }
    return true;
}

void fg_fft_lanes_deinit(fg_fft_lanes *f)
{
    free(f->twiddle);
    free(f->split);
    free(f->spread);
    memset(f, 0, sizeof *f);
}

/* u e^{-i a}, given cos a and sin a */
static inline void rotate(fg_vf *ur, fg_vf *ui, fg_vf c, fg_vf s)
{
    fg_vf r = *ur * c + *ui * s;
    *ui = *ui * c - *ur * s;
    *ur = r;
}

/* A radix-2 butterfly: a, b (v[0..4): re, im of each) become a + b and
 * a - b (which the stage then turns). */
static inline void butterfly2(fg_vf v[4])
{
    fg_vf dr = v[0] - v[2], di = v[1] - v[3];
    v[0] = v[0] + v[2];
    v[1] = v[1] + v[3];
    v[2] = dr;
    v[3] = di;
}

/* A radix-4 butterfly: the quarters a, b, c, d (v[0..8): re, im of each)
 * become a + b + c + d, a - ib - c + id, a - b + c - d, a + ib - c - id,
 * in that order (the last three of which the stage then turns: turn4). */
static inline void butterfly4(fg_vf v[8])
{
    fg_vf t0r = v[0] + v[4], t0i = v[1] + v[5], t1r = v[0] - v[4], t1i = v[1] - v[5];
    fg_vf t2r = v[2] + v[6], t2i = v[3] + v[7], er = v[2] - v[6], ei = v[3] - v[7];
    /* -i e = (ei, -er) */
    v[0] = t0r + t2r;
    v[1] = t0i + t2i;
    v[2] = t1r + ei;
    v[3] = t1i - er;
    v[4] = t0r - t2r;
    v[5] = t0i - t2i;
    v[6] = t1r - ei;
    v[7] = t1i + er;
}

/* The last three outputs of butterfly4 turned by the angles of tw (cos
 * then sin, k = 1, 2, 3). */
static inline void turn4(fg_vf v[8], const fg_vf tw[6])
{
    for (int k = 0; k < 3; k++)
        rotate(&v[2 + 2 * k], &v[3 + 2 * k], tw[2 * k], tw[2 * k + 1]);
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
        fg_vf v[4] = {get(x, a), get(x, m + a), get(x, b), get(x, m + b)};
        butterfly2(v);
        if (turn)
            rotate(&v[2], &v[3], c, s);
        put(y, ya, v[0]);
        put(y, m + ya, v[1]);
        put(y, yb, v[2]);
        put(y, m + yb, v[3]);
    }
}

/* The same for radix 4: the quarters of each len-point transform through
 * butterfly4, turned by e^{-2 pi i k p / len}, written to y at stride
 * 4 st. tw: the stage's cos and sin runs for k = 1, 2, 3. */
static inline void radix4(const float *x, float *y, size_t m, size_t st, size_t quarter, size_t p,
                          const float *tw, bool turn)
{
    fg_vf t[6];
    for (int r = 0; r < 6; r++)
        t[r] = fg_vf_set(turn ? tw[r * quarter + p] : 0.0f);
    const size_t gap = st * quarter;
    for (size_t q = 0; q < st; q++) {
        size_t a = q + st * p, y0 = q + 4 * st * p;
        fg_vf v[8];
        for (int k = 0; k < 4; k++) {
            v[2 * k] = get(x, a + k * gap);
            v[2 * k + 1] = get(x, m + a + k * gap);
        }
        butterfly4(v);
        if (turn)
            turn4(v, t);
        for (int j = 0; j < 4; j++) {
            put(y, y0 + j * st, v[2 * j]);
            put(y, m + y0 + j * st, v[2 * j + 1]);
        }
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

/* The forward split of the pair k, m - k: v[0..4) = Z[k] (re, im) and
 * Z[m-k] in, X[k] and X[m-k] out; c, s: cos and sin of 2 pi k / N.
 * X[k] = E[k] + W^k O[k], W = e^{-2 pi i / N}, from Z[k] and conj Z[m-k]. */
static inline void split_forward(fg_vf v[4], fg_vf c, fg_vf s)
{
    const fg_vf half = fg_vf_set(0.5f);
    fg_vf er = half * (v[0] + v[2]), ei = half * (v[1] - v[3]);
    fg_vf tr = half * (v[1] + v[3]), ti = half * (v[2] - v[0]); /* O */
    rotate(&tr, &ti, c, s);
    v[0] = er + tr;
    v[1] = ei + ti;
    v[2] = er - tr;
    v[3] = ti - ei;
}

/* The inverse's split of the pair k, m - k: v = X[k], X[m-k] in; out the
 * conjugates of Z[k] = E + i O and Z[m-k], E = (X[k] + conj X[m-k]) h,
 * O = W^{-k} (X[k] - conj X[m-k]) h (h = 1/N, the transform's scale);
 * c, s: cos and -sin of 2 pi k / N. */
static inline void split_inverse(fg_vf v[4], fg_vf c, fg_vf s, fg_vf h)
{
    fg_vf er = h * (v[0] + v[2]), ei = h * (v[1] - v[3]);
    fg_vf or_ = h * (v[0] - v[2]), oi = h * (v[1] + v[3]);
    rotate(&or_, &oi, c, s);
    v[0] = er - oi;
    v[1] = -(ei + or_);
    v[2] = er + oi;
    v[3] = ei - or_;
}

void fg_fft_lanes_forward(const fg_fft_lanes *f, float *x, float *work)
{
    const size_t m = f->n / 2;
    const float *z = complex_fft(f, x, work);
    /* the pair k, m - k at once, from z into x */
    fg_vf z0r = get(z, 0), z0i = get(z, m);
    for (size_t k = 1; k < m / 2; k++) {
        size_t j = m - k;
        fg_vf v[4] = {get(z, k), get(z, m + k), get(z, j), get(z, m + j)};
        split_forward(v, fg_vf_set(f->split[2 * k]), fg_vf_set(f->split[2 * k + 1]));
        put(x, k, v[0]);
        put(x, m + k, v[1]);
        put(x, j, v[2]);
        put(x, m + j, v[3]);
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
    /* conj Z, since the inverse transform of Z is the conjugate of the
     * forward one of conj Z, written where the stages end in x */
    float *y = f->stages % 2 ? work : x;
    const fg_vf h = fg_vf_set(1.0f / (float)f->n), h2 = h + h;
    fg_vf x0 = get(x, 0), xm = get(x, m);
    for (size_t k = 1; k < m / 2; k++) {
        size_t j = m - k;
        fg_vf v[4] = {get(x, k), get(x, m + k), get(x, j), get(x, m + j)};
        split_inverse(v, fg_vf_set(f->split[2 * k]), fg_vf_set(-f->split[2 * k + 1]), h);
        put(y, k, v[0]);
        put(y, m + k, v[1]);
        put(y, j, v[2]);
        put(y, m + j, v[3]);
    }
    put(y, m / 2, h2 * get(x, m / 2));
    put(y, m + m / 2, h2 * get(x, m + m / 2));
    put(y, 0, h * (x0 + xm));
    put(y, m, h * (xm - x0));
    complex_fft(f, y, y == x ? work : x);
    for (size_t k = 0; k < m; k++)
        put(x, m + k, -get(x, m + k));
}

/* ---- One signal, its elements across the lanes ----
 * The same stages, butterflies and splits, element by element, as the
 * lane transform computes for each lane: vectors now hold FG_VF_LANES
 * neighbouring elements of one signal (butterfly index a = q + st p,
 * contiguous in what a stage reads), with each element's twiddle from
 * the spread tables. A butterfly with p = 0 is not turned, as in the lane
 * transform, so both give the same floats bit for bit. */

static inline fg_vf load(const float *p)
{
    return fg_vf_load(p);
}

/* The V elements p[-(V-1) .. 0], last first. */
static inline fg_vf load_reversed(const float *p)
{
#ifdef FG_VF_SHUFFLE
    return fg_vf_reverse(fg_vf_load(p - (V - 1)));
#else
    float t[V];
    for (unsigned l = 0; l < V; l++)
        t[l] = p[-(ptrdiff_t)l];
    return fg_vf_load(t);
#endif
}

/* v's lanes to p[0], p[-1], ..., p[-(V-1)]. */
static inline void store_reversed(float *p, fg_vf v)
{
#ifdef FG_VF_SHUFFLE
    fg_vf_store(p - (V - 1), fg_vf_reverse(v));
#else
    float t[V];
    fg_vf_store(t, v);
    for (unsigned l = 0; l < V; l++)
        p[-(ptrdiff_t)l] = t[l];
#endif
}

/* out lanes from turned, except those of butterflies a + l < st (p = 0),
 * which keep plain. */
static inline fg_vf unturned_first(fg_vf turned, fg_vf plain, size_t a, size_t st)
{
    float t[V], u[V];
    fg_vf_store(t, turned);
    fg_vf_store(u, plain);
    for (unsigned l = 0; l < V && a + l < st; l++)
        t[l] = u[l];
    return fg_vf_load(t);
}

/* Outputs v[2j], v[2j + 1] (re, im) of butterflies a .. a + V - 1 to
 * y[q + r st p + j st] (and + m), j < r, for a stage of stride st < V. */
static void scatter_outputs(float *y, size_t m, size_t st, size_t r, size_t a, const fg_vf *v)
{
    float t[8][V];
    for (size_t j = 0; j < 2 * r; j++)
        fg_vf_store(t[j], v[j]);
    for (unsigned l = 0; l < V; l++) {
        size_t p = (a + l) / st, y0 = (a + l) % st + r * st * p;
        for (size_t j = 0; j < r; j++) {
            y[y0 + j * st] = t[2 * j][l];
            y[m + y0 + j * st] = t[2 * j + 1][l];
        }
    }
}

/* The radix-2 stage (the first: st = 1) on one signal. tw: its spread cos
 * and sin runs, m / 2 each. */
static void radix2_one(const float *x, float *y, size_t m, const float *tw)
{
    const size_t half = m / 2;
    for (size_t a = 0; a < half; a += V) {
        fg_vf v[4] = {load(x + a), load(x + m + a), load(x + a + half), load(x + m + a + half)};
        butterfly2(v);
        fg_vf dr = v[2], di = v[3];
        rotate(&v[2], &v[3], load(tw + a), load(tw + half + a));
        if (a == 0) {
            v[2] = unturned_first(v[2], dr, a, 1);
            v[3] = unturned_first(v[3], di, a, 1);
        }
#ifdef FG_VF_SHUFFLE
        fg_vf_interleave(v[0], v[2], y + 2 * a);
        fg_vf_interleave(v[1], v[3], y + m + 2 * a);
#else
        scatter_outputs(y, m, 1, 2, a, v);
#endif
    }
}

/* A radix-4 stage of stride st = 2^shift on one signal. tw: its six
 * spread runs (cos, sin for k = 1, 2, 3), m / 4 each. */
static void radix4_one(const float *x, float *y, size_t m, unsigned shift, const float *tw)
{
    const size_t st = (size_t)1 << shift;
    const size_t gap = m / 4;
    for (size_t a = 0; a < gap; a += V) {
        fg_vf v[8], t[6];
        for (int k = 0; k < 4; k++) {
            v[2 * k] = load(x + a + k * gap);
            v[2 * k + 1] = load(x + m + a + k * gap);
        }
        for (int r = 0; r < 6; r++)
            t[r] = load(tw + r * gap + a);
        butterfly4(v);
        if (a + V <= st) {
            /* p = 0 in every lane: not turned */
        } else if (a >= st) {
            turn4(v, t);
        } else {
            fg_vf plain[8];
            memcpy(plain, v, sizeof plain);
            turn4(v, t);
            for (int k = 2; k < 8; k++)
                v[k] = unturned_first(v[k], plain[k], a, st);
        }
        if (st >= V) {
            size_t y0 = (a & (st - 1)) + ((a >> shift) << (shift + 2)); /* q + 4 st p */
            for (int j = 0; j < 4; j++) {
                fg_vf_store(y + y0 + j * st, v[2 * j]);
                fg_vf_store(y + m + y0 + j * st, v[2 * j + 1]);
            }
            continue;
        }
#ifdef FG_VF_SHUFFLE
        if (st == 1) { /* y[4a + j]: the outputs transposed */
            fg_vf re[4] = {v[0], v[2], v[4], v[6]}, im[4] = {v[1], v[3], v[5], v[7]};
            fg_vf_transpose(re);
            fg_vf_transpose(im);
            for (unsigned l = 0; l < V; l++) {
                fg_vf_store(y + 4 * (a + l), re[l]);
                fg_vf_store(y + m + 4 * (a + l), im[l]);
            }
            continue;
        }
#endif
        scatter_outputs(y, m, st, 4, a, v);
    }
}

/* complex_fft on one signal. */
static float *complex_fft_one(const fg_fft_lanes *f, float *x, float *other)
{
    const size_t m = f->n / 2;
    const float *tw = f->spread;
    float *src = x, *dst = other;
    size_t len = m;
    if (f->radix2) {
        radix2_one(src, dst, m, tw);
        tw += m;
        dst = src;
        src = other;
        len /= 2;
    }
    unsigned shift = f->radix2;
    for (; len >= 4; len /= 4, shift += 2) {
        radix4_one(src, dst, m, shift, tw);
        tw += 6 * (m / 4);
        float *t = src;
        src = dst;
        dst = t;
    }
    return src;
}

/* The split's cos and sin runs of the single-signal path (k < m / 2). */
static const float *split_runs(const fg_fft_lanes *f)
{
    return f->spread + f->spread_stages;
}

void fg_fft_lanes_forward_one(const fg_fft_lanes *f, float *x, float *work)
{
    const size_t m = f->n / 2;
    const float *z = complex_fft_one(f, x, work);
    const float *cs = split_runs(f), *sn = cs + m / 2;
    float z0r = z[0], z0i = z[m];
    size_t k = 1;
    for (; k + V <= m / 2; k += V) {
        size_t j = m - k;
        fg_vf v[4] = {load(z + k), load(z + m + k), load_reversed(z + j), load_reversed(z + m + j)};
        split_forward(v, load(cs + k), load(sn + k));
        fg_vf_store(x + k, v[0]);
        fg_vf_store(x + m + k, v[1]);
        store_reversed(x + j, v[2]);
        store_reversed(x + m + j, v[3]);
    }
    for (; k < m / 2; k++) { /* the last few pairs, each in every lane */
        size_t j = m - k;
        fg_vf v[4] = {fg_vf_set(z[k]), fg_vf_set(z[m + k]), fg_vf_set(z[j]), fg_vf_set(z[m + j])};
        split_forward(v, fg_vf_set(cs[k]), fg_vf_set(sn[k]));
        float t[4][V];
        for (int e = 0; e < 4; e++)
            fg_vf_store(t[e], v[e]);
        x[k] = t[0][0];
        x[m + k] = t[1][0];
        x[j] = t[2][0];
        x[m + j] = t[3][0];
    }
    x[m / 2] = z[m / 2];
    x[m + m / 2] = -z[m + m / 2];
    x[0] = z0r + z0i;
    x[m] = z0r - z0i;
}

void fg_fft_lanes_inverse_one(const fg_fft_lanes *f, float *x, float *work)
{
    const size_t m = f->n / 2;
    float *y = f->stages % 2 ? work : x;
    const float *cs = split_runs(f), *sn = cs + m / 2;
    const float h = 1.0f / (float)f->n, h2 = h + h;
    const fg_vf hv = fg_vf_set(h);
    float x0 = x[0], xm = x[m];
    size_t k = 1;
    for (; k + V <= m / 2; k += V) {
        size_t j = m - k;
        fg_vf v[4] = {load(x + k), load(x + m + k), load_reversed(x + j), load_reversed(x + m + j)};
        split_inverse(v, load(cs + k), -load(sn + k), hv);
        fg_vf_store(y + k, v[0]);
        fg_vf_store(y + m + k, v[1]);
        store_reversed(y + j, v[2]);
        store_reversed(y + m + j, v[3]);
    }
    for (; k < m / 2; k++) {
        size_t j = m - k;
        fg_vf v[4] = {fg_vf_set(x[k]), fg_vf_set(x[m + k]), fg_vf_set(x[j]), fg_vf_set(x[m + j])};
        split_inverse(v, fg_vf_set(cs[k]), fg_vf_set(-sn[k]), hv);
        float t[4][V];
        for (int e = 0; e < 4; e++)
            fg_vf_store(t[e], v[e]);
        y[k] = t[0][0];
        y[m + k] = t[1][0];
        y[j] = t[2][0];
        y[m + j] = t[3][0];
    }
    y[m / 2] = h2 * x[m / 2];
    y[m + m / 2] = h2 * x[m + m / 2];
    y[0] = h * (x0 + xm);
    y[m] = h * (xm - x0);
    complex_fft_one(f, y, y == x ? work : x);
    for (size_t e = m; e < 2 * m; e += V)
        fg_vf_store(x + e, -load(x + e));
}
