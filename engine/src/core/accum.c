/* The difference-domain accumulator (core/accum_internal.h). */
#include <math.h>
#include <string.h>

#include "accum_internal.h"

void fg_accum_restart(fg_accum *b, double *d3, uint32_t n)
{
    b->d3 = d3;
    b->n = n;
    for (int j = 0; j < 3; j++)
        b->state[j] = b->sum[j] = 0.0;
    b->until = 0;
}

/* The running sums at sample -1: those carried, and what the three samples
 * before the block that waves added give: the second difference, the
 * first difference and y. */
static void start_sums(const fg_accum *b, double sum[3])
{
    const double *s = b->state;
    sum[0] = b->sum[0] + (s[0] - 2.0 * s[1] + s[2]);
    sum[1] = b->sum[1] + (s[0] - s[1]);
    sum[2] = b->sum[2] + s[0];
}

/* Leaves b at the next block, frames on, its sums at the last sample. */
static void move_on(fg_accum *b, const double sum[3], uint32_t frames)
{
    b->d3 += frames;
    b->n -= frames;
    b->until -= (int32_t)frames;
    if (!isfinite(sum[0]) || !isfinite(sum[1]) || !isfinite(sum[2])) {
        memset(b->d3, 0, b->n * sizeof *b->d3);
        fg_accum_restart(b, b->d3, b->n);
        return;
    }
    const bool silent = !fg_accum_sounds(b);
    for (int j = 0; j < 3; j++) {
        b->sum[j] = silent ? 0.0 : sum[j];
        b->state[j] = 0.0;
    }
}

/* Samples [from, frames) of b from the sums at from - 1, left at the last.
 * Three running sums rather than one third-order recurrence: each carries
 * only an add from sample to sample, so the loop is not latency-bound. */
static void end_from(fg_accum *b, float *out, double sum[3], uint32_t from, uint32_t frames)
{
    double d2 = sum[0], d1 = sum[1], y = sum[2];
    for (uint32_t k = from; k < frames; k++) {
        d2 += b->d3[k];
        b->d3[k] = 0.0;
        d1 += d2;
        y += d1;
        out[k] += (float)y;
    }
    sum[0] = d2;
    sum[1] = d1;
    sum[2] = y;
}

static void end_one(fg_accum *b, float *out, uint32_t frames)
{
    double sum[3];
    start_sums(b, sum);
    end_from(b, out, sum, 0, frames);
    move_on(b, sum, frames);
}

/* Two at once: each runs end_one's sums in its order (the same floats),
 * and the two sets of sums do not wait on each other. */
static void end_two(fg_accum *a, float *out_a, fg_accum *b, float *out_b, uint32_t frames)
{
    double s[3], t[3];
    start_sums(a, s);
    start_sums(b, t);
    double d2 = s[0], e2 = t[0], d1 = s[1], e1 = t[1], y = s[2], z = t[2];
    for (uint32_t k = 0; k < frames; k++) {
        d2 += a->d3[k];
        e2 += b->d3[k];
        a->d3[k] = 0.0;
        b->d3[k] = 0.0;
        d1 += d2;
        e1 += e2;
        y += d1;
        z += e1;
        out_a[k] += (float)y;
        out_b[k] += (float)z;
    }
    move_on(a, (double[3]){d2, d1, y}, frames);
    move_on(b, (double[3]){e2, e1, z}, frames);
}

/* Four, one per lane of fg_accum_end_four_avx2's vectors, each in
 * end_one's order (the same floats); the last frames % 4 samples of each
 * as end_one ends them. */
static void end_four(fg_accum *const b[4], float *const out[4], uint32_t frames)
{
    double sum[3][4];
    for (unsigned c = 0; c < 4; c++) {
        double one[3];
        start_sums(b[c], one);
        for (int j = 0; j < 3; j++)
            sum[j][c] = one[j];
    }
    uint32_t from = fg_accum_end_four_avx2(b, out, sum, frames);
    for (unsigned c = 0; c < 4; c++) {
        double one[3] = {sum[0][c], sum[1][c], sum[2][c]};
        end_from(b[c], out[c], one, from, frames);
        move_on(b[c], one, frames);
    }
}

void fg_accum_end_all(fg_accum *const *b, float *const *out, unsigned count, uint32_t frames,
                      bool avx2)
{
    /* sounding ones held back, to be ended together */
    fg_accum *held[4];
    float *held_out[4];
    unsigned holding = 0;
    const unsigned group = avx2 ? 4 : 2;
    for (unsigned i = 0; i < count; i++) {
        if (!fg_accum_sounds(b[i]))
            continue;
        held[holding] = b[i];
        held_out[holding++] = out[i];
        if (holding == group) {
            if (group == 4)
                end_four(held, held_out, frames);
            else
                end_two(held[0], held_out[0], held[1], held_out[1], frames);
            holding = 0;
        }
    }
    unsigned k = 0;
    for (; k + 2 <= holding; k += 2)
        end_two(held[k], held_out[k], held[k + 1], held_out[k + 1], frames);
    if (k < holding)
        end_one(held[k], held_out[k], frames);
}
