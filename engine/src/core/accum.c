/* The difference-domain accumulator (core/accum_internal.h). */
#include <string.h>

#include "accum_internal.h"

void fg_accum_begin(fg_accum *b, double *d3, size_t n)
{
    b->d3 = d3;
    b->n = n;
    b->state[0] = b->state[1] = b->state[2] = 0.0;
    b->touched = false;
    memset(d3, 0, n * sizeof *d3);
}

void fg_accum_restart(fg_accum *b, size_t n)
{
    b->n = n;
    b->state[0] = b->state[1] = b->state[2] = 0.0;
    b->touched = false;
}

/* The running sums at sample -1 from the three samples before the block:
 * the second difference, the first difference and y. */
static void start_sums(const fg_accum *b, double sum[3])
{
    const double *s = b->state;
    sum[0] = s[0] - 2.0 * s[1] + s[2];
    sum[1] = s[0] - s[1];
    sum[2] = s[0];
}

/* Samples [from, n) of b from the sums at from - 1. Three running sums
 * rather than one third-order recurrence: each carries only an add from
 * sample to sample, so the loop is not latency-bound. */
static void end_from(fg_accum *b, float *out, const double sum[3], size_t from)
{
    double d2 = sum[0], d1 = sum[1], y = sum[2];
    for (size_t k = from; k < b->n; k++) {
        d2 += b->d3[k];
        b->d3[k] = 0.0;
        d1 += d2;
        y += d1;
        out[k] += (float)y;
    }
}

static void end_one(fg_accum *b, float *out)
{
    double sum[3];
    start_sums(b, sum);
    end_from(b, out, sum, 0);
}

/* Two blocks of one length at once: each runs end_one's sums in its order
 * (the same floats), and the two sets of sums do not wait on each other. */
static void end_two(fg_accum *a, float *out_a, fg_accum *b, float *out_b)
{
    double s[3], t[3];
    start_sums(a, s);
    start_sums(b, t);
    double d2 = s[0], e2 = t[0], d1 = s[1], e1 = t[1], y = s[2], z = t[2];
    for (size_t k = 0; k < a->n; k++) {
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
}

/* Four blocks of one length, one per lane of fg_accum_end_four_avx2's
 * vectors, each in end_one's order (the same floats); the last n % 4
 * samples of each as end_one ends. */
static void end_four(fg_accum *const b[4], float *const out[4])
{
    double sum[3][4];
    for (unsigned c = 0; c < 4; c++) {
        double one[3];
        start_sums(b[c], one);
        for (int j = 0; j < 3; j++)
            sum[j][c] = one[j];
    }
    size_t from = fg_accum_end_four_avx2(b, out, sum);
    for (unsigned c = 0; c < 4; c++)
        end_from(b[c], out[c], (double[3]){sum[0][c], sum[1][c], sum[2][c]}, from);
}

void fg_accum_end_all(fg_accum *const *b, float *const *out, unsigned count, bool avx2)
{
    /* touched blocks of one length held back, to be ended together */
    fg_accum *held[4];
    float *held_out[4];
    unsigned holding = 0;
    const unsigned group = avx2 ? 4 : 2;
    for (unsigned i = 0; i <= count; i++) {
        bool last = i == count;
        if (!last && !b[i]->touched)
            continue;
        if (holding > 0 && (last || held[0]->n != b[i]->n)) {
            unsigned k = 0;
            for (; k + 2 <= holding; k += 2)
                end_two(held[k], held_out[k], held[k + 1], held_out[k + 1]);
            if (k < holding)
                end_one(held[k], held_out[k]);
            holding = 0;
        }
        if (last)
            break;
        held[holding] = b[i];
        held_out[holding++] = out[i];
        if (holding == group) {
            if (group == 4)
                end_four(held, held_out);
            else
                end_two(held[0], held_out[0], held[1], held_out[1]);
            holding = 0;
        }
    }
}
