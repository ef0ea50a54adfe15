#include <stdlib.h>
#include <string.h>

#include "convolver_internal.h"

#define BLOCK_MAX 65536u
#define V FG_VF_LANES
#define ALIGN 64u

/* count floats, zeroed, on a cache line (vector loads need no alignment,
 * but a spectrum that starts on a line is read without splits) */
static float *alloc_floats(size_t count)
{
    size_t bytes = (count * sizeof(float) + ALIGN - 1) / ALIGN * ALIGN;
    float *p = aligned_alloc(ALIGN, bytes);
    if (p)
        memset(p, 0, bytes);
    return p;
}

void fg_convolver_deinit(fg_convolver *c)
{
    fg_fft_lanes_deinit(&c->fft);
    free(c->filter);
    free(c->history);
    free(c->live);
    free(c->quiet);
    free(c->fed);
    free(c->awake);
    free(c->given);
    free(c->in);
    free(c->out);
    free(c->acc);
    free(c->pairs);
    free(c->lanes);
    free(c->work);
    free(c->zeros);
    memset(c, 0, sizeof *c);
}

/* The packed spectra (fft_lanes_internal.h) of every partition of every
 * response, each transformed in double and rounded once. */
static bool transform_filter(fg_convolver *c, size_t length, const double *filter)
{
    const size_t B = c->block, P = c->partitions, n = 2 * B;
    fg_fft fft;
    double *x = malloc((n + 2) * sizeof *x);
    if (!x || !fg_fft_init(&fft, n)) {
        free(x);
        return false;
    }
    for (unsigned i = 0; i < c->inputs; i++)
        for (unsigned o = 0; o < c->outputs; o++)
            for (size_t p = 0; p < P; p++) {
                const double *h = filter + ((size_t)i * c->outputs + o) * length;
                size_t first = p * B, taps = length - first < B ? length - first : B;
                memset(x, 0, (n + 2) * sizeof *x);
                memcpy(x, h + first, taps * sizeof *x);
                fg_fft_forward(&fft, x, x);
                float *spec = c->filter + (((size_t)i * P + p) * c->outputs + o) * n;
                for (size_t k = 0; k < B; k++) {
                    spec[k] = (float)x[2 * k];
                    spec[B + k] = (float)x[2 * k + 1];
                }
                spec[B] = (float)x[n]; /* X[B], where Im X[0] = 0 would be */
            }
    fg_fft_deinit(&fft);
    free(x);
    return true;
}

bool fg_convolver_init(fg_convolver *c, unsigned inputs, unsigned outputs, size_t length,
                       size_t block, const double *filter)
{
    memset(c, 0, sizeof *c);
    if (inputs == 0 || outputs == 0 || length == 0 || !filter || block < 2 || block > BLOCK_MAX ||
        (block & (block - 1)) != 0 || !fg_fft_lanes_init(&c->fft, 2 * block))
        return false;
    c->mac = fg_spectrum_mac_pick(block);
    c->fft_avx2 = fg_fft_avx2_available() && fg_fft_avx2_init(&c->fft_avx2_plan, 2 * block);
    c->inputs = inputs;
    c->outputs = outputs;
    c->block = block;
    c->partitions = (length + block - 1) / block;
    const size_t n = 2 * block, P = c->partitions;
    c->filter = alloc_floats((size_t)inputs * outputs * P * n);
    c->history = alloc_floats((size_t)inputs * P * n);
    c->live = calloc((size_t)inputs * P, sizeof *c->live);
    c->quiet = calloc(inputs, sizeof *c->quiet);
    c->fed = calloc(inputs, sizeof *c->fed);
    c->words = (inputs + 63) / 64;
    c->awake = calloc(c->words, sizeof *c->awake);
    c->given = calloc(c->words, sizeof *c->given);
    c->in = alloc_floats((size_t)inputs * n);
    c->out = alloc_floats((size_t)outputs * block);
    c->acc = alloc_floats((size_t)(outputs + 1) * n);
    c->pairs = malloc(2 * P * sizeof *c->pairs);
    c->lanes = alloc_floats(n * V);
    c->work = alloc_floats(n * V);
    c->zeros = alloc_floats(n);
    if (!c->filter || !c->history || !c->live || !c->quiet || !c->fed || !c->awake || !c->given ||
        !c->in || !c->out || !c->acc || !c->pairs || !c->lanes || !c->work || !c->zeros ||
        !transform_filter(c, length, filter)) {
        fg_convolver_deinit(c);
        return false;
    }
    for (unsigned i = 0; i < inputs; i++)
        c->quiet[i] = P + 2; /* silence before the first frame */
    return true;
}

/* Whether x[0 .. n) is all zero (-0 included), FG_VF_LANES at a time. */
static bool all_zero(const float *x, size_t n)
{
    size_t k = 0;
    for (; k + 4 * V <= n; k += 4 * V) {
        fg_vi nz = (fg_vf_load(x + k) != 0.0f) | (fg_vf_load(x + k + V) != 0.0f) |
                   (fg_vf_load(x + k + 2 * V) != 0.0f) | (fg_vf_load(x + k + 3 * V) != 0.0f);
        int32_t lane[V];
        memcpy(lane, &nz, sizeof lane);
        for (unsigned l = 0; l < V; l++)
            if (lane[l])
                return false;
    }
    for (; k < n; k++)
        if (x[k] != 0.0f)
            return false;
    return true;
}

/* The window win (2B frames) split into x: frame 2k as element k, frame
 * 2k + 1 as element B + k. */
static void split_window(const float *win, float *x, size_t B)
{
    size_t k = 0;
#ifdef FG_VF_SHUFFLE
    for (; k + V <= B; k += V) {
        fg_vf a = fg_vf_load(win + 2 * k), b = fg_vf_load(win + 2 * k + V);
        fg_vf_store(x + k, fg_vf_even(a, b));
        fg_vf_store(x + B + k, fg_vf_odd(a, b));
    }
#endif
    for (; k < B; k++) {
        x[k] = win[2 * k];
        x[B + k] = win[2 * k + 1];
    }
}

/* Lane l of c->lanes gets the window win[l] (2B frames) split: frame 2k
 * as element k, frame 2k + 1 as element B + k. */
static void gather_windows(fg_convolver *c, const float *const *win)
{
    const size_t B = c->block;
#ifdef FG_VF_SHUFFLE
    if (B % V == 0) {
        for (size_t k = 0; k < B; k += V) {
            fg_vf even[V], odd[V];
            for (unsigned l = 0; l < V; l++) {
                fg_vf a = fg_vf_load(win[l] + 2 * k), b = fg_vf_load(win[l] + 2 * k + V);
                even[l] = fg_vf_even(a, b);
                odd[l] = fg_vf_odd(a, b);
            }
            fg_vf_transpose(even);
            fg_vf_transpose(odd);
            for (unsigned j = 0; j < V; j++) {
                fg_vf_store(c->lanes + (k + j) * V, even[j]);
                fg_vf_store(c->lanes + (B + k + j) * V, odd[j]);
            }
        }
        return;
    }
#endif
    for (unsigned l = 0; l < V; l++)
        for (size_t k = 0; k < B; k++) {
            c->lanes[k * V + l] = win[l][2 * k];
            c->lanes[(B + k) * V + l] = win[l][2 * k + 1];
        }
}

/* dst[l][0 .. 2B) = lane l of c->lanes, l < count. */
static void scatter_lanes(const fg_convolver *c, float *const *dst, unsigned count)
{
    const size_t n = 2 * c->block;
#ifdef FG_VF_SHUFFLE
    for (size_t e = 0; e < n; e += V) { /* n = 2B >= 4 */
        fg_vf r[V];
        for (unsigned j = 0; j < V; j++)
            r[j] = fg_vf_load(c->lanes + (e + j) * V);
        fg_vf_transpose(r);
        for (unsigned l = 0; l < count; l++)
            fg_vf_store(dst[l] + e, r[l]);
    }
#else
    for (unsigned l = 0; l < count; l++)
        for (size_t e = 0; e < n; e++)
            dst[l][e] = c->lanes[e * V + l];
#endif
}

/* Lane l of c->lanes = src[l][0 .. 2B), l < FG_VF_LANES. */
static void fill_lanes(fg_convolver *c, const float *const *src)
{
    const size_t n = 2 * c->block;
#ifdef FG_VF_SHUFFLE
    for (size_t e = 0; e < n; e += V) {
        fg_vf r[V];
        for (unsigned l = 0; l < V; l++)
            r[l] = fg_vf_load(src[l] + e);
        fg_vf_transpose(r);
        for (unsigned j = 0; j < V; j++)
            fg_vf_store(c->lanes + (e + j) * V, r[j]);
    }
#else
    for (unsigned l = 0; l < V; l++)
        for (size_t e = 0; e < n; e++)
            c->lanes[e * V + l] = src[l][e];
#endif
}

/* One window (2B frames) to its packed spectrum in x, by fg_fft_avx2 where
 * the convolver chose it, else by the lanes' single-signal path. */
static void forward_one(fg_convolver *c, const float *win, float *x)
{
#ifdef FG_FFT_AVX2
    if (c->fft_avx2) {
        fg_fft_avx2_forward(&c->fft_avx2_plan, win, x);
        return;
    }
#endif
    split_window(win, x, c->block);
    fg_fft_lanes_forward_one(&c->fft, x, c->work);
}

/* A packed spectrum in x back to its split window, in place. */
static void inverse_one(fg_convolver *c, float *x)
{
#ifdef FG_FFT_AVX2
    if (c->fft_avx2) {
        fg_fft_avx2_inverse(&c->fft_avx2_plan, x);
        return;
    }
#endif
    fg_fft_lanes_inverse_one(&c->fft, x, c->work);
}

/* The forward transforms of the inputs in who[0 .. count) into their
 * newest history slots, count <= FG_VF_LANES: one per lane, or one at a
 * time by fg_fft_avx2 where the convolver chose it, or, for fewer inputs
 * than lanes, each with its elements across the lanes (the same floats:
 * fft_lanes_internal.h); then their windows move on by a block. */
static void forward_batch(fg_convolver *c, const unsigned *who, unsigned count)
{
    const size_t B = c->block, n = 2 * B;
    float *slot[V];
    for (unsigned l = 0; l < V; l++) /* lanes past count are not written */
        slot[l] = l < count ? c->history + ((size_t)who[l] * c->partitions + c->newest) * n : NULL;
    if (c->fft_avx2 || (c->fft.one && count < V)) {
        for (unsigned l = 0; l < count; l++)
            forward_one(c, c->in + (size_t)who[l] * n, slot[l]);
    } else {
        const float *win[V];
        for (unsigned l = 0; l < V; l++)
            win[l] = l < count ? c->in + (size_t)who[l] * n : c->zeros;
        gather_windows(c, win);
        fg_fft_lanes_forward(&c->fft, c->lanes, c->work);
        scatter_lanes(c, slot, count);
    }
    for (unsigned l = 0; l < count; l++)
        memcpy(c->in + (size_t)who[l] * n, c->in + (size_t)who[l] * n + B, B * sizeof(float));
}

/* The outputs' spectra in c->acc back to time: the second half of each
 * window (overlap-save) is its next B output frames. */
static void inverse_outputs(fg_convolver *c)
{
    const size_t B = c->block, n = 2 * B;
    for (unsigned o0 = 0; o0 < c->outputs; o0 += V) {
        unsigned count = c->outputs - o0 < V ? c->outputs - o0 : V;
        const float *spectra[V];
        float *time[V];
        for (unsigned l = 0; l < V; l++) {
            time[l] = l < count ? c->acc + (size_t)(o0 + l) * n : NULL;
            spectra[l] = l < count ? time[l] : c->zeros;
        }
        /* each window, split, where its spectrum was */
        if (c->fft_avx2 || (c->fft.one && count < V)) {
            for (unsigned l = 0; l < count; l++)
                inverse_one(c, time[l]);
        } else {
            fill_lanes(c, spectra);
            fg_fft_lanes_inverse(&c->fft, c->lanes, c->work);
            scatter_lanes(c, time, count);
        }
        /* sample s of the window is element s / 2 (even s) or B + s / 2 */
        for (unsigned l = 0; l < count; l++) {
            float *y = c->out + (size_t)(o0 + l) * B;
            size_t k = B / 2;
#ifdef FG_VF_SHUFFLE
            for (; k + V <= B; k += V)
                fg_vf_interleave(fg_vf_load(time[l] + k), fg_vf_load(time[l] + B + k),
                                 y + 2 * k - B);
#endif
            for (; k < B; k++) {
                y[2 * k - B] = time[l][k];
                y[2 * k + 1 - B] = time[l][B + k];
            }
        }
    }
}

/* The block in[.][B .. 2B) is complete: its spectrum joins the history
 * and the next B output frames are computed. */
static void run_block(fg_convolver *c)
{
    const size_t B = c->block, P = c->partitions, n = 2 * B, O = c->outputs;
    c->newest = (c->newest + 1) % P;
    bool any = false;
    unsigned who[V], count = 0;
    for (size_t w = 0; w < c->words; w++)
        for (uint64_t bits = c->awake[w]; bits; bits &= bits - 1) {
            unsigned i = (unsigned)(64 * w) + (unsigned)__builtin_ctzll(bits);
            float *x = c->in + (size_t)i * n;
            /* a block spectrum is zero once this block and the one before are */
            bool silent = !c->fed[i] || all_zero(x + B, B);
            c->fed[i] = false;
            c->quiet[i] = silent ? (c->quiet[i] < P + 2 ? c->quiet[i] + 1 : P + 2) : 0;
            if (c->quiet[i] == P + 2) /* every slot's flag below is down by now */
                c->awake[w] &= ~(bits & -bits);
            bool live = c->quiet[i] <= 1;
            c->live[(size_t)i * P + c->newest] = live;
            if (live) { /* (else both halves of its window are zero already) */
                who[count++] = i;
                if (count == V) {
                    forward_batch(c, who, count);
                    count = 0;
                }
            }
            any = any || c->quiet[i] <= P;
        }
    if (count > 0)
        forward_batch(c, who, count);
    if (!any) {
        memset(c->out, 0, O * B * sizeof *c->out);
        return;
    }
    memset(c->acc, 0, (O + 1) * n * sizeof *c->acc);
    const float **x = c->pairs, **h = c->pairs + P;
    for (size_t w = 0; w < c->words; w++)
        for (uint64_t bits = c->awake[w]; bits; bits &= bits - 1) {
            unsigned i = (unsigned)(64 * w) + (unsigned)__builtin_ctzll(bits);
            if (c->quiet[i] > P)
                continue; /* its whole history is zero */
            size_t slots = 0;
            for (size_t p = 0; p < P; p++) {
                size_t slot = (c->newest + P - p) % P;
                if (!c->live[(size_t)i * P + slot])
                    continue; /* a block of silence p blocks ago */
                x[slots] = c->history + ((size_t)i * P + slot) * n;
                h[slots++] = c->filter + ((size_t)i * P + p) * O * n;
            }
            /* outputs two at a time; an odd last one pairs with the spare */
            for (size_t o = 0; o < O; o += 2) {
                size_t o1 = o + 1 < O ? o + 1 : O;
                c->mac(c->acc + o * n, c->acc + o1 * n, x, h, o * n, (o1 < O ? o1 : o) * n, slots,
                       B);
            }
        }
    inverse_outputs(c);
}

void fg_convolver_process(fg_convolver *c, const float *const *in, float *const *out, size_t n)
{
    const size_t B = c->block;
    for (size_t w = 0; w < c->words; w++)
        c->given[w] = 0;
    for (unsigned i = 0; i < c->inputs; i++)
        if (in[i])
            c->given[i / 64] |= (uint64_t)1 << (i % 64);
    size_t done = 0;
    while (done < n) {
        size_t run = B - c->fill < n - done ? B - c->fill : n - done;
        for (size_t w = 0; w < c->words; w++) {
            c->awake[w] |= c->given[w];
            for (uint64_t bits = c->awake[w]; bits; bits &= bits - 1) {
                unsigned i = (unsigned)(64 * w) + (unsigned)__builtin_ctzll(bits);
                float *to = c->in + (size_t)i * 2 * B + B + c->fill;
                if (in[i]) {
                    memcpy(to, in[i] + done, run * sizeof(float));
                    c->fed[i] = true;
                } else if (c->quiet[i] < 2) {
                    /* (from two silent blocks on, both halves of the
                     * window are zero: run_block moves no block of it) */
                    memset(to, 0, run * sizeof(float));
                }
            }
        }
        /* + 0: a sum that flushed to -0 leaves as +0, so silence has one
         * pattern of bits (a host adding another engine's zeros to it, as
         * the LV2 plugin does while it swaps engines, changes nothing) */
        for (unsigned o = 0; o < c->outputs; o++) {
            const float *y = c->out + (size_t)o * B + c->fill;
            size_t k = 0;
            for (; k + V <= run; k += V)
                fg_vf_store(out[o] + done + k, fg_vf_load(y + k) + 0.0f);
            for (; k < run; k++)
                out[o][done + k] = y[k] + 0.0f;
        }
        c->fill += run;
        done += run;
        if (c->fill == B) {
            run_block(c);
            c->fill = 0;
        }
    }
}
