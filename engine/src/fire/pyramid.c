#include <string.h>

#include "pyramid_internal.h"

static const double kernel[5] = {1.0 / 16, 4.0 / 16, 6.0 / 16, 4.0 / 16, 1.0 / 16};

static size_t mirror(int64_t i, size_t n)
{
    int64_t last = (int64_t)n - 1;
    if (n == 1)
        return 0;
    while (i < 0 || i > last) {
        if (i < 0)
            i = -i;
        if (i > last)
            i = 2 * last - i;
    }
    return (size_t)i;
}

void fg_pyramid_reduce(const double *in, size_t n, double *out)
{
    size_t m = fg_pyramid_reduced_length(n);
    for (size_t j = 0; j < m; j++) {
        int64_t c = 2 * (int64_t)j;
        double s = 0.0;
        if (c >= 2 && c + 2 < (int64_t)n) {
            for (int k = 0; k < 5; k++)
                s += kernel[k] * in[c - 2 + k];
        } else {
            for (int k = 0; k < 5; k++)
                s += kernel[k] * in[mirror(c - 2 + k, n)];
        }
        out[j] = s;
    }
}

void fg_reducer_reset(fg_reducer *r)
{
    memset(r, 0, sizeof *r);
}

int fg_reducer_push(fg_reducer *r, double x, double *out)
{
    memmove(r->history, r->history + 1, 4 * sizeof(double));
    r->history[4] = x;
    uint64_t t = r->taken++;
    /* output m is complete at input t = 2m + 2 */
    if (t < 2 || (t & 1))
        return 0;
    double s = 0.0;
    for (int k = 0; k < 5; k++)
        s += kernel[k] * r->history[k];
    *out = s;
    return 1;
}
