/* The engine object: creation with the storage of every kind of source,
 * destruction, and the any-thread getters. */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine_internal.h"
#include "fg_big_alloc.h"
#include "fg_prefault.h"
#include "fg_rules.h"
#include "spatial/binaural_internal.h"
#include "spatial/layout_internal.h"

#define MAX_BLOCK_LIMIT 65536u
#define MAX_VOICES_LIMIT 65536u
#define SEGMENT_LIMIT (1u << 26)
#define SETTING_LIMIT 10.0 /* metres of ear spacing, seconds of look-ahead */
#define WORK_LIMIT FG_WORK_PER_FRAME_MAX

/* The defaults, as engine.h documents them. */
static const fg_engine_config defaults = {
    .sample_rate_hz = 48000.0,
    .max_block_frames = 4096,
    .channels = 2,
    .max_voices = 64,
    .segment_capacity = 131072,
    .speed_of_sound_m_s = 343.0,
    .ear_spacing_m = 0.175,
    .max_lookahead_s = 0.25,
    .max_adopt_per_block = 8,
    .air_temperature_k = 293.15,
    .air_humidity_pct = 70.0,
    .air_pressure_kpa = 101.325,
    .work_per_frame = FG_WORK_PER_FRAME_DEFAULT,
};

fg_result fg_engine_config_resolve(const fg_engine_config *in, fg_engine_config *out)
{
    if (!out)
        return FG_ERR_NULL;
    if (!in) {
        *out = defaults;
        return FG_OK;
    }
    if (!isfinite(in->sample_rate_hz) || !isfinite(in->speed_of_sound_m_s) ||
        !isfinite(in->ear_spacing_m) || !isfinite(in->max_lookahead_s) ||
        !isfinite(in->air_temperature_k) || !isfinite(in->air_humidity_pct) ||
        !isfinite(in->air_pressure_kpa))
        return FG_ERR_NOT_FINITE;
    if (in->sample_rate_hz != 0 && (in->sample_rate_hz < FG_SAMPLE_RATE_MIN_HZ ||
                                    in->sample_rate_hz > FG_SAMPLE_RATE_MAX_HZ))
        return FG_ERR_SAMPLE_RATE;
    uint32_t order = 0, channels = FG_DEF(in->channels, defaults.channels);
    switch (in->layout) {
    case FG_LAYOUT_STEREO:
        if (in->ambisonic_order != 0 || channels > 2)
            return FG_ERR_ARGUMENT;
        break;
    case FG_LAYOUT_BINAURAL:
        if (in->ambisonic_order != 0 || (in->channels != 0 && in->channels != 2) || !in->hrirs)
            return FG_ERR_ARGUMENT;
        channels = 2;
        break;
    case FG_LAYOUT_AMBISONICS:
        order = FG_DEF(in->ambisonic_order, FG_AMBISONIC_ORDER_MIN);
        if (order > FG_AMBISONIC_ORDER_MAX)
            return FG_ERR_ARGUMENT;
        channels = fg_ambisonic_channels(order);
        if (in->channels != 0 && in->channels != channels)
            return FG_ERR_ARGUMENT;
        break;
    default:
        return FG_ERR_ARGUMENT;
    }
    if (in->max_block_frames > MAX_BLOCK_LIMIT || in->max_voices > MAX_VOICES_LIMIT ||
        in->segment_capacity > SEGMENT_LIMIT ||
        (in->speed_of_sound_m_s != 0 && (in->speed_of_sound_m_s < FG_SPEED_OF_SOUND_MIN_M_S ||
                                         in->speed_of_sound_m_s > FG_SPEED_OF_SOUND_MAX_M_S)) ||
        in->ear_spacing_m < 0 || in->ear_spacing_m > SETTING_LIMIT ||
        in->work_per_frame > WORK_LIMIT || in->max_lookahead_s < 0 ||
        in->max_lookahead_s > SETTING_LIMIT || in->max_adopt_per_block > MAX_VOICES_LIMIT ||
        in->chunk_frames > MAX_BLOCK_LIMIT ||
        (in->air_temperature_k != 0 &&
         (in->air_temperature_k < 200 || in->air_temperature_k > 350)) ||
        in->air_humidity_pct < 0 || in->air_humidity_pct > 100 ||
        (in->air_pressure_kpa != 0 && (in->air_pressure_kpa < 10 || in->air_pressure_kpa > 200)))
        return FG_ERR_ARGUMENT;
    if (in->layout != FG_LAYOUT_BINAURAL && in->hrirs)
        return FG_ERR_ARGUMENT;
    double fs = FG_DEF(in->sample_rate_hz, defaults.sample_rate_hz);
    if (in->hrirs) {
        fg_result hr = fg_binaural_check(in->hrirs, fs);
        if (hr != FG_OK)
            return hr;
    }
    *out = (fg_engine_config){
        .sample_rate_hz = fs,
        .max_block_frames = FG_DEF(in->max_block_frames, defaults.max_block_frames),
        .channels = channels,
        .max_voices = FG_DEF(in->max_voices, defaults.max_voices),
        .segment_capacity = FG_DEF(in->segment_capacity, defaults.segment_capacity),
        .speed_of_sound_m_s = FG_DEF(in->speed_of_sound_m_s, defaults.speed_of_sound_m_s),
        .ear_spacing_m = FG_DEF(in->ear_spacing_m, defaults.ear_spacing_m),
        .max_lookahead_s = FG_DEF(in->max_lookahead_s, defaults.max_lookahead_s),
        .max_adopt_per_block = FG_DEF(in->max_adopt_per_block, defaults.max_adopt_per_block),
        .air_temperature_k = FG_DEF(in->air_temperature_k, defaults.air_temperature_k),
        .air_humidity_pct = FG_DEF(in->air_humidity_pct, defaults.air_humidity_pct),
        .air_pressure_kpa = FG_DEF(in->air_pressure_kpa, defaults.air_pressure_kpa),
        .work_per_frame = FG_DEF(in->work_per_frame, defaults.work_per_frame),
        .chunk_frames = in->chunk_frames,
        .layout = in->layout,
        .ambisonic_order = order,
        .hrirs = in->hrirs,
    };
    return FG_OK;
}

/* The engine's kind i: the built-in ones, then the caller's kinds[]. */
static const fg_source_kind *kind_at(const fg_source_kind *const *kinds, size_t i)
{
    return i < fg_builtin_kind_count ? fg_builtin_kinds[i] : kinds[i - fg_builtin_kind_count];
}

/* Whether kinds[0..count), after the built-in ones, can be added: each
 * given (FG_ERR_NULL), none twice and at most FG_MAX_SOURCE_KINDS in all
 * (FG_ERR_ARGUMENT); the first that cannot decides. */
static fg_result check_kinds(const fg_source_kind *const *kinds, size_t count)
{
    const fg_source_kind *seen[FG_MAX_SOURCE_KINDS];
    size_t n = 0;
    for (size_t i = 0; i < fg_builtin_kind_count + count; i++) {
        const fg_source_kind *kind = kind_at(kinds, i);
        if (!kind)
            return FG_ERR_NULL;
        if (n == FG_MAX_SOURCE_KINDS)
            return FG_ERR_ARGUMENT;
        for (size_t j = 0; j < n; j++)
            if (seen[j] == kind)
                return FG_ERR_ARGUMENT;
        seen[n++] = kind;
    }
    return FG_OK;
}

/* Where the engine's object, its voice slots and each kind's pool of
 * states lie in one allocation, each on cache lines of its own (a state:
 * the sim thread may write one voice's, a pose, while the audio thread
 * reads another's). One fg_big_calloc (fg_big_alloc.h) maps the 1.9 MB
 * object and its pools as one huge page where the kernel allows: as
 * calloc and aligned_alloc gave them, a render wrote ~45 of their pages,
 * a page fault each (~13 us on the machine measured). */
typedef struct engine_layout {
    size_t voices, free_slots, live, active, pool[FG_MAX_SOURCE_KINDS], bytes;
} engine_layout;

/* offset rounded up to the next cache line, plus bytes; false on overflow */
static bool layout_next(size_t *offset, size_t bytes, size_t *at)
{
    size_t a = (*offset + FG_CACHE_LINE - 1) / FG_CACHE_LINE * FG_CACHE_LINE;
    if (a < *offset || bytes > SIZE_MAX - a)
        return false;
    *at = a;
    *offset = a + bytes;
    return true;
}

/* A kind's state stride: voice_bytes rounded up to whole cache lines. */
static size_t kind_stride(const fg_source_kind *kind)
{
    size_t lines = (kind->voice_bytes + FG_CACHE_LINE - 1) / FG_CACHE_LINE;
    return (lines ? lines : 1) * FG_CACHE_LINE;
}

/* The layout for max_voices slots and the kinds; false when its size
 * overflows. */
static bool engine_layout_of(uint32_t max_voices, const fg_source_kind *const *kinds, size_t count,
                             engine_layout *l)
{
    /* max_voices <= MAX_VOICES_LIMIT: the arrays of slots cannot overflow */
    size_t end = sizeof(fg_engine), v = max_voices;
    bool ok = layout_next(&end, v * sizeof(fg_voice), &l->voices) &&
              layout_next(&end, v * sizeof(uint32_t), &l->free_slots) &&
              layout_next(&end, v, &l->live) &&
              layout_next(&end, v * sizeof(fg_voice *), &l->active);
    for (size_t i = 0; i < fg_builtin_kind_count + count && ok; i++) {
        size_t stride = kind_stride(kind_at(kinds, i));
        ok = stride <= SIZE_MAX / v && layout_next(&end, stride * v, &l->pool[i]);
    }
    /* a cache line more, to align the object where the allocation is not */
    l->bytes = end + FG_CACHE_LINE;
    return ok && l->bytes > end;
}

fg_result fg_engine_create_with(const fg_engine_config *config,
                                const fg_source_kind *const *kinds, size_t count,
                                fg_engine **out)
{
    if (!out || (count > 0 && !kinds))
        return FG_ERR_NULL;
    *out = NULL;
    fg_engine_config cfg;
    fg_result r = fg_engine_config_resolve(config, &cfg);
    if (r != FG_OK)
        return r;
    r = check_kinds(kinds, count);
    if (r != FG_OK)
        return r;
    engine_layout l;
    if (!engine_layout_of(cfg.max_voices, kinds, count, &l))
        return FG_ERR_NO_MEMORY;
    unsigned char *block = fg_big_calloc(l.bytes, 1);
    if (!block)
        return FG_ERR_NO_MEMORY;
    unsigned char *base = block + (-(uintptr_t)block & (FG_CACHE_LINE - 1));
    fg_engine *e = (fg_engine *)(void *)base;
    e->block = block;
    e->cfg = cfg;
    e->voices = (fg_voice *)(void *)(base + l.voices);
    e->free_slots = (uint32_t *)(void *)(base + l.free_slots);
    e->live = base + l.live;
    e->active = (fg_voice **)(void *)(base + l.active);
    for (size_t i = 0; i < fg_builtin_kind_count + count && r == FG_OK; i++) {
        fg_kind_slot *k = &e->kinds[e->kind_count++];
        k->kind = kind_at(kinds, i);
        k->stride = kind_stride(k->kind);
        k->pool = base + l.pool[i];
        /* the states are zeroed: mapped now, before the audio thread reads
         * them (fg_prefault.h) */
        fg_prefault_zeroed(k->pool, k->stride * cfg.max_voices);
        r = k->kind->create ? k->kind->create(&e->cfg, &k->storage) : FG_OK;
    }
    bool ok = r == FG_OK && fg_ring_init(&e->inbox, cfg.max_voices, sizeof(fg_voice *));
    ok = ok && fg_ring_init(&e->garbage, cfg.max_voices, sizeof(fg_voice *));
    fg_air air = {cfg.air_temperature_k - 273.15, cfg.air_humidity_pct, cfg.air_pressure_kpa};
    if (r == FG_OK)
        r = ok ? fg_bus_set_init(&e->buses, fg_layout_bus_channels(&cfg), cfg.max_block_frames,
                                 cfg.chunk_frames, cfg.sample_rate_hz, cfg.speed_of_sound_m_s,
                                 fg_layout_ears(&cfg) == 2 ? 0.5 * cfg.ear_spacing_m : 0.0, &air)
               : FG_ERR_NO_MEMORY;
    if (r == FG_OK && cfg.layout == FG_LAYOUT_BINAURAL) {
        unsigned planes = fg_layout_bus_channels(&cfg);
        const uint32_t frames = e->buses.max_frames;
        e->field_store = calloc((size_t)planes * frames, sizeof *e->field_store);
        for (unsigned ch = 0; ch < planes && e->field_store; ch++)
            e->field[ch] = e->field_store + (size_t)ch * frames;
        if (e->field_store)
            fg_prefault_zeroed(e->field_store, (size_t)planes * frames * sizeof *e->field_store);
        r = e->field_store ? fg_binaural_init(&e->binaural, cfg.hrirs)
                           : FG_ERR_NO_MEMORY;
    }
    e->cfg.hrirs = NULL; /* borrowed for create only */
    if (r != FG_OK) {
        fg_engine_destroy(e);
        return r;
    }
    for (uint32_t i = 0; i < cfg.max_voices; i++) {
        e->voices[i].slot = i;
        atomic_init(&e->voices[i].stop, false);
        e->free_slots[i] = cfg.max_voices - 1 - i;
    }
    e->free_count = cfg.max_voices;
    fg_listener origin = {.forward = {0, 1, 0}, .up = {0, 0, 1}};
    fg_pose_queue_init(&e->listener, &origin);
    fg_trajectory_init(&e->trajectory, &origin, 1);
    e->poses_seen = 1;
    atomic_init(&e->frames, 0);
    *out = e;
    return FG_OK;
}

fg_result fg_engine_create(const fg_engine_config *config, fg_engine **out)
{
    return fg_engine_create_with(config, NULL, 0, out);
}

void fg_engine_destroy(fg_engine *e)
{
    if (!e)
        return;
    fg_ring_deinit(&e->inbox);
    fg_ring_deinit(&e->garbage);
    fg_bus_set_deinit(&e->buses);
    fg_binaural_deinit(&e->binaural);
    free(e->field_store);
    for (size_t i = 0; i < e->kind_count; i++)
        if (e->kinds[i].kind->destroy)
            e->kinds[i].kind->destroy(e->kinds[i].storage);
    fg_big_free(e->block);
}

void fg_engine_get_config(const fg_engine *e, fg_engine_config *out)
{
    FG_REQUIRE(e && out);
    *out = e->cfg;
}

const fg_engine_config *fg_engine_config_in_use(const fg_engine *e)
{
    return &e->cfg;
}

fg_result fg_engine_set_listener(fg_engine *e, const fg_listener *pose)
{
    if (!e || !pose)
        return FG_ERR_NULL;
    fg_result r = fg_listener_check(pose);
    if (r != FG_OK)
        return r;
    fg_listener stamped = *pose;
    if (stamped.time_s == 0)
        stamped.time_s = fg_engine_time_s(e);
    (void)fg_pose_queue_push(&e->listener, &stamped);
    return FG_OK;
}

void fg_engine_get_listener(const fg_engine *e, fg_listener *out)
{
    FG_REQUIRE(e && out);
    fg_pose_queue_latest(&e->listener, out);
}

void fg_engine_get_report(const fg_engine *e, fg_engine_report *out)
{
    FG_REQUIRE(e && out);
    fg_counters *c = (fg_counters *)&e->counters;
#define LOAD(field) out->field = atomic_load_explicit(&c->field, memory_order_relaxed);
    LOAD(posted)
    LOAD(dropped_posts)
    LOAD(adopted)
    LOAD(finished)
    LOAD(collected)
    LOAD(late_events)
    LOAD(late_samples)
    LOAD(skipped_repeats)
    LOAD(skipped_work)
    LOAD(non_finite_voices)
    LOAD(non_finite_blocks)
    LOAD(blocks)
    LOAD(blocks_over_budget)
    LOAD(work_units)
    LOAD(peak_block_work)
#undef LOAD
}

uint64_t fg_engine_frames(const fg_engine *e)
{
    FG_REQUIRE_OR(e, 0);
    return atomic_load_explicit(&((fg_engine *)e)->frames, memory_order_acquire);
}

double fg_engine_time_s(const fg_engine *e)
{
    FG_REQUIRE_OR(e, 0.0);
    return (double)fg_engine_frames(e) / e->cfg.sample_rate_hz;
}
