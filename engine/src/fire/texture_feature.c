#include <math.h>

#include "texture_internal.h"

void fg_texture_shape_init(fg_texture_shape *s, int levels, int h, int hf)
{
    s->levels = levels;
    s->h = h;
    s->hf = hf;
    s->fine_len = 2 * h * hf - h + 1;
    s->coarse_len = 2 * h * hf + 1;
    s->dims = s->fine_len + s->coarse_len;
    s->value_len = 2 * h + 1;
}

static double view_at(const fg_level_view *v, int64_t i)
{
    return i < v->first ? 0.0 : v->data[(uint64_t)i & v->mask];
}

/* Level l + 1 at (c / 2 + j), c >= 0: exact for even c, the mean of the
 * two neighbours for odd c. */
static double coarse_at(const fg_level_view *v, int64_t c, int64_t j)
{
    int64_t base = c / 2 + j;
    if ((c & 1) == 0)
        return view_at(v, base);
    return 0.5 * (view_at(v, base) + view_at(v, base + 1));
}

void fg_texture_feature(const fg_texture_shape *s, const fg_level_view *fine,
                        const fg_level_view *coarse, int64_t c, double coarse_scale, float *out)
{
    int64_t h = s->h, span = (int64_t)s->h * s->hf;
    int k = 0;
    for (int64_t n = c - 2 * span; n <= c - h; n++)
        out[k++] = (float)view_at(fine, n);
    for (int64_t j = -span; j <= span; j++)
        out[k++] = (float)(coarse_scale * coarse_at(coarse, c, j));
}

double fg_texture_coarse_mean(const fg_texture_shape *s, const fg_level_view *coarse, int64_t c)
{
    int64_t span = (int64_t)s->h * s->hf;
    double sum = 0.0;
    for (int64_t j = -span; j <= span; j++)
        sum += fabs(coarse_at(coarse, c, j));
    return sum / (double)s->coarse_len;
}

/* First index with sorted[i] >= v (lower) or > v (upper). */
static size_t bound(const double *sorted, size_t n, double v, int upper)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (upper ? sorted[mid] <= v : sorted[mid] < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

double fg_sorted_cdf(const double *sorted, size_t n, double v)
{
    if (n < 2)
        return 0.5;
    size_t lo = bound(sorted, n, v, 0), hi = bound(sorted, n, v, 1);
    double rank;
    if (hi > lo) {
        rank = 0.5 * (double)(lo + hi - 1); /* a run of values equal to v */
    } else if (lo == 0) {
        return 0.0;
    } else if (lo == n) {
        return 1.0;
    } else {
        double a = sorted[lo - 1], b = sorted[lo];
        rank = (double)(lo - 1) + (v - a) / (b - a);
    }
    return rank / (double)(n - 1);
}

double fg_sorted_quantile(const double *sorted, size_t n, double q)
{
    if (n == 1)
        return sorted[0];
    double x = q * (double)(n - 1);
    if (x <= 0.0)
        return sorted[0];
    if (x >= (double)(n - 1))
        return sorted[n - 1];
    size_t i = (size_t)x;
    double t = x - (double)i;
    return sorted[i] + t * (sorted[i + 1] - sorted[i]);
}
