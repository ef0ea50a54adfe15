/* The texture as an immutable, validated object; the symmetry's map of
 * flow angles; the level law. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aero_internal.h"
#include "fg_math.h"

struct fg_aero_texture {
    fg_aero_texture_desc desc;
    double *polygon;
    fg_aero_source *source;
    fg_aero_direction *direction;
    float *samples;
};

static double wrap(double a, double period)
{
    a = fmod(a, period);
    return a < 0.0 ? a + period : a;
}

void fg_aero_symmetry_range(uint32_t order, uint32_t mirror, double mirror_angle, double *lo,
                            double *span)
{
    if (order == 0) {
        *lo = *span = 0.0;
    } else if (mirror) {
        *lo = mirror_angle;
        *span = FG_PI / order;
    } else {
        *lo = 0.0;
        *span = 2.0 * FG_PI / order;
    }
}

double fg_aero_symmetry_map(uint32_t order, uint32_t mirror, double mirror_angle, double angle,
                            int *flip)
{
    *flip = 0;
    if (order == 0)
        return 0.0;
    double period = 2.0 * FG_PI / order;
    if (!mirror)
        return wrap(angle, period);
    double d = wrap(angle - mirror_angle, period);
    if (d > 0.5 * period) {
        d = period - d;
        *flip = 1;
    }
    return mirror_angle + d;
}

static int finite_positive(double v)
{
    return isfinite(v) && v > 0.0;
}

static int shape_dims(fg_aero_shape s)
{
    switch (s) {
    case FG_AERO_CIRCLE:
    case FG_AERO_RECTANGLE:
    case FG_AERO_POLYGON:
        return 2;
    case FG_AERO_SPHERE:
    case FG_AERO_CLUB:
        return 3;
    }
    return 0;
}

static fg_result check_shape(const fg_aero_texture_desc *d)
{
    double v[4] = {d->length_m, d->height_m, d->diameter_m[0], d->diameter_m[1]};
    for (int i = 0; i < 4; i++)
        if (!isfinite(v[i]))
            return FG_ERR_NOT_FINITE;
    switch (d->shape) {
    case FG_AERO_CIRCLE:
    case FG_AERO_SPHERE:
        return d->length_m > 0.0 ? FG_OK : FG_ERR_ARGUMENT;
    case FG_AERO_RECTANGLE:
        return d->length_m > 0.0 && d->height_m > 0.0 ? FG_OK : FG_ERR_ARGUMENT;
    case FG_AERO_CLUB:
        return d->diameter_m[0] > 0.0 && d->diameter_m[1] > 0.0 &&
                       d->length_m > fmax(d->diameter_m[0], d->diameter_m[1])
                   ? FG_OK
                   : FG_ERR_ARGUMENT;
    case FG_AERO_POLYGON:
        if (d->polygon_vertices < 3 || d->polygon_vertices > FG_AERO_MAX_POLYGON)
            return FG_ERR_ARGUMENT;
        if (!d->polygon_xy)
            return FG_ERR_NULL;
        for (uint32_t i = 0; i < 2 * d->polygon_vertices; i++)
            if (!isfinite(d->polygon_xy[i]))
                return FG_ERR_NOT_FINITE;
        return FG_OK;
    }
    return FG_ERR_ARGUMENT;
}

static fg_result check_scalars(const fg_aero_texture_desc *d)
{
    double v[] = {d->reference_m, d->speed_m_s, d->viscosity_m2_s, d->density_kg_m3,
                  d->reynolds, d->sample_rate_hz, d->cells_per_length, d->mirror_angle_rad};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i]))
            return FG_ERR_NOT_FINITE;
    if (!finite_positive(d->reference_m) || !finite_positive(d->speed_m_s) ||
        !finite_positive(d->viscosity_m2_s) || !finite_positive(d->density_kg_m3) ||
        !finite_positive(d->sample_rate_hz) || !finite_positive(d->cells_per_length))
        return FG_ERR_ARGUMENT;
    double re = d->reference_m * d->speed_m_s / d->viscosity_m2_s;
    if (!(fabs(d->reynolds - re) <= 1e-6 * re))
        return FG_ERR_ARGUMENT;
    if (d->rotation_order > 12 || d->mirror > 1)
        return FG_ERR_ARGUMENT;
    if (d->mirror && d->rotation_order > 0 &&
        !(d->mirror_angle_rad >= 0.0 && d->mirror_angle_rad < FG_PI / d->rotation_order))
        return FG_ERR_ARGUMENT;
    return FG_OK;
}

static fg_result check_sources(const fg_aero_texture_desc *d)
{
    if (d->dims == 2 ? d->sources != 1 : (d->sources < 1 || d->sources > FG_AERO_MAX_SOURCES))
        return FG_ERR_ARGUMENT;
    if (!d->source)
        return FG_ERR_NULL;
    for (uint32_t s = 0; s < d->sources; s++) {
        if (!isfinite(d->source[s].position_m) || !isfinite(d->source[s].span_m))
            return FG_ERR_NOT_FINITE;
        if (!(d->source[s].span_m > 0.0))
            return FG_ERR_ARGUMENT;
    }
    return FG_OK;
}

/* Directions and their samples; *floats gets the total sample count. */
static fg_result check_directions(const fg_aero_texture_desc *d, size_t *floats)
{
    if (d->directions < 1 || d->directions > FG_AERO_MAX_DIRECTIONS)
        return FG_ERR_ARGUMENT;
    if (d->rotation_order == 0 && d->directions != 1)
        return FG_ERR_ARGUMENT;
    if (!d->direction)
        return FG_ERR_NULL;
    double lo, span;
    fg_aero_symmetry_range(d->rotation_order, d->mirror, d->mirror_angle_rad, &lo, &span);
    const double slack = 1e-9;
    size_t total = 0;
    for (uint32_t i = 0; i < d->directions; i++) {
        const fg_aero_direction *r = &d->direction[i];
        double v[] = {r->angle_rad, r->frontal_m, r->frequency_hz, r->strouhal,
                      r->lift_amplitude, r->drag_mean, r->transient_s};
        for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
            if (!isfinite(v[k]))
                return FG_ERR_NOT_FINITE;
        int in_range = d->rotation_order == 0
                           ? r->angle_rad == 0.0
                           : r->angle_rad >= lo - slack &&
                                 (d->mirror ? r->angle_rad <= lo + span + slack
                                            : r->angle_rad < lo + span - slack);
        if (!in_range || (i > 0 && !(r->angle_rad > d->direction[i - 1].angle_rad)))
            return FG_ERR_ARGUMENT;
        if (!(r->frontal_m > 0.0) || r->frequency_hz < 0.0 || r->lift_amplitude < 0.0 ||
            r->transient_s < 0.0 || (r->periods < 1 && r->frequency_hz != 0.0) || r->frames < 1 ||
            r->frames > FG_AERO_MAX_FRAMES)
            return FG_ERR_ARGUMENT;
        if (!r->samples)
            return FG_ERR_NULL;
        size_t n = (size_t)r->frames * d->sources * d->components;
        for (size_t k = 0; k < n; k++)
            if (!isfinite(r->samples[k]))
                return FG_ERR_NOT_FINITE;
        total += n;
    }
    *floats = total;
    return FG_OK;
}

static fg_result check(const fg_aero_texture_desc *d, size_t *floats)
{
    if ((unsigned)d->tone > FG_AERO_CAVITY)
        return FG_ERR_ARGUMENT;
    int dims = shape_dims(d->shape);
    if (dims == 0 || d->dims != (uint32_t)dims || d->components != d->dims)
        return FG_ERR_ARGUMENT;
    fg_result r = check_shape(d);
    if (r == FG_OK)
        r = check_scalars(d);
    if (r == FG_OK)
        r = check_sources(d);
    if (r == FG_OK)
        r = check_directions(d, floats);
    return r;
}

fg_result fg_aero_texture_create(const fg_aero_texture_desc *d, fg_aero_texture **out)
{
    if (!d || !out)
        return FG_ERR_NULL;
    size_t floats = 0;
    fg_result r = check(d, &floats);
    if (r != FG_OK)
        return r;
    fg_aero_texture *t = calloc(1, sizeof *t);
    if (!t)
        return FG_ERR_NO_MEMORY;
    t->desc = *d;
    size_t pv = d->shape == FG_AERO_POLYGON ? 2 * (size_t)d->polygon_vertices : 0;
    t->polygon = pv ? malloc(pv * sizeof(double)) : NULL;
    t->source = malloc(d->sources * sizeof *t->source);
    t->direction = malloc(d->directions * sizeof *t->direction);
    t->samples = malloc(floats * sizeof(float));
    if ((pv && !t->polygon) || !t->source || !t->direction || !t->samples) {
        fg_aero_texture_destroy(t);
        return FG_ERR_NO_MEMORY;
    }
    if (pv)
        memcpy(t->polygon, d->polygon_xy, pv * sizeof(double));
    else
        t->desc.polygon_vertices = 0;
    memcpy(t->source, d->source, d->sources * sizeof *t->source);
    float *s = t->samples;
    for (uint32_t i = 0; i < d->directions; i++) {
        t->direction[i] = d->direction[i];
        size_t n = (size_t)d->direction[i].frames * d->sources * d->components;
        memcpy(s, d->direction[i].samples, n * sizeof(float));
        t->direction[i].samples = s;
        s += n;
    }
    t->desc.polygon_xy = t->polygon;
    t->desc.source = t->source;
    t->desc.direction = t->direction;
    *out = t;
    return FG_OK;
}

void fg_aero_texture_destroy(fg_aero_texture *t)
{
    if (!t)
        return;
    free(t->polygon);
    free(t->source);
    free(t->direction);
    free(t->samples);
    free(t);
}

const fg_aero_texture_desc *fg_aero_texture_get(const fg_aero_texture *t)
{
    return &t->desc;
}

void fg_aero_texture_lookup(const fg_aero_texture *t, double angle, fg_aero_lookup *out)
{
    const fg_aero_texture_desc *d = &t->desc;
    const fg_aero_direction *dir = d->direction;
    uint32_t n = d->directions;
    int flip = 0;
    double a = isfinite(angle) ? fg_aero_symmetry_map(d->rotation_order, d->mirror,
                                                      d->mirror_angle_rad, angle, &flip)
                               : dir[0].angle_rad;
    out->lift_sign = flip ? -1.0f : 1.0f;
    out->index[0] = out->index[1] = 0;
    out->weight[0] = 1.0f;
    out->weight[1] = 0.0f;
    if (n == 1)
        return;
    double lo, span;
    fg_aero_symmetry_range(d->rotation_order, d->mirror, d->mirror_angle_rad, &lo, &span);
    uint32_t i0, i1;
    double a0, a1;
    if (a < dir[0].angle_rad || a >= dir[n - 1].angle_rad) {
        if (d->mirror) { /* a closed range: hold the nearer end */
            out->index[0] = out->index[1] = a < dir[0].angle_rad ? 0 : n - 1;
            return;
        }
        /* periodic: between the last and the first, one period on */
        i0 = n - 1;
        i1 = 0;
        a0 = dir[n - 1].angle_rad;
        a1 = dir[0].angle_rad + span;
        if (a < dir[0].angle_rad)
            a += span;
    } else {
        uint32_t l = 0, h = n - 1; /* dir[l] <= a < dir[h] */
        while (h - l > 1) {
            uint32_t m = (l + h) / 2;
            if (dir[m].angle_rad <= a)
                l = m;
            else
                h = m;
        }
        i0 = l;
        i1 = h;
        a0 = dir[l].angle_rad;
        a1 = dir[h].angle_rad;
    }
    double w = (a - a0) / (a1 - a0);
    w = w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
    out->index[0] = i0;
    out->index[1] = i1;
    out->weight[0] = (float)(1.0 - w);
    out->weight[1] = (float)w;
}

double fg_aero_pressure_scale(const fg_aero_texture *t, double speed)
{
    if (!(speed > 0.0) || !isfinite(speed))
        return 0.0;
    double r = speed / t->desc.speed_m_s;
    return t->desc.tone == FG_AERO_CAVITY ? r * r : r * r * r;
}
