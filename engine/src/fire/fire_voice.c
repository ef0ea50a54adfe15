/* The fire voice on the sim and frame threads: checking and posting it
 * (fg_fire_voice_post, the model's prepare and release, the kind's
 * rings), its poses, the producer's pushes and close, and its report. The
 * audio thread's half is fire_voice_render.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fg_vec3.h"
#include "fire_voice_internal.h"

static fg_result create_storage(const fg_engine_config *cfg, void **storage)
{
    (void)cfg;
    fg_fire_storage *s = calloc(1, sizeof *s);
    if (!s)
        return FG_ERR_NO_MEMORY;
    *storage = s;
    return FG_OK;
}

static void destroy_storage(void *storage)
{
    fg_fire_storage *s = storage;
    if (!s)
        return;
    for (unsigned i = 0; i < FG_FIRE_VOICE_MAX; i++)
        if (s->allocated[i])
            fg_sample_ring_deinit(&s->ring[i]);
    free(s);
}

const fg_source_kind fg_fire_kind = {
    .name = "fire",
    .voice_bytes = sizeof(fg_fire_voice_state),
    .create = create_storage,
    .destroy = destroy_storage,
};

static bool finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static fg_result check_pose(const fg_fire_pose *p)
{
    if (!finite3(p->position) || !finite3(p->velocity) || !isfinite(p->time_s))
        return FG_ERR_NOT_FINITE;
    if (p->time_s < 0.0 || fg_v3_len(fg_v3_load(p->velocity)) > FG_FIRE_MAX_SPEED_M_S)
        return FG_ERR_ARGUMENT;
    for (int k = 0; k < 3; k++)
        if (fabs(p->position[k]) > FG_TREE_MAX_COORDINATE_M)
            return FG_ERR_ARGUMENT;
    return FG_OK;
}

void fg_fire_pose_record(const fg_fire_pose *p, fg_listener *out)
{
    *out = (fg_listener){.time_s = p->time_s, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    memcpy(out->position, p->position, sizeof out->position);
    memcpy(out->velocity, p->velocity, sizeof out->velocity);
}

static uint64_t ring_frames(const fg_engine_config *cfg, double ring_s)
{
    double s = ring_s > 0.0 ? ring_s : FG_FIRE_RING_DEFAULT_S;
    return (uint64_t)ceil(s * cfg->sample_rate_hz);
}

fg_result fg_fire_voice_post(fg_engine *e, const fg_fire_voice *f, fg_voice_id *id)
{
    if (!e || !f)
        return FG_ERR_NULL;
    if (!isfinite(f->gain) || !isfinite(f->emit_time_s) || !isfinite(f->ring_s))
        return FG_ERR_NOT_FINITE;
    fg_result r = check_pose(&f->pose);
    if (r != FG_OK)
        return r;
    if (f->gain < 0.0 || (f->emit_time_s < 0.0 && f->emit_time_s != FG_EMIT_NOW))
        return FG_ERR_ARGUMENT;
    if (f->absorption != FG_ABSORPTION_OFF && f->absorption != FG_ABSORPTION_ISO9613)
        return FG_ERR_ARGUMENT;
    if (f->ring_s != 0.0 && !(f->ring_s >= FG_FIRE_RING_MIN_S && f->ring_s <= FG_FIRE_RING_MAX_S))
        return FG_ERR_ARGUMENT;
    fg_fire_voice stamped = *f;
    if (stamped.pose.time_s == 0)
        stamped.pose.time_s = fg_engine_time_s(e);
    return fg_engine_post_source(e, &fg_fire_ops, &stamped, id);
}

/* A free ring of at least frames for a new voice: one already big enough,
 * else a free slot (re)allocated; FG_FIRE_VOICE_MAX when none is free. */
static fg_result take_ring(fg_fire_storage *s, uint64_t frames, unsigned *index)
{
    uint64_t want = fg_sample_ring_capacity_for(frames);
    unsigned spare = FG_FIRE_VOICE_MAX;
    for (unsigned i = 0; i < FG_FIRE_VOICE_MAX; i++) {
        if (s->in_use[i])
            continue;
        if (s->allocated[i] && fg_sample_ring_capacity(&s->ring[i]) == want) {
            *index = i;
            return FG_OK;
        }
        if (spare == FG_FIRE_VOICE_MAX || !s->allocated[i])
            spare = i;
    }
    if (spare == FG_FIRE_VOICE_MAX)
        return FG_ERR_POOL_FULL;
    fg_sample_ring fresh;
    if (!fg_sample_ring_init(&fresh, frames))
        return FG_ERR_NO_MEMORY;
    if (s->allocated[spare])
        fg_sample_ring_deinit(&s->ring[spare]);
    s->ring[spare] = fresh;
    s->allocated[spare] = true;
    *index = spare;
    return FG_OK;
}

fg_result fg_fire_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                          const fg_post_context *post)
{
    (void)ops;
    const fg_fire_voice *f = desc;
    fg_fire_voice_state *v = voice;
    fg_fire_storage *s = post->storage;
    unsigned index;
    fg_result r = take_ring(s, ring_frames(post->cfg, f->ring_s), &index);
    if (r != FG_OK)
        return r;
    s->in_use[index] = true;
    v->ring = &s->ring[index];
    v->ring_index = index;
    fg_sample_ring_reset(v->ring);
    fg_listener record;
    fg_fire_pose_record(&f->pose, &record);
    fg_pose_queue_init(&v->queue, &record);
    fg_trajectory_init(&v->path, &record, 1);
    v->poses_seen = 1;
    v->gain = f->gain > 0.0 ? f->gain : 1.0;
    v->emit_s = f->emit_time_s;
    v->bus = FG_BUS_DRY;
    v->next_share = 0.0;
    if (f->absorption == FG_ABSORPTION_ISO9613) {
        fg_bus_set_design_bands(post->buses);
        double d = fg_v3_len(fg_v3_sub(fg_v3_load(f->pose.position), fg_v3_load(post->pose->position)));
        v->bus = fg_bus_for_distance(post->buses, d, &v->next_share);
    }
    v->ears = fg_layout_ears(post->cfg);
    memset(v->end, 0, sizeof v->end);
    v->envelope = 0.0;
    v->dry = false;
    v->covered = 0;
    v->released = 0;
    atomic_store_explicit(&v->closed, false, memory_order_relaxed);
    atomic_store_explicit(&v->read_frame, INT64_MIN, memory_order_relaxed);
    atomic_store_explicit(&v->underrun_frames, 0, memory_order_relaxed);
    atomic_store_explicit(&v->underruns, 0, memory_order_relaxed);
    atomic_store_explicit(&v->blocks, 0, memory_order_relaxed);
    return FG_OK;
}

void fg_fire_release(void *voice, void *storage)
{
    fg_fire_voice_state *v = voice;
    fg_fire_storage *s = storage;
    s->in_use[v->ring_index] = false;
    v->ring = NULL;
}

fg_result fg_fire_voice_set_pose(fg_engine *e, fg_voice_id id, const fg_fire_pose *pose)
{
    if (!e || !pose)
        return FG_ERR_NULL;
    fg_fire_voice_state *v = fg_engine_voice_state(e, id, &fg_fire_kind);
    if (!v)
        return FG_ERR_NOT_FOUND;
    fg_result r = check_pose(pose);
    if (r != FG_OK)
        return r;
    fg_fire_pose stamped = *pose;
    if (stamped.time_s == 0)
        stamped.time_s = fg_engine_time_s(e);
    fg_listener record;
    fg_fire_pose_record(&stamped, &record);
    (void)fg_pose_queue_push(&v->queue, &record);
    return FG_OK;
}

fg_result fg_fire_voice_push(fg_engine *e, fg_voice_id id, const float *x, size_t frames,
                             size_t *pushed)
{
    if (pushed)
        *pushed = 0;
    if (!e || !pushed || (!x && frames > 0))
        return FG_ERR_NULL;
    fg_fire_voice_state *v = fg_engine_voice_state(e, id, &fg_fire_kind);
    if (!v)
        return FG_ERR_NOT_FOUND;
    if (atomic_load_explicit(&v->closed, memory_order_relaxed))
        return FG_ERR_ARGUMENT;
    for (size_t i = 0; i < frames; i++) {
        if (!isfinite(x[i]))
            return FG_ERR_NOT_FINITE;
        if (fabsf(x[i]) > (float)FG_FIRE_MAX_PRESSURE_PA)
            return FG_ERR_ARGUMENT;
    }
    *pushed = fg_sample_ring_write(v->ring, x, frames);
    return FG_OK;
}

fg_result fg_fire_voice_close(fg_engine *e, fg_voice_id id)
{
    if (!e)
        return FG_ERR_NULL;
    fg_fire_voice_state *v = fg_engine_voice_state(e, id, &fg_fire_kind);
    if (!v)
        return FG_ERR_NOT_FOUND;
    atomic_store_explicit(&v->closed, true, memory_order_release);
    return FG_OK;
}

fg_result fg_fire_voice_get_report(fg_engine *e, fg_voice_id id, fg_fire_voice_report *out)
{
    if (!e || !out)
        return FG_ERR_NULL;
    fg_fire_voice_state *v = fg_engine_voice_state(e, id, &fg_fire_kind);
    if (!v)
        return FG_ERR_NOT_FOUND;
    int64_t read = atomic_load_explicit(&v->read_frame, memory_order_relaxed);
    *out = (fg_fire_voice_report){
        .capacity_frames = fg_sample_ring_capacity(v->ring),
        .pushed_frames = fg_sample_ring_head(v->ring),
        .held_frames = fg_sample_ring_held(v->ring),
        .read_frame = read,
        .underrun_frames = atomic_load_explicit(&v->underrun_frames, memory_order_relaxed),
        .underruns = atomic_load_explicit(&v->underruns, memory_order_relaxed),
        .blocks = atomic_load_explicit(&v->blocks, memory_order_relaxed),
        .closed = atomic_load_explicit(&v->closed, memory_order_relaxed),
    };
    return FG_OK;
}
