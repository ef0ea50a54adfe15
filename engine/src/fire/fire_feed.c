/* Feeding a fire voice from a flux series: fg_fire_sound on the sim
 * thread, its p = dI/dt scaled to pascals at 1 m, pushed into the voice's
 * ring; what the ring cannot take yet waits in the feed. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "fg_math.h"
#include "fulgur/fire_voice.h"

#define DEFAULT_STEPS 64
#define MAX_STEPS 65536
#define DRY_AIR_J_KG_K 287.05 /* the specific gas constant of dry air */

struct fg_fire_feed {
    fg_fire_sound *sound;
    double sample_rate_hz;
    size_t max_steps;
    float *pending;      /* frames computed, not yet pushed: [first, count) */
    size_t first, count, capacity;
    bool drained;
};

double fg_fire_pascals_per_flux_rate(const fg_engine_config *cfg)
{
    double t = cfg && cfg->air_temperature_k > 0.0 ? cfg->air_temperature_k : 293.15;
    double p = cfg && cfg->air_pressure_kpa > 0.0 ? cfg->air_pressure_kpa : 101.325;
    return p * 1e3 / (DRY_AIR_J_KG_K * t) / (4.0 * FG_PI);
}

fg_result fg_fire_feed_create(const fg_fire_sound_config *config, size_t max_steps,
                              fg_fire_feed **out)
{
    if (!config || !out)
        return FG_ERR_NULL;
    if (max_steps > MAX_STEPS)
        return FG_ERR_ARGUMENT;
    fg_fire_feed *f = calloc(1, sizeof *f);
    if (!f)
        return FG_ERR_NO_MEMORY;
    fg_result r = fg_fire_sound_create(config, &f->sound);
    if (r != FG_OK) {
        free(f);
        return r;
    }
    fg_fire_sound_config used;
    fg_fire_sound_get_config(f->sound, &used);
    f->sample_rate_hz = used.sample_rate_hz;
    f->max_steps = max_steps ? max_steps : DEFAULT_STEPS;
    size_t a = fg_fire_sound_max_frames(f->sound, f->max_steps);
    size_t b = fg_fire_sound_drain_frames(f->sound);
    f->capacity = a > b ? a : b;
    f->pending = malloc(f->capacity * sizeof *f->pending);
    if (!f->pending) {
        fg_fire_sound_destroy(f->sound);
        free(f);
        return FG_ERR_NO_MEMORY;
    }
    *out = f;
    return FG_OK;
}

void fg_fire_feed_destroy(fg_fire_feed *f)
{
    if (!f)
        return;
    fg_fire_sound_destroy(f->sound);
    free(f->pending);
    free(f);
}

double fg_fire_feed_latency_s(const fg_fire_feed *f)
{
    return fg_fire_sound_latency_s(f->sound);
}

size_t fg_fire_feed_pending(const fg_fire_feed *f)
{
    return f->count - f->first;
}

/* Pushes what is pending; returns FG_OK with nothing left, or an error. */
static fg_result flush(fg_fire_feed *f, fg_engine *e, fg_voice_id id)
{
    size_t pushed = 0;
    fg_result r = fg_fire_voice_push(e, id, f->pending + f->first, f->count - f->first, &pushed);
    if (r != FG_OK)
        return r;
    f->first += pushed;
    if (f->first == f->count)
        f->first = f->count = 0;
    return FG_OK;
}

/* The engine's pascals per unit of p, or 0 when its rate is not the
 * sound's. */
static double scale_for(const fg_fire_feed *f, const fg_engine *e)
{
    fg_engine_config cfg;
    fg_engine_get_config(e, &cfg);
    return cfg.sample_rate_hz == f->sample_rate_hz ? fg_fire_pascals_per_flux_rate(&cfg) : 0.0;
}

/* Scales the frames just computed, [count, count + n), and keeps them. */
static void keep(fg_fire_feed *f, size_t n, double scale)
{
    for (size_t i = 0; i < n; i++)
        f->pending[f->count + i] = (float)(f->pending[f->count + i] * scale);
    f->count += n;
}

fg_result fg_fire_feed_push(fg_fire_feed *f, fg_engine *e, fg_voice_id id,
                            const double *flux, size_t steps, size_t *taken)
{
    if (taken)
        *taken = 0;
    if (!f || !e || !taken || (!flux && steps > 0))
        return FG_ERR_NULL;
    double scale = scale_for(f, e);
    if (scale == 0.0)
        return FG_ERR_SAMPLE_RATE;
    for (size_t i = 0; i < steps; i++) {
        if (!isfinite(flux[i]))
            return FG_ERR_NOT_FINITE;
        if (fabs(flux[i]) > FG_FIRE_MAX_FLUX_M3_S)
            return FG_ERR_ARGUMENT;
    }
    fg_result r = flush(f, e, id);
    size_t done = 0;
    while (r == FG_OK && f->count == 0 && done < steps) {
        size_t n = steps - done < f->max_steps ? steps - done : f->max_steps;
        size_t frames = 0;
        r = fg_fire_sound_process(f->sound, flux + done, n, f->pending, f->capacity, &frames);
        if (r != FG_OK)
            break;
        done += n;
        keep(f, frames, scale);
        r = flush(f, e, id);
    }
    *taken = done;
    return r;
}

fg_result fg_fire_feed_finish(fg_fire_feed *f, fg_engine *e, fg_voice_id id, bool *done)
{
    if (done)
        *done = false;
    if (!f || !e || !done)
        return FG_ERR_NULL;
    double scale = scale_for(f, e);
    if (scale == 0.0)
        return FG_ERR_SAMPLE_RATE;
    fg_result r = flush(f, e, id);
    if (r != FG_OK)
        return r;
    if (!f->drained && f->count == 0) {
        size_t frames = 0;
        r = fg_fire_sound_drain(f->sound, f->pending, f->capacity, &frames);
        if (r != FG_OK)
            return r;
        f->drained = true;
        keep(f, frames, scale);
        r = flush(f, e, id);
        if (r != FG_OK)
            return r;
    }
    if (f->drained && f->count == 0) {
        r = fg_fire_voice_close(e, id);
        *done = r == FG_OK;
    }
    return r;
}
