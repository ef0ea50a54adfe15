/* The engine object: creation, the sim-thread calls (post, stop, collect),
 * the audio-thread render, and the any-thread getters. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime(CLOCK_MONOTONIC) */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/engine_internal.h"
#include "core/fp_env_internal.h"

#define MAX_BLOCK_LIMIT 65536u
#define MAX_VOICES_LIMIT 65536u
#define SEGMENT_LIMIT (1u << 26)
#define SETTING_LIMIT 10.0 /* metres of ear spacing, seconds of look-ahead */

void fg_engine_config_default(fg_engine_config *c)
{
    if (!c)
        return;
    *c = (fg_engine_config){
        .sample_rate_hz = 48000.0,
        .max_block_frames = 4096,
        .channels = 2,
        .max_voices = 64,
        .segment_capacity = 131072,
        .speed_of_sound_m_s = 343.0,
        .ear_spacing_m = 0.18,
        .max_lookahead_s = 0.25,
        .max_adopt_per_block = 8,
        .air_temperature_k = 293.15,
        .air_humidity_pct = 70.0,
        .air_pressure_kpa = 101.325,
    };
}

static fg_result resolve_config(const fg_engine_config *in, fg_engine_config *out)
{
    fg_engine_config_default(out);
    if (!in)
        return FG_OK;
    if (!isfinite(in->sample_rate_hz) || !isfinite(in->speed_of_sound_m_s) ||
        !isfinite(in->ear_spacing_m) || !isfinite(in->max_lookahead_s) ||
        !isfinite(in->air_temperature_k) || !isfinite(in->air_humidity_pct) ||
        !isfinite(in->air_pressure_kpa))
        return FG_ERR_NOT_FINITE;
    if (in->sample_rate_hz != 0 && (in->sample_rate_hz < 8000 || in->sample_rate_hz > 384000))
        return FG_ERR_SAMPLE_RATE;
    if (in->max_block_frames > MAX_BLOCK_LIMIT || (in->channels != 0 && in->channels > 2) ||
        in->max_voices > MAX_VOICES_LIMIT || in->segment_capacity > SEGMENT_LIMIT ||
        in->speed_of_sound_m_s < 0 || in->ear_spacing_m < 0 || in->ear_spacing_m > SETTING_LIMIT ||
        in->max_lookahead_s < 0 || in->max_lookahead_s > SETTING_LIMIT ||
        in->max_adopt_per_block > MAX_VOICES_LIMIT ||
        (in->air_temperature_k != 0 && (in->air_temperature_k < 200 || in->air_temperature_k > 350)) ||
        in->air_humidity_pct < 0 || in->air_humidity_pct > 100 ||
        (in->air_pressure_kpa != 0 && (in->air_pressure_kpa < 10 || in->air_pressure_kpa > 200)))
        return FG_ERR_ARGUMENT;
#define TAKE(field) \
    if (in->field != 0) \
        out->field = in->field;
    TAKE(sample_rate_hz)
    TAKE(max_block_frames)
    TAKE(channels)
    TAKE(max_voices)
    TAKE(segment_capacity)
    TAKE(speed_of_sound_m_s)
    TAKE(ear_spacing_m)
    TAKE(max_lookahead_s)
    TAKE(max_adopt_per_block)
    TAKE(air_temperature_k)
    TAKE(air_humidity_pct)
    TAKE(air_pressure_kpa)
#undef TAKE
    return FG_OK;
}

fg_result fg_engine_create(const fg_engine_config *config, fg_engine **out)
{
    if (!out)
        return FG_ERR_NULL;
    *out = NULL;
    fg_engine_config cfg;
    fg_result r = resolve_config(config, &cfg);
    if (r != FG_OK)
        return r;
    fg_engine *e = calloc(1, sizeof *e);
    if (!e)
        return FG_ERR_NO_MEMORY;
    e->cfg = cfg;
    size_t nodes = (size_t)cfg.segment_capacity + 1;
    e->voices = calloc(cfg.max_voices, sizeof *e->voices);
    e->free_slots = calloc(cfg.max_voices, sizeof *e->free_slots);
    e->live = calloc(cfg.max_voices, 1);
    e->active = calloc(cfg.max_voices, sizeof *e->active);
    e->events = calloc(cfg.segment_capacity, sizeof *e->events);
    e->main_index = calloc(cfg.segment_capacity, sizeof *e->main_index);
    e->scratch.path_m = calloc(nodes, sizeof *e->scratch.path_m);
    e->scratch.junction = calloc(nodes, sizeof *e->scratch.junction);
    e->scratch.main = calloc(nodes, 1);
    e->scratch.order = calloc(nodes, sizeof *e->scratch.order);
    e->scratch.order_tmp = calloc(nodes, sizeof *e->scratch.order_tmp);
    bool ok = e->voices && e->free_slots && e->live && e->active && e->events &&
              e->main_index && e->scratch.path_m && e->scratch.junction && e->scratch.main &&
              e->scratch.order && e->scratch.order_tmp;
    ok = ok && fg_arena_init(&e->arena, cfg.segment_capacity, cfg.max_voices);
    ok = ok && fg_ring_init(&e->inbox, cfg.max_voices, sizeof(fg_voice *));
    ok = ok && fg_ring_init(&e->garbage, cfg.max_voices, sizeof(fg_voice *));
    fg_air air = {cfg.air_temperature_k - 273.15, cfg.air_humidity_pct, cfg.air_pressure_kpa};
    r = ok ? fg_bus_set_init(&e->buses, cfg.channels, cfg.max_block_frames, cfg.sample_rate_hz,
                             cfg.speed_of_sound_m_s, &air)
           : FG_ERR_NO_MEMORY;
    if (r != FG_OK) {
        fg_engine_destroy(e);
        return r;
    }
    e->abe = fg_abe_params_default();
    for (uint32_t i = 0; i < cfg.max_voices; i++) {
        e->voices[i].slot = i;
        atomic_init(&e->voices[i].stop, false);
        e->free_slots[i] = cfg.max_voices - 1 - i;
    }
    e->free_count = cfg.max_voices;
    fg_listener origin = {.forward = {0, 1, 0}, .up = {0, 0, 1}};
    fg_listener_cell_init(&e->listener, &origin);
    e->pose = origin;
    atomic_init(&e->frames, 0);
    *out = e;
    return FG_OK;
}

void fg_engine_destroy(fg_engine *e)
{
    if (!e)
        return;
    fg_ring_deinit(&e->inbox);
    fg_ring_deinit(&e->garbage);
    fg_arena_deinit(&e->arena);
    fg_bus_set_deinit(&e->buses);
    free(e->scratch.order_tmp);
    free(e->scratch.order);
    free(e->scratch.main);
    free(e->scratch.junction);
    free(e->scratch.path_m);
    free(e->main_index);
    free(e->events);
    free(e->active);
    free(e->live);
    free(e->free_slots);
    free(e->voices);
    free(e);
}

void fg_engine_get_config(const fg_engine *e, fg_engine_config *out)
{
    if (e && out)
        *out = e->cfg;
}

static void count(atomic_uint_least64_t *counter)
{
    atomic_fetch_add_explicit(counter, 1, memory_order_relaxed);
}

fg_result fg_engine_post(fg_engine *e, const fg_discharge *d, fg_voice_id *id)
{
    if (!e || !d || !d->nodes)
        return FG_ERR_NULL;
    /* the capacity first, so a wild count is never walked */
    if (d->node_count > (size_t)e->cfg.segment_capacity + 1)
        return FG_ERR_CAPACITY;
    fg_result r = fg_tree_check(d->nodes, d->node_count, NULL);
    if (r != FG_OK)
        return r;
    r = fg_discharge_check(d);
    if (r != FG_OK)
        return r;
    size_t events = fg_discharge_events(d);
    if (events > e->cfg.segment_capacity)
        return FG_ERR_CAPACITY;
    if (fg_ring_space(&e->inbox) == 0) {
        count(&e->counters.dropped_posts);
        return FG_ERR_QUEUE_FULL;
    }
    size_t extent;
    if (e->free_count == 0 || !fg_arena_alloc(&e->arena, events, &extent)) {
        count(&e->counters.dropped_posts);
        return FG_ERR_POOL_FULL;
    }
    if (d->propagation.absorption == FG_ABSORPTION_ISO9613)
        fg_bus_set_design_bands(&e->buses);
    fg_voice *v = &e->voices[e->free_slots[--e->free_count]];
    v->extent = extent;
    v->events = &e->events[extent];
    v->main_index = &e->main_index[extent];
    fg_prepare_voice(e, v, d);
    v->generation++;
    e->live[v->slot] = 1;
    bool pushed = fg_ring_push(&e->inbox, &v);
    (void)pushed; /* space was checked above and only this thread pushes */
    count(&e->counters.posted);
    if (id)
        *id = ((fg_voice_id)v->generation << 32) | (v->slot + 1u);
    return FG_OK;
}

fg_result fg_engine_stop(fg_engine *e, fg_voice_id id)
{
    if (!e)
        return FG_ERR_NULL;
    uint64_t slot = (id & 0xffffffffu) - 1u;
    if ((id & 0xffffffffu) == 0 || slot >= e->cfg.max_voices || !e->live[slot] ||
        e->voices[slot].generation != (uint32_t)(id >> 32))
        return FG_ERR_NOT_FOUND;
    atomic_store_explicit(&e->voices[slot].stop, true, memory_order_release);
    return FG_OK;
}

size_t fg_engine_collect(fg_engine *e)
{
    if (!e)
        return 0;
    size_t n = 0;
    fg_voice *v;
    while (fg_ring_pop(&e->garbage, &v)) {
        fg_arena_free(&e->arena, v->extent, v->event_count);
        e->live[v->slot] = 0;
        e->free_slots[e->free_count++] = v->slot;
        count(&e->counters.collected);
        n++;
    }
    return n;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

fg_result fg_engine_render(fg_engine *e, float *const *out, uint32_t nframes)
{
    if (!e || !out)
        return FG_ERR_NULL;
    for (uint32_t ch = 0; ch < e->cfg.channels; ch++)
        if (!out[ch])
            return FG_ERR_NULL;
    for (uint32_t ch = 0; ch < e->cfg.channels; ch++)
        memset(out[ch], 0, (size_t)nframes * sizeof(float));
    if (nframes > e->cfg.max_block_frames)
        return FG_ERR_BLOCK_SIZE;
    if (nframes == 0)
        return FG_OK;

    double t_begin = now_s();
    fg_fp_env env = fg_fp_env_flush_denormals();
    uint64_t start = atomic_load_explicit(&e->frames, memory_order_relaxed);

    fg_voice *adopted;
    for (uint32_t k = 0; k < e->cfg.max_adopt_per_block && fg_ring_pop(&e->inbox, &adopted);
         k++) {
        fg_voice_adopt(e, adopted, (double)start);
        e->active[e->active_count++] = adopted;
        count(&e->counters.adopted);
    }

    fg_listener_cell_try_read(&e->listener, &e->pose, &e->pose_serial);
    fg_ears ears;
    fg_listener_ears(&e->pose, e->cfg.channels, e->cfg.ear_spacing_m, &ears);
    fg_bus_set_begin(&e->buses, nframes);
    fg_block_context ctx = {
        .start_frame = (double)start,
        .frames = nframes,
        .ears = &ears,
        .position = e->pose.position,
        .serial = e->pose_serial,
        .buses = &e->buses,
    };
    for (uint32_t i = 0; i < e->active_count;) {
        fg_voice *v = e->active[i];
        if (fg_voice_render(e, v, &ctx)) {
            e->active[i] = e->active[--e->active_count];
            bool pushed = fg_ring_push(&e->garbage, &v);
            (void)pushed; /* the ring holds max_voices: never full */
            count(&e->counters.finished);
        } else {
            i++;
        }
    }
    fg_bus_set_end(&e->buses, out, nframes);

    atomic_store_explicit(&e->frames, start + nframes, memory_order_release);
    count(&e->counters.blocks);
    fg_fp_env_restore(env);
    if (now_s() - t_begin > nframes / e->cfg.sample_rate_hz)
        count(&e->counters.blocks_over_budget);
    return FG_OK;
}

fg_result fg_engine_set_listener(fg_engine *e, const fg_listener *pose)
{
    if (!e || !pose)
        return FG_ERR_NULL;
    fg_result r = fg_listener_check(pose);
    if (r != FG_OK)
        return r;
    fg_listener_cell_write(&e->listener, pose);
    return FG_OK;
}

void fg_engine_get_listener(const fg_engine *e, fg_listener *out)
{
    unsigned serial;
    if (e && out)
        fg_listener_cell_read(&e->listener, out, &serial);
}

void fg_engine_get_stats(const fg_engine *e, fg_engine_stats *out)
{
    if (!e || !out)
        return;
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
    LOAD(blocks)
    LOAD(blocks_over_budget)
#undef LOAD
}

uint64_t fg_engine_frames(const fg_engine *e)
{
    return e ? atomic_load_explicit(&((fg_engine *)e)->frames, memory_order_acquire) : 0;
}

double fg_engine_time_s(const fg_engine *e)
{
    return e ? (double)fg_engine_frames(e) / e->cfg.sample_rate_hz : 0.0;
}
