/* fulgur view: set-up, the frame loop on the GL thread, the report. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/commands.h"
#include "common/clock.h"
#include "picture/picture.h"
#include "view.h"

/* Takes the sim thread's answers: each tree becomes a flash at its emit
 * time with the engine's stroke offsets. */
static void take_replies(view *v, fgg_picture *pic)
{
    view_request *q;
    while ((q = view_ring_pop(&v->from_sim))) {
        v->replies++;
        if (q->error[0]) {
            fprintf(stderr, "fulgur view: %s\n", q->error);
        } else if (q->kind == VIEW_REQ_STOP) {
            fgg_picture_remove(pic, v->hold_flash);
            v->hold_flash = 0;
        } else {
            v->posted++;
            fgg_flash f;
            picture_flash(&q->post, q->preset, q->emit_s, q->strokes_s, q->stroke_count, &f);
            uint32_t id = 0;
            if (fgg_picture_add(pic, &f, &id) != FG_OK)
                fprintf(stderr, "fulgur view: the picture refused a discharge: %s\n",
                        fgg_error_message());
            if (q->kind == VIEW_REQ_HOLD)
                v->hold_flash = id;
        }
        free(q->nodes);
        free(q);
    }
}

/* Publishes where the scene's listener is at t_s, with that time and its
 * velocity (the parser refused paths whose directions could go parallel). */
static void publish_listener(view *v, double t_s)
{
    fg_listener pose;
    scene_listener_at(v->s, t_s, &pose);
    pose.time_s = t_s;
    fg_result r = fg_engine_set_listener(v->engine, &pose);
    (void)r;
}

/* Publishes each live aero object's pose at t_s and moves the picture's
 * fires and objects to now_s. Returns -1 with the message in
 * v->frame_error, or with a GL error. */
static int move_sources(view *v, fgg_picture *pic, double t_s)
{
    for (size_t i = 0; i < v->s->aero_count; i++)
        if (!v->aero_done[i] &&
            scene_aero_publish_pose(v->s, i, v->engine, v->aero_ids[i], t_s, &v->aero_done[i],
                                    v->frame_error, sizeof v->frame_error) != FG_OK)
            return -1;
    return picture_sources_move(pic, v->s, v->now_s, v->source_ids, v->frame_error,
                                sizeof v->frame_error);
}

/* One frame: the listener and the objects, events, the scene's timeline,
 * answers, the picture at now_s. Returns -1 on a GL error or a refused
 * pose (v->frame_error). */
static int frame(view *v, fgg_context *ctx, fgg_picture *pic, uint32_t k,
                 const view_event *events, size_t count, size_t *next)
{
    bool headless = v->opt.backend != FGG_BACKEND_WINDOW;
    /* headless: the audio has played the last frame before this one
     * publishes poses, so each block of sound sees the same poses in every
     * run (a pose queued further ahead moves the paths' rounding) */
    if (headless && k > 0)
        view_wait_audio(v);
    double before = v->now_s;
    v->now_s = headless ? k / v->opt.fps : fg_engine_time_s(v->engine);
    /* the head one frame ahead, at the end of the sound this frame lets
     * play, as a VR runtime predicts it for the frame's display */
    publish_listener(v, v->now_s + 1.0 / v->opt.fps);
    if (move_sources(v, pic, v->now_s + 1.0 / v->opt.fps) != 0)
        return -1;
    if (!headless && !view_window_poll(v, ctx))
        v->quit = true;
    for (; *next < count && events[*next].frame <= k; ++*next)
        view_apply(v, &events[*next]);
    view_timeline_step(v, k == 0 ? 0 : v->now_s - before);
    /* headless: every request answered before the audio passes this frame */
    while (headless && v->replies < v->requests && !atomic_load(&v->stop)) {
        take_replies(v, pic);
        monotonic_sleep_until_ns(monotonic_now_ns() + 200000);
    }
    take_replies(v, pic);
    view_overlay_show(v);
    fgg_camera cam;
    view_camera_get(&v->cam, &cam);
    if (fgg_picture_draw(pic, &cam, v->now_s) != FG_OK)
        return -1;
    if (!headless) {
        int w, h;
        fgg_context_framebuffer_size(ctx, &w, &h);
        fgg_picture_blit(pic, w, h);
        fgg_context_present(ctx);
    } else if (v->opt.png_dir) {
        char path[4096];
        snprintf(path, sizeof path, "%s/frame_%04u.png", v->opt.png_dir, (unsigned)k);
        if (fgg_picture_write_png(pic, path) != FG_OK)
            return -1;
    }
    if (headless) {
        uint64_t target = (uint64_t)llround((k + 1) / v->opt.fps * v->rate_hz);
        atomic_store(&v->fire_target, target);
        while (v->s->fire_count && atomic_load(&v->fire_done) < target && !atomic_load(&v->stop))
            monotonic_sleep_until_ns(monotonic_now_ns() + 200000);
        view_release_audio(v, target);
    }
    return 0;
}

static int loop(view *v, fgg_context *ctx, fgg_picture *pic, char *err, size_t err_size)
{
    view_event *events = NULL;
    size_t count = 0, next = 0;
    if (v->opt.script_path &&
        view_script_load(v->opt.script_path, &events, &count, err, err_size) != 0)
        return CLI_USAGE;
    uint64_t t0 = monotonic_now_ns();
    int rc = CLI_OK;
    for (uint32_t k = 0; (!v->opt.frames || k < v->opt.frames) && !v->quit; k++) {
        if (atomic_load(&v->stop))
            break; /* the audio thread ended: its error is reported below */
        if (frame(v, ctx, pic, k, events, count, &next) != 0) {
            snprintf(err, err_size, "%s", v->frame_error[0] ? v->frame_error : fgg_error_message());
            rc = v->frame_error[0] ? CLI_USAGE : CLI_RUNTIME; /* the scene's motion */
            break;
        }
        v->frames_drawn = k + 1;
        if (v->opt.backend == FGG_BACKEND_WINDOW)
            monotonic_sleep_until_ns(monotonic_deadline_ns(t0, k + 1, 1 / v->opt.fps));
    }
    free(events);
    /* headless: the sound of every frame drawn, then stop */
    if (v->opt.backend != FGG_BACKEND_WINDOW)
        view_wait_audio(v);
    return rc;
}

static void report(view *v, uint32_t frames)
{
    fg_engine_report st;
    fg_engine_get_report(v->engine, &st);
    FILE *to = v->opt.audio.kind == AUDIO_DRIVER_RAW ? stderr : stdout;
    fprintf(to,
            "{\"frames\": %u, \"requests\": %llu, \"posted\": %llu, \"adopted\": %llu, "
            "\"late_events\": %llu, \"audio_frames\": %llu}\n",
            (unsigned)frames, (unsigned long long)v->requests, (unsigned long long)st.posted,
            (unsigned long long)st.adopted, (unsigned long long)st.late_events,
            (unsigned long long)atomic_load(&v->audio_done));
}

/* Posts the scene's aero objects and fires (their sound at the view's
 * rate) before the threads start. Returns 0, or -1 with a message and *rc. */
static int post_sources(view *v, int *rc, char *err, size_t err_size)
{
    const scene *s = v->s;
    v->aero_ids = calloc(s->aero_count + 1, sizeof *v->aero_ids);
    v->aero_done = calloc(s->aero_count + 1, sizeof *v->aero_done);
    if (!v->aero_ids || !v->aero_done) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    fg_result r = scene_aero_post_all(s, v->engine, v->aero_ids, err, err_size);
    if (r == FG_OK && (r = scene_fire_job_init(&v->fires, s, v->rate_hz, err, err_size)) == FG_OK)
        r = scene_fire_job_post_all(&v->fires, v->engine, err, err_size);
    if (r == FG_OK)
        return 0;
    *rc = r == FG_ERR_NO_MEMORY || r == FG_ERR_POOL_FULL || r == FG_ERR_QUEUE_FULL ? CLI_RUNTIME
                                                                                   : CLI_USAGE;
    return -1;
}

/* GL, engine, driver and threads up; the loop; everything down in reverse. */
static int view_scene(view *v)
{
    char err[512] = "";
    int rc = CLI_RUNTIME;
    fgg_context *ctx = NULL;
    fgg_picture *pic = NULL;
    pthread_t sim, audio;
    int started = 0;
    v->rate_hz = v->s->sample_rate_hz; /* a live device's, once open */
    v->block_frames = v->s->block_frames;
    fgg_context_config cc = {.backend = v->opt.backend, .width = v->opt.size.width,
                             .height = v->opt.size.height, .title = "fulgur view"};
    fgg_picture_config pc;
    picture_config(v->s, v->opt.size.width, v->opt.size.height, &pc);
    if (scene_build(v->s, err, sizeof err) != 0) {
        rc = CLI_USAGE;
        goto done;
    }
    if (view_timeline_init(v) != 0) {
        snprintf(err, sizeof err, "out of memory");
        goto done;
    }
    if (fgg_context_create(&cc, &ctx) != FG_OK || fgg_picture_create(ctx, &pc, &pic) != FG_OK) {
        snprintf(err, sizeof err, "--gl %s: %s", fgg_backend_name(v->opt.backend),
                 fgg_error_message());
        goto done;
    }
    v->pic = pic;
    if (!(v->source_ids = calloc(v->s->fire_count + v->s->aero_count + 1,
                                 sizeof *v->source_ids))) {
        snprintf(err, sizeof err, "out of memory");
        goto done;
    }
    if (picture_add_surroundings(pic, v->s, err, sizeof err) != 0 ||
        picture_sources_add(pic, v->s, 0.0, v->source_ids, err, sizeof err) != 0)
        goto done;
    char why[256];
    v->overlay = view_overlay_create(v->opt.size.height, why, sizeof why);
    v->overlay_on = v->opt.backend == FGG_BACKEND_WINDOW && v->overlay;
    if (!v->overlay && v->opt.backend == FGG_BACKEND_WINDOW)
        fprintf(stderr, "fulgur view: no overlay of the controls: %s\n", why);
    if (v->opt.backend == FGG_BACKEND_WINDOW && view_window_attach(v, ctx) != 0) {
        snprintf(err, sizeof err, "--gl window: this build has no GLFW input");
        goto done;
    }
    if (view_open_live(v, &v->rate_hz, &rc, err, sizeof err) != 0)
        goto done;
    rc = CLI_USAGE;
    if (scene_read_hrirs(v->s, v->opt.sofa, v->rate_hz, &v->hrirs, err, sizeof err) != 0)
        goto done;
    fg_engine_config cfg;
    scene_engine_config(v->s, &cfg); /* with the HRIRs */
    cfg.max_block_frames = v->block_frames;
    cfg.sample_rate_hz = v->rate_hz;
    rc = CLI_RUNTIME;
    if (fg_engine_create(&cfg, &v->engine) != FG_OK) {
        snprintf(err, sizeof err, "cannot create the engine");
        goto done;
    }
    fg_listener pose;
    scene_listener_at(v->s, 0, &pose); /* where the path starts, at time 0 */
    if (fg_engine_set_listener(v->engine, &pose) != FG_OK) { /* checked by the parser */
        snprintf(err, sizeof err, "the engine refused the scene's listener");
        goto done;
    }
    if (post_sources(v, &rc, err, sizeof err) != 0)
        goto done;
    rc = CLI_RUNTIME;
    for (uint32_t ch = 0; ch < v->s->channels; ch++)
        if (!(v->planes[ch] = calloc(v->block_frames, sizeof(float)))) {
            snprintf(err, sizeof err, "out of memory");
            goto done;
        }
    if (audio_driver_start(&v->driver, &v->opt.audio, v->rate_hz, v->s->channels,
                           v->block_frames, AUDIO_FRAMES_UNBOUNDED, (float)v->s->gain, err,
                           sizeof err))
        goto done;
    /* a live device's callback takes the audio thread's place */
    bool live = v->live != NULL;
    started = pthread_create(&sim, NULL, view_sim_thread, v) == 0;
    if (started && v->live)
        started += live_audio_start(v->live, err, sizeof err) == 0;
    else
        started += started && pthread_create(&audio, NULL, view_audio_thread, v) == 0;
    if (started == 2)
        rc = loop(v, ctx, pic, err, sizeof err);
    else if (!err[0])
        snprintf(err, sizeof err, "cannot start the threads");
    view_stop(v);
    live_audio_close(v->live); /* no callback after this */
    v->live = NULL;
    if (started >= 1)
        pthread_join(sim, NULL);
    if (started == 2 && !live)
        pthread_join(audio, NULL);
    take_replies(v, pic); /* answers the loop did not take: free them */
    for (view_request *q; (q = view_ring_pop(&v->to_sim));)
        free(q);
    if (rc == CLI_OK && v->sim_error[0]) {
        snprintf(err, sizeof err, "%s", v->sim_error);
        rc = CLI_RUNTIME;
    } else if (rc == CLI_OK && v->render_result != FG_OK) {
        snprintf(err, sizeof err, "render: %s", fg_result_str(v->render_result));
        rc = CLI_RUNTIME;
    } else if (rc == CLI_OK && v->audio_error[0]) {
        snprintf(err, sizeof err, "%s", v->audio_error);
        rc = CLI_RUNTIME;
    }
    char stop_err[512];
    if (audio_driver_stop(&v->driver, rc == CLI_OK, stop_err, sizeof stop_err) != 0 &&
        rc == CLI_OK) {
        snprintf(err, sizeof err, "%s", stop_err);
        rc = CLI_RUNTIME;
    }
    if (rc == CLI_OK)
        report(v, v->frames_drawn);
done:
    live_audio_close(v->live);
    fg_engine_destroy(v->engine);
    scene_fire_job_deinit(&v->fires);
    free(v->aero_ids);
    free(v->aero_done);
    free(v->source_ids);
    sofa_hrirs_free(&v->hrirs);
    for (uint32_t ch = 0; ch < SCENE_MAX_CHANNELS; ch++)
        free(v->planes[ch]);
    view_overlay_destroy(v->overlay);
    view_timeline_deinit(v);
    fgg_picture_destroy(pic);
    fgg_context_destroy(ctx);
    if (rc != CLI_OK)
        fprintf(stderr, "fulgur view: %s\n", err);
    return rc;
}

/* The scene in the layout asked for, which must have something to show: a
 * discharge (the first is the one space triggers), a fire or an aero
 * object; ambisonics only where no live device plays (they open 1 or 2
 * channels). */
static int load_scene(const view_options *opt, scene *s)
{
    char err[512];
    const char *path = opt->scene_path;
    if (scene_load(path, s, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur view: %s\n", err);
        return -1;
    }
    if (opt->layout.given)
        scene_set_layout(s, opt->layout.layout);
    bool live = audio_output_is_live(&opt->audio) &&
                (opt->audio.kind != AUDIO_DRIVER_AUTO || opt->backend == FGG_BACKEND_WINDOW);
    if (s->channels > 2 && live) {
        fprintf(stderr, "fulgur view: %s: layout: ambisonics of order %u is %u channels and the "
                        "live devices play 1 or 2: use --audio wav:FILE, raw:- or null\n",
                path, (unsigned)s->ambisonic_order, (unsigned)s->channels);
        scene_deinit(s);
        return -1;
    }
    if (s->discharge_count + s->fire_count + s->aero_count == 0) {
        fprintf(stderr, "fulgur view: %s: needs a discharge, a fire or an aero object to show\n",
                path);
        scene_deinit(s);
        return -1;
    }
    return 0;
}

int view_main(int argc, char **argv)
{
    view_options opt;
    options_result parsed = view_parse_options(argc, argv, &opt);
    if (parsed != OPTIONS_OK)
        return parsed == OPTIONS_HELP ? CLI_OK : CLI_USAGE;
    scene s;
    if (load_scene(&opt, &s) != 0)
        return CLI_USAGE;
    view *v = calloc(1, sizeof *v); /* large: the requests' state */
    if (!v) {
        fputs("fulgur view: out of memory\n", stderr);
        scene_deinit(&s);
        return CLI_RUNTIME;
    }
    v->opt = opt;
    v->s = &s;
    int rc = CLI_RUNTIME;
    if (!fg_ring_init(&v->to_sim, VIEW_RING_SIZE, sizeof(void *)) ||
        !fg_ring_init(&v->from_sim, VIEW_RING_SIZE, sizeof(void *))) {
        fputs("fulgur view: out of memory\n", stderr);
    } else {
        pthread_mutex_init(&v->lock, NULL);
        pthread_cond_init(&v->changed, NULL);
        rc = view_scene(v);
        pthread_cond_destroy(&v->changed);
        pthread_mutex_destroy(&v->lock);
    }
    fg_ring_deinit(&v->to_sim);
    fg_ring_deinit(&v->from_sim);
    scene_deinit(&s);
    free(v);
    return rc;
}
