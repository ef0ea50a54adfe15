/* The fires of a scene in the render loop (scene_render.c) and in fulgur
 * run: each posted as a fire voice at its start, its flux turned into
 * sound by an fg_fire_feed on the render's thread (the sim thread) and
 * pushed as far ahead as its ring takes, closed when its flux is spent; a
 * moving fire's poses published with the listener's. A live simulation
 * ("live": true) is stepped there too, one step whenever the feed has
 * given the ring everything, so it runs no further ahead than the ring. */
#ifndef HOST_SCENE_SCENE_FIRE_RENDER_H
#define HOST_SCENE_SCENE_FIRE_RENDER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "scene.h"

typedef struct scene_fire_job {
    const scene *s;
    fg_fire_texture *texture;  /* trained once when a fire asks for texture synthesis */
    fg_fire_feed **feeds;
    fg_voice_id *ids;          /* 0 until posted */
    size_t *given;             /* flux steps taken by the feed */
    fg_flame_sim **sims;       /* a live fire's simulation; NULL for the others */
    double **live_flux;        /* its flux so far (room for all its steps) */
    size_t *made;              /* flux steps there are: flux_count, a live one's so far */
    bool *closed, *done;       /* stream closed; voice collected */
    uint64_t *underruns;       /* each fire's last reported underrun frames */
    size_t posted;
    uint64_t underrun_frames;  /* summed */
} scene_fire_job;

/* Makes the feeds (and the texture) for s's fires, their sound at
 * rate_hz (the scene's, or the one fulgur run's device runs at). Returns
 * FG_OK, or FG_ERR_NO_MEMORY / the fire sound's error with a message in
 * err. [main-thread] */
fg_result scene_fire_job_init(scene_fire_job *job, const scene *s, double rate_hz, char *err,
                              size_t err_size);

/* Frees what init made; the engine must be destroyed first. */
void scene_fire_job_deinit(scene_fire_job *job);

/* Posts the fires starting before horizon_s (publishing a moving fire's
 * poses from its start up to poses_until_s, every pose_period_s), then
 * pushes each live fire's sound as far as its ring takes and closes the
 * spent ones. Returns FG_OK or the engine's refusal, with a message. */
fg_result scene_fire_job_feed(scene_fire_job *job, fg_engine *engine, double horizon_s,
                              double poses_until_s, double pose_period_s, char *err,
                              size_t err_size);

/* A live host's fires: every fire posted now (each sounding from its own
 * start), its ring filled as far as it takes, before the host's threads
 * start. Returns as scene_fire_job_feed. [main-thread] */
fg_result scene_fire_job_post_all(scene_fire_job *job, fg_engine *engine, char *err,
                                  size_t err_size);

/* Then, on the host's sim thread: publishes the moving fires' poses at
 * the ticks k * pose_period_s from *tick up to until_s (*tick moves on),
 * and pushes every stream as far as its ring takes. Returns as
 * scene_fire_job_feed. */
fg_result scene_fire_job_follow(scene_fire_job *job, fg_engine *engine, double until_s,
                                double pose_period_s, uint64_t *tick, char *err,
                                size_t err_size);

/* Whether every fire's voice has finished and been collected (as the
 * feed and the poses find out): nothing more to feed or move. */
bool scene_fire_job_over(const scene_fire_job *job);

/* Publishes every live moving fire's pose at t_s. */
fg_result scene_fire_job_poses(scene_fire_job *job, fg_engine *engine, double t_s, char *err,
                               size_t err_size);

#endif
