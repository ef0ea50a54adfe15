/* fulgur run: the set-up, three threads, the report. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/commands.h"
#include "common/temp_file.h"
#include "run_gate.h"

/* --audio jack or portaudio: connects to the device, whose rate (JACK: the
 * server's) the engine then runs at. Returns 0, or -1 with a message and
 * *rc the exit code (CLI_USAGE when there is no server or device). */
static int open_live(run_ctx *run, int *rc, char *err, size_t err_size)
{
    const audio_output *out = &run->opt.audio;
    live_config lc = {.kind = out->kind == AUDIO_DRIVER_JACK ? LIVE_JACK : LIVE_PORTAUDIO,
                      .target = out->wav_path, .client_name = "fulgur",
                      .channels = run->s->channels, .rate_hz = run->rate_hz,
                      .block_frames = run->block_frames, .max_chunk_frames = run->block_frames,
                      .process = run_live_process, .user = run};
    live_result r = live_audio_open(&lc, &run->live, err, err_size);
    if (r != LIVE_OK) {
        *rc = r == LIVE_ABSENT ? CLI_USAGE : CLI_RUNTIME;
        return -1;
    }
    double rate = live_audio_rate_hz(run->live);
    if (run->opt.rate_hz && rate != run->opt.rate_hz) {
        snprintf(err, err_size, "--rate %u: %s runs at %.0f Hz", (unsigned)run->opt.rate_hz,
                 live_audio_describe(run->live), rate);
        *rc = CLI_USAGE;
        return -1;
    }
    run->rate_hz = rate;
    return 0;
}

/* Posts every aero object and every fire (each sounds from its own emit
 * time; a fire's ring filled as far as it takes, its sound made at the
 * run's rate, which a device's may make other than the scene's) before
 * the threads start: the sim thread then posts only discharges, and feeds
 * and moves the fires. Returns 0, or -1 with a message and *rc: a full
 * pool or queue or no memory is the run's (try --voices), the rest the
 * scene's. */
static int post_sources(run_ctx *run, int *rc, char *err, size_t err_size)
{
    fg_result r = scene_aero_post_all(run->s, run->engine, run->aero_ids, err, err_size);
    if (r == FG_OK && (r = scene_fire_job_init(&run->fires, run->s, run->rate_hz, err,
                                               err_size)) == FG_OK)
        r = scene_fire_job_post_all(&run->fires, run->engine, err, err_size);
    if (r == FG_OK)
        return 0;
    bool room = r == FG_ERR_POOL_FULL || r == FG_ERR_QUEUE_FULL;
    if (room)
        snprintf(err + strlen(err), err_size - strlen(err), " (try --voices)");
    *rc = room || r == FG_ERR_NO_MEMORY ? CLI_RUNTIME : CLI_USAGE;
    return -1;
}

/* Allocates what the threads use; the engine last. */
static int set_up(run_ctx *run, int *rc, char *err, size_t err_size)
{
    const scene *s = run->s;
    size_t n = s->discharge_count ? s->discharge_count : 1;
    run->paced = run->opt.audio.kind == AUDIO_DRIVER_NULL || audio_output_is_live(&run->opt.audio);
    run->block_frames = run->opt.block_frames ? run->opt.block_frames : s->block_frames;
    run->rate_hz = run->opt.rate_hz ? run->opt.rate_hz : s->sample_rate_hz;
    *rc = CLI_RUNTIME;
    if (audio_output_is_live(&run->opt.audio) && open_live(run, rc, err, err_size) != 0)
        return -1;
    double seconds = run->opt.seconds ? run->opt.seconds : s->duration_s;
    run->until_done = seconds == 0;
    run->limit_frames = (uint64_t)llround((seconds ? seconds : SCENE_MAX_DURATION_S) * run->rate_hz);
    run->order = scene_post_order(s);
    run->post_frame = calloc(n, sizeof *run->post_frame);
    run->post_ns = calloc(n, sizeof *run->post_ns);
    run->post_event_s = calloc(n, sizeof *run->post_event_s);
    run->adopt_frame = calloc(n, sizeof *run->adopt_frame);
    run->adopt_ns = calloc(n, sizeof *run->adopt_ns);
    run->aero_ids = calloc(s->aero_count + 1, sizeof *run->aero_ids);
    run->aero_done = calloc(s->aero_count + 1, sizeof *run->aero_done);
    bool planes = true;
    for (uint32_t ch = 0; ch < s->channels; ch++)
        planes &= (run->planes[ch] = calloc(run->block_frames, sizeof(float))) != NULL;
    /* callback and post call to 1 us up to 50 ms; jitter to 10 us up to 1 s */
    int hists = run_hist_init(&run->callback, 1e-6, 50000) |
                run_hist_init(&run->post_call, 1e-6, 50000) |
                run_hist_init(&run->jitter, 1e-5, 100000);
    if (!run->order || !run->post_frame || !run->post_ns || !run->post_event_s ||
        !run->adopt_frame || !run->adopt_ns || !run->aero_ids || !run->aero_done || !planes ||
        hists) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    if (run_gate_init(&run->gate) != 0) {
        snprintf(err, err_size, "cannot create the lock-step gate");
        return -1;
    }
    if (scene_read_hrirs(run->s, run->opt.sofa, run->rate_hz, &run->hrirs, err, err_size) != 0) {
        *rc = CLI_USAGE;
        return -1;
    }
    fg_engine_config cfg;
    scene_engine_config(s, &cfg);
    cfg.sample_rate_hz = run->rate_hz;
    cfg.max_block_frames = run->block_frames;
    cfg.max_voices = run->opt.voices;
    cfg.segment_capacity = run->opt.segments;
    fg_engine_config defaults;
    if (!cfg.segment_capacity && fg_engine_config_resolve(NULL, &defaults) == FG_OK) {
        /* as render does, for the trees known before the run */
        size_t explicit_segments = 0;
        for (size_t i = 0; i < s->discharge_count; i++)
            if (!s->discharges[i].generator)
                explicit_segments += s->discharges[i].post.node_count - 1;
        if (explicit_segments > defaults.segment_capacity)
            cfg.segment_capacity = explicit_segments > RUN_MAX_SEGMENTS
                                       ? RUN_MAX_SEGMENTS
                                       : (uint32_t)explicit_segments;
    }
    fg_result r = fg_engine_create(&cfg, &run->engine);
    if (r != FG_OK) {
        snprintf(err, err_size, "engine: %s", fg_result_str(r));
        return -1;
    }
    return post_sources(run, rc, err, err_size);
}

static void tear_down(run_ctx *run)
{
    live_audio_close(run->live); /* no callback after this */
    run->live = NULL;
    fg_engine_destroy(run->engine);
    scene_fire_job_deinit(&run->fires);
    sofa_hrirs_free(&run->hrirs);
    run_gate_deinit(&run->gate);
    free(run->order);
    free(run->post_frame);
    free(run->post_ns);
    free(run->post_event_s);
    free(run->adopt_frame);
    free(run->adopt_ns);
    free(run->aero_ids);
    free(run->aero_done);
    for (uint32_t ch = 0; ch < SCENE_MAX_CHANNELS; ch++)
        free(run->planes[ch]);
    run_hist_deinit(&run->callback);
    run_hist_deinit(&run->post_call);
    run_hist_deinit(&run->jitter);
}

/* A live device plays the audio thread's part: started after the frame
 * and sim threads, it runs until its callback or the sim thread stops the
 * run (or the server goes away), then it is closed before they are joined. */
static int run_live(run_ctx *run, char *err, size_t err_size)
{
    if (live_audio_start(run->live, err, err_size) != 0)
        return -1;
    while (!run_stopping(run) && !live_audio_lost(run->live))
        monotonic_sleep_until_ns(monotonic_now_ns() + 10000000);
    int lost = live_audio_lost(run->live) && !run_stopping(run);
    run->live_xruns = live_audio_xruns(run->live);
    live_audio_close(run->live); /* the callbacks end here */
    run->live = NULL;
    if (lost) {
        snprintf(err, err_size, "the sound server went away (at frame %llu)",
                 (unsigned long long)run->frames_out);
        return -1;
    }
    return 0;
}

/* Starts the three threads (two and the live device) and joins them.
 * Returns -1 with a message when one could not start (the others are
 * stopped and joined) or the live device failed. */
static int run_threads(run_ctx *run, char *err, size_t err_size)
{
    void *(*const bodies[3])(void *) = {run_frame_thread, run_sim_thread, run_audio_thread};
    bool live = run->live != NULL;
    int wanted = live ? 2 : 3;
    pthread_t threads[3];
    int started = 0;
    run->start_ns = monotonic_now_ns();
    while (started < wanted && pthread_create(&threads[started], NULL, bodies[started], run) == 0)
        started++;
    int live_failed = started == wanted && live && run_live(run, err, err_size) != 0;
    if (started < wanted || live || live_failed)
        run_stop(run);
    for (int i = 0; i < started; i++)
        pthread_join(threads[i], NULL);
    if (started < wanted) {
        snprintf(err, err_size, "cannot start the threads");
        return -1;
    }
    return live_failed ? -1 : 0;
}

/* Writes the report's text to to (a stream of the report's temporary file,
 * or stdout/stderr). */
static int write_report(const run_ctx *run, double wall_s, FILE *to, char *err, size_t err_size)
{
    char *text = run_report_json(run, wall_s);
    if (!text) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    int bad = !to || fprintf(to, "%s\n", text) < 0 || fflush(to) != 0;
    free(text);
    if (bad)
        snprintf(err, err_size, "writing the report failed");
    return bad ? -1 : 0;
}

/* The WAV (if any) and the report file (if any) are written to temporaries
 * and committed together once the run succeeded: a failure leaves neither. */
static int run_scene(run_ctx *run)
{
    char err[512] = "";
    const char *report_path = run->opt.report_path;
    temp_file report;
    if (report_path && temp_file_open(&report, report_path, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    int rc = CLI_RUNTIME;
    int ok = set_up(run, &rc, err, sizeof err) == 0 &&
             audio_driver_start(&run->driver, &run->opt.audio, run->rate_hz, run->s->channels,
                                run->block_frames, run->limit_frames, (float)run->s->gain, err,
                                sizeof err) == 0;
    if (!ok) {
        tear_down(run);
        if (report_path)
            temp_file_abort(&report);
        fprintf(stderr, "fulgur: %s\n", err);
        return rc;
    }
    if (run->live)
        snprintf(run->live_description, sizeof run->live_description, "%s",
                 live_audio_describe(run->live));
    uint64_t t0 = monotonic_now_ns();
    ok = run_threads(run, err, sizeof err) == 0;
    double wall_s = (double)(monotonic_now_ns() - t0) * 1e-9;
    int fail_rc = CLI_RUNTIME;
    if (ok && run->sim_error[0]) {
        snprintf(err, sizeof err, "%s", run->sim_error);
        fail_rc = run->sim_error_in_scene ? CLI_USAGE : CLI_RUNTIME;
        ok = 0;
    } else if (ok && run->frame_error[0]) {
        snprintf(err, sizeof err, "%s", run->frame_error);
        fail_rc = CLI_USAGE; /* the scene's motion */
        ok = 0;
    } else if (ok && run->render_result != FG_OK) {
        snprintf(err, sizeof err, "render at frame %llu: %s",
                 (unsigned long long)run->frames_out, fg_result_str(run->render_result));
        ok = 0;
    } else if (ok && run->audio_error[0]) {
        snprintf(err, sizeof err, "%s", run->audio_error);
        ok = 0;
    }
    if (ok && report_path)
        ok = write_report(run, wall_s, temp_file_stream(&report), err, sizeof err) == 0;
    char stop_err[512];
    if (audio_driver_stop(&run->driver, ok, stop_err, sizeof stop_err) != 0 && ok) {
        snprintf(err, sizeof err, "%s", stop_err);
        ok = 0;
    }
    if (report_path) {
        if (ok)
            ok = temp_file_commit(&report, err, sizeof err) == 0;
        else
            temp_file_abort(&report);
    } else if (ok) {
        FILE *to = run->opt.audio.kind == AUDIO_DRIVER_RAW ? stderr : stdout;
        ok = write_report(run, wall_s, to, err, sizeof err) == 0;
    }
    tear_down(run);
    if (!ok) {
        fprintf(stderr, "fulgur: %s\n", err);
        return fail_rc;
    }
    return CLI_OK;
}

int run_main(int argc, char **argv)
{
    run_options opt;
    options_result parsed = run_parse_options(argc, argv, &opt);
    if (parsed != OPTIONS_OK)
        return parsed == OPTIONS_HELP ? CLI_OK : CLI_USAGE;
    char err[512];
    if ((opt.audio.kind == AUDIO_DRIVER_WAV &&
         temp_file_check_output(opt.audio.wav_path, opt.scene_path, err, sizeof err) != 0) ||
        (opt.report_path &&
         temp_file_check_output(opt.report_path, opt.scene_path, err, sizeof err) != 0)) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_USAGE;
    }
    scene s;
    if (scene_load(opt.scene_path, &s, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_USAGE;
    }
    if (opt.layout.given)
        scene_set_layout(&s, opt.layout.layout);
    if (s.channels > 2 && audio_output_is_live(&opt.audio)) { /* live_audio.h: 1 or 2 */
        fprintf(stderr, "fulgur: %s: layout: ambisonics of order %u is %u channels and the live "
                        "devices play 1 or 2: use --audio wav:FILE or raw:-\n",
                opt.scene_path, (unsigned)s.ambisonic_order, (unsigned)s.channels);
        scene_deinit(&s);
        return CLI_USAGE;
    }
    int rc = CLI_RUNTIME;
    run_ctx *run = calloc(1, sizeof *run); /* large: the measurements' state */
    if (run) {
        run->opt = opt;
        run->s = &s;
        rc = run_scene(run);
    } else {
        fputs("fulgur: out of memory\n", stderr);
    }
    free(run);
    scene_deinit(&s);
    return rc;
}
