/* The frame thread: a VR application's 90 Hz loop, reduced to the head.
 * Each tick it publishes where the head will be one tick later, with its
 * velocity, angular velocity and that time on the engine clock, as a VR runtime predicts the
 * head for the frame's display time: the scene's pose path, or for a scene
 * with one fixed pose a small sway (a few centimetres and degrees, seeded,
 * a smooth function of time so lock-step runs repeat exactly). The engine
 * joins the poses into a continuous path (fg_engine_set_listener). The
 * same tick publishes every aero object's pose at that time, sampled from
 * its motion (fg_aero_object_set_pose), as render does. */
#include <math.h>
#include <string.h>

#include <stdio.h>

#include "run_gate.h"
#include "fg_rng.h"
#include "fg_vec3.h"


typedef struct sway {
    double freq_hz[3];  /* x, z, yaw */
    double phase[3];
} sway;

static void sway_init(sway *w, uint64_t seed)
{
    uint64_t state = seed ^ 0x5357415955ull;
    for (int k = 0; k < 3; k++) {
        w->freq_hz[k] = 0.1 + 0.4 * fg_splitmix64_uniform(&state);  /* slow, as a seated head drifts */
        w->phase[k] = 2 * FG_PI * fg_splitmix64_uniform(&state);
    }
}

/* The fixed pose moved by the sway at t: x and z translation, yaw about up. */
static void sway_apply(const sway *w, double t, fg_listener *pose)
{
    double a[3], da[3];
    for (int k = 0; k < 3; k++) {
        double arg = 2 * FG_PI * w->freq_hz[k] * t + w->phase[k];
        a[k] = sin(arg);
        da[k] = 2 * FG_PI * w->freq_hz[k] * cos(arg);
    }
    pose->position[0] += RUN_SWAY_M * a[0];
    pose->position[2] += RUN_SWAY_M * a[1];
    pose->velocity[0] = RUN_SWAY_M * da[0];
    pose->velocity[2] = RUN_SWAY_M * da[1];
    /* Rodrigues' rotation of forward about the (unit) up axis */
    double yaw = RUN_SWAY_YAW_RAD * a[2], c = cos(yaw), s = sin(yaw);
    fg_vec3 u = fg_v3_load(pose->up), f = fg_v3_load(pose->forward);
    double cross[3], along[3], out[3];
    fg_v3_store(fg_v3_cross(u, f), cross);
    fg_v3_store(fg_v3_scale(u, fg_v3_dot(u, f)), along);
    for (int k = 0; k < 3; k++)
        out[k] = pose->forward[k] * c + cross[k] * s + along[k] * (1 - c);
    memcpy(pose->forward, out, sizeof out);
    fg_v3_store(fg_v3_scale(fg_v3_unit(u), RUN_SWAY_YAW_RAD * da[2]), pose->angular_velocity);
}

static void set_pose(run_ctx *run, const sway *w, double t)
{
    fg_listener pose;
    scene_listener_at(run->s, t, &pose);
    if (run->s->pose_count == 1)
        sway_apply(w, t, &pose);
    pose.time_s = t;
    /* the scene parser rejects paths whose directions could go parallel */
    if (fg_engine_set_listener(run->engine, &pose) == FG_OK)
        run->frames_set++;
}

/* Publishes each live aero object's pose at t. Returns false (the message
 * in run->frame_error) when the engine refused one. */
static bool set_aero_poses(run_ctx *run, double t)
{
    for (size_t i = 0; i < run->s->aero_count; i++) {
        if (run->aero_done[i])
            continue;
        if (scene_aero_publish_pose(run->s, i, run->engine, run->aero_ids[i], t,
                                    &run->aero_done[i], run->frame_error,
                                    sizeof run->frame_error) != FG_OK)
            return false;
        run->aero_poses_set += !run->aero_done[i];
    }
    return true;
}

void *run_frame_thread(void *arg)
{
    run_ctx *run = arg;
    sway w;
    sway_init(&w, run->s->seed);
    double period_s = 1.0 / run->opt.frame_hz;
    for (uint64_t tick = 0; !run_stopping(run); tick++) {
        if (run->paced) {
            uint64_t deadline = monotonic_deadline_ns(run->start_ns, tick, period_s);
            monotonic_sleep_until_ns(deadline);
            run_hist_add(&run->jitter, (double)(int64_t)(monotonic_now_ns() - deadline) * 1e-9);
        } else {
            /* the tick comes when the engine clock reaches it */
            uint64_t seen = 0;
            while (!run_stopping(run) && run_tick_at(run, seen = fg_engine_frames(run->engine)) < tick)
                run_wait_engine_past(run, seen);
        }
        if (tick == 0) {
            set_pose(run, &w, 0.0); /* where the path starts, before the first lead */
            if (!set_aero_poses(run, 0.0))
                break;
        }
        double t = (double)(tick + RUN_POSE_LEAD_TICKS) * period_s;
        set_pose(run, &w, t);
        if (!set_aero_poses(run, t))
            break;
        run_publish_tick(run, tick);
    }
    if (run->frame_error[0])
        run_stop(run);
    return NULL;
}
