#include "wm_reference.h"

/* P at the sample edge n - 1/2. */
static double edge_integral(const fg_wm_event *e, long n)
{
    return fg_wm_integral(&e->shape, ((double)n - 0.5 - e->center) / e->width);
}

void ref_wm_add_direct(const fg_wm_event *e, double *out, size_t n)
{
    long first, last;
    fg_wm_event_span(e, &first, &last);
    if (first < 0)
        first = 0;
    if (last > (long)n - 1)
        last = (long)n - 1;
    if (first > last)
        return;
    /* the average over one sample is its integral over one sample, and
     * d(samples) = width d(tau) */
    double lo = edge_integral(e, first);
    for (long k = first; k <= last; k++) {
        double hi = edge_integral(e, k + 1);
        out[k] += e->width * (hi - lo);
        lo = hi;
    }
}
