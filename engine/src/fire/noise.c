#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "noise_internal.h"
#include "fg_math.h"

bool fg_noise_init(fg_noise *n, const fg_fft *fft, const double *magnitude, uint64_t seed)
{
    memset(n, 0, sizeof *n);
    size_t m = fft->n, half = m / 2;
    n->fft = fft;
    n->magnitude = calloc(half + 1, sizeof(double));
    n->window = malloc(sizeof(double) * half);
    n->frame = malloc(sizeof(double) * (m + 2));
    n->ready = malloc(sizeof(double) * half);
    n->tail = malloc(sizeof(double) * half);
    if (!n->magnitude || !n->window || !n->frame || !n->ready || !n->tail) {
        fg_noise_deinit(n);
        return false;
    }
    /* E[s^2] of one frame is (2 / M^2) sum |X_k|^2 over 0 < k < M/2 */
    double power = 0.0;
    for (size_t k = 1; k < half; k++)
        power += magnitude[k] * magnitude[k];
    if (!(power > 0.0)) {
        fg_noise_deinit(n);
        return false;
    }
    double scale = (double)m / sqrt(2.0 * power);
    for (size_t k = 1; k < half; k++)
        n->magnitude[k] = magnitude[k] * scale;
    for (size_t k = 0; k < half; k++)
        n->window[k] = sin(FG_PI * ((double)k + 0.5) / (double)m);
    n->seed = seed;
    fg_noise_reset(n);
    return true;
}

void fg_noise_deinit(fg_noise *n)
{
    free(n->magnitude);
    free(n->window);
    free(n->frame);
    free(n->ready);
    free(n->tail);
    memset(n, 0, sizeof *n);
}

/* One frame: its first half, windowed, completes ready[] with the last
 * frame's tail; its second half becomes the next tail. */
static void next_frame(fg_noise *n)
{
    size_t m = n->fft->n, half = m / 2;
    double *f = n->frame;
    f[0] = f[1] = f[m] = f[m + 1] = 0.0;
    for (size_t k = 1; k < half; k++) {
        double theta = fg_rng_range(&n->rng, -FG_PI, FG_PI);
        f[2 * k] = n->magnitude[k] * cos(theta);
        f[2 * k + 1] = n->magnitude[k] * sin(theta);
    }
    fg_fft_inverse(n->fft, f, f);
    for (size_t k = 0; k < half; k++) {
        n->ready[k] = n->tail[k] + f[k] * n->window[k];
        n->tail[k] = f[half + k] * n->window[half - 1 - k];
    }
    n->pos = 0;
}

void fg_noise_reset(fg_noise *n)
{
    size_t half = n->fft->n / 2;
    fg_rng_seed(&n->rng, n->seed);
    memset(n->tail, 0, sizeof(double) * half);
    /* the first frame only fills the tail: from then on every sample is
     * the sum of two windowed frames */
    next_frame(n);
    n->pos = half;
}

double fg_noise_next(fg_noise *n)
{
    if (n->pos == n->fft->n / 2)
        next_frame(n);
    return n->ready[n->pos++];
}
