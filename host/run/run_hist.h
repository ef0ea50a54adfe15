/* A fixed-bin histogram of durations for fulgur run: preallocated, so the
 * audio thread can add to it; quantiles to the bin width; exact maximum. */
#ifndef HOST_RUN_RUN_HIST_H
#define HOST_RUN_RUN_HIST_H

#include <stddef.h>
#include <stdint.h>

typedef struct run_hist {
    uint32_t *bins;
    size_t bin_count;
    double bin_s;      /* width of one bin */
    uint64_t count;
    uint64_t overflow; /* values beyond the last bin */
    double max_s;
    double sum_s;
} run_hist;

/* Allocates bin_count bins of bin_s seconds. Returns 0, or -1 when out of
 * memory. [main-thread] */
int run_hist_init(run_hist *h, double bin_s, size_t bin_count);

/* Frees the bins; zeroes *h. */
void run_hist_deinit(run_hist *h);

/* Counts one value (negative counts as 0). Never allocates. One writer. */
void run_hist_add(run_hist *h, double value_s);

/* The q-quantile (0..1): the upper edge of the bin that holds it, or the
 * maximum when it lies beyond the bins; 0 when empty. */
double run_hist_quantile(const run_hist *h, double q);

/* Values in [lo_s, hi_s). */
uint64_t run_hist_count_between(const run_hist *h, double lo_s, double hi_s);

#endif
