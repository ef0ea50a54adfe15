#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bwe_internal.h"

size_t fg_bwe_fft_length(int half_window)
{
    size_t m = FG_FFT_MIN_SIZE;
    while (m < 7 * (size_t)half_window)
        m *= 2;
    return m;
}

static double f_low_at(const fg_bwe_params *p, double f)
{
    if (f <= p->blend_low_hz)
        return 1.0;
    if (f >= p->blend_high_hz)
        return 0.0;
    return (p->blend_high_hz - f) / (p->blend_high_hz - p->blend_low_hz);
}

bool fg_bwe_weights_init(fg_bwe_weights *w, const fg_bwe_params *p, size_t m)
{
    w->bins = m / 2 + 1;
    w->f_low = malloc(sizeof(double) * w->bins);
    w->f_high = malloc(sizeof(double) * w->bins);
    w->g2 = malloc(sizeof(double) * w->bins);
    if (!w->f_low || !w->f_high || !w->g2) {
        fg_bwe_weights_deinit(w);
        return false;
    }
    for (size_t k = 0; k < w->bins; k++) {
        double f = (double)k * p->sample_rate_hz / (double)m;
        double z = (f - p->f_cut_hz) / p->sigma_cut_hz;
        w->f_low[k] = f_low_at(p, f);
        w->f_high[k] = 1.0 - w->f_low[k];
        w->g2[k] = exp(-z * z); /* g^2, g = exp(-z^2 / 2) */
    }
    return true;
}

void fg_bwe_weights_deinit(fg_bwe_weights *w)
{
    free(w->f_low);
    free(w->f_high);
    free(w->g2);
    memset(w, 0, sizeof *w);
}

double fg_bwe_beta(const fg_bwe_weights *w, const double *P, const double *Q, fg_beta_case *how)
{
    double a = 0.0, b = 0.0, c = 0.0;
    for (size_t k = 0; k < w->bins; k++) {
        double g2 = w->g2[k], lo = w->f_low[k], hi = w->f_high[k];
        double pr = P[2 * k], pi = P[2 * k + 1], qr = Q[2 * k], qi = Q[2 * k + 1];
        double pp = pr * pr + pi * pi, qq = qr * qr + qi * qi;
        a += g2 * hi * hi * qq;
        b += 2.0 * g2 * lo * hi * (pr * qr + pi * qi);
        c += g2 * (lo * lo - 1.0) * pp;
    }
    if (!(a > 0.0)) {
        *how = FG_BETA_DEGENERATE;
        return 0.0;
    }
    double disc = b * b - 4.0 * a * c;
    if (disc >= 0.0) {
        /* the larger root, (-b + s) / 2a, written so nothing cancels */
        double s = sqrt(disc), root;
        if (b < 0.0)
            root = (-b + s) / (2.0 * a);
        else if (b + s > 0.0)
            root = -2.0 * c / (b + s);
        else
            root = 0.0; /* b = c = 0: both roots are 0 */
        if (root >= 0.0) {
            *how = FG_BETA_ROOT;
            return root;
        }
    }
    /* no real root, or none >= 0 (c > 0: impossible with F_low <= 1): the
     * beta >= 0 nearest the quadratic's minimum */
    *how = FG_BETA_NO_ROOT;
    return fmax(0.0, -b / (2.0 * a));
}

void fg_bwe_blend(const fg_bwe *b, double *P, const double *Q, double beta, double *y)
{
    const fg_bwe_weights *w = &b->weights;
    for (size_t k = 0; k < w->bins; k++) {
        double lo = w->f_low[k], hi = beta * w->f_high[k];
        P[2 * k] = lo * P[2 * k] + hi * Q[2 * k];
        P[2 * k + 1] = lo * P[2 * k + 1] + hi * Q[2 * k + 1];
    }
    fg_fft_inverse(&b->fft, P, y);
}

bool fg_bwe_init(fg_bwe *b, const fg_bwe_params *p)
{
    memset(b, 0, sizeof *b);
    b->params = *p;
    b->m = fg_bwe_fft_length(p->half_window);
    size_t ring = 1;
    while (ring < 2 * (size_t)p->beta_half_window)
        ring *= 2;
    b->ring_mask = ring - 1;
    if (!fg_fft_init(&b->fft, b->m) || !fg_bwe_weights_init(&b->weights, p, b->m))
        goto fail;
    if (p->beta_half_window > p->half_window) {
        b->ma = FG_FFT_MIN_SIZE;
        while (b->ma < 2 * (size_t)p->beta_half_window + 1)
            b->ma *= 2;
        b->pa = malloc(sizeof(double) * (b->ma + 2));
        b->na = malloc(sizeof(double) * (b->ma + 2));
        if (!b->pa || !b->na || !fg_fft_init(&b->fft_beta, b->ma) ||
            !fg_bwe_weights_init(&b->weights_beta, p, b->ma))
            goto fail;
    }
    /* the noise's spectrum: f^(-alpha/2), high-passed by F_high */
    double *magnitude = malloc(sizeof(double) * b->weights.bins);
    if (!magnitude)
        goto fail;
    for (size_t k = 1; k < b->weights.bins; k++) {
        double f = (double)k * p->sample_rate_hz / (double)b->m;
        magnitude[k] = pow(f, -0.5 * p->alpha) * b->weights.f_high[k];
    }
    magnitude[0] = 0.0;
    bool noise_ok = fg_noise_init(&b->noise, &b->fft, magnitude, p->seed);
    free(magnitude);
    if (!noise_ok)
        goto fail;
    b->p_ring = malloc(sizeof(double) * ring);
    b->n_ring = malloc(sizeof(double) * ring);
    b->acc = malloc(sizeof(double) * b->m);
    b->pw = malloc(sizeof(double) * (b->m + 2));
    b->nw = malloc(sizeof(double) * (b->m + 2));
    if (!b->p_ring || !b->n_ring || !b->acc || !b->pw || !b->nw)
        goto fail;
    fg_bwe_reset(b);
    return true;
fail:
    fg_bwe_deinit(b);
    return false;
}

void fg_bwe_deinit(fg_bwe *b)
{
    fg_noise_deinit(&b->noise);
    fg_bwe_weights_deinit(&b->weights);
    fg_fft_deinit(&b->fft);
    fg_bwe_weights_deinit(&b->weights_beta);
    fg_fft_deinit(&b->fft_beta);
    free(b->pa);
    free(b->na);
    free(b->p_ring);
    free(b->n_ring);
    free(b->acc);
    free(b->pw);
    free(b->nw);
    memset(b, 0, sizeof *b);
}

void fg_bwe_reset(fg_bwe *b)
{
    fg_noise_reset(&b->noise);
    memset(b->acc, 0, sizeof(double) * b->m);
    b->taken = b->next_window = b->released = 0;
    b->stats = (fg_bwe_stats){0};
}

size_t fg_bwe_max_frames(const fg_bwe *b, size_t n)
{
    return n + (size_t)b->params.half_window;
}

size_t fg_bwe_latency(const fg_bwe *b)
{
    return b->m / 2 + (size_t)b->params.beta_half_window - 1;
}

/* The input and its noise around c under the triangle of half-width
 * `half`, centred in an FFT buffer of m points: p_W and N_W = |p_W| N. */
static void window_signals(const fg_bwe *b, int64_t c, int64_t half, size_t m, double *pw,
                           double *nw)
{
    int64_t mid = (int64_t)(m / 2);
    memset(pw, 0, sizeof(double) * m);
    memset(nw, 0, sizeof(double) * m);
    for (int64_t d = 1 - half; d < half; d++) {
        int64_t t = c + d;
        if (t < 0)
            continue; /* silence before the start */
        double w = 1.0 - (double)llabs(d) / (double)half;
        double x = w * b->p_ring[(uint64_t)t & b->ring_mask];
        pw[mid + d] = x;
        nw[mid + d] = fabs(x) * b->n_ring[(uint64_t)t & b->ring_mask];
    }
}

/* Window next_window: beta, blend, overlap-add, release what is final. */
static size_t run_window(fg_bwe *b, float *out)
{
    int64_t wh = b->params.half_window, half = (int64_t)(b->m / 2);
    int64_t c = (int64_t)b->next_window * wh;
    window_signals(b, c, wh, b->m, b->pw, b->nw);
    fg_fft_forward(&b->fft, b->pw, b->pw);
    fg_fft_forward(&b->fft, b->nw, b->nw);
    fg_beta_case how;
    double beta;
    if (b->ma) {
        window_signals(b, c, b->params.beta_half_window, b->ma, b->pa, b->na);
        fg_fft_forward(&b->fft_beta, b->pa, b->pa);
        fg_fft_forward(&b->fft_beta, b->na, b->na);
        beta = fg_bwe_beta(&b->weights_beta, b->pa, b->na, &how);
    } else {
        beta = fg_bwe_beta(&b->weights, b->pw, b->nw, &how);
    }
    fg_bwe_blend(b, b->pw, b->nw, beta, b->pw);
    b->stats.windows++;
    b->stats.degenerate += how == FG_BETA_DEGENERATE;
    b->stats.no_root += how == FG_BETA_NO_ROOT;
    b->stats.last_beta = beta;
    for (int64_t m = 0; m < 2 * half; m++) {
        int64_t t = c - half + m;
        if (t >= 0)
            b->acc[(uint64_t)t % b->m] += b->pw[m];
    }
    b->next_window++;
    int64_t final_end = (int64_t)b->next_window * wh - half;
    size_t made = 0;
    while ((int64_t)b->released < final_end) {
        double *slot = &b->acc[b->released % b->m];
        out[made++] = (float)*slot;
        *slot = 0.0;
        b->released++;
    }
    return made;
}

size_t fg_bwe_push(fg_bwe *b, const float *p, size_t n, float *out)
{
    size_t made = 0;
    uint64_t wh = (uint64_t)b->params.half_window, a = (uint64_t)b->params.beta_half_window;
    for (size_t k = 0; k < n; k++) {
        uint64_t t = b->taken++;
        b->p_ring[t & b->ring_mask] = p[k];
        b->n_ring[t & b->ring_mask] = fg_noise_next(&b->noise);
        /* window i needs the input up to c_i + A - 1 */
        if (b->taken == b->next_window * wh + a)
            made += run_window(b, out + made);
    }
    return made;
}
