/* The sim thread's side of the engine: handing a voice of any model to
 * the audio thread, stopping it, and reclaiming the finished. */
#include <stdlib.h>

#include "engine_internal.h"
#include "fg_rules.h"

static fg_kind_slot *kind_slot(fg_engine *e, const fg_source_kind *kind)
{
    for (size_t i = 0; i < e->kind_count; i++)
        if (e->kinds[i].kind == kind)
            return &e->kinds[i];
    return NULL;
}

fg_result fg_engine_post_source(fg_engine *e, const fg_source_ops *ops, const void *desc,
                                fg_voice_id *id)
{
    fg_kind_slot *k = kind_slot(e, ops->kind);
    if (!k)
        return FG_ERR_UNSUPPORTED;
    if (fg_ring_space(&e->inbox) == 0) {
        fg_count(&e->counters.dropped_posts, 1);
        return FG_ERR_QUEUE_FULL;
    }
    if (e->free_count == 0) {
        fg_count(&e->counters.dropped_posts, 1);
        return FG_ERR_POOL_FULL;
    }
    fg_voice *v = &e->voices[e->free_slots[e->free_count - 1]];
    void *state = k->pool + (size_t)v->slot * k->stride;
    fg_listener pose;
    uint64_t number = fg_pose_queue_latest(&e->listener, &pose);
    fg_post_context post = {&e->cfg, &pose, 2 * number + 1, &e->buses, k->storage};
    fg_result r = ops->prepare(ops, state, desc, &post);
    if (r != FG_OK) {
        if (r == FG_ERR_POOL_FULL)
            fg_count(&e->counters.dropped_posts, 1);
        return r;
    }
    e->free_count--;
    v->ops = ops;
    v->state = state;
    v->storage = k->storage;
    atomic_store_explicit(&v->stop, false, memory_order_relaxed);
    v->generation++;
    e->live[v->slot] = 1;
    bool pushed = fg_ring_push(&e->inbox, &v);
    (void)pushed; /* space was checked above and only this thread pushes */
    fg_count(&e->counters.posted, 1);
    if (id)
        *id = ((fg_voice_id)v->generation << 32) | (v->slot + 1u);
    return FG_OK;
}

/* The live voice with this id, or NULL. */
static fg_voice *live_voice(fg_engine *e, fg_voice_id id)
{
    uint64_t slot = (id & 0xffffffffu) - 1u;
    if ((id & 0xffffffffu) == 0 || slot >= e->cfg.max_voices || !e->live[slot] ||
        e->voices[slot].generation != (uint32_t)(id >> 32))
        return NULL;
    return &e->voices[slot];
}

fg_result fg_engine_stop(fg_engine *e, fg_voice_id id)
{
    if (!e)
        return FG_ERR_NULL;
    fg_voice *v = live_voice(e, id);
    if (!v)
        return FG_ERR_NOT_FOUND;
    atomic_store_explicit(&v->stop, true, memory_order_release);
    return FG_OK;
}

void *fg_engine_voice_state(fg_engine *e, fg_voice_id id, const fg_source_kind *kind)
{
    fg_voice *v = live_voice(e, id);
    return v && v->ops->kind == kind ? v->state : NULL;
}

size_t fg_engine_collect(fg_engine *e)
{
    FG_REQUIRE_OR(e, 0);
    size_t n = 0;
    fg_voice *v;
    while (fg_ring_pop(&e->garbage, &v)) {
        if (v->ops->release)
            v->ops->release(v->state, v->storage);
        e->live[v->slot] = 0;
        e->free_slots[e->free_count++] = v->slot;
        fg_count(&e->counters.collected, 1);
        n++;
    }
    return n;
}
