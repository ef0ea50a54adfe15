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

/* Three running sums rather than one third-order recurrence: each carries
 * only an add from sample to sample, so the loop is not latency-bound. */
static void end_one(fg_accum *b, float *out)
{
    const double *s = b->state;
    double d2 = s[0] - 2.0 * s[1] + s[2]; /* second difference at -1 */
    double d1 = s[0] - s[1];              /* first difference at -1 */
    double y = s[0];
    for (size_t k = 0; k < b->n; k++) {
        d2 += b->d3[k];
        b->d3[k] = 0.0;
        d1 += d2;
        y += d1;
        out[k] += (float)y;
    }
}

/* Two blocks of one length at once: each runs end_one's sums in its order
 * (the same floats), and the two sets of sums do not wait on each other. */
static void end_two(fg_accum *a, float *out_a, fg_accum *b, float *out_b)
{
    const double *s = a->state, *t = b->state;
    double d2 = s[0] - 2.0 * s[1] + s[2], e2 = t[0] - 2.0 * t[1] + t[2];
    double d1 = s[0] - s[1], e1 = t[0] - t[1];
    double y = s[0], z = t[0];
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

void fg_accum_end_all(fg_accum *const *b, float *const *out, unsigned count)
{
    fg_accum *held = NULL;
    float *held_out = NULL;
    for (unsigned i = 0; i < count; i++) {
        if (!b[i]->touched)
            continue;
        if (!held) {
            held = b[i];
            held_out = out[i];
        } else if (held->n == b[i]->n) {
            end_two(held, held_out, b[i], out[i]);
            held = NULL;
        } else {
            end_one(held, held_out);
            held = b[i];
            held_out = out[i];
        }
    }
    if (held)
        end_one(held, held_out);
}
