#include <stdlib.h>
#include <string.h>

#include "convolver_internal.h"

#define BLOCK_MAX 65536u

void fg_convolver_deinit(fg_convolver *c)
{
    fg_fft_deinit(&c->fft);
    free(c->filter);
    free(c->history);
    free(c->quiet);
    free(c->in);
    free(c->out);
    free(c->acc);
    memset(c, 0, sizeof *c);
}

bool fg_convolver_init(fg_convolver *c, unsigned inputs, unsigned outputs, size_t length,
                       size_t block, const double *filter)
{
    memset(c, 0, sizeof *c);
    if (inputs == 0 || outputs == 0 || length == 0 || !filter || block < 2 || block > BLOCK_MAX ||
        (block & (block - 1)) != 0 || !fg_fft_init(&c->fft, 2 * block))
        return false;
    c->inputs = inputs;
    c->outputs = outputs;
    c->block = block;
    c->partitions = (length + block - 1) / block;
    c->bins = block + 1;
    size_t spectrum = 2 * c->bins, pairs = (size_t)inputs * outputs;
    c->filter = calloc(pairs * c->partitions * spectrum, sizeof *c->filter);
    c->history = calloc((size_t)inputs * c->partitions * spectrum, sizeof *c->history);
    c->quiet = calloc(inputs, sizeof *c->quiet);
    c->in = calloc((size_t)inputs * 2 * block, sizeof *c->in);
    c->out = calloc((size_t)outputs * block, sizeof *c->out);
    c->acc = calloc(spectrum, sizeof *c->acc);
    if (!c->filter || !c->history || !c->quiet || !c->in || !c->out || !c->acc) {
        fg_convolver_deinit(c);
        return false;
    }
    /* each partition: B taps, zero-padded to 2B, transformed */
    for (size_t pair = 0; pair < pairs; pair++) {
        for (size_t p = 0; p < c->partitions; p++) {
            double *spec = c->filter + (pair * c->partitions + p) * spectrum;
            size_t first = p * block, taps = length - first < block ? length - first : block;
            memcpy(spec, filter + pair * length + first, taps * sizeof *spec);
            fg_fft_forward(&c->fft, spec, spec);
        }
    }
    for (unsigned i = 0; i < inputs; i++)
        c->quiet[i] = c->partitions + 2; /* silence before the first frame */
    return true;
}

static bool all_zero(const double *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (x[k] != 0.0)
            return false;
    return true;
}

/* The block in[.][B .. 2B) is complete: its spectrum joins the history
 * and the next B output frames are computed. */
static void run_block(fg_convolver *c)
{
    const size_t B = c->block, P = c->partitions, spectrum = 2 * c->bins;
    c->newest = (c->newest + 1) % P;
    bool any = false;
    for (unsigned i = 0; i < c->inputs; i++) {
        double *x = c->in + (size_t)i * 2 * B;
        /* a block spectrum is zero once this block and the one before are */
        c->quiet[i] = all_zero(x + B, B) ? (c->quiet[i] < P + 2 ? c->quiet[i] + 1 : P + 2) : 0;
        double *slot = c->history + ((size_t)i * P + c->newest) * spectrum;
        if (c->quiet[i] <= 1)
            fg_fft_forward(&c->fft, x, slot);
        else if (c->quiet[i] <= P + 1)
            memset(slot, 0, spectrum * sizeof *slot);
        memcpy(x, x + B, B * sizeof *x);
        any = any || c->quiet[i] <= P;
    }
    for (unsigned o = 0; o < c->outputs; o++) {
        double *y = c->out + (size_t)o * B;
        if (!any) {
            memset(y, 0, B * sizeof *y);
            continue;
        }
        double *acc = c->acc;
        memset(acc, 0, spectrum * sizeof *acc);
        for (unsigned i = 0; i < c->inputs; i++) {
            if (c->quiet[i] > P)
                continue; /* its whole history is zero */
            const double *h = c->filter + ((size_t)i * c->outputs + o) * P * spectrum;
            for (size_t p = 0; p < P; p++) {
                const double *x = c->history + ((size_t)i * P + (c->newest + P - p) % P) * spectrum;
                const double *hp = h + p * spectrum;
                for (size_t k = 0; k < spectrum; k += 2) {
                    acc[k] += x[k] * hp[k] - x[k + 1] * hp[k + 1];
                    acc[k + 1] += x[k] * hp[k + 1] + x[k + 1] * hp[k];
                }
            }
        }
        fg_fft_inverse(&c->fft, acc, acc);
        /* overlap-save: the second half is the linear convolution */
        memcpy(y, acc + B, B * sizeof *y);
    }
}

void fg_convolver_process(fg_convolver *c, const float *const *in, float *const *out, size_t n)
{
    const size_t B = c->block;
    size_t done = 0;
    while (done < n) {
        size_t run = B - c->fill < n - done ? B - c->fill : n - done;
        for (unsigned i = 0; i < c->inputs; i++) {
            double *x = c->in + (size_t)i * 2 * B + B + c->fill;
            for (size_t k = 0; k < run; k++)
                x[k] = in[i][done + k];
        }
        for (unsigned o = 0; o < c->outputs; o++) {
            const double *y = c->out + (size_t)o * B + c->fill;
            for (size_t k = 0; k < run; k++)
                out[o][done + k] = (float)y[k];
        }
        c->fill += run;
        done += run;
        if (c->fill == B) {
            run_block(c);
            c->fill = 0;
        }
    }
}
