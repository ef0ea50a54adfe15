/* The block loop shared by fulgur render and libfulgur-scene. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene_render.h"

/* The listener's path is published as a 100 Hz frame loop would publish
 * it, each pose with its time and velocity, this far ahead of the audio:
 * every wave a block plays then arrives between two known poses, at the
 * same poses whatever the block size. Blocks so long that more poses than
 * the engine takes at once would fall in one get sparser poses. */
#define POSE_HZ 100.0
#define POSE_LEAD_S 0.2
#define POSES_PER_BLOCK_MAX 48

typedef struct render_job {
    const scene *s;
    fg_engine *engine;
    size_t *order;          /* the discharge indices by emit time, then index */
    size_t next;            /* the next of order to post */
    fg_voice_id *aero_ids;  /* per aero object: its voice once posted, 0 before */
    bool *aero_done;        /* posted and since collected */
    bool *aero_warned;      /* counted in aero_beyond_range */
    size_t aeros_posted;
    float *planes[SCENE_MAX_CHANNELS];
    size_t segments;
    uint32_t block_frames;  /* scene_render_block_frames */
    double pose_period_s;   /* between published poses */
    uint64_t next_pose;     /* the next pose to publish, in periods from 0 */
    scene_fire_job fires;
} render_job;

static fg_result create_engine(render_job *job, char *err, size_t err_size)
{
    const scene *s = job->s;
    size_t events = 0; /* a ground image holds each segment twice (fg_engine_post) */
    for (size_t i = 0; i < s->discharge_count; i++) {
        const fg_discharge *d = &s->discharges[i].post;
        job->segments += d->node_count - 1;
        events += (d->node_count - 1) * (d->propagation.ground_reflection > 0 ? 2 : 1);
    }
    job->block_frames = scene_render_block_frames(s);
    double block_s = job->block_frames / s->sample_rate_hz;
    job->pose_period_s = fmax(1.0 / POSE_HZ, (block_s + POSE_LEAD_S) / POSES_PER_BLOCK_MAX);
    fg_engine_config cfg;
    scene_engine_config(s, &cfg);
    cfg.max_block_frames = job->block_frames;
    cfg.chunk_frames = SCENE_RENDER_CHUNK_FRAMES;
    cfg.max_voices = (uint32_t)(s->discharge_count + s->aero_count + s->fire_count);
    cfg.segment_capacity = events > UINT32_MAX ? UINT32_MAX : (uint32_t)events;
    /* an offline render has no deadline: the bound only keeps each block
     * finite, and a block takes every voice posted before it, so that no
     * voice starts later for a shorter block */
    cfg.work_per_frame = FG_WORK_PER_FRAME_MAX;
    cfg.max_adopt_per_block = cfg.max_voices;
    fg_result r = fg_engine_create(&cfg, &job->engine);
    if (r != FG_OK) {
        snprintf(err, err_size, "engine for %zu discharges and %zu segments: %s",
                 s->discharge_count, job->segments, fg_result_str(r));
        return r;
    }
    job->order = scene_post_order(s);
    job->aero_ids = calloc(s->aero_count + 1, sizeof *job->aero_ids);
    job->aero_done = calloc(s->aero_count + 1, sizeof *job->aero_done);
    job->aero_warned = calloc(s->aero_count + 1, sizeof *job->aero_warned);
    bool planes = true;
    for (uint32_t ch = 0; ch < s->channels; ch++)
        planes = (job->planes[ch] = malloc((size_t)job->block_frames * sizeof(float))) && planes;
    if (!job->order || !job->aero_ids || !job->aero_done || !job->aero_warned || !planes) {
        snprintf(err, err_size, "out of memory");
        return FG_ERR_NO_MEMORY;
    }
    return scene_fire_job_init(&job->fires, s, s->sample_rate_hz, err, err_size);
}

/* Publishes aero object i's pose at t, unless it has finished. */
static fg_result publish_aero_pose(render_job *job, size_t i, double t, char *err,
                                   size_t err_size)
{
    if (!job->aero_ids[i] || job->aero_done[i])
        return FG_OK;
    return scene_aero_publish_pose(job->s, i, job->engine, job->aero_ids[i], t,
                                   &job->aero_done[i], err, err_size);
}

/* Posts every discharge whose emit time falls before horizon_s. */
static fg_result post_due(render_job *job, double horizon_s, char *err, size_t err_size)
{
    for (; job->next < job->s->discharge_count; job->next++) {
        size_t i = job->order[job->next];
        const scene_discharge *d = &job->s->discharges[i];
        if (d->post.emit_time_s >= horizon_s)
            break;
        fg_result r = fg_engine_post(job->engine, &d->post, NULL);
        if (r != FG_OK) {
            snprintf(err, err_size, "discharges[%zu]: the engine refused it: %s", i,
                     fg_result_str(r));
            return r;
        }
    }
    for (size_t i = 0; i < job->s->aero_count; i++) {
        const fg_aero_object *o = &job->s->aeros[i].post;
        if (job->aero_ids[i] || o->emit_time_s >= horizon_s)
            continue;
        fg_result r = fg_aero_object_post(job->engine, o, &job->aero_ids[i]);
        if (r != FG_OK) {
            snprintf(err, err_size, "aero_objects[%zu]: the engine refused it: %s", i,
                     fg_result_str(r));
            return r;
        }
        job->aeros_posted++;
        /* the poses from its emission on that the others already have */
        for (uint64_t k = (uint64_t)ceil(o->emit_time_s / job->pose_period_s); k < job->next_pose;
             k++) {
            if ((r = publish_aero_pose(job, i, (double)k * job->pose_period_s, err, err_size)) !=
                FG_OK)
                return r;
        }
    }
    return FG_OK;
}

/* Counts in the report the live aero objects that have met speeds beyond
 * their texture's Reynolds range (each once). */
static void count_beyond_range(render_job *job, scene_render_report *report)
{
    for (size_t i = 0; i < job->s->aero_count; i++) {
        fg_aero_report a;
        if (job->aero_ids[i] && !job->aero_done[i] && !job->aero_warned[i] &&
            fg_aero_object_get_report(job->engine, job->aero_ids[i], &a) == FG_OK &&
            a.beyond_range_blocks > 0) {
            job->aero_warned[i] = true;
            report->aero_beyond_range++;
        }
    }
}

/* Publishes the listener's poses up to horizon_s. */
static fg_result publish_poses(render_job *job, double horizon_s, char *err, size_t err_size)
{
    for (double t; (t = (double)job->next_pose * job->pose_period_s) <= horizon_s;
         job->next_pose++) {
        fg_listener pose;
        scene_listener_at(job->s, t, &pose);
        pose.time_s = t;
        fg_result r = fg_engine_set_listener(job->engine, &pose);
        if (r != FG_OK) {
            snprintf(err, err_size, "listener at %.6f s: %s (forward and up interpolate to "
                                    "parallel directions?)", t, fg_result_str(r));
            return r;
        }
        for (size_t i = 0; i < job->s->aero_count; i++)
            if ((r = publish_aero_pose(job, i, t, err, err_size)) != FG_OK)
                return r;
        if ((r = scene_fire_job_poses(&job->fires, job->engine, t, err, err_size)) != FG_OK)
            return r;
    }
    return FG_OK;
}

/* Frames the output still sounds once every voice has finished: the
 * binaural filters' delay and the length of their responses. */
static uint64_t ring_out_frames(const scene *s)
{
    return s->layout == FG_LAYOUT_BINAURAL ? FG_BINAURAL_LATENCY_FRAMES + s->hrirs->length : 0;
}

static fg_result run(render_job *job, const scene_render_sink *sink, scene_render_report *report,
               char *err, size_t err_size)
{
    const scene *s = job->s;
    double rate = s->sample_rate_hz;
    uint64_t limit = scene_frame_limit(s), end = UINT64_MAX;
    while (report->frames < limit) {
        uint64_t frame = report->frames;
        double t = (double)frame / rate;
        uint32_t n =
            limit - frame < job->block_frames ? (uint32_t)(limit - frame) : job->block_frames;
        fg_result r;
        if ((r = publish_poses(job, t + n / rate + POSE_LEAD_S, err, err_size)) != FG_OK ||
            (r = post_due(job, t + n / rate + SCENE_POST_LEAD_S, err, err_size)) != FG_OK ||
            (r = scene_fire_job_feed(&job->fires, job->engine, t + n / rate + SCENE_POST_LEAD_S,
                                     job->next_pose * job->pose_period_s, job->pose_period_s,
                                     err, err_size)) != FG_OK)
            return r;
        r = fg_engine_render(job->engine, job->planes, n);
        if (r != FG_OK) {
            snprintf(err, err_size, "render at %.6f s: %s", t, fg_result_str(r));
            return r;
        }
        if ((r = sink->block(sink->context, job->planes, n, err, err_size)) != FG_OK)
            return r;
        count_beyond_range(job, report);
        fg_engine_collect(job->engine);
        report->frames += n;
        fg_engine_get_report(job->engine, &report->engine);
        if (s->duration_s == 0 && end == UINT64_MAX && job->next == s->discharge_count &&
            job->aeros_posted == s->aero_count && job->fires.posted == s->fire_count &&
            report->engine.finished == s->discharge_count + s->aero_count + s->fire_count)
            end = report->frames + ring_out_frames(s);
        if (report->frames >= end)
            return FG_OK;
    }
    report->capped = s->duration_s == 0;
    return FG_OK;
}

uint32_t scene_render_block_frames(const scene *s)
{
    return s->block_given ? s->block_frames : SCENE_RENDER_BLOCK_FRAMES;
}

uint64_t scene_frame_limit(const scene *s)
{
    return (uint64_t)llround((s->duration_s > 0 ? s->duration_s : SCENE_MAX_DURATION_S) *
                             s->sample_rate_hz);
}

fg_result scene_render(const scene *s, const scene_render_sink *sink,
                       scene_render_report *report, char *err, size_t err_size)
{
    scene_render_report local;
    if (!report)
        report = &local;
    *report = (scene_render_report){0};
    render_job job = {.s = s};
    fg_result rc = create_engine(&job, err, err_size);
    if (rc == FG_OK)
        rc = run(&job, sink, report, err, err_size);
    report->segments = job.segments;
    if (job.engine)
        fg_engine_get_report(job.engine, &report->engine);
    report->fire_underrun_frames = job.fires.underrun_frames;
    fg_engine_destroy(job.engine);
    scene_fire_job_deinit(&job.fires);
    free(job.order);
    free(job.aero_ids);
    free(job.aero_done);
    free(job.aero_warned);
    for (uint32_t ch = 0; ch < SCENE_MAX_CHANNELS; ch++)
        free(job.planes[ch]);
    return rc;
}
