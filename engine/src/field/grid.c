/* The field's grid: creation with the memory check, and its geometry. */
#include <math.h>
#include <stdlib.h>

#include "fg_rules.h"
#include "field_internal.h"

/* The sizes a field of config has, defaults filled in; 0 if one is out of
 * range. */
static int sizes(const fg_grid_config *c, int n[3])
{
    for (int a = 0; a < 3; a++) {
        n[a] = FG_DEF(c->size[a], FG_FIELD_DEFAULT_SIZE);
        if (n[a] < FG_FIELD_MIN_SIZE || n[a] > FG_FIELD_MAX_SIZE)
            return 0;
    }
    return 1;
}

size_t fg_field_memory_bytes(const fg_grid_config *config)
{
    FG_REQUIRE_OR(config, 0);
    int n[3];
    if (!sizes(config, n))
        return 0;
    size_t count = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    /* phi, the labels, and the float x, r, z, p, q */
    return count * (sizeof(double) + 1 + 5 * sizeof(float)) + fg_multigrid_bytes(n) +
           sizeof(fg_field);
}

fg_result fg_field_create(const fg_grid_config *config, fg_field **out)
{
    if (!config || !out)
        return FG_ERR_NULL;
    int n[3];
    for (int a = 0; a < 3; a++)
        if (!isfinite(config->min_m[a]) || !isfinite(config->max_m[a]))
            return FG_ERR_NOT_FINITE;
    if (!sizes(config, n))
        return FG_ERR_ARGUMENT;
    for (int a = 0; a < 3; a++)
        if (!(config->max_m[a] > config->min_m[a]))
            return FG_ERR_ARGUMENT;
    size_t limit = FG_DEF(config->max_bytes, FG_FIELD_DEFAULT_MAX_BYTES);
    if (fg_field_memory_bytes(config) > limit)
        return FG_ERR_CAPACITY;

    fg_field *f = calloc(1, sizeof *f);
    if (!f)
        return FG_ERR_NO_MEMORY;
    f->config = *config;
    f->config.max_bytes = limit;
    for (int a = 0; a < 3; a++) {
        f->config.size[a] = n[a];
        f->h[a] = (config->max_m[a] - config->min_m[a]) / (n[a] - 1);
    }
    size_t count = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    f->phi = calloc(count, sizeof(double));
    f->x = calloc(count, sizeof(float));
    f->r = calloc(count, sizeof(float));
    f->z = calloc(count, sizeof(float));
    f->p = calloc(count, sizeof(float));
    f->q = calloc(count, sizeof(float));
    f->label = calloc(count, 1);
    f->b_norm = -1.0;
    if (!f->phi || !f->x || !f->r || !f->z || !f->p || !f->q || !f->label ||
        fg_multigrid_init(f) != FG_OK) {
        fg_field_destroy(f);
        return FG_ERR_NO_MEMORY;
    }
    *out = f;
    return FG_OK;
}

void fg_field_destroy(fg_field *f)
{
    if (!f)
        return;
    fg_multigrid_deinit(f);
    free(f->phi);
    free(f->x);
    free(f->r);
    free(f->z);
    free(f->p);
    free(f->q);
    free(f->label);
    free(f->sites);
    free(f);
}

void fg_field_get_config(const fg_field *f, fg_grid_config *out)
{
    FG_REQUIRE(f && out);
    *out = f->config;
}

void fg_field_cell(const fg_field *f, double out_m[3])
{
    FG_REQUIRE(f && out_m);
    for (int a = 0; a < 3; a++)
        out_m[a] = f->h[a];
}

void fg_field_nearest(const fg_field *f, const double x[3], int ijk[3])
{
    for (int a = 0; a < 3; a++) {
        double u = floor((x[a] - f->config.min_m[a]) / f->h[a] + 0.5);
        double top = f->config.size[a] - 1;
        ijk[a] = (int)(u < 0.0 ? 0.0 : (u > top ? top : u));
    }
}
