/* fulgur render: a scene through the real-time engine, block by block, into
 * a 32-bit float WAV. The engine is driven exactly as a device callback
 * would drive it; nothing else synthesizes sound. */
#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>

#include "common/audio_file.h"
#include "common/clock.h"
#include "common/commands.h"
#include "common/options.h"
#include "common/temp_file.h"
#include "scene/scene.h"
#ifdef FULGUR_HAVE_GPU
#include "render_picture.h"
#endif

/* Discharges are posted this long before their emit time, so the engine
 * prepares them off the audio path, as a simulation thread would. */
#define POST_LEAD_S 0.5

static const char about[] =
    "Renders the scene (docs/scene-format.md) through fg_engine_render in blocks of the\n"
    "scene's \"block\" frames and writes 32-bit float WAV in pascals times \"gain\".\n";

static const char notes[] =
    "Exit: 0 done, 1 runtime error, 2 bad arguments or scene (the message names the path).\n";

typedef struct render_job {
    const scene *s;
    fg_engine *engine;
    size_t *order;          /* the discharge indices by emit time, then index */
    size_t next;            /* the next of order to post */
    float *planes[2];
    float *interleaved;
    SNDFILE *wav;
    size_t segments;
} render_job;

static int create_engine(render_job *job, char *err, size_t err_size)
{
    const scene *s = job->s;
    for (size_t i = 0; i < s->discharge_count; i++)
        job->segments += s->discharges[i].post.node_count - 1;
    fg_engine_config cfg;
    scene_engine_config(s, &cfg);
    cfg.max_voices = (uint32_t)s->discharge_count;
    cfg.segment_capacity = job->segments > UINT32_MAX ? UINT32_MAX : (uint32_t)job->segments;
    fg_result r = fg_engine_create(&cfg, &job->engine);
    if (r != FG_OK) {
        snprintf(err, err_size, "engine for %zu discharges and %zu segments: %s",
                 s->discharge_count, job->segments, fg_result_str(r));
        return -1;
    }
    job->order = scene_post_order(s);
    job->interleaved = malloc((size_t)s->block_frames * s->channels * sizeof(float));
    for (uint32_t ch = 0; ch < s->channels; ch++)
        job->planes[ch] = malloc((size_t)s->block_frames * sizeof(float));
    if (!job->order || !job->interleaved || !job->planes[0] ||
        (s->channels == 2 && !job->planes[1])) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    return 0;
}

/* Posts every discharge whose emit time falls before horizon_s. */
static int post_due(render_job *job, double horizon_s, char *err, size_t err_size)
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
            return -1;
        }
    }
    return 0;
}

static int write_block(render_job *job, uint32_t frames, char *err, size_t err_size)
{
    audio_interleave(job->planes, job->s->channels, frames, (float)job->s->gain, job->interleaved);
    if (sf_writef_float(job->wav, job->interleaved, frames) != frames) {
        snprintf(err, err_size, "writing the WAV: %s", sf_strerror(job->wav));
        return -1;
    }
    return 0;
}

/* The most frames a render of s writes: its duration, else the cap. */
static uint64_t frame_limit(const scene *s)
{
    return (uint64_t)llround((s->duration_s > 0 ? s->duration_s : SCENE_MAX_DURATION_S) *
                             s->sample_rate_hz);
}

/* The block loop; *frames_out receives the frames written. */
static int run(render_job *job, uint64_t *frames_out, char *err, size_t err_size)
{
    const scene *s = job->s;
    double rate = s->sample_rate_hz;
    uint64_t limit = frame_limit(s);
    uint64_t frame = 0;
    while (frame < limit) {
        double t = (double)frame / rate;
        fg_listener pose;
        scene_listener_at(s, t, &pose);
        fg_result r = fg_engine_set_listener(job->engine, &pose);
        if (r != FG_OK) {
            snprintf(err, err_size, "listener at %.6f s: %s (forward and up interpolate to "
                                    "parallel directions?)", t, fg_result_str(r));
            return -1;
        }
        uint32_t n = limit - frame < s->block_frames ? (uint32_t)(limit - frame) : s->block_frames;
        if (post_due(job, t + n / rate + POST_LEAD_S, err, err_size) != 0)
            return -1;
        r = fg_engine_render(job->engine, job->planes, n);
        if (r != FG_OK) {
            snprintf(err, err_size, "render at %.6f s: %s", t, fg_result_str(r));
            return -1;
        }
        if (write_block(job, n, err, err_size) != 0)
            return -1;
        fg_engine_collect(job->engine);
        frame += n;
        fg_engine_report stats;
        fg_engine_get_report(job->engine, &stats);
        if (s->duration_s == 0 && job->next == s->discharge_count &&
            stats.finished == s->discharge_count)
            break;
    }
    if (s->duration_s == 0 && frame == limit)
        fprintf(stderr, "fulgur: stopped at the %.0f s cap with discharges still sounding\n",
                SCENE_MAX_DURATION_S);
    *frames_out = frame;
    return 0;
}

static int open_wav(render_job *job, temp_file *out, char *err, size_t err_size)
{
    job->wav = audio_wav_open(out->fd, out->path, job->s->sample_rate_hz, job->s->channels,
                              frame_limit(job->s), err, err_size);
    return job->wav ? 0 : -1;
}

static void release(render_job *job)
{
    fg_engine_destroy(job->engine);
    free(job->order);
    free(job->interleaved);
    free(job->planes[0]);
    free(job->planes[1]);
}

/* The picture (--png) into its temporary file, when asked for. */
static int draw(const scene *s, temp_file *png, double png_time, char *err, size_t err_size)
{
    if (!png->path)
        return 0;
#ifdef FULGUR_HAVE_GPU
    return render_picture(s, png->temp_path, png->path, png_time, err, err_size);
#else
    (void)s;
    (void)png_time;
    snprintf(err, err_size, "--png needs gpu/");
    return -1;
#endif
}

/* Renders the WAV and draws the picture (png->path NULL: none) into
 * temporary files and commits them together: a failure of either leaves
 * neither. */
static int render_file(const scene *s, const char *out_path, temp_file *png, double png_time)
{
    char err[512];
    render_job job = {.s = s};
    temp_file out;
    uint64_t frames = 0;
    uint64_t t0 = monotonic_now_ns();
    int ok = create_engine(&job, err, sizeof err) == 0 &&
             temp_file_open(&out, out_path, err, sizeof err) == 0;
    if (!ok) {
        release(&job);
        if (png->path)
            temp_file_abort(png);
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    ok = open_wav(&job, &out, err, sizeof err) == 0 && run(&job, &frames, err, sizeof err) == 0;
    if (job.wav && sf_close(job.wav) != 0 && ok) {
        snprintf(err, sizeof err, "%s: closing the WAV failed", out_path);
        ok = 0;
    }
    if (ok)
        ok = draw(s, png, png_time, err, sizeof err) == 0;
    if (ok)
        ok = temp_file_commit(&out, err, sizeof err) == 0;
    else
        temp_file_abort(&out);
    if (png->path) {
        if (ok)
            ok = temp_file_commit(png, err, sizeof err) == 0;
        else
            temp_file_abort(png);
    }
    fg_engine_report stats;
    fg_engine_get_report(job.engine, &stats);
    release(&job);
    if (!ok) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    double wall = (double)(monotonic_now_ns() - t0) * 1e-9;
    double seconds = (double)frames / s->sample_rate_hz;
    printf("%s: %zu discharges, %zu segments, %.3f s of sound (%u ch, %.0f Hz) in %.3f s wall, "
           "%llu late events (%llu late samples)\n",
           out_path, s->discharge_count, job.segments, seconds, (unsigned)s->channels,
           s->sample_rate_hz, wall, (unsigned long long)stats.late_events,
           (unsigned long long)stats.late_samples);
    return CLI_OK;
}

int render_main(int argc, char **argv)
{
    const char *scene_path = NULL, *out_path = NULL, *png_path = NULL;
    double png_time = NAN; /* NAN: not given (the parser takes finite numbers only) */
    const option table[] = {
        {"-o", OPTION_TEXT, &out_path, "OUT.wav", .help = "the WAV to write", .required = true},
        {"--png", OPTION_TEXT, &png_path, "OUT.png",
         .help = "also draw the discharges (docs/picture.md) from the scene's\n"
                 "\"camera\" into a PNG (needs gpu/: FULGUR_GPU)"},
        {"--png-time", OPTION_NUMBER, &png_time, "SECONDS",
         .help = "the picture's time (default: the first return stroke)",
         .range = {.lo = -INFINITY, .hi = INFINITY}},
        {0},
    };
    const command_line cl = {"fulgur render", "SCENE.json", 1, 1, about, notes, table};
    size_t operands;
    options_result parsed = options_parse(&cl, argc, argv, &scene_path, &operands);
    if (parsed == OPTIONS_OK && !isnan(png_time) && !png_path)
        parsed = options_fail(&cl, "--png-time needs --png");
    if (parsed != OPTIONS_OK)
        return parsed == OPTIONS_HELP ? CLI_OK : CLI_USAGE;
#ifndef FULGUR_HAVE_GPU
    if (png_path) {
        options_fail(&cl, "--png needs the picture, and this fulgur was built without gpu/ "
                          "(configure with -DFULGUR_GPU=ON, libepoxy, EGL, libpng)");
        return CLI_USAGE;
    }
#endif
    char err[512];
    if (temp_file_check_output(out_path, scene_path, err, sizeof err) != 0 ||
        (png_path && temp_file_check_output(png_path, scene_path, err, sizeof err) != 0)) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_USAGE;
    }
    scene s;
    if (scene_load(scene_path, &s, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_USAGE;
    }
    if (scene_build(&s, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        scene_deinit(&s);
        return CLI_USAGE;
    }
    temp_file png = {.fd = -1};
    if (png_path && temp_file_open(&png, png_path, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        scene_deinit(&s);
        return CLI_RUNTIME;
    }
    int rc = render_file(&s, out_path, &png, png_time);
    scene_deinit(&s);
    return rc;
}
