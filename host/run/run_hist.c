/* Fixed-bin histograms. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run_hist.h"

int run_hist_init(run_hist *h, double bin_s, size_t bin_count)
{
    memset(h, 0, sizeof *h);
    h->bins = calloc(bin_count, sizeof *h->bins);
    if (!h->bins)
        return -1;
    h->bin_count = bin_count;
    h->bin_s = bin_s;
    return 0;
}

void run_hist_deinit(run_hist *h)
{
    free(h->bins);
    memset(h, 0, sizeof *h);
}

void run_hist_add(run_hist *h, double value_s)
{
    if (!(value_s > 0))
        value_s = 0;
    double bin = floor(value_s / h->bin_s);
    if (bin < (double)h->bin_count)
        h->bins[(size_t)bin]++;
    else
        h->overflow++;
    h->count++;
    h->sum_s += value_s;
    if (value_s > h->max_s)
        h->max_s = value_s;
}

double run_hist_quantile(const run_hist *h, double q)
{
    if (h->count == 0)
        return 0;
    /* the rank of the quantile, 1-based: ceil(q * count), at least 1 */
    uint64_t rank = (uint64_t)ceil(q * (double)h->count);
    if (rank == 0)
        rank = 1;
    uint64_t seen = 0;
    for (size_t i = 0; i < h->bin_count; i++) {
        seen += h->bins[i];
        if (seen >= rank)
            return fmin((double)(i + 1) * h->bin_s, h->max_s);
    }
    return h->max_s;
}

uint64_t run_hist_count_between(const run_hist *h, double lo_s, double hi_s)
{
    uint64_t n = 0;
    for (size_t i = 0; i < h->bin_count; i++) {
        double lo = (double)i * h->bin_s;
        if (lo >= lo_s && lo < hi_s)
            n += h->bins[i];
    }
    if ((double)h->bin_count * h->bin_s < hi_s && (double)h->bin_count * h->bin_s >= lo_s)
        n += h->overflow;
    return n;
}
