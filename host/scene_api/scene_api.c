/* libfulgur-scene over host/scene: parse, build, the one render loop, and
 * the WAV writer of fulgur render. */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <errno.h>

#include "common/aero_texture_file.h"
#include "common/audio_file.h"
#include "common/temp_file.h"
#include "fg_array.h"
#include "fg_big_alloc.h"
#include "fulgur/scene_api.h"
#include "scene/scene.h"
#include "scene/scene_render.h"

struct fgs_scene {
    scene s;
    bool built;
    float *samples;          /* interleaved, frames * channels */
    size_t capacity;         /* floats */
    uint64_t frames;
};

/* Where a call's message goes: the caller's err, or scratch when it gave
 * none. */
typedef struct message {
    char *text;
    size_t size;
    char scratch[512];
} message;

static void message_init(message *m, char *err, size_t err_size)
{
    m->text = err && err_size > 0 ? err : m->scratch;
    m->size = err && err_size > 0 ? err_size : sizeof m->scratch;
    m->text[0] = '\0';
}

/* The parser and the generators say "out of memory" when it ran out;
 * everything else they refuse is the scene's fault. */
static fg_result scene_fault(const message *m)
{
    return strstr(m->text, "out of memory") ? FG_ERR_NO_MEMORY : FG_ERR_ARGUMENT;
}

static fg_result parsed(int rc, scene *s, fgs_scene **out, message *m)
{
    if (rc != 0)
        return scene_fault(m);
    fgs_scene *made = calloc(1, sizeof *made);
    if (!made) {
        scene_deinit(s);
        snprintf(m->text, m->size, "out of memory");
        return FG_ERR_NO_MEMORY;
    }
    made->s = *s;
    *out = made;
    return FG_OK;
}

fg_result fgs_scene_parse(const char *json, size_t size, const char *const *sets,
                          size_t set_count, fgs_scene **out, char *err, size_t err_size)
{
    message m;
    message_init(&m, err, err_size);
    if (out)
        *out = NULL;
    if (!out || (!json && size > 0) || (!sets && set_count > 0)) {
        snprintf(m.text, m.size, "%s", fg_result_str(FG_ERR_NULL));
        return FG_ERR_NULL;
    }
    scene s;
    int rc = scene_parse_with(json ? json : "", size, sets, set_count, &s, m.text, m.size);
    return parsed(rc, &s, out, &m);
}

fg_result fgs_scene_load(const char *path, const char *const *sets, size_t set_count,
                         fgs_scene **out, char *err, size_t err_size)
{
    message m;
    message_init(&m, err, err_size);
    if (out)
        *out = NULL;
    if (!path || !out || (!sets && set_count > 0)) {
        snprintf(m.text, m.size, "%s", fg_result_str(FG_ERR_NULL));
        return FG_ERR_NULL;
    }
    char *text;
    size_t size;
    if (scene_read_file(path, &text, &size, m.text, m.size) != 0)
        return FG_ERR_IO;
    scene s;
    char dir[4096];
    int rc = scene_parse_in(text, size, sets, set_count, scene_dir_of(path, dir, sizeof dir), &s,
                            m.text, m.size);
    fg_big_free(text);
    return parsed(rc, &s, out, &m);
}

void fgs_scene_destroy(fgs_scene *handle)
{
    if (!handle)
        return;
    scene_deinit(&handle->s);
    free(handle->samples);
    free(handle);
}

void fgs_scene_get_info(const fgs_scene *handle, fgs_scene_info *out)
{
    assert(handle && out);
    if (!handle || !out)
        return;
    const struct scene *s = &handle->s;
    *out = (fgs_scene_info){
        .sample_rate_hz = s->sample_rate_hz,
        .channels = s->channels,
        .block_frames = scene_render_block_frames(s),
        .duration_s = s->duration_s,
        .seed = s->seed,
        .gain = s->gain,
        .discharge_count = s->discharge_count,
    };
}

/* The render's blocks, interleaved with the gain, appended to the samples. */
typedef struct sample_sink {
    fgs_scene *handle;
    float peak;
} sample_sink;

static fg_result append_block(void *context, float *const *planes, uint32_t frames, char *err,
                              size_t err_size)
{
    sample_sink *k = context;
    fgs_scene *fs = k->handle;
    uint32_t channels = fs->s.channels;
    size_t used = (size_t)fs->frames * channels, n = (size_t)frames * channels;
    float *grown = fg_array_grow(fs->samples, &fs->capacity, used + n, sizeof(float), 1 << 16);
    if (!grown) {
        snprintf(err, err_size, "out of memory for %.1f s of sound",
                 (double)(fs->frames + frames) / fs->s.sample_rate_hz);
        return FG_ERR_NO_MEMORY;
    }
    fs->samples = grown;
    audio_interleave(planes, channels, frames, (float)fs->s.gain, fs->samples + used);
    k->peak = audio_peak(fs->samples + used, n, k->peak);
    fs->frames += frames;
    return FG_OK;
}

fg_result fgs_scene_render(fgs_scene *handle, fgs_render_report *report, char *err,
                           size_t err_size)
{
    message m;
    message_init(&m, err, err_size);
    if (report)
        *report = (fgs_render_report){0};
    if (!handle) {
        snprintf(m.text, m.size, "%s", fg_result_str(FG_ERR_NULL));
        return FG_ERR_NULL;
    }
    handle->frames = 0;
    if (!handle->built) {
        if (scene_build(&handle->s, m.text, m.size) != 0)
            return scene_fault(&m);
        handle->built = true;
    }
    const struct scene *s = &handle->s;
    if (s->duration_s > 0) { /* the whole length at once */
        size_t need = (size_t)llround(s->duration_s * s->sample_rate_hz) * s->channels;
        float *grown = fg_array_grow(handle->samples, &handle->capacity, need ? need : 1,
                                     sizeof(float), need ? need : 1);
        if (!grown) {
            snprintf(m.text, m.size, "out of memory for %.1f s of sound", s->duration_s);
            return FG_ERR_NO_MEMORY;
        }
        handle->samples = grown;
    }
    sample_sink k = {.handle = handle};
    scene_render_sink sink = {append_block, &k};
    scene_render_report rep;
    fg_result r = scene_render(s, &sink, &rep, m.text, m.size);
    if (r != FG_OK) {
        handle->frames = 0;
        return r;
    }
    if (report)
        *report = (fgs_render_report){
            .frames = rep.frames,
            .segments = rep.segments,
            .peak = k.peak,
            .capped = rep.capped,
            .engine = rep.engine,
        };
    return FG_OK;
}

const float *fgs_scene_samples(const fgs_scene *handle, uint64_t *frames)
{
    if (frames)
        *frames = handle && handle->frames ? handle->frames : 0;
    return handle && handle->frames ? handle->samples : NULL;
}

fg_result fgs_wav_write(const char *path, const float *samples, uint64_t frames,
                        uint32_t channels, double sample_rate_hz, char *err, size_t err_size)
{
    message m;
    message_init(&m, err, err_size);
    char *msg = m.text;
    size_t msg_size = m.size;
    if (!path || (!samples && frames > 0)) {
        snprintf(msg, msg_size, "%s", fg_result_str(FG_ERR_NULL));
        return FG_ERR_NULL;
    }
    if ((channels != 1 && channels != 2) || !(sample_rate_hz >= 8000 && sample_rate_hz <= 384000) ||
        sample_rate_hz != floor(sample_rate_hz)) {
        snprintf(msg, msg_size, "%s: %u channels at %g Hz: expected 1 or 2 channels at an "
                                "integer rate in 8000..384000 Hz", path, (unsigned)channels,
                 sample_rate_hz);
        return FG_ERR_ARGUMENT;
    }
    temp_file out;
    if (temp_file_open(&out, path, msg, msg_size) != 0)
        return FG_ERR_IO;
    audio_wav *wav = audio_wav_open(out.fd, path, sample_rate_hz, channels, frames, msg,
                                    msg_size);
    int ok = wav != NULL;
    char why[256];
    if (ok && audio_wav_write(wav, samples, frames, why, sizeof why) != 0) {
        snprintf(msg, msg_size, "%s: %s", path, why);
        ok = 0;
    }
    if (wav && audio_wav_close(wav) != 0 && ok) {
        snprintf(msg, msg_size, "%s: closing the WAV failed", path);
        ok = 0;
    }
    if (!ok) {
        temp_file_abort(&out);
        return FG_ERR_IO;
    }
    return temp_file_commit(&out, msg, msg_size) == 0 ? FG_OK : FG_ERR_IO;
}

fg_result fgs_aero_texture_load(const char *path, fg_aero_texture **out, char *err,
                                size_t err_size)
{
    message m;
    message_init(&m, err, err_size);
    if (!path || !out) {
        snprintf(m.text, m.size, "%s", fg_result_str(FG_ERR_NULL));
        return FG_ERR_NULL;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(m.text, m.size, "%s: cannot open: %s", path, strerror(errno));
        return FG_ERR_IO;
    }
    fclose(f);
    return aero_texture_load(path, out, m.text, m.size) == 0 ? FG_OK : FG_ERR_ARGUMENT;
}
