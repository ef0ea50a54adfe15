/* fulgur render: a scene through the real-time engine, block by block, into
 * a 32-bit float WAV. The engine is driven exactly as a device callback
 * would drive it; nothing else synthesizes sound. */
#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>

#include "common/audio_file.h"
#include "common/calibration.h"
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
    "Levels: by default a sample is the pressure in pascals (times the scene's \"gain\"),\n"
    "so 1.0 (full scale) is 1 Pa and loud scenes exceed it: players clip them (a warning\n"
    "says so). --gain-db or --normalize make a listenable file; its calibration, the\n"
    "pascals that full scale stands for, is then written into the WAV's comment\n"
    "(LIST/INFO ICMT, \"fulgur calibration: full scale = X Pa\") and printed, and\n"
    "fulgur analyze reads it back to pascals.\n"
    "Exit: 0 done, 1 runtime error, 2 bad arguments or scene (the message names the path).\n";

/* The level of the written samples, from the command line. */
typedef struct render_level {
    double gain_db;        /* NAN: not given */
    double normalize_dbfs; /* NAN: not given; else the peak wanted */
} render_level;

typedef struct render_job {
    const scene *s;
    fg_engine *engine;
    size_t *order;          /* the discharge indices by emit time, then index */
    size_t next;            /* the next of order to post */
    float *planes[2];
    float *interleaved;
    SNDFILE *wav;           /* NULL: a pass that only measures the peak */
    float scale;            /* a sample = pascals x scale */
    double peak;            /* the largest |sample| written (or measured) */
    size_t segments;
} render_job;

static int create_engine(render_job *job, char *err, size_t err_size)
{
    const scene *s = job->s;
    size_t capacity = 0; /* a ground image counts each segment twice (fulgur/engine.h) */
    for (size_t i = 0; i < s->discharge_count; i++) {
        const fg_discharge *d = &s->discharges[i].post;
        job->segments += d->node_count - 1;
        capacity += (d->node_count - 1) * (d->propagation.ground_reflection > 0 ? 2 : 1);
    }
    fg_engine_config cfg;
    scene_engine_config(s, &cfg);
    cfg.max_voices = (uint32_t)s->discharge_count;
    cfg.segment_capacity = capacity > UINT32_MAX ? UINT32_MAX : (uint32_t)capacity;
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
    audio_interleave(job->planes, job->s->channels, frames, job->scale, job->interleaved);
    for (size_t i = 0; i < (size_t)frames * job->s->channels; i++)
        job->peak = fmax(job->peak, fabs(job->interleaved[i]));
    if (job->wav && sf_writef_float(job->wav, job->interleaved, frames) != frames) {
        snprintf(err, err_size, "writing the WAV: %s", sf_strerror(job->wav));
        return -1;
    }
    return 0;
}

/* The block loop; *frames_out receives the frames written. */
static int run(render_job *job, uint64_t *frames_out, char *err, size_t err_size)
{
    const scene *s = job->s;
    double rate = s->sample_rate_hz;
    uint64_t limit = (uint64_t)llround((s->duration_s > 0 ? s->duration_s : SCENE_MAX_DURATION_S) *
                                       rate);
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

/* A file at a level other than pascals says which (common/calibration.h);
 * one in pascals stays byte for byte what it always was. */
static int open_wav(render_job *job, temp_file *out, char *err, size_t err_size)
{
    job->wav = audio_wav_open(out->fd, out->path, job->s->sample_rate_hz, job->s->channels, err,
                              err_size);
    if (!job->wav)
        return -1;
    return job->scale == 1.0f ? 0 : calibration_write(job->wav, 1.0 / job->scale, err, err_size);
}

static void release(render_job *job)
{
    fg_engine_destroy(job->engine);
    free(job->order);
    free(job->interleaved);
    free(job->planes[0]);
    free(job->planes[1]);
}

/* --normalize: the peak of a pass that renders without writing, at the
 * scene's gain. The engine is deterministic: the written pass repeats
 * these samples exactly, scaled. */
static int measure_peak(const scene *s, double *peak, char *err, size_t err_size)
{
    render_job job = {.s = s, .scale = (float)s->gain};
    uint64_t frames;
    int rc = create_engine(&job, err, err_size) == 0 && run(&job, &frames, err, err_size) == 0
                 ? 0 : -1;
    *peak = job.peak;
    release(&job);
    return rc;
}

/* The scale of the written samples: the scene's gain, times --gain-db, or
 * what brings the peak to --normalize. Returns -1 with a message. */
static int level_scale(const scene *s, const render_level *level, float *scale, char *err,
                       size_t err_size)
{
    double gain = s->gain;
    if (!isnan(level->gain_db))
        gain *= pow(10, level->gain_db / 20);
    if (!isnan(level->normalize_dbfs)) {
        double peak;
        if (measure_peak(s, &peak, err, err_size) != 0)
            return -1;
        if (!(peak > 0)) {
            snprintf(err, err_size, "--normalize: the scene is silent (peak 0): nothing to scale");
            return -1;
        }
        gain *= pow(10, level->normalize_dbfs / 20) / peak;
    }
    *scale = (float)gain;
    if (!(*scale > 0) || !isfinite(*scale)) {
        snprintf(err, err_size, "the level gives a scale of %g, outside a 32-bit float", gain);
        return -1;
    }
    return 0;
}

static int render_file(const scene *s, const char *out_path, const render_level *level)
{
    char err[512];
    render_job job = {.s = s};
    temp_file out;
    uint64_t frames = 0;
    uint64_t t0 = monotonic_now_ns();
    int ok = level_scale(s, level, &job.scale, err, sizeof err) == 0 &&
             create_engine(&job, err, sizeof err) == 0 &&
             temp_file_open(&out, out_path, err, sizeof err) == 0;
    if (!ok) {
        release(&job);
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    ok = open_wav(&job, &out, err, sizeof err) == 0 && run(&job, &frames, err, sizeof err) == 0;
    if (job.wav && sf_close(job.wav) != 0 && ok) {
        snprintf(err, sizeof err, "%s: closing the WAV failed", out_path);
        ok = 0;
    }
    if (ok)
        ok = temp_file_commit(&out, err, sizeof err) == 0;
    else
        temp_file_abort(&out);
    fg_engine_report stats;
    fg_engine_get_report(job.engine, &stats);
    release(&job);
    if (!ok) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    double wall = (double)(monotonic_now_ns() - t0) * 1e-9;
    double seconds = (double)frames / s->sample_rate_hz;
    double full_scale_pa = 1.0 / job.scale;
    printf("%s: %zu discharges, %zu segments, %.3f s of sound (%u ch, %.0f Hz) in %.3f s wall, "
           "%llu late events (%llu late samples); peak %+.1f dBFS, full scale = %.6g Pa%s\n",
           out_path, s->discharge_count, job.segments, seconds, (unsigned)s->channels,
           s->sample_rate_hz, wall, (unsigned long long)stats.late_events,
           (unsigned long long)stats.late_samples, calibration_dbfs(job.peak), full_scale_pa,
           job.scale == 1.0f ? " (pascals)" : " (in the WAV's comment)");
    if (job.peak > 1.0)
        fprintf(stderr,
                "fulgur: warning: %s peaks at %+.1f dBFS (%.4g Pa): a player clips it above "
                "0 dBFS; --normalize -1 makes it listenable\n",
                out_path, calibration_dbfs(job.peak), job.peak * full_scale_pa);
    return CLI_OK;
}

int render_main(int argc, char **argv)
{
    const char *scene_path = NULL, *out_path = NULL, *png_path = NULL;
    double png_time = NAN; /* NAN: not given (the parser takes finite numbers only) */
    render_level level = {NAN, NAN};
    const option table[] = {
        {"-o", OPTION_TEXT, &out_path, "OUT.wav", .help = "the WAV to write", .required = true},
        {"--png", OPTION_TEXT, &png_path, "OUT.png",
         .help = "also draw the discharges (docs/picture.md) from the scene's\n"
                 "\"camera\" into a PNG (needs gpu/: FULGUR_GPU)"},
        {"--png-time", OPTION_NUMBER, &png_time, "SECONDS",
         .help = "the picture's time (default: the first return stroke)",
         .range = {.lo = -INFINITY, .hi = INFINITY}},
        {"--gain-db", OPTION_NUMBER, &level.gain_db, "DB",
         .help = "multiply the samples by 10^(DB/20) (default 0: pascals)",
         .range = {.lo = -200, .hi = 200}},
        {"--normalize", OPTION_NUMBER, &level.normalize_dbfs, "PEAK_DBFS",
         .help = "scale the samples so that the peak is PEAK_DBFS, e.g. -1\n"
                 "(renders twice: once to find the peak)",
         .range = {.lo = -100, .hi = 0}},
        {0},
    };
    const command_line cl = {"fulgur render", "SCENE.json", 1, 1, about, notes, table};
    size_t operands;
    options_result parsed = options_parse(&cl, argc, argv, &scene_path, &operands);
    if (parsed == OPTIONS_OK && !isnan(png_time) && !png_path)
        parsed = options_fail(&cl, "--png-time needs --png");
    if (parsed == OPTIONS_OK && !isnan(level.gain_db) && !isnan(level.normalize_dbfs))
        parsed = options_fail(&cl, "--gain-db and --normalize both set the level: give one");
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
    int rc = render_file(&s, out_path, &level);
#ifdef FULGUR_HAVE_GPU
    if (rc == CLI_OK && png_path &&
        render_picture(&s, png_path, png_time, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        rc = CLI_RUNTIME;
    }
#endif
    scene_deinit(&s);
    return rc;
}
