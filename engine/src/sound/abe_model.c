/* Abe et al.'s model: a harmonic-series N-wave per source point, one point
 * per stride segments, rendered sample by sample into the buses' float
 * buffers. */
#include "discharge_schedule.h"

/* Source points per discharge at most, evenly along the tree. */
#define MAX_SOURCES 512

static size_t abe_stride(size_t segments)
{
    return (segments + MAX_SOURCES - 1) / MAX_SOURCES;
}

static void abe_wave(const fg_sound_config *p, const fg_event *ev, const fg_ear_path *path,
                     fg_event_ear *ear)
{
    (void)p;
    fg_abe_wave w;
    fg_abe_wave_init(&w, &fg_abe_defaults, ev->mid, path->ear, 0.0, path->c_m_s);
    ear->abe = (fg_abe_ear){w.f0_hz, w.peak_pa * path->gain, w.gamma};
}

/* The ear's wave, arrival relative to the emission. */
static fg_abe_wave abe_of(const fg_event_ear *ear)
{
    fg_abe_wave w = {.arrival_s = ear->center_s, .f0_hz = ear->abe.f0_hz,
                     .peak_pa = ear->abe.peak_pa, .gamma = ear->abe.gamma, .rate = ear->rate};
    fg_abe_wave_set_decay(&w, &fg_abe_defaults);
    return w;
}

static double abe_start_s(const fg_event *ev, const fg_event_ear *ear, double c_m_s)
{
    (void)ev;
    (void)c_m_s;
    return ear->center_s;
}

static bool abe_finite(const fg_event *ev, const fg_event_ear *ear, double fs_hz, double c_m_s)
{
    (void)ev;
    (void)c_m_s;
    fg_abe_wave w = abe_of(ear);
    return fg_abe_wave_in_range(&w, fs_hz);
}

/* The work bound's price of one path (docs/limits.md): each sample sums
 * the series, harmonics terms, after per-sample exponentials and sines
 * taken as ABE_OVERHEAD_TERMS terms (a judgement: the engine's voice
 * always sums 16 harmonics, so the two parts are not measured apart).
 * bench_work_bound measures a sample of the 16-harmonic series, 32 terms,
 * at about the CPU time of one unit (a WM-wave's evaluation of one ear). */
#define ABE_OVERHEAD_TERMS 16
#define ABE_TERMS_PER_UNIT 32

/* The wave of ear as play's instance places it in the block. */
static fg_abe_wave abe_placed(const fg_event_ear *ear, const fg_event_play *play)
{
    fg_abe_wave w = abe_of(ear);
    w.arrival_s += play->offset_s + play->origin_frame / play->fs_hz;
    return w;
}

static uint64_t abe_path_units(const fg_event_ear *ear, const fg_event_play *play)
{
    fg_abe_wave w = abe_placed(ear, play);
    if (!fg_abe_wave_in_range(&w, play->fs_hz))
        return 0; /* abe_add refuses it before any sample */
    int64_t a, b;
    fg_abe_wave_span(&w, play->fs_hz, &a, &b);
    a = a < 0 ? 0 : a;
    b = b >= (int64_t)play->frames ? (int64_t)play->frames - 1 : b;
    if (b < a)
        return 0;
    uint64_t terms = (uint64_t)(b - a + 1) * (w.harmonics + ABE_OVERHEAD_TERMS);
    return (terms + ABE_TERMS_PER_UNIT - 1) / ABE_TERMS_PER_UNIT;
}

static fg_wave_status abe_place(const fg_event *ev, const fg_event_ear *ear,
                                const fg_event_play *play, fg_wave_place *at)
{
    (void)ev;
    at->abe = abe_placed(ear, play);
    if (!fg_abe_wave_in_range(&at->abe, play->fs_hz))
        return FG_WAVE_NON_FINITE;
    int64_t a, b;
    fg_abe_wave_span(&at->abe, play->fs_hz, &a, &b);
    at->first = (long)a;
    at->last = (long)b;
    return b < 0 ? FG_WAVE_DONE : FG_WAVE_SOUNDING;
}

static fg_wave_status abe_add(const fg_event_ear *ear, const fg_event_play *play,
                              const fg_wave_place *at)
{
    (void)ear;
    const double fs = play->fs_hz;
    fg_abe_wave w = at->abe;
    int64_t a, b;
    fg_abe_wave_span(&w, fs, &a, &b);
    if (a >= (int64_t)play->frames)
        return FG_WAVE_PENDING;
    double peak = w.peak_pa;
    for (unsigned c = 0; c < play->channels; c++) {
        for (int k = 0; k < FG_PLAY_BUSES; k++) {
            if (play->share[k] == 0.0)
                continue;
            w.peak_pa = peak * (play->gain[c] * play->share[k]);
            float *out = fg_bus_pre(play->buses, play->bus[k], play->ch[c]);
            if (!fg_abe_wave_render(&w, fs, 0, out, play->frames))
                return FG_WAVE_NON_FINITE;
        }
    }
    return FG_WAVE_SOUNDING;
}

static bool abe_render(void *voice, bool stopping, const fg_block_context *block)
{
    return fg_discharge_render_with(voice, stopping, block, abe_place, abe_add);
}

static const fg_discharge_model abe_model = {
    .stride = abe_stride,
    .wave = abe_wave,
    .start_s = abe_start_s,
    .finite = abe_finite,
    .path_units = abe_path_units, /* its series, sample by sample */
    .writes_ahead = false,        /* its series into the block's planes */
};

const fg_source_ops fg_source_abe = {
    .name = "abe",
    .kind = &fg_discharge_kind,
    .model = &abe_model,
    .prepare = fg_discharge_prepare,
    .adopt = fg_discharge_adopt,
    .render = abe_render,
    .release = fg_discharge_release,
};
