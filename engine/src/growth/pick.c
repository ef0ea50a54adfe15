#include "pick_internal.h"

int fg_pick(const double *w, int n, double u)
{
    double sum = 0.0;
    for (int i = 0; i < n; i++)
        sum += w[i] > 0.0 ? w[i] : 0.0;
    if (!(sum > 0.0))
        return -1;
    double target = u * sum, acc = 0.0;
    int last = -1;
    for (int i = 0; i < n; i++) {
        if (w[i] <= 0.0)
            continue;
        acc += w[i];
        last = i; /* the last eligible one absorbs rounding at the top */
        if (target < acc)
            return i;
    }
    return last;
}
