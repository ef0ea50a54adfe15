/* The fires in the render loop: see scene_fire_render.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene_fire_render.h"

fg_result scene_fire_job_init(scene_fire_job *job, const scene *s, double rate_hz, char *err,
                              size_t err_size)
{
    *job = (scene_fire_job){.s = s};
    size_t n = s->fire_count;
    if (n == 0)
        return FG_OK;
    job->feeds = calloc(n, sizeof *job->feeds);
    job->ids = calloc(n, sizeof *job->ids);
    job->given = calloc(n, sizeof *job->given);
    job->closed = calloc(n, sizeof *job->closed);
    job->done = calloc(n, sizeof *job->done);
    job->underruns = calloc(n, sizeof *job->underruns);
    job->sims = calloc(n, sizeof *job->sims);
    job->live_flux = calloc(n, sizeof *job->live_flux);
    job->made = calloc(n, sizeof *job->made);
    if (!job->feeds || !job->ids || !job->given || !job->closed || !job->done || !job->underruns ||
        !job->sims || !job->live_flux || !job->made) {
        snprintf(err, err_size, "fires: out of memory");
        return FG_ERR_NO_MEMORY;
    }
    for (size_t i = 0; i < n; i++) {
        const scene_fire *f = &s->fires[i];
        job->made[i] = f->live ? 0 : f->flux_count;
        fg_result r;
        if (f->live && (r = fg_flame_sim_create(&f->sim, &job->sims[i])) != FG_OK) {
            snprintf(err, err_size, "fires[%zu].simulation: %s", i, fg_result_str(r));
            return r;
        }
        if (f->live && !(job->live_flux[i] = malloc(f->flux_count * sizeof(double)))) {
            snprintf(err, err_size, "fires[%zu].simulation: out of memory", i);
            return FG_ERR_NO_MEMORY;
        }
    }
    for (size_t i = 0; i < n; i++) {
        fg_fire_sound_config sc = s->fires[i].sound;
        sc.sample_rate_hz = rate_hz;
        fg_result r;
        if (sc.extension == FG_FIRE_TEXTURE && !job->texture &&
            (r = fg_fire_texture_create_default(rate_hz, &job->texture)) != FG_OK) {
            snprintf(err, err_size, "fires[%zu]: training the default texture at %.0f Hz: %s", i,
                     rate_hz, fg_result_str(r));
            return r;
        }
        sc.texture = sc.extension == FG_FIRE_TEXTURE ? job->texture : NULL;
        if ((r = fg_fire_feed_create(&sc, 0, &job->feeds[i])) != FG_OK) {
            snprintf(err, err_size, "fires[%zu]: its sound at %.0f Hz: %s", i, rate_hz,
                     fg_result_str(r));
            return r;
        }
    }
    return FG_OK;
}

void scene_fire_job_deinit(scene_fire_job *job)
{
    for (size_t i = 0; job->feeds && i < job->s->fire_count; i++)
        fg_fire_feed_destroy(job->feeds[i]);
    for (size_t i = 0; job->sims && i < job->s->fire_count; i++)
        fg_flame_sim_destroy(job->sims[i]);
    for (size_t i = 0; job->live_flux && i < job->s->fire_count; i++)
        free(job->live_flux[i]);
    free(job->sims);
    free(job->live_flux);
    free(job->made);
    fg_fire_texture_destroy(job->texture);
    free(job->feeds);
    free(job->ids);
    free(job->given);
    free(job->closed);
    free(job->done);
    free(job->underruns);
    *job = (scene_fire_job){0};
}

bool scene_fire_job_over(const scene_fire_job *job)
{
    for (size_t i = 0; i < job->s->fire_count; i++)
        if (!job->done[i])
            return false;
    return true;
}

static fg_result publish(scene_fire_job *job, fg_engine *e, size_t i, double t_s, char *err,
                         size_t err_size)
{
    const scene_fire *f = &job->s->fires[i];
    if (!job->ids[i] || job->done[i] || f->path_count < 2)
        return FG_OK;
    fg_fire_pose pose;
    scene_fire_pose_at(f, t_s, &pose);
    if (pose.time_s == 0.0)
        pose.time_s = 1e-9;
    fg_result r = fg_fire_voice_set_pose(e, job->ids[i], &pose);
    if (r == FG_ERR_NOT_FOUND) {
        job->done[i] = true;
        return FG_OK;
    }
    if (r != FG_OK)
        snprintf(err, err_size, "fires[%zu]: its pose at %.6f s: %s", i, t_s, fg_result_str(r));
    return r;
}

fg_result scene_fire_job_poses(scene_fire_job *job, fg_engine *e, double t_s, char *err,
                               size_t err_size)
{
    for (size_t i = 0; i < job->s->fire_count; i++) {
        fg_result r = publish(job, e, i, t_s, err, err_size);
        if (r != FG_OK)
            return r;
    }
    return FG_OK;
}

/* One step of fire i's live simulation: its flux appended. */
static fg_result step_live(scene_fire_job *job, size_t i, char *err, size_t err_size)
{
    fg_flame_flux flux;
    fg_result r = fg_flame_sim_step(job->sims[i], &flux);
    if (r != FG_OK) {
        snprintf(err, err_size, "fires[%zu].simulation: the flame simulation failed at step %zu: %s",
                 i, job->made[i], fg_result_str(r));
        return r;
    }
    job->live_flux[i][job->made[i]++] = flux.flux_m3_s;
    return FG_OK;
}

/* Pushes fire i's sound as far as its ring takes, a live simulation
 * stepped whenever the ring has taken all there is; closes it once
 * spent. */
static fg_result push(scene_fire_job *job, fg_engine *e, size_t i, char *err, size_t err_size)
{
    const scene_fire *f = &job->s->fires[i];
    fg_fire_voice_report rep;
    if (fg_fire_voice_get_report(e, job->ids[i], &rep) != FG_OK) {
        job->done[i] = true; /* finished and collected */
        return FG_OK;
    }
    job->underrun_frames += rep.underrun_frames - job->underruns[i];
    job->underruns[i] = rep.underrun_frames;
    if (job->closed[i])
        return FG_OK;
    const double *flux = job->sims[i] ? job->live_flux[i] : f->flux_m3_s;
    fg_result r = FG_OK;
    for (;;) {
        size_t taken = 0;
        r = fg_fire_feed_push(job->feeds[i], e, job->ids[i], flux + job->given[i],
                              job->made[i] - job->given[i], &taken);
        job->given[i] += taken;
        if (r != FG_OK || job->given[i] == f->flux_count)
            break;
        if (job->given[i] < job->made[i]) {
            if (taken > 0)
                continue;
            break; /* the ring is full */
        }
        if (!job->sims[i] || fg_fire_feed_pending(job->feeds[i]) > 0)
            break; /* the ring took the steps but not yet all their sound */
        if ((r = step_live(job, i, err, err_size)) != FG_OK)
            return r;
    }
    if (r == FG_OK && job->given[i] == f->flux_count)
        r = fg_fire_feed_finish(job->feeds[i], e, job->ids[i], &job->closed[i]);
    if (r != FG_OK)
        snprintf(err, err_size, "fires[%zu]: streaming its sound: %s", i, fg_result_str(r));
    return r;
}

fg_result scene_fire_job_feed(scene_fire_job *job, fg_engine *e, double horizon_s,
                              double poses_until_s, double pose_period_s, char *err,
                              size_t err_size)
{
    for (size_t i = 0; i < job->s->fire_count; i++) {
        const scene_fire *f = &job->s->fires[i];
        fg_result r;
        if (!job->ids[i] && f->post.emit_time_s < horizon_s) {
            if ((r = fg_fire_voice_post(e, &f->post, &job->ids[i])) != FG_OK) {
                snprintf(err, err_size, "fires[%zu]: the engine refused it: %s", i,
                         fg_result_str(r));
                return r;
            }
            job->posted++;
            for (uint64_t k = (uint64_t)ceil(f->post.emit_time_s / pose_period_s);
                 (double)k * pose_period_s < poses_until_s; k++)
                if ((r = publish(job, e, i, (double)k * pose_period_s, err, err_size)) != FG_OK)
                    return r;
        }
        if (job->ids[i] && !job->done[i] && (r = push(job, e, i, err, err_size)) != FG_OK)
            return r;
    }
    return FG_OK;
}

fg_result scene_fire_job_post_all(scene_fire_job *job, fg_engine *e, char *err, size_t err_size)
{
    return scene_fire_job_feed(job, e, INFINITY, 0.0, 1.0, err, err_size);
}

fg_result scene_fire_job_follow(scene_fire_job *job, fg_engine *e, double until_s,
                                double pose_period_s, uint64_t *tick, char *err, size_t err_size)
{
    fg_result r = FG_OK;
    for (double t; r == FG_OK && (t = (double)*tick * pose_period_s) <= until_s; ++*tick)
        r = scene_fire_job_poses(job, e, t, err, err_size);
    return r == FG_OK ? scene_fire_job_feed(job, e, INFINITY, 0.0, pose_period_s, err, err_size)
                      : r;
}
