#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "texture_synth_internal.h"

#define GAIN_RING 1024

static int64_t span_of(const fg_texture_shape *s)
{
    return (int64_t)s->h * s->hf;
}

bool fg_texture_synth_init(fg_texture_synth *s, const fg_fire_texture *texture,
                           double level_history_s)
{
    memset(s, 0, sizeof *s);
    s->texture = texture;
    s->shape = texture->shape;
    s->epsilon = texture->config.epsilon;
    uint64_t ring = 1;
    while (ring < (uint64_t)(8 * (2 * span_of(&s->shape) + 4 * s->shape.h)))
        ring *= 2;
    s->ring_mask = ring - 1;
    s->gain_mask = GAIN_RING - 1;
    double coarse_rate = texture->config.sample_rate_hz / (double)(1u << (s->shape.levels - 1));
    s->history_cap = (size_t)ceil(level_history_s * coarse_rate);
    if (s->history_cap < 1)
        s->history_cap = 1;
    bool ok = true;
    for (int l = 0; l < s->shape.levels; l++)
        ok = ok && (s->ring[l] = malloc(sizeof(double) * ring));
    ok = ok && (s->gain = malloc(sizeof(double) * GAIN_RING));
    ok = ok && (s->history_sorted = malloc(sizeof(double) * s->history_cap));
    ok = ok && (s->history_fifo = malloc(sizeof(double) * s->history_cap));
    if (!ok) {
        fg_texture_synth_deinit(s);
        return false;
    }
    fg_texture_synth_reset(s);
    return true;
}

void fg_texture_synth_deinit(fg_texture_synth *s)
{
    for (int l = 0; l < FG_TEXTURE_MAX_LEVELS; l++)
        free(s->ring[l]);
    free(s->gain);
    free(s->history_sorted);
    free(s->history_fifo);
    memset(s, 0, sizeof *s);
}

void fg_texture_synth_reset(fg_texture_synth *s)
{
    for (int l = 0; l < s->shape.levels; l++) {
        s->complete[l] = s->written[l] = 0;
        if (l + 1 < s->shape.levels) {
            fg_reducer_reset(&s->reducer[l]);
            s->next_window[l] = 0;
        }
    }
    s->emitted = 0;
    s->history_len = s->history_head = 0;
    s->stats = (fg_texture_synth_stats){0};
}

/* F_S: a sliding window of the last history_cap magnitudes, kept sorted. */
static void history_add(fg_texture_synth *s, double v)
{
    double *sorted = s->history_sorted;
    if (s->history_len == s->history_cap) {
        double old = s->history_fifo[s->history_head];
        size_t lo = 0, hi = s->history_len;
        while (lo < hi) {
            size_t mid = lo + (hi - lo) / 2;
            if (sorted[mid] < old)
                lo = mid + 1;
            else
                hi = mid;
        }
        memmove(sorted + lo, sorted + lo + 1, sizeof(double) * (s->history_len - lo - 1));
        s->history_len--;
    }
    size_t lo = 0, hi = s->history_len;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (sorted[mid] <= v)
            lo = mid + 1;
        else
            hi = mid;
    }
    memmove(sorted + lo + 1, sorted + lo, sizeof(double) * (s->history_len - lo));
    sorted[lo] = v;
    s->history_len++;
    s->history_fifo[s->history_head] = v;
    s->history_head = (s->history_head + 1) % s->history_cap;
}

static fg_level_view view(const fg_texture_synth *s, int level_index)
{
    return (fg_level_view){.data = s->ring[level_index], .mask = s->ring_mask, .first = 0};
}

/* Window next_window[l] of level index l (0: the output) can be made
 * once the coarser level is final up to c/2 + h h_f. */
static bool window_ready(const fg_texture_synth *s, int l)
{
    int64_t c = (int64_t)s->next_window[l] * s->shape.h;
    int64_t need = c / 2 + span_of(&s->shape) + (c & 1);
    return s->complete[l + 1] > need;
}

/* eq. 17 for the window centred at c on level L - 1: the scale of its
 * coarse part; *gain = 1 / r, or 0 for silence. */
static double range_scale(fg_texture_synth *s, const fg_level_view *coarse, int64_t c, double *gain)
{
    const fg_fire_texture *t = s->texture;
    double avg = fg_texture_coarse_mean(&s->shape, coarse, c);
    if (!(avg > 0.0)) {
        s->stats.silent++;
        *gain = 0.0;
        return 0.0;
    }
    double q = fg_sorted_cdf(s->history_sorted, s->history_len, avg);
    double train = fg_sorted_quantile(t->amplitudes, t->amplitude_count, q);
    if (train < t->amplitude_floor)
        train = t->amplitude_floor;
    *gain = avg / train;
    return train / avg;
}

static void make_window(fg_texture_synth *s, int l)
{
    const fg_texture_shape *sh = &s->shape;
    int64_t h = sh->h, c = (int64_t)s->next_window[l] * h;
    int coarsest = l + 2 == sh->levels;
    /* the rings hold what is read: the coarse part, and this level from
     * its fine part to the window's end */
    assert(s->complete[l + 1] - (c / 2 - span_of(sh)) <= (int64_t)s->ring_mask + 1);
    assert(2 * span_of(sh) + h < (int64_t)s->ring_mask + 1);
    if (!s->dry) {
        fg_level_view fine = view(s, l), coarse = view(s, l + 1);
        double scale = 1.0, gain = 1.0;
        if (coarsest)
            scale = range_scale(s, &coarse, c, &gain);
        fg_texture_feature(sh, &fine, &coarse, c, scale, s->feature);
        const fg_texture_dictionary *d = &s->texture->dict[l];
        size_t id = fg_kdtree_nearest(&d->tree, s->feature, s->epsilon, NULL);
        s->stats.queries++;
        s->stats.choices = (s->stats.choices ^ (uint64_t)id) * 0x100000001b3u;
        if (coarsest)
            s->gain[s->next_window[l] & s->gain_mask] = gain;
        /* clear the samples this window is the first to touch, then add */
        double *ring = s->ring[l];
        for (int64_t n = s->written[l]; n <= c + h; n++)
            ring[(uint64_t)n & s->ring_mask] = 0.0;
        const float *value = d->values + id * (size_t)sh->value_len;
        for (int64_t m = 0; m <= 2 * h; m++) {
            int64_t n = c - h + m;
            if (n < 0)
                continue;
            double w = (double)(h - llabs(m - h)) / (double)h;
            ring[(uint64_t)n & s->ring_mask] += w * value[m];
        }
    }
    if (s->written[l] < c + h + 1)
        s->written[l] = c + h + 1;
    s->complete[l] = c + 1;
    s->next_window[l]++;
}

/* Output sample n needs the gains of the level-(L-1) windows on either
 * side of it. */
static bool emit_ready(const fg_texture_synth *s, int64_t *i0, double *frac)
{
    if ((int64_t)s->emitted >= s->complete[0])
        return false;
    int64_t hop = (int64_t)s->shape.h << (s->shape.levels - 2);
    *i0 = (int64_t)s->emitted / hop;
    *frac = (double)((int64_t)s->emitted % hop) / (double)hop;
    assert((int64_t)s->next_window[s->shape.levels - 2] - *i0 <= (int64_t)s->gain_mask + 1);
    return (int64_t)s->next_window[s->shape.levels - 2] > *i0 + 1;
}

static size_t advance(fg_texture_synth *s, float *out)
{
    for (int l = s->shape.levels - 2; l >= 0; l--)
        while (window_ready(s, l))
            make_window(s, l);
    size_t made = 0;
    int64_t i0;
    double frac;
    while (emit_ready(s, &i0, &frac)) {
        if (!s->dry) {
            double g0 = s->gain[(uint64_t)i0 & s->gain_mask];
            double g1 = s->gain[(uint64_t)(i0 + 1) & s->gain_mask];
            double y = s->ring[0][s->emitted & s->ring_mask];
            out[made] = (float)((g0 + frac * (g1 - g0)) * y);
        }
        made++;
        s->emitted++;
    }
    return made;
}

/* One input sample through the reducers; a new coarsest sample is stored
 * and enters F_S. */
static void take(fg_texture_synth *s, double x)
{
    int L = s->shape.levels;
    for (int l = 0; l + 1 < L; l++) {
        double y;
        if (!fg_reducer_push(&s->reducer[l], x, &y))
            return;
        x = y;
    }
    if (!s->dry) {
        s->ring[L - 1][(uint64_t)s->complete[L - 1] & s->ring_mask] = x;
        history_add(s, fabs(x));
    }
    s->complete[L - 1]++;
}

size_t fg_texture_synth_push(fg_texture_synth *s, const float *p, size_t n, float *out)
{
    size_t made = 0;
    for (size_t k = 0; k < n; k++) {
        take(s, p ? p[k] : 0.0);
        made += advance(s, out ? out + made : NULL);
    }
    return made;
}

size_t fg_texture_synth_latency(const fg_texture_synth *s)
{
    /* the same ring sizes, so that the rings' span asserts check the
     * schedule too */
    fg_texture_synth dry = {.shape = s->shape, .dry = true, .ring_mask = s->ring_mask,
                            .gain_mask = s->gain_mask};
    /* after a few periods of the schedule (h 2^(L-1) input samples) the
     * lag repeats; take its largest value over many */
    int64_t period = (int64_t)s->shape.h << (s->shape.levels - 1);
    int64_t steps = 64 * period + 8192, worst = 0;
    for (int64_t t = 1; t <= steps; t++) {
        fg_texture_synth_push(&dry, NULL, 1, NULL);
        /* input 0 .. t-1 taken, output 0 .. emitted-1 final */
        int64_t lag = t - (int64_t)dry.emitted;
        if (lag > worst)
            worst = lag;
    }
    return (size_t)worst;
}
