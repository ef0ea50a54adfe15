/* The flux-series stream: Mitchell-Netravali, high-pass, extension. */
#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "bwe_internal.h"
#include "highpass_internal.h"
#include "mitchell_internal.h"
#include "texture_synth_internal.h"
#include "fulgur/fire.h"

#define MIN_RATE_HZ 8000.0
#define MAX_RATE_HZ 384000.0
/* Table 1 is for a 360 Hz simulation; its frequencies scale with the rate. */
#define TABLE1_SIM_HZ 360.0

struct fg_fire_sound {
    fg_fire_sound_config config;
    fg_mn_stream mn;
    fg_iir highpass;
    int use_highpass;
    fg_bwe bwe;
    fg_texture_synth synth;
    double *p;            /* one step's p, double and float */
    float *pf;
    size_t p_cap;
    size_t extension_latency;
    int drained;
    fg_fire_sound_stats stats;
};

static double def(double v, double d)
{
    return v == 0.0 ? d : v;
}

static void fill_defaults(fg_fire_sound_config *c)
{
    c->sample_rate_hz = def(c->sample_rate_hz, 48000.0);
    c->sim_rate_hz = def(c->sim_rate_hz, TABLE1_SIM_HZ);
    c->highpass_hz = def(c->highpass_hz, 30.0);
    c->level_history_s = def(c->level_history_s, 10.0);
    double k = c->sim_rate_hz / TABLE1_SIM_HZ;
    fg_fire_bwe_config *b = &c->bwe;
    b->alpha = def(b->alpha, 3.0);
    b->f_cut_hz = def(b->f_cut_hz, 180.0 * k);
    b->sigma_cut_hz = def(b->sigma_cut_hz, 10.0 * k);
    b->blend_low_hz = def(b->blend_low_hz, 165.0 * k);
    b->blend_high_hz = def(b->blend_high_hz, 195.0 * k);
    /* the windows in frames only from a rate check() accepts: a NaN or
     * huge one would overflow the conversion to int (UBSan) */
    if (!(c->sample_rate_hz >= MIN_RATE_HZ && c->sample_rate_hz <= MAX_RATE_HZ))
        return;
    if (b->half_window_frames == 0)
        b->half_window_frames = (int)lround(500.0 * c->sample_rate_hz / 44100.0);
    /* an analysis window of 1 / sigma_cut: one that resolves g */
    if (b->beta_half_window_frames == 0 && b->sigma_cut_hz > 0.0 && isfinite(b->sigma_cut_hz)) {
        double a = round(c->sample_rate_hz / b->sigma_cut_hz);
        b->beta_half_window_frames =
            a < b->half_window_frames ? b->half_window_frames : a > 524288.0 ? 524288 : (int)a;
    }
}

static fg_result check(const fg_fire_sound_config *c)
{
    const fg_fire_bwe_config *b = &c->bwe;
    double values[] = {c->sample_rate_hz, c->sim_rate_hz, c->highpass_hz, c->level_history_s,
                       b->alpha, b->f_cut_hz, b->sigma_cut_hz, b->blend_low_hz,
                       b->blend_high_hz};
    for (size_t i = 0; i < sizeof values / sizeof values[0]; i++)
        if (!isfinite(values[i]))
            return FG_ERR_NOT_FINITE;
    double fs = c->sample_rate_hz, nyquist = fs / 2.0;
    if (fs < MIN_RATE_HZ || fs > MAX_RATE_HZ)
        return FG_ERR_SAMPLE_RATE;
    if (c->sim_rate_hz < 10.0 || c->sim_rate_hz > fs / 4.0 || c->highpass_hz >= nyquist ||
        c->level_history_s <= 0.0 || c->level_history_s > 3600.0)
        return FG_ERR_ARGUMENT;
    switch (c->extension) {
    case FG_FIRE_BANDWIDTH_EXTENSION:
        if (b->alpha < 0.5 || b->alpha > 6.0 || b->sigma_cut_hz <= 0.0 ||
            !(0.0 < b->blend_low_hz && b->blend_low_hz < b->f_cut_hz &&
              b->f_cut_hz < b->blend_high_hz && b->blend_high_hz < nyquist) ||
            b->half_window_frames < 16 || b->half_window_frames > 65536 ||
            b->beta_half_window_frames < b->half_window_frames ||
            b->beta_half_window_frames > 524288)
            return FG_ERR_ARGUMENT;
        break;
    case FG_FIRE_TEXTURE:
        if (!c->texture || c->texture->config.sample_rate_hz != fs)
            return FG_ERR_ARGUMENT;
        break;
    case FG_FIRE_LOW_ONLY:
        break;
    default:
        return FG_ERR_ARGUMENT;
    }
    return FG_OK;
}

fg_result fg_fire_sound_create(const fg_fire_sound_config *config, fg_fire_sound **out)
{
    if (!config || !out)
        return FG_ERR_NULL;
    *out = NULL;
    fg_fire_sound_config c = *config;
    fill_defaults(&c);
    fg_result r = check(&c);
    if (r != FG_OK)
        return r;
    fg_fire_sound *s = calloc(1, sizeof *s);
    if (!s)
        return FG_ERR_NO_MEMORY;
    s->config = c;
    fg_mn_init(&s->mn, c.sim_rate_hz, c.sample_rate_hz);
    s->p_cap = fg_mn_max_frames_per_step(&s->mn);
    s->p = malloc(sizeof(double) * s->p_cap);
    s->pf = malloc(sizeof(float) * s->p_cap);
    bool ok = s->p && s->pf;
    if (c.extension == FG_FIRE_BANDWIDTH_EXTENSION && ok) {
        fg_bwe_params p = {
            .sample_rate_hz = c.sample_rate_hz,
            .alpha = c.bwe.alpha,
            .f_cut_hz = c.bwe.f_cut_hz,
            .sigma_cut_hz = c.bwe.sigma_cut_hz,
            .blend_low_hz = c.bwe.blend_low_hz,
            .blend_high_hz = c.bwe.blend_high_hz,
            .half_window = c.bwe.half_window_frames,
            .beta_half_window = c.bwe.beta_half_window_frames,
            .seed = c.bwe.seed,
        };
        ok = fg_bwe_init(&s->bwe, &p);
        if (ok)
            s->extension_latency = fg_bwe_latency(&s->bwe);
    } else if (c.extension == FG_FIRE_TEXTURE && ok) {
        ok = fg_texture_synth_init(&s->synth, c.texture, c.level_history_s);
        if (ok)
            s->extension_latency = fg_texture_synth_latency(&s->synth);
    }
    if (!ok) {
        fg_fire_sound_destroy(s);
        return FG_ERR_NO_MEMORY;
    }
    fg_fire_sound_reset(s);
    *out = s;
    return FG_OK;
}

void fg_fire_sound_destroy(fg_fire_sound *s)
{
    if (!s)
        return;
    if (s->config.extension == FG_FIRE_BANDWIDTH_EXTENSION)
        fg_bwe_deinit(&s->bwe);
    else if (s->config.extension == FG_FIRE_TEXTURE)
        fg_texture_synth_deinit(&s->synth);
    free(s->p);
    free(s->pf);
    free(s);
}

void fg_fire_sound_get_config(const fg_fire_sound *s, fg_fire_sound_config *out)
{
    assert(s && out);
    *out = s->config;
}

void fg_fire_sound_reset(fg_fire_sound *s)
{
    fg_mn_init(&s->mn, s->config.sim_rate_hz, s->config.sample_rate_hz);
    s->use_highpass = s->config.highpass_hz > 0.0;
    if (s->use_highpass)
        fg_fire_highpass_design(&s->highpass, s->config.highpass_hz, s->config.sample_rate_hz);
    if (s->config.extension == FG_FIRE_BANDWIDTH_EXTENSION)
        fg_bwe_reset(&s->bwe);
    else if (s->config.extension == FG_FIRE_TEXTURE)
        fg_texture_synth_reset(&s->synth);
    s->drained = 0;
    s->stats = (fg_fire_sound_stats){0};
}

/* Mitchell-Netravali's 2 steps, in frames, plus the extension's. */
static double latency_frames(const fg_fire_sound *s)
{
    return 2.0 * s->config.sample_rate_hz / s->config.sim_rate_hz + (double)s->extension_latency;
}

double fg_fire_sound_latency_s(const fg_fire_sound *s)
{
    assert(s);
    return latency_frames(s) / s->config.sample_rate_hz;
}

size_t fg_fire_sound_max_frames(const fg_fire_sound *s, size_t steps)
{
    assert(s);
    /* the extension holds back at most its latency, so it never returns
     * more than it took plus that; saturates rather than wraps */
    if (steps > (SIZE_MAX - s->extension_latency) / s->p_cap)
        return SIZE_MAX;
    return steps * s->p_cap + s->extension_latency;
}

/* Hold steps that drain the stream: the latency, in steps, and margin. */
static size_t drain_steps(const fg_fire_sound *s)
{
    return (size_t)ceil(latency_frames(s) * s->config.sim_rate_hz / s->config.sample_rate_hz) + 3;
}

size_t fg_fire_sound_drain_frames(const fg_fire_sound *s)
{
    return fg_fire_sound_max_frames(s, drain_steps(s));
}

static size_t one_step(fg_fire_sound *s, double flux, float *out)
{
    size_t n = fg_mn_push(&s->mn, flux, s->p);
    for (size_t k = 0; k < n; k++)
        s->pf[k] = (float)s->p[k];
    if (s->use_highpass)
        fg_iir_process(&s->highpass, s->pf, n);
    switch (s->config.extension) {
    case FG_FIRE_BANDWIDTH_EXTENSION:
        return fg_bwe_push(&s->bwe, s->pf, n, out);
    case FG_FIRE_TEXTURE:
        return fg_texture_synth_push(&s->synth, s->pf, n, out);
    default:
        memcpy(out, s->pf, sizeof(float) * n);
        return n;
    }
}

static void update_stats(fg_fire_sound *s)
{
    if (s->config.extension == FG_FIRE_BANDWIDTH_EXTENSION) {
        s->stats.windows = s->bwe.stats.windows;
        s->stats.beta_degenerate = s->bwe.stats.degenerate;
        s->stats.beta_no_root = s->bwe.stats.no_root;
        s->stats.last_beta = s->bwe.stats.last_beta;
    } else if (s->config.extension == FG_FIRE_TEXTURE) {
        s->stats.texture_queries = s->synth.stats.queries;
        s->stats.texture_silent = s->synth.stats.silent;
    }
}

fg_result fg_fire_sound_process(fg_fire_sound *s, const double *flux_m3_s, size_t steps,
                                float *out, size_t capacity, size_t *frames)
{
    if (!s || !frames)
        return FG_ERR_NULL;
    *frames = 0;
    if ((!flux_m3_s && steps > 0) || (!out && capacity > 0))
        return FG_ERR_NULL;
    if (s->drained)
        return FG_ERR_ARGUMENT;
    for (size_t i = 0; i < steps; i++) {
        if (!isfinite(flux_m3_s[i]))
            return FG_ERR_NOT_FINITE;
        if (fabs(flux_m3_s[i]) > FG_FIRE_MAX_FLUX_M3_S)
            return FG_ERR_ARGUMENT;
    }
    if (capacity < fg_fire_sound_max_frames(s, steps))
        return FG_ERR_CAPACITY;
    size_t made = 0;
    for (size_t i = 0; i < steps; i++)
        made += one_step(s, flux_m3_s[i], out + made);
    s->stats.flux_steps += steps;
    s->stats.frames += made;
    update_stats(s);
    *frames = made;
    return FG_OK;
}

fg_result fg_fire_sound_drain(fg_fire_sound *s, float *out, size_t capacity, size_t *frames)
{
    if (!s || !frames)
        return FG_ERR_NULL;
    *frames = 0;
    if (!out && capacity > 0)
        return FG_ERR_NULL;
    if (s->drained)
        return FG_ERR_ARGUMENT;
    if (capacity < fg_fire_sound_drain_frames(s))
        return FG_ERR_CAPACITY;
    s->drained = 1;
    uint64_t taken = s->stats.flux_steps;
    if (taken == 0)
        return FG_OK;
    /* every frame up to the time of the last flux sample */
    double last_t = (double)(taken - 1) / s->config.sim_rate_hz;
    uint64_t target = (uint64_t)floor(last_t * s->config.sample_rate_hz) + 1;
    double hold = s->mn.flux[(taken - 1) % FG_MN_HISTORY];
    size_t made = 0;
    for (size_t i = 0, n = drain_steps(s); i < n; i++)
        made += one_step(s, hold, out + made);
    uint64_t before = s->stats.frames;
    size_t keep = target > before ? (size_t)(target - before) : 0;
    if (keep > made)
        keep = made;
    s->stats.frames += keep;
    update_stats(s);
    *frames = keep;
    return FG_OK;
}

void fg_fire_sound_get_stats(const fg_fire_sound *s, fg_fire_sound_stats *out)
{
    assert(s && out);
    *out = s->stats;
}
