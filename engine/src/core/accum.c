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
    if (b->touched)
        memset(b->d3, 0, b->n * sizeof *b->d3);
    b->n = n;
    b->state[0] = b->state[1] = b->state[2] = 0.0;
    b->touched = false;
}

/* Three running sums rather than one third-order recurrence: each carries
 * only an add from sample to sample, so the loop is not latency-bound. */
void fg_accum_end(const fg_accum *b, float *out, float gain)
{
    if (!b->touched)
        return;
    const double *s = b->state;
    double d2 = s[0] - 2.0 * s[1] + s[2]; /* second difference at -1 */
    double d1 = s[0] - s[1];              /* first difference at -1 */
    double y = s[0];
    for (size_t k = 0; k < b->n; k++) {
        d2 += b->d3[k];
        d1 += d2;
        y += d1;
        out[k] += gain * (float)y;
    }
}
