/* Posting a discharge: the public fg_engine_post, its checks, the one
 * table from fg_discharge.model to a source model, and the discharge
 * kind's storage (the segment events of every live voice). */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <math.h>
#include <stdlib.h>

#include "fg_big_alloc.h"
#include "fg_rules.h"
#include "discharge_internal.h"

#define REPEAT_MIN_DEFAULT_S 0.010
#define REPEAT_MAX_DEFAULT_S 0.050

/* The source model of each fg_voice_model: the only place that names them. */
static const fg_source_ops *const models[] = {
    [FG_MODEL_WM] = &fg_source_wm,
    [FG_MODEL_ABE] = &fg_source_abe,
};
#define MODEL_COUNT (sizeof models / sizeof models[0])

void fg_discharge_repeat_range(const fg_discharge *d, double *min_s, double *max_s)
{
    *min_s = FG_DEF(d->repeat_min_s, REPEAT_MIN_DEFAULT_S);
    *max_s = FG_DEF(d->repeat_max_s, REPEAT_MAX_DEFAULT_S);
}

fg_result fg_discharge_check(const fg_discharge *d)
{
    fg_propagation_config propagation;
    fg_result r = fg_sound_config_check(&d->sound);
    if (r == FG_OK)
        r = fg_propagation_config_resolve(&d->propagation, &propagation);
    if (r != FG_OK)
        return r;
    if ((unsigned)d->model >= MODEL_COUNT)
        return FG_ERR_ARGUMENT;
    if (!isfinite(d->emit_time_s) || !isfinite(d->repeat_min_s) || !isfinite(d->repeat_max_s) ||
        !isfinite(d->duration_s))
        return FG_ERR_NOT_FINITE;
    if (d->emit_time_s < 0 && d->emit_time_s != FG_EMIT_NOW)
        return FG_ERR_ARGUMENT;
    if (d->strokes > FG_MAX_STROKES)
        return FG_ERR_ARGUMENT;
    if (!d->continuous)
        return FG_OK;
    double lo, hi;
    fg_discharge_repeat_range(d, &lo, &hi);
    if (d->strokes > 1 || lo < FG_REPEAT_MIN_S || lo > hi || hi > FG_REPEAT_MAX_S ||
        d->duration_s < 0)
        return FG_ERR_ARGUMENT;
    return FG_OK;
}

size_t fg_discharge_events(const fg_discharge *d, const fg_discharge_model *m)
{
    size_t segments = d->node_count - 1;
    size_t stride = m->stride(segments);
    size_t events = (segments + stride - 1) / stride;
    return d->propagation.ground_reflection > 0 ? 2 * events : events;
}

fg_result fg_engine_post(fg_engine *e, const fg_discharge *d, fg_voice_id *id)
{
    if (!e || !d || !d->nodes)
        return FG_ERR_NULL;
    const fg_engine_config *cfg = fg_engine_config_in_use(e);
    /* the capacity first, so a wild count is never walked */
    if (d->node_count > (size_t)cfg->segment_capacity + 1)
        return FG_ERR_CAPACITY;
    fg_result r = fg_tree_check(d->nodes, d->node_count, NULL);
    if (r != FG_OK)
        return r;
    r = fg_discharge_check(d);
    if (r != FG_OK)
        return r;
    const fg_source_ops *ops = models[d->model];
    if (fg_discharge_events(d, ops->model) > cfg->segment_capacity)
        return FG_ERR_CAPACITY;
    return fg_engine_post_source(e, ops, d, id);
}

void fg_discharge_release(void *voice, void *storage)
{
    fg_discharge_voice *v = voice;
    fg_discharge_store *s = storage;
    fg_arena_free(&s->arena, v->extent, v->event_count);
}

static void destroy_store(void *storage)
{
    fg_discharge_store *s = storage;
    if (!s)
        return;
    fg_arena_deinit(&s->arena);
    fg_big_free(s->scratch.order);
    fg_big_free(s->events);
    free(s);
}

_Static_assert(sizeof(fg_sort_pair) >= sizeof(double) + sizeof(uint32_t) + 1 &&
                   _Alignof(fg_sort_pair) >= _Alignof(double),
               "path_m, junction and main fit in order_tmp's storage (fg_prep_scratch)");

static fg_result create_store(const fg_engine_config *cfg, void **storage)
{
    fg_discharge_store *s = calloc(1, sizeof *s);
    *storage = s;
    if (!s)
        return FG_ERR_NO_MEMORY;
    size_t nodes = (size_t)cfg->segment_capacity + 1;
    /* the events and the main channel's indices in one allocation: 9 438
     * segments' indices (38 kB) took 9 page faults apart */
    _Static_assert(sizeof *s->events % _Alignof(uint32_t) == 0, "the indices follow the events");
    s->events = fg_big_calloc(cfg->segment_capacity, sizeof *s->events + sizeof *s->main_index);
    if (s->events)
        s->main_index = (uint32_t *)(void *)(s->events + cfg->segment_capacity);
    /* the sort and its scratch in one allocation (fg_big_alloc.h): 9 438
     * segments' two of 151 kB took 74 page faults apart */
    s->scratch.order = fg_big_calloc(2 * nodes, sizeof *s->scratch.order);
    if (s->scratch.order) {
        s->scratch.order_tmp = s->scratch.order + nodes;
        s->scratch.path_m = (double *)(void *)s->scratch.order_tmp;
        s->scratch.junction = (uint32_t *)(void *)(s->scratch.path_m + nodes);
        s->scratch.main = (uint8_t *)(s->scratch.junction + nodes);
    }
    bool ok = s->events && s->scratch.order;
    ok = ok && fg_arena_init(&s->arena, cfg->segment_capacity, cfg->max_voices);
    return ok ? FG_OK : FG_ERR_NO_MEMORY;
}

const fg_source_kind fg_discharge_kind = {
    .name = "discharge",
    .voice_bytes = sizeof(fg_discharge_voice),
    .create = create_store,
    .destroy = destroy_store,
};
