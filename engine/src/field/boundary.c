/* Dirichlet boundary conditions from shapes: validation, normalisation of
 * the potentials, rasterisation onto the nodes, and classification of
 * points. */
#include <math.h>
#include <string.h>

#include "field_internal.h"

static int finite3(const double *x)
{
    return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]);
}

static fg_result check_shape(const fg_shape *s)
{
    if (!isfinite(s->potential) || !finite3(s->centre_m) || !isfinite(s->radius_m) ||
        !finite3(s->box_min_m) || !finite3(s->box_max_m) || !finite3(s->normal))
        return FG_ERR_NOT_FINITE;
    if ((int)s->role < FG_ROLE_FIXED || (int)s->role > FG_ROLE_TARGET)
        return FG_ERR_ARGUMENT;
    switch (s->kind) {
    case FG_SHAPE_SPHERE:
        return s->radius_m > 0.0 ? FG_OK : FG_ERR_ARGUMENT;
    case FG_SHAPE_BOX:
        for (int a = 0; a < 3; a++)
            if (s->box_max_m[a] < s->box_min_m[a])
                return FG_ERR_ARGUMENT;
        return FG_OK;
    case FG_SHAPE_PLANE:
        return (s->normal[0] != 0.0 || s->normal[1] != 0.0 || s->normal[2] != 0.0)
                   ? FG_OK
                   : FG_ERR_ARGUMENT;
    case FG_SHAPE_POINT:
    case FG_SHAPE_GROUND:
        return FG_OK;
    }
    return FG_ERR_ARGUMENT;
}

/* Whether sphere s covers a point whose offsets from its centre have the
 * squares dx2, dy2, dz2. */
static inline int sphere_covers(const fg_shape *s, double dx2, double dy2, double dz2)
{
    int in = (dx2 + dy2) + dz2 <= s->radius_m * s->radius_m;
    return s->outside ? !in : in;
}

static inline double square(double v)
{
    return v * v;
}

int fg_shape_contains(const fg_shape *s, const double x[3])
{
    double dot = 0.0;
    int in = 1;
    switch (s->kind) {
    case FG_SHAPE_SPHERE:
        return sphere_covers(s, square(x[0] - s->centre_m[0]), square(x[1] - s->centre_m[1]),
                             square(x[2] - s->centre_m[2]));
    case FG_SHAPE_BOX:
        for (int a = 0; a < 3; a++)
            in = in && x[a] >= s->box_min_m[a] && x[a] <= s->box_max_m[a];
        return s->outside ? !in : in;
    case FG_SHAPE_PLANE:
        for (int a = 0; a < 3; a++)
            dot += (x[a] - s->centre_m[a]) * s->normal[a];
        return dot <= 0.0;
    case FG_SHAPE_GROUND:
        return x[2] <= 0.0;
    case FG_SHAPE_POINT:
        return 0;
    }
    return 0;
}

static uint8_t region_of(fg_shape_role role)
{
    return role == FG_ROLE_ORIGIN ? FG_REGION_ORIGIN
                                  : (role == FG_ROLE_TARGET ? FG_REGION_TARGET : FG_REGION_FIXED);
}

/* The normalised potential of each shape; FG_OK or the error with *bad. */
static fg_result normalise(const fg_shape *s, size_t count, double *value, size_t *bad)
{
    int have[3] = {0, 0, 0};
    double volts[3] = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < count; i++) {
        int r = (int)s[i].role;
        if (r == FG_ROLE_FIXED)
            continue;
        if (have[r] && s[i].potential != volts[r]) {
            *bad = i;
            return FG_ERR_ARGUMENT;
        }
        have[r] = 1;
        volts[r] = s[i].potential;
    }
    *bad = count;
    if (!have[FG_ROLE_ORIGIN] || !have[FG_ROLE_TARGET])
        return FG_ERR_ARGUMENT;
    double vo = volts[FG_ROLE_ORIGIN], vt = volts[FG_ROLE_TARGET];
    int raw = vo == 0.0 && vt == 0.0;
    if (!raw && vo == vt)
        return FG_ERR_ARGUMENT;
    for (size_t i = 0; i < count; i++) {
        if (s[i].role == FG_ROLE_ORIGIN)
            value[i] = 0.0;
        else if (s[i].role == FG_ROLE_TARGET)
            value[i] = 1.0;
        else
            value[i] = raw ? s[i].potential : (s[i].potential - vo) / (vt - vo);
    }
    return FG_OK;
}

static void node_pos(const fg_field *f, int i, int j, int k, double x[3])
{
    x[0] = f->config.min_m[0] + i * f->h[0];
    x[1] = f->config.min_m[1] + j * f->h[1];
    x[2] = f->config.min_m[2] + k * f->h[2];
}

static int inside_box(const fg_field *f, const double x[3])
{
    for (int a = 0; a < 3; a++)
        if (x[a] < f->config.min_m[a] || x[a] > f->config.max_m[a])
            return 0;
    return 1;
}

/* Node range [lo, hi] that can hold the shape (all nodes for unbounded ones). */
static void node_range(const fg_field *f, const fg_shape *s, int lo[3], int hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = 0;
        hi[a] = f->config.size[a] - 1;
        double a0, a1;
        if (s->kind == FG_SHAPE_SPHERE && !s->outside) {
            a0 = s->centre_m[a] - s->radius_m;
            a1 = s->centre_m[a] + s->radius_m;
        } else if (s->kind == FG_SHAPE_BOX && !s->outside) {
            a0 = s->box_min_m[a];
            a1 = s->box_max_m[a];
        } else {
            continue;
        }
        double u0 = ceil((a0 - f->config.min_m[a]) / f->h[a]);
        double u1 = floor((a1 - f->config.min_m[a]) / f->h[a]);
        if (u0 > lo[a])
            lo[a] = u0 > hi[a] + 1 ? hi[a] + 1 : (int)u0;
        if (u1 < hi[a])
            hi[a] = u1 < -1 ? -1 : (int)u1;
    }
}

/* Visits the nodes a shape covers and labels them when write; returns
 * whether it covers any (without write, from the first one it finds). */
static int cover(fg_field *f, const fg_shape *s, double value, int write)
{
    const fg_level *L = &f->level[0];
    double x[3];
    if (s->kind == FG_SHAPE_POINT) {
        if (!inside_box(f, s->centre_m))
            return 0;
        int c[3];
        fg_field_nearest(f, s->centre_m, c);
        if (write) {
            size_t id = fg_level_index(L, c[0], c[1], c[2]);
            f->label[id] = region_of(s->role);
            f->phi[id] = value;
        }
        return 1;
    }
    int lo[3], hi[3];
    node_range(f, s, lo, hi);
    int covered = 0;
    for (int k = lo[2]; k <= hi[2]; k++)
        for (int j = lo[1]; j <= hi[1]; j++) {
            /* A sphere's row (the plasma ball's glass covers most of the
             * grid) squares its y and z offsets once. */
            node_pos(f, 0, j, k, x);
            const double dy2 = square(x[1] - s->centre_m[1]), dz2 = square(x[2] - s->centre_m[2]);
            for (int i = lo[0]; i <= hi[0]; i++) {
                node_pos(f, i, j, k, x);
                if (s->kind == FG_SHAPE_SPHERE
                        ? !sphere_covers(s, square(x[0] - s->centre_m[0]), dy2, dz2)
                        : !fg_shape_contains(s, x))
                    continue;
                if (!write)
                    return 1;
                covered = 1;
                size_t id = fg_level_index(L, i, j, k);
                f->label[id] = region_of(s->role);
                f->phi[id] = value;
            }
        }
    return covered;
}

/* A sphere smaller than a cell is a point at its centre. */
static fg_shape as_point(const fg_shape *s)
{
    fg_shape p = *s;
    p.kind = FG_SHAPE_POINT;
    return p;
}

fg_result fg_field_set_shapes(fg_field *f, const fg_shape *shapes, size_t count, size_t *bad)
{
    size_t dummy;
    if (!bad)
        bad = &dummy;
    *bad = count;
    if (!f || (count > 0 && !shapes))
        return FG_ERR_NULL;
    if (count > FG_FIELD_MAX_SHAPES)
        return FG_ERR_ARGUMENT;
    for (size_t i = 0; i < count; i++) {
        fg_result r = check_shape(&shapes[i]);
        if (r != FG_OK) {
            *bad = i;
            return r;
        }
    }
    double value[FG_FIELD_MAX_SHAPES];
    fg_result r = normalise(shapes, count, value, bad);
    if (r != FG_OK)
        return r;
    fg_shape use[FG_FIELD_MAX_SHAPES];
    for (size_t i = 0; i < count; i++) {
        use[i] = shapes[i];
        if (cover(f, &use[i], 0.0, 0))
            continue;
        if (use[i].kind == FG_SHAPE_SPHERE && !use[i].outside) {
            use[i] = as_point(&use[i]);
            if (cover(f, &use[i], 0.0, 0))
                continue;
        }
        *bad = i;
        return FG_ERR_ARGUMENT;
    }

    memset(f->label, FG_REGION_FREE, f->level[0].count);
    for (size_t i = 0; i < count; i++)
        cover(f, &use[i], value[i], 1);
    memcpy(f->shapes, use, count * sizeof use[0]);
    f->shape_count = count;
    fg_field_labels_changed(f);
    return FG_OK;
}

fg_result fg_field_classify(const fg_field *f, const double *pts, size_t n, uint8_t *out)
{
    if (!f || (n > 0 && (!pts || !out)))
        return FG_ERR_NULL;
    for (size_t p = 0; p < n; p++)
        if (!finite3(&pts[3 * p]))
            return FG_ERR_NOT_FINITE;
    for (size_t p = 0; p < n; p++) {
        const double *x = &pts[3 * p];
        uint8_t region = FG_REGION_OUTSIDE;
        if (inside_box(f, x)) {
            int c[3];
            fg_field_nearest(f, x, c);
            region = f->label[fg_level_index(&f->level[0], c[0], c[1], c[2])];
        }
        for (size_t s = f->shape_count; s-- > 0;)
            if (fg_shape_contains(&f->shapes[s], x)) {
                region = region_of(f->shapes[s].role);
                break;
            }
        out[p] = region;
    }
    return FG_OK;
}

void fg_field_labels_changed(fg_field *f)
{
    f->operators_dirty = 1;
    f->b_norm = -1.0;
    f->sites_valid = 0;
}
