/* Reading the field: trilinear sampling, the origin sites, and the field
 * source a growth model reads. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fg_rules.h"
#include "field_internal.h"

static int finite3(const double *x)
{
    return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]);
}

fg_result fg_field_sample(const fg_field *f, const double *pts, size_t n, double *out)
{
    if (!f || (n > 0 && (!pts || !out)))
        return FG_ERR_NULL;
    for (size_t p = 0; p < n; p++)
        if (!finite3(&pts[3 * p]))
            return FG_ERR_NOT_FINITE;
    const fg_level *L = &f->level[0];
    size_t sy = (size_t)L->n[0], sz = sy * (size_t)L->n[1];
    for (size_t p = 0; p < n; p++) {
        int c[3];
        double t[3];
        for (int a = 0; a < 3; a++) {
            double u = (pts[3 * p + a] - f->config.min_m[a]) / f->h[a];
            double top = L->n[a] - 1;
            u = u < 0.0 ? 0.0 : (u > top ? top : u);
            c[a] = (int)u;
            if (c[a] > L->n[a] - 2)
                c[a] = L->n[a] - 2;
            t[a] = u - c[a];
        }
        const double *v = &f->phi[fg_level_index(L, c[0], c[1], c[2])];
        double x00 = v[0] + t[0] * (v[1] - v[0]);
        double x10 = v[sy] + t[0] * (v[sy + 1] - v[sy]);
        double x01 = v[sz] + t[0] * (v[sz + 1] - v[sz]);
        double x11 = v[sz + sy] + t[0] * (v[sz + sy + 1] - v[sz + sy]);
        double y0 = x00 + t[1] * (x10 - x00);
        double y1 = x01 + t[1] * (x11 - x01);
        out[p] = y0 + t[2] * (y1 - y0);
    }
    return FG_OK;
}

/* Whether row (j, k) of the labels holds an ORIGIN node, for the rows
 * (0 outside the grid). */
static int row_has_origin(const uint8_t *rows, const int *n, int j, int k)
{
    return j >= 0 && j < n[1] && k >= 0 && k < n[2] && rows[j + (size_t)n[1] * (size_t)k];
}

/* The free face neighbours of ORIGIN nodes, found by one pass over the
 * labels and kept until the labels change. Only rows next to a row with
 * an ORIGIN node (or it) can hold one. */
static fg_result find_origin_sites(fg_field *f)
{
    const fg_level *L = &f->level[0];
    const int *n = L->n;
    size_t sy = (size_t)n[0], sz = sy * (size_t)n[1], count = 0;
    const uint8_t *lab = f->label;
    uint8_t *rows = malloc((size_t)n[1] * (size_t)n[2]);
    if (!rows)
        return FG_ERR_NO_MEMORY;
    for (int k = 0; k < n[2]; k++)
        for (int j = 0; j < n[1]; j++)
            rows[j + (size_t)n[1] * (size_t)k] =
                memchr(lab + fg_level_index(L, 0, j, k), FG_REGION_ORIGIN, sy) != NULL;
    for (int pass = 0; pass < 2; pass++) {
        count = 0;
        for (int k = 0; k < n[2]; k++)
            for (int j = 0; j < n[1]; j++) {
                if (!row_has_origin(rows, n, j, k) && !row_has_origin(rows, n, j - 1, k) &&
                    !row_has_origin(rows, n, j + 1, k) && !row_has_origin(rows, n, j, k - 1) &&
                    !row_has_origin(rows, n, j, k + 1))
                    continue;
                for (int i = 0; i < n[0]; i++) {
                    size_t id = fg_level_index(L, i, j, k);
                    if (lab[id] != FG_REGION_FREE)
                        continue;
                    if (!((i > 0 && lab[id - 1] == FG_REGION_ORIGIN) ||
                          (i < n[0] - 1 && lab[id + 1] == FG_REGION_ORIGIN) ||
                          (j > 0 && lab[id - sy] == FG_REGION_ORIGIN) ||
                          (j < n[1] - 1 && lab[id + sy] == FG_REGION_ORIGIN) ||
                          (k > 0 && lab[id - sz] == FG_REGION_ORIGIN) ||
                          (k < n[2] - 1 && lab[id + sz] == FG_REGION_ORIGIN)))
                        continue;
                    if (pass == 1) {
                        f->sites[3 * count + 0] = f->config.min_m[0] + i * f->h[0];
                        f->sites[3 * count + 1] = f->config.min_m[1] + j * f->h[1];
                        f->sites[3 * count + 2] = f->config.min_m[2] + k * f->h[2];
                    }
                    count++;
                }
            }
        if (pass == 0) {
            free(f->sites);
            f->sites = malloc((count ? count : 1) * 3 * sizeof(double));
            if (!f->sites) {
                free(rows);
                return FG_ERR_NO_MEMORY;
            }
        }
    }
    free(rows);
    f->site_count = count;
    f->sites_valid = 1;
    return FG_OK;
}

size_t fg_field_origin_sites(fg_field *f, double *pts, size_t max)
{
    FG_REQUIRE_OR(f, 0);
    if (!f->sites_valid && find_origin_sites(f) != FG_OK)
        return 0;
    size_t n = f->site_count < max ? f->site_count : max;
    if (pts)
        memcpy(pts, f->sites, n * 3 * sizeof(double));
    return f->site_count;
}

static fg_result src_sample(void *ctx, const double *pts, size_t n, double *out)
{
    return fg_field_sample(ctx, pts, n, out);
}

static fg_result src_classify(void *ctx, const double *pts, size_t n, uint8_t *out)
{
    return fg_field_classify(ctx, pts, n, out);
}

static size_t src_origin_sites(void *ctx, double *pts, size_t max)
{
    return fg_field_origin_sites(ctx, pts, max);
}

void fg_field_source_init(fg_field *f, fg_field_source *out)
{
    FG_REQUIRE(f && out);
    double cell = f->h[0];
    if (f->h[1] < cell)
        cell = f->h[1];
    if (f->h[2] < cell)
        cell = f->h[2];
    *out = (fg_field_source){f, src_sample, src_classify, src_origin_sites, cell};
}
