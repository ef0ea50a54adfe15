/* Training (section 5.1-5.2): G_T, the dictionaries and their trees. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pyramid_internal.h"
#include "texture_internal.h"

#define MIN_RATE_HZ 8000.0
#define MAX_RATE_HZ 384000.0

static void fill_defaults(fg_fire_texture_config *c)
{
    if (c->levels == 0)
        c->levels = 6;
    if (c->half_width == 0)
        c->half_width = 4;
    if (c->feature_multiplier == 0)
        c->feature_multiplier = 3;
    if (c->epsilon == 0.0)
        c->epsilon = 1.0;
    else if (c->epsilon < 0.0)
        c->epsilon = 0.0;
    if (c->max_bytes == 0)
        c->max_bytes = FG_FIRE_TEXTURE_DEFAULT_MAX_BYTES;
}

/* Windows i of level l (n samples, the coarser level nc) whose feature and
 * value lie inside the pyramid: c = i h >= 2 h h_f, c + h < n, and
 * c/2 + h h_f (rounded up) < nc. */
static void window_range(const fg_texture_shape *s, size_t n, size_t nc, size_t *first,
                         size_t *count)
{
    size_t h = (size_t)s->h, span = (size_t)(s->h * s->hf);
    size_t i0 = (2 * span + h - 1) / h, i = i0;
    while (i * h + h < n && (i * h + 1) / 2 + span < nc)
        i++;
    *first = i0;
    *count = i > i0 ? i - i0 : 0;
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void fg_fire_texture_destroy(fg_fire_texture *t)
{
    if (!t)
        return;
    for (int l = 0; l < FG_TEXTURE_MAX_LEVELS - 1; l++) {
        free(t->dict[l].values);
        fg_kdtree_free(&t->dict[l].tree);
    }
    free(t->amplitudes);
    free(t);
}

static void free_levels(double **g, int levels)
{
    for (int l = 0; l < levels; l++)
        free(g[l]);
}

fg_result fg_fire_texture_create(const fg_fire_texture_config *config, fg_fire_texture **out)
{
    if (!config || !out)
        return FG_ERR_NULL;
    *out = NULL;
    if (!config->samples)
        return FG_ERR_NULL;
    fg_fire_texture_config c = *config;
    c.samples = NULL;
    fill_defaults(&c);
    if (!isfinite(c.sample_rate_hz) || !isfinite(c.epsilon))
        return FG_ERR_NOT_FINITE;
    if (c.sample_rate_hz < MIN_RATE_HZ || c.sample_rate_hz > MAX_RATE_HZ)
        return FG_ERR_SAMPLE_RATE;
    double seconds = (double)c.frames / c.sample_rate_hz;
    if (seconds < FG_FIRE_TRAINING_MIN_S || seconds > FG_FIRE_TRAINING_MAX_S)
        return FG_ERR_ARGUMENT;
    if (c.levels < 2 || c.levels > FG_TEXTURE_MAX_LEVELS || c.half_width < 1 ||
        c.half_width > 16 || c.feature_multiplier < 1 || c.feature_multiplier > 8)
        return FG_ERR_ARGUMENT;
    for (size_t i = 0; i < c.frames; i++)
        if (!isfinite(config->samples[i]))
            return FG_ERR_NOT_FINITE;

    fg_texture_shape shape;
    fg_texture_shape_init(&shape, c.levels, c.half_width, c.feature_multiplier);
    int L = c.levels;
    size_t len[FG_TEXTURE_MAX_LEVELS], first[FG_TEXTURE_MAX_LEVELS], count[FG_TEXTURE_MAX_LEVELS];
    len[0] = c.frames;
    for (int l = 1; l < L; l++)
        len[l] = fg_pyramid_reduced_length(len[l - 1]);
    size_t bytes = sizeof(fg_fire_texture) + len[L - 1] * sizeof(double);
    for (int l = 0; l + 1 < L; l++) {
        window_range(&shape, len[l], len[l + 1], &first[l], &count[l]);
        if (count[l] == 0)
            return FG_ERR_ARGUMENT;
        bytes += count[l] * (size_t)shape.value_len * sizeof(float) +
                 fg_kdtree_bytes(count[l], (size_t)shape.dims);
    }
    if (bytes > c.max_bytes)
        return FG_ERR_CAPACITY;

    /* G_T */
    double *g[FG_TEXTURE_MAX_LEVELS] = {0};
    for (int l = 0; l < L; l++)
        if (!(g[l] = malloc(sizeof(double) * len[l]))) {
            free_levels(g, L);
            return FG_ERR_NO_MEMORY;
        }
    for (size_t i = 0; i < c.frames; i++)
        g[0][i] = config->samples[i];
    for (int l = 1; l < L; l++)
        fg_pyramid_reduce(g[l - 1], len[l - 1], g[l]);

    fg_fire_texture *t = calloc(1, sizeof *t);
    float *features = NULL;
    if (!t)
        goto no_memory;
    t->config = c;
    t->shape = shape;
    t->bytes = bytes;

    /* F_T: the amplitudes of the coarsest level */
    t->amplitude_count = len[L - 1];
    if (!(t->amplitudes = malloc(sizeof(double) * len[L - 1])))
        goto no_memory;
    double mean = 0.0;
    for (size_t i = 0; i < len[L - 1]; i++) {
        t->amplitudes[i] = fabs(g[L - 1][i]);
        mean += t->amplitudes[i] / (double)len[L - 1];
    }
    if (!(mean > 0.0)) {
        free_levels(g, L);
        fg_fire_texture_destroy(t);
        return FG_ERR_ARGUMENT;
    }
    qsort(t->amplitudes, len[L - 1], sizeof(double), compare_double);
    /* a quiet training moment mapped from a loud input must not divide by
     * zero (eq. 17's inverse, the output gain) */
    t->amplitude_floor = 1e-3 * mean;

    /* D_1 .. D_{L-1} */
    for (int l = 0; l + 1 < L; l++) {
        fg_texture_dictionary *d = &t->dict[l];
        size_t dims = (size_t)shape.dims, vlen = (size_t)shape.value_len;
        features = malloc(sizeof(float) * count[l] * dims);
        d->values = malloc(sizeof(float) * count[l] * vlen);
        if (!features || !d->values)
            goto no_memory;
        d->count = count[l];
        fg_level_view fine = {.data = g[l], .mask = UINT64_MAX, .first = 0};
        fg_level_view coarse = {.data = g[l + 1], .mask = UINT64_MAX, .first = 0};
        for (size_t w = 0; w < count[l]; w++) {
            int64_t centre = (int64_t)((first[l] + w) * (size_t)shape.h);
            fg_texture_feature(&shape, &fine, &coarse, centre, 1.0, features + w * dims);
            for (size_t m = 0; m < vlen; m++)
                d->values[w * vlen + m] = (float)g[l][centre - shape.h + (int64_t)m];
        }
        if (!fg_kdtree_build(&d->tree, features, count[l], dims))
            goto no_memory;
        free(features);
        features = NULL;
    }
    free_levels(g, L);
    *out = t;
    return FG_OK;

no_memory:
    free(features);
    free_levels(g, L);
    fg_fire_texture_destroy(t);
    return FG_ERR_NO_MEMORY;
}

fg_result fg_fire_texture_create_default(double sample_rate_hz, fg_fire_texture **out)
{
    if (!out)
        return FG_ERR_NULL;
    *out = NULL;
    if (!isfinite(sample_rate_hz) || sample_rate_hz < MIN_RATE_HZ || sample_rate_hz > MAX_RATE_HZ)
        return FG_ERR_SAMPLE_RATE;
    size_t frames = (size_t)ceil(FG_FIRE_DEFAULT_TRAINING_S * sample_rate_hz);
    float *clip = malloc(sizeof(float) * frames);
    if (!clip)
        return FG_ERR_NO_MEMORY;
    fg_result r = fg_fire_training_clip(sample_rate_hz, 1, clip, frames);
    if (r == FG_OK) {
        fg_fire_texture_config c = {.samples = clip, .frames = frames,
                                    .sample_rate_hz = sample_rate_hz};
        r = fg_fire_texture_create(&c, out);
    }
    free(clip);
    return r;
}

void fg_fire_texture_get_info(const fg_fire_texture *t, fg_fire_texture_info *out)
{
    assert(t && out);
    *out = (fg_fire_texture_info){.config = t->config, .feature_dims = t->shape.dims,
                                  .bytes = t->bytes};
    for (int l = 0; l + 1 < t->shape.levels; l++)
        out->dictionary[l] = t->dict[l].count;
}
