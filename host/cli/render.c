/* fulgur render: scenes through the real-time engine (scene/scene_render.h,
 * the loop libfulgur-scene shares), each into a 32-bit float WAV. */
#define _POSIX_C_SOURCE 200809L /* fileno */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "common/audio_file.h"
#include "common/calibration.h"
#include "common/clock.h"
#include "common/commands.h"
#include "common/options.h"
#include "common/progress.h"
#include "common/sofa_hrir.h"
#include "common/temp_file.h"
#include "render_manifest.h"
#include "render_output.h"
#include "scene/scene.h"
#include "scene/scene_render.h"
#ifdef FULGUR_HAVE_GPU
#include "gl_module.h"
#endif

/* --set at most, per call. */
#define MAX_SETS 256

static const char about[] =
    "Renders each scene (docs/scene-format.md) through fg_engine_render in blocks of the\n"
    "scene's \"block\" frames (512 when it gives none) and writes 32-bit float WAV in\n"
    "pascals times \"gain\".\n"
    "Several scenes: -o names a directory (SCENE's NAME.wav in it) or a pattern with\n"
    "{name} and {index} (out/{name}-{index}.wav). Every scene is read and checked\n"
    "before the first is rendered. On a terminal, work longer than 2 s shows a\n"
    "progress line (docs/batch.md).\n";

static const char notes[] =
    "Levels: by default a sample is the pressure in pascals (times the scene's \"gain\"),\n"
    "so 1.0 (full scale) is 1 Pa and loud scenes exceed it: players clip them (a warning\n"
    "says so). --gain-db or --normalize make a listenable file; its calibration, the\n"
    "pascals that full scale stands for, is then written into the WAV's comment\n"
    "(LIST/INFO ICMT, \"fulgur calibration: full scale = X Pa\") and printed, and\n"
    "fulgur analyze reads it back to pascals.\n"
    "Layouts (docs/spatial.md; --layout, else the scene's \"layout\"): stereo (the default)\n"
    "is the scene's \"channels\", left and right ears on a spherical head;\n"
    "ambisonics:ORDER writes AmbiX, (ORDER+1)^2 channels in ACN order with SN3D\n"
    "normalisation (4, 9 or 16 for orders 1, 2, 3); binaural writes left and right\n"
    "through the measured HRIRs of a SOFA file (--sofa, else layout.sofa, default the\n"
    "MIT KEMAR set of Debian's libmysofa1), 64 frames late.\n"
    "Exit: 0 done, 1 runtime error, 2 bad arguments or scene (the message names the path).\n";

/* The --set values, in order. */
typedef struct set_list {
    const char *items[MAX_SETS];
    size_t count;
} set_list;

static int add_set(const char *text, void *value, char *why, size_t why_size)
{
    set_list *list = value;
    if (list->count == MAX_SETS) {
        snprintf(why, why_size, "more than %d --set", MAX_SETS);
        return -1;
    }
    list->items[list->count++] = text;
    return 0;
}

/* The level of the written samples, from the command line. */
typedef struct render_level {
    double gain_db;        /* NAN: not given */
    double normalize_dbfs; /* NAN: not given; else the peak wanted */
} render_level;

/* What the sink writes a scene's blocks into. */
typedef struct wav_sink {
    const scene *s;
    audio_wav *wav;        /* NULL: a pass that only measures the peak */
    float scale;           /* a sample = pascals x scale */
    const char *path;
    float *interleaved;    /* capacity frames; the first `buffered` await writing */
    uint32_t capacity, buffered;
    float peak;
    uint64_t frames;
    /* the frames of the first and the last sample above AUDIBLE_PA
     * (UINT64_MAX, 0 while there is none) */
    uint64_t first_audible, last_audible;
    progress *line;
} wav_sink;

/* The sink gathers blocks into writes of at least this many bytes: one
 * write() per block of 256 stereo frames (2 KiB) costs four times the
 * CPU (issue 17's profile). The bytes written are the same. */
#define WAV_WRITE_BYTES (64u * 1024u)

/* Frames of interleaved room for s: a block at least, WAV_WRITE_BYTES or
 * more. */
static uint32_t sink_capacity(const scene *s)
{
    uint32_t frames = WAV_WRITE_BYTES / (uint32_t)(s->channels * sizeof(float));
    uint32_t block = scene_render_block_frames(s);
    return frames > block ? frames : block;
}

/* Writes the gathered frames; FG_ERR_IO with a message when it fails. */
static fg_result flush_sink(wav_sink *w, char *err, size_t err_size)
{
    uint64_t n = w->buffered;
    w->buffered = 0;
    if (w->wav && n > 0 && audio_wav_write(w->wav, w->interleaved, n, err, err_size) != 0)
        return FG_ERR_IO;
    return FG_OK;
}

/* A sample above 20 uPa (0 dB SPL, the threshold of hearing at 1 kHz,
 * ISO 226) is sound; a render whose sound spans less than
 * MOSTLY_SILENT_SHARE of its length, when it lasts MOSTLY_SILENT_MIN_S or
 * more, is mostly silence, and render says so (a far listener, a late
 * discharge or a slow return stroke once wrote an hour of silence without
 * a word). */
#define AUDIBLE_PA 20e-6
#define MOSTLY_SILENT_SHARE 0.1
#define MOSTLY_SILENT_MIN_S 1.0

/* Whether frame f of a block of interleaved frames holds a sample above
 * audible. */
static bool frame_audible(const float *block, uint32_t channels, uint32_t f, float audible)
{
    for (uint32_t ch = 0; ch < channels; ch++)
        if (fabsf(block[(size_t)f * channels + ch]) > audible)
            return true;
    return false;
}

/* Where the block's sound (its interleaved frames) starts and ends, in
 * frames of the render: its last audible frame, looked for from the end,
 * and its first until the render's first is known. */
static void note_audible(wav_sink *w, const float *block, uint32_t frames)
{
    const uint32_t channels = w->s->channels;
    const float audible = (float)(AUDIBLE_PA * w->scale);
    uint32_t end = frames;
    while (end > 0 && !frame_audible(block, channels, end - 1, audible))
        end--;
    if (end == 0)
        return;
    w->last_audible = w->frames + end - 1;
    if (w->first_audible == UINT64_MAX) {
        uint32_t f = 0;
        while (!frame_audible(block, channels, f, audible))
            f++;
        w->first_audible = w->frames + f;
    }
}

static fg_result write_block(void *context, float *const *planes, uint32_t frames, char *err,
                             size_t err_size)
{
    wav_sink *w = context;
    if (w->capacity - w->buffered < frames && flush_sink(w, err, err_size) != FG_OK)
        return FG_ERR_IO;
    float *to = w->interleaved + (size_t)w->buffered * w->s->channels;
    audio_interleave(planes, w->s->channels, frames, w->scale, to);
    w->peak = audio_peak(to, (size_t)frames * w->s->channels, w->peak);
    note_audible(w, to, frames);
    if (w->wav) /* the --normalize pass keeps nothing */
        w->buffered += frames;
    w->frames += frames;
    if (w->line) /* NULL: the --normalize pass */
        progress_update(w->line, (double)w->frames / w->s->sample_rate_hz, monotonic_now_ns());
    return FG_OK;
}

/* The warning of a render that is silent or mostly silence. */
static void warn_silence(const char *out_path, const wav_sink *w)
{
    double rate = w->s->sample_rate_hz, length_s = (double)w->frames / rate;
    if (length_s < MOSTLY_SILENT_MIN_S)
        return;
    if (w->first_audible == UINT64_MAX) {
        fprintf(stderr, "fulgur: warning: %s is silent: no sample above %.0f uPa (0 dB SPL) in "
                        "its %.3f s\n",
                out_path, AUDIBLE_PA * 1e6, length_s);
        return;
    }
    double sound_s = (double)(w->last_audible - w->first_audible + 1) / rate;
    if (sound_s < MOSTLY_SILENT_SHARE * length_s)
        fprintf(stderr,
                "fulgur: warning: %s is mostly silence: its sound (above %.0f uPa, 0 dB SPL) "
                "spans %.3f s (%.3f to %.3f s) of its %.3f s; a far listener, a late "
                "discharge or a slow return stroke? (\"duration\" sets the length)\n",
                out_path, AUDIBLE_PA * 1e6, sound_s, w->first_audible / rate,
                (w->last_audible + 1) / rate, length_s);
}

/* What one file's render gives the manifest. */
typedef struct render_result {
    uint64_t frames;
    float peak;
    float scale;
} render_result;

/* --normalize: the peak of a pass that renders without writing, at the
 * scene's gain. The engine is deterministic: the written pass repeats
 * these samples exactly, scaled. */
static int measure_peak(const scene *s, double *peak, char *err, size_t err_size)
{
    wav_sink w = {.s = s,
                  .scale = (float)s->gain,
                  .capacity = scene_render_block_frames(s),
                  .first_audible = UINT64_MAX};
    w.interleaved = malloc((size_t)w.capacity * s->channels * sizeof(float));
    if (!w.interleaved) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    scene_render_sink sink = {write_block, &w};
    int rc = scene_render(s, &sink, NULL, err, err_size) == FG_OK ? 0 : -1;
    free(w.interleaved);
    *peak = w.peak;
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

/* A file at a level other than pascals says which (common/calibration.h);
 * one in pascals stays byte for byte what it always was. */
static audio_wav *open_wav(const temp_file *out, const scene *s, float scale, char *err,
                           size_t err_size)
{
    audio_wav *wav = audio_wav_open(out->fd, out->path, s->sample_rate_hz, s->channels,
                                  scene_frame_limit(s), err, err_size);
    if (wav && scale != 1.0f && calibration_write(wav, 1.0 / scale, err, err_size) != 0) {
        audio_wav_close(wav);
        return NULL;
    }
    return wav;
}

/* The --png picture of one scene; file.path NULL: none. */
typedef struct picture_job {
    temp_file file;
    double time_s; /* NAN: the first return stroke */
    int width, height;
} picture_job;

/* The picture into its temporary file, when asked for. */
static int draw(const scene *s, const picture_job *pic, char *err, size_t err_size)
{
    if (!pic->file.path)
        return 0;
#ifdef FULGUR_HAVE_GPU
    const gl_module *gl = gl_module_get(err, err_size);
    return gl ? gl->render_picture(s, pic->file.temp_path, pic->file.path, pic->time_s,
                                   pic->width, pic->height, err, err_size)
              : -1;
#else
    (void)s;
    snprintf(err, err_size, "--png needs gpu/");
    return -1;
#endif
}

/* Renders s into out_path and draws its picture, into temporary files
 * committed together: a failure of either leaves neither. Updates line;
 * the summary line goes to `summary` (NULL: none). */
static int render_file(const scene *s, const char *out_path, const render_level *level,
                       picture_job *pic, FILE *summary, progress *line, render_result *result)
{
    char err[512];
    uint64_t t0 = monotonic_now_ns();
    wav_sink w = {.s = s, .path = out_path, .first_audible = UINT64_MAX, .line = line};
    if (level_scale(s, level, &w.scale, err, sizeof err) != 0) {
        if (pic->file.path)
            temp_file_abort(&pic->file);
        progress_clear(line);
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    w.capacity = sink_capacity(s);
    w.interleaved = malloc((size_t)w.capacity * s->channels * sizeof(float));
    temp_file out;
    if (!w.interleaved || temp_file_open(&out, out_path, err, sizeof err) != 0) {
        if (!w.interleaved)
            snprintf(err, sizeof err, "out of memory");
        free(w.interleaved);
        if (pic->file.path)
            temp_file_abort(&pic->file);
        progress_clear(line);
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    w.wav = open_wav(&out, s, w.scale, err, sizeof err);
    scene_render_sink sink = {write_block, &w};
    scene_render_report rep;
    int ok = w.wav && scene_render(s, &sink, &rep, err, sizeof err) == FG_OK &&
             flush_sink(&w, err, sizeof err) == FG_OK;
    progress_clear(line);
    if (w.wav && audio_wav_close(w.wav) != 0 && ok) {
        snprintf(err, sizeof err, "%s: closing the WAV failed", out_path);
        ok = 0;
    }
    free(w.interleaved);
    if (ok)
        ok = draw(s, pic, err, sizeof err) == 0;
    if (ok)
        ok = temp_file_commit(&out, err, sizeof err) == 0;
    else
        temp_file_abort(&out);
    if (pic->file.path) {
        if (ok)
            ok = temp_file_commit(&pic->file, err, sizeof err) == 0;
        else
            temp_file_abort(&pic->file);
    }
    if (!ok) {
        fprintf(stderr, "fulgur: %s\n", err);
        return CLI_RUNTIME;
    }
    if (rep.capped)
        fprintf(stderr, "fulgur: stopped at the %.0f s cap with discharges still sounding\n",
                SCENE_MAX_DURATION_S);
    if (rep.engine.skipped_work || rep.engine.skipped_repeats)
        fprintf(stderr, "fulgur: warning: %llu work units and %llu continuous repeats were "
                        "skipped (the per-block work bound, or 64 emissions of one voice at "
                        "once: docs/limits.md)\n",
                (unsigned long long)rep.engine.skipped_work,
                (unsigned long long)rep.engine.skipped_repeats);
    if (rep.aero_beyond_range)
        fprintf(stderr, "fulgur: warning: %zu aero objects met cross-flows outside their "
                        "textures' Reynolds range (%g to %g): played on by the same laws, "
                        "less accurately (docs/aero-objects.md)\n",
                rep.aero_beyond_range, FG_AERO_RE_MIN, FG_AERO_RE_MAX);
    double wall = (double)(monotonic_now_ns() - t0) * 1e-9;
    double seconds = (double)rep.frames / s->sample_rate_hz;
    double full_scale_pa = 1.0 / w.scale;
    if (summary)
        fprintf(summary,
                "%s: %zu discharges, %zu segments, %.3f s of sound (%u ch, %.0f Hz) in %.3f s "
                "wall, %llu late events (%llu late samples); peak %+.1f dBFS, full scale = "
                "%.6g Pa%s\n",
                out_path, s->discharge_count, rep.segments, seconds, (unsigned)s->channels,
                s->sample_rate_hz, wall, (unsigned long long)rep.engine.late_events,
                (unsigned long long)rep.engine.late_samples, calibration_dbfs(w.peak),
                full_scale_pa, w.scale == 1.0f ? " (pascals)" : " (in the WAV's comment)");
    if (summary && w.peak > 1.0f)
        fprintf(stderr,
                "fulgur: warning: %s peaks at %+.1f dBFS (%.4g Pa): a player clips it above "
                "0 dBFS; --normalize -1 makes it listenable\n",
                out_path, calibration_dbfs(w.peak), w.peak * full_scale_pa);
    if (summary)
        warn_silence(out_path, &w);
    *result = (render_result){rep.frames, w.peak, w.scale};
    return CLI_OK;
}

/* The command line, read and checked. */
typedef struct render_args {
    const char **scenes;
    size_t scene_count;
    const char *out;
    const char *png;
    double png_time;
    option_size png_size; /* 0: not given (1280x720) */
    render_level level;
    const char *manifest;
    bool quiet;
    set_list sets;
    scene_layout_choice layout; /* every scene's, over their "layout" */
    const char *sofa;
} render_args;

/* Every scene read with the --set values; a bad one stops them all. "SCENE: "
 * starts the message when there are several. */
static int load_scenes(const render_args *a, scene *scenes, sofa_hrirs *hrirs)
{
    char err[512];
    for (size_t i = 0; i < a->scene_count; i++) {
        if (scene_load_with(a->scenes[i], a->sets.items, a->sets.count, &scenes[i], err,
                            sizeof err) == 0) {
            if (a->layout.given)
                scene_set_layout(&scenes[i], a->layout.layout);
            if (scene_read_hrirs(&scenes[i], a->sofa, scenes[i].sample_rate_hz, &hrirs[i], err,
                                 sizeof err) == 0)
                continue;
            scene_deinit(&scenes[i]);
        }
        if (a->scene_count > 1)
            fprintf(stderr, "fulgur: %s: %s\n", a->scenes[i], err);
        else
            fprintf(stderr, "fulgur: %s\n", err);
        for (size_t k = 0; k < i; k++)
            scene_deinit(&scenes[k]);
        return -1;
    }
    return 0;
}

/* Builds and renders scene i (and its picture); its manifest line to
 * manifest (may be NULL). */
static int render_one(const render_args *a, size_t i, scene *s, char *const *wavs,
                      char *const *pngs, FILE *manifest, progress *line)
{
    char err[512], label[300];
    if (a->scene_count > 1)
        snprintf(label, sizeof label, "[%zu/%zu] %s", i + 1, a->scene_count, a->scenes[i]);
    else
        snprintf(label, sizeof label, "%s", a->scenes[i]);
    progress_item(line, label, s->duration_s, monotonic_now_ns());
    if (scene_build(s, err, sizeof err) != 0) {
        progress_clear(line);
        if (a->scene_count > 1)
            fprintf(stderr, "fulgur: %s: %s\n", a->scenes[i], err);
        else
            fprintf(stderr, "fulgur: %s\n", err);
        return CLI_USAGE;
    }
    FILE *summary = a->quiet ? NULL : a->manifest && !strcmp(a->manifest, "-") ? stderr : stdout;
    bool sized = a->png_size.width != 0;
    picture_job pic = {.file = {.fd = -1}, .time_s = a->png_time,
                       .width = sized ? a->png_size.width : 1280,
                       .height = sized ? a->png_size.height : 720};
    if (pngs && temp_file_open(&pic.file, pngs[i], err, sizeof err) != 0) {
        progress_clear(line);
        fprintf(stderr, "fulgur: %s\n", err);
        scene_deinit(s);
        return CLI_RUNTIME;
    }
    render_result result = {0};
    int rc = render_file(s, wavs[i], &a->level, &pic, summary, line, &result);
    manifest_row row = {a->scenes[i], a->sets.items, a->sets.count, wavs[i], s, result.frames,
                        result.peak, result.scale};
    if (rc == CLI_OK && manifest && manifest_write(manifest, &row) != 0) {
        fprintf(stderr, "fulgur: writing the manifest failed\n");
        rc = CLI_RUNTIME;
    }
    scene_deinit(s);
    return rc;
}

/* The --manifest stream: stdout for "-", else a file that appears when
 * every scene has rendered. */
static int open_manifest(const char *path, temp_file *file, FILE **out, char *err,
                         size_t err_size)
{
    *out = NULL;
    if (!path)
        return 0;
    if (strcmp(path, "-") == 0) {
        *out = stdout;
        return 0;
    }
    if (temp_file_open(file, path, err, err_size) != 0)
        return -1;
    if (!(*out = temp_file_stream(file))) {
        temp_file_abort(file);
        snprintf(err, err_size, "%s: out of memory", path);
        return -1;
    }
    return 0;
}

/* Renders every scene in order; stops at the first failure. */
static int render_all(const render_args *a, scene *scenes, char *const *wavs, char *const *pngs)
{
    char err[512];
    temp_file manifest_file;
    FILE *manifest;
    if (render_output_make_directory("-o", a->out, err, sizeof err) != 0 ||
        (a->png && render_output_make_directory("--png", a->png, err, sizeof err) != 0) ||
        open_manifest(a->manifest, &manifest_file, &manifest, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        for (size_t i = 0; i < a->scene_count; i++)
            scene_deinit(&scenes[i]);
        return CLI_RUNTIME;
    }
    progress line;
    progress_begin(&line, !a->quiet && isatty(fileno(stderr)) ? stderr : NULL, "s of sound",
                   monotonic_now_ns());
    int rc = CLI_OK;
    size_t i = 0;
    for (; i < a->scene_count && rc == CLI_OK; i++)
        rc = render_one(a, i, &scenes[i], wavs, pngs, manifest, &line);
    progress_clear(&line);
    for (; i < a->scene_count; i++)
        scene_deinit(&scenes[i]);
    if (manifest && manifest != stdout) {
        if (rc != CLI_OK) {
            temp_file_abort(&manifest_file);
        } else if (temp_file_commit(&manifest_file, err, sizeof err) != 0) {
            fprintf(stderr, "fulgur: %s\n", err);
            rc = CLI_RUNTIME;
        }
    }
    return rc;
}

/* Refuses (-1 with a message) an output that is a device, FIFO or
 * directory, or that is one of the scenes read (temp_file_check_output). */
static int check_outputs(const render_args *a, char *const *wavs, char *const *pngs, char *err,
                         size_t err_size)
{
    for (size_t i = 0; i < a->scene_count; i++)
        for (size_t k = 0; k < a->scene_count; k++)
            if (temp_file_check_output(wavs[i], a->scenes[k], err, err_size) != 0 ||
                (pngs && temp_file_check_output(pngs[i], a->scenes[k], err, err_size) != 0))
                return -1;
    return 0;
}

static int parse_args(int argc, char **argv, render_args *a)
{
    const option table[] = {
        {"-o", OPTION_TEXT, &a->out, "OUT", .required = true,
         .help = "the WAV to write; for several scenes a directory or a\n"
                 "pattern with {name} and {index}"},
        {"--set", OPTION_PARSED, &a->sets, "KEY=VALUE", .parse = add_set,
         .help = "set a value in every scene before it is checked; KEY a\n"
                 "JSON path (discharges[0].offset[1]), VALUE JSON or a\n"
                 "string; repeatable, applied in order"},
        {"--manifest", OPTION_TEXT, &a->manifest, "FILE",
         .help = "a JSON line per file written: scene, seed, duration, peak,\n"
                 "calibration (- : stdout, the summary lines then to stderr)"},
        SCENE_LAYOUT_OPTIONS(&a->layout, &a->sofa, ""),
        {"--quiet", OPTION_FLAG, &a->quiet,
         .help = "no summary line, no progress line, no warning of clipping or\n"
                 "silence"},
        {"--png", OPTION_TEXT, &a->png, "OUT.png",
         .help = "also draw the discharges (docs/picture.md) from the scene's\n"
                 "\"camera\" into a PNG (needs gpu/: FULGUR_GPU); named as -o"},
        {"--png-time", OPTION_NUMBER, &a->png_time, "SECONDS",
         .help = "the picture's time (default: the first return stroke)",
         .range = {.lo = -INFINITY, .hi = INFINITY}},
        {"--size", OPTION_PARSED, &a->png_size, "WxH",
         .help = "the picture in pixels (default 1280x720)", .parse = option_parse_size},
        {"--gain-db", OPTION_NUMBER, &a->level.gain_db, "DB",
         .help = "multiply the samples by 10^(DB/20) (default 0: pascals)",
         .range = {.lo = -200, .hi = 200}},
        {"--normalize", OPTION_NUMBER, &a->level.normalize_dbfs, "PEAK_DBFS",
         .help = "scale the samples so that the peak is PEAK_DBFS, e.g. -1\n"
                 "(renders twice: once to find the peak)",
         .range = {.lo = -100, .hi = 0}},
        {0},
    };
    const command_line cl = {"fulgur render", "SCENE.json...", 1, (size_t)argc, about, notes,
                             table};
    options_result parsed = options_parse(&cl, argc, argv, a->scenes, &a->scene_count);
    if (parsed == OPTIONS_OK && (!isnan(a->png_time) || a->png_size.width) && !a->png)
        parsed = options_fail(&cl, "%s needs --png", a->png_size.width ? "--size" : "--png-time");
    if (parsed == OPTIONS_OK && !isnan(a->level.gain_db) && !isnan(a->level.normalize_dbfs))
        parsed = options_fail(&cl, "--gain-db and --normalize both set the level: give one");
#ifndef FULGUR_HAVE_GPU
    if (parsed == OPTIONS_OK && a->png)
        parsed = options_fail(&cl, "--png needs the picture, and this fulgur was built without "
                                   "gpu/ (configure with -DFULGUR_GPU=ON, libepoxy, EGL, libpng)");
#endif
    if (parsed != OPTIONS_OK)
        return parsed == OPTIONS_HELP ? CLI_OK : CLI_USAGE;
    return -1;
}

int render_main(int argc, char **argv)
{
    /* NAN: not given (the parser takes finite numbers only) */
    render_args a = {.png_time = NAN, .level = {NAN, NAN}};
    a.scenes = calloc((size_t)argc, sizeof *a.scenes);
    scene *scenes = calloc((size_t)argc, sizeof *scenes);
    char **wavs = calloc((size_t)argc, sizeof *wavs), **pngs = calloc((size_t)argc, sizeof *pngs);
    sofa_hrirs *hrirs = calloc((size_t)argc, sizeof *hrirs);
    if (!a.scenes || !scenes || !wavs || !pngs || !hrirs) {
        fprintf(stderr, "fulgur: out of memory\n");
        free(a.scenes), free(scenes), free(wavs), free(pngs), free(hrirs);
        return CLI_RUNTIME;
    }
    char err[512];
    int rc = parse_args(argc, argv, &a);
    if (rc < 0 && a.sofa && a.layout.given && a.layout.layout.layout != FG_LAYOUT_BINAURAL) {
        fprintf(stderr, "fulgur render: --sofa %s: only with --layout binaural\n", a.sofa);
        rc = CLI_USAGE;
    }
    if (rc < 0 &&
        (render_output_paths("-o", a.out, a.scenes, a.scene_count, ".wav", wavs, err,
                             sizeof err) != 0 ||
         (a.png && render_output_paths("--png", a.png, a.scenes, a.scene_count, ".png", pngs,
                                       err, sizeof err) != 0))) {
        fprintf(stderr, "fulgur render: %s\n", err);
        rc = CLI_USAGE;
    } else if (rc < 0 && check_outputs(&a, wavs, a.png ? pngs : NULL, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur: %s\n", err);
        rc = CLI_USAGE;
    }
    if (rc < 0)
        rc = load_scenes(&a, scenes, hrirs) == 0
                 ? render_all(&a, scenes, wavs, a.png ? pngs : NULL)
                 : CLI_USAGE;
    for (size_t i = 0; i < a.scene_count; i++)
        sofa_hrirs_free(&hrirs[i]);
    free(hrirs);
    render_output_free(wavs, a.scene_count);
    render_output_free(pngs, a.scene_count);
    free(a.scenes), free(scenes), free(wavs), free(pngs);
    return rc;
}
