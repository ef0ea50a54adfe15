/* The aero object on the sim and frame threads: checking and posting it
 * (fg_aero_object_post, the model's prepare), its poses and its report.
 * The audio thread's half is aero_voice.c. */
#include <math.h>
#include <string.h>

#include "aero_voice_internal.h"
#include "fg_vec3.h"
#include "fulgur/tree.h"

#define CORRELATION_LENGTHS 3.0 /* source spacing, in reference_m */
#define MIN_GUST_PERIOD_S 0.05
#define MAX_GUST_PERIOD_S 600.0

const fg_source_kind fg_aero_kind = {
    .name = "aero object",
    .voice_bytes = sizeof(fg_aero_voice),
};

uint32_t fg_aero_default_sources(double length_m, double d_m)
{
    double n = floor(length_m / (CORRELATION_LENGTHS * d_m));
    return n < 1.0 ? 1u : n > 1e9 ? 1000000000u : (uint32_t)n;
}

static bool finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* The pose's own checks, then the listener's (lengths, not parallel) on
 * its normal and axis as forward and up. */
static fg_result check_pose(const fg_aero_pose *p)
{
    if (!finite3(p->position) || !finite3(p->axis) || !finite3(p->normal) ||
        !finite3(p->velocity) || !finite3(p->angular_velocity) || !isfinite(p->time_s))
        return FG_ERR_NOT_FINITE;
    if (fg_v3_len(fg_v3_load(p->velocity)) > FG_AERO_MAX_SPEED_M_S)
        return FG_ERR_ARGUMENT;
    fg_listener raw = {.time_s = p->time_s};
    memcpy(raw.position, p->position, sizeof raw.position);
    memcpy(raw.forward, p->normal, sizeof raw.forward);
    memcpy(raw.up, p->axis, sizeof raw.up);
    memcpy(raw.velocity, p->velocity, sizeof raw.velocity);
    memcpy(raw.angular_velocity, p->angular_velocity, sizeof raw.angular_velocity);
    return fg_listener_check(&raw);
}

void fg_aero_pose_record(const fg_aero_pose *p, fg_listener *out)
{
    fg_vec3 a = fg_v3_unit(fg_v3_load(p->axis)), n = fg_v3_unit(fg_v3_load(p->normal));
    fg_vec3 x = fg_v3_unit(fg_v3_sub(n, fg_v3_scale(a, fg_v3_dot(n, a))));
    *out = (fg_listener){.time_s = p->time_s};
    memcpy(out->position, p->position, sizeof out->position);
    memcpy(out->velocity, p->velocity, sizeof out->velocity);
    memcpy(out->angular_velocity, p->angular_velocity, sizeof out->angular_velocity);
    out->velocity_given = p->velocity_given;
    fg_v3_store(x, out->forward);
    fg_v3_store(fg_v3_cross(a, x), out->up); /* forward x up = the axis */
}

static fg_result check_wind(const fg_aero_wind *w)
{
    if (!finite3(w->velocity) || !isfinite(w->gust) || !isfinite(w->gust_period_s))
        return FG_ERR_NOT_FINITE;
    if (fg_v3_len(fg_v3_load(w->velocity)) > FG_AERO_MAX_SPEED_M_S || w->gust < 0.0 ||
        w->gust > 1.0)
        return FG_ERR_ARGUMENT;
    if (w->gust_period_s != 0.0 &&
        !(w->gust_period_s >= MIN_GUST_PERIOD_S && w->gust_period_s <= MAX_GUST_PERIOD_S))
        return FG_ERR_ARGUMENT;
    return FG_OK;
}

static fg_result check_object(const fg_aero_object *o, const fg_aero_texture_desc *t,
                              uint32_t *sources)
{
    if (!isfinite(o->start_m) || !isfinite(o->end_m) || !isfinite(o->gain) ||
        !isfinite(o->emit_time_s) || !isfinite(o->duration_s))
        return FG_ERR_NOT_FINITE;
    if (o->body != FG_AERO_STICK && o->body != FG_AERO_COMPACT)
        return FG_ERR_ARGUMENT;
    if ((o->body == FG_AERO_STICK) != (t->dims == 2))
        return FG_ERR_ARGUMENT; /* a texture for the other body */
    if (o->gain < 0.0 || o->duration_s < 0.0 ||
        (o->emit_time_s < 0.0 && o->emit_time_s != FG_EMIT_NOW))
        return FG_ERR_ARGUMENT;
    if (o->absorption != FG_ABSORPTION_OFF && o->absorption != FG_ABSORPTION_ISO9613)
        return FG_ERR_ARGUMENT;
    if (o->body == FG_AERO_STICK) {
        if (!(o->end_m > o->start_m) || fabs(o->start_m) > FG_TREE_MAX_COORDINATE_M ||
            fabs(o->end_m) > FG_TREE_MAX_COORDINATE_M)
            return FG_ERR_ARGUMENT;
        *sources = o->sources ? o->sources
                              : fg_aero_default_sources(o->end_m - o->start_m, t->reference_m);
    } else {
        *sources = t->sources;
    }
    if (*sources > FG_AERO_OBJECT_MAX_SOURCES)
        return FG_ERR_ARGUMENT;
    fg_result r = check_wind(&o->wind);
    return r != FG_OK ? r : check_pose(&o->pose);
}

fg_result fg_aero_object_post(fg_engine *e, const fg_aero_object *o, fg_voice_id *id)
{
    if (!e || !o || !o->texture)
        return FG_ERR_NULL;
    const fg_aero_texture_desc *t = fg_aero_texture_get(o->texture);
    uint32_t sources;
    fg_result r = check_object(o, t, &sources);
    if (r != FG_OK)
        return r;
    fg_aero_object stamped = *o;
    if (stamped.pose.time_s == 0)
        stamped.pose.time_s = fg_engine_time_s(e);
    stamped.sources = sources;
    return fg_engine_post_source(e, &fg_aero_ops, &stamped, id);
}

fg_result fg_aero_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                          const fg_post_context *post)
{
    (void)ops;
    const fg_aero_object *o = desc;
    fg_aero_voice *v = voice;
    const fg_aero_texture_desc *t = fg_aero_texture_get(o->texture);
    fg_listener record;
    fg_aero_pose_record(&o->pose, &record);
    fg_pose_queue_init(&v->queue, &record);
    fg_trajectory_init(&v->path, &record, 1);
    v->poses_seen = 1;
    v->texture = o->texture;
    v->tex = t;
    v->body = o->body;
    fg_aero_wind_box_init(v, &o->wind);
    v->gain = o->gain > 0.0 ? o->gain : 1.0;
    v->emit_s = o->emit_time_s;
    v->end_s = INFINITY;
    v->duration_s = o->duration_s;
    v->bus = FG_BUS_DRY;
    v->next_share = 0.0;
    if (o->absorption == FG_ABSORPTION_ISO9613) {
        fg_bus_set_design_bands(post->buses);
        double r = fg_v3_len(fg_v3_sub(fg_v3_load(o->pose.position), fg_v3_load(post->pose->position)));
        v->bus = fg_bus_for_distance(post->buses, r, &v->next_share);
    }
    v->source_count = o->sources;
    for (uint32_t i = 0; i < o->sources; i++) {
        fg_aero_source_state *s = &v->source[i];
        memset(s, 0, sizeof *s);
        if (o->body == FG_AERO_STICK) {
            s->span_m = (o->end_m - o->start_m) / o->sources;
            s->along_m = o->start_m + (i + 0.5) * s->span_m;
            s->texture_source = 0;
        } else {
            s->span_m = 1.0;
            s->along_m = t->source[i].position_m;
            s->texture_source = i;
        }
    }
    atomic_store_explicit(&v->blocks, 0, memory_order_relaxed);
    atomic_store_explicit(&v->beyond_range_blocks, 0, memory_order_relaxed);
    atomic_store_explicit(&v->max_speed_um_s, 0, memory_order_relaxed);
    return FG_OK;
}

fg_result fg_aero_object_set_pose(fg_engine *e, fg_voice_id id, const fg_aero_pose *pose)
{
    if (!e || !pose)
        return FG_ERR_NULL;
    fg_aero_voice *v = fg_engine_voice_state(e, id, &fg_aero_kind);
    if (!v)
        return FG_ERR_NOT_FOUND;
    fg_result r = check_pose(pose);
    if (r != FG_OK)
        return r;
    fg_aero_pose stamped = *pose;
    if (stamped.time_s == 0)
        stamped.time_s = fg_engine_time_s(e);
    fg_listener record;
    fg_aero_pose_record(&stamped, &record);
    (void)fg_pose_queue_push(&v->queue, &record);
    return FG_OK;
}

fg_result fg_aero_object_set_wind(fg_engine *e, fg_voice_id id, const fg_aero_wind *wind)
{
    if (!e || !wind)
        return FG_ERR_NULL;
    fg_aero_voice *v = fg_engine_voice_state(e, id, &fg_aero_kind);
    if (!v)
        return FG_ERR_NOT_FOUND;
    fg_result r = check_wind(wind);
    if (r != FG_OK)
        return r;
    fg_aero_wind_box_push(v, wind);
    return FG_OK;
}

fg_result fg_aero_object_get_report(fg_engine *e, fg_voice_id id, fg_aero_report *out)
{
    if (!e || !out)
        return FG_ERR_NULL;
    fg_aero_voice *v = fg_engine_voice_state(e, id, &fg_aero_kind);
    if (!v)
        return FG_ERR_NOT_FOUND;
    *out = (fg_aero_report){
        .sources = v->source_count,
        .blocks = atomic_load_explicit(&v->blocks, memory_order_relaxed),
        .beyond_range_blocks = atomic_load_explicit(&v->beyond_range_blocks, memory_order_relaxed),
        .max_speed_m_s = 1e-6 * (double)atomic_load_explicit(&v->max_speed_um_s, memory_order_relaxed),
    };
    return FG_OK;
}
