#include <errno.h>
#include <math.h>
#include <samplerate.h>
#include <stdarg.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fire_training.h"
#include "wav_file.h"
#include "fulgur/fire.h"

#define MIN_RATE_HZ 8000.0
#define MAX_RATE_HZ 384000.0

/* err = "path: " and the formatted rest; returns -1. */
static int fail(char *err, size_t err_size, const char *path, const char *format, ...)
    __attribute__((format(printf, 4, 5)));
static int fail(char *err, size_t err_size, const char *path, const char *format, ...)
{
    int used = snprintf(err, err_size, "%s: ", path);
    if (used >= 0 && (size_t)used < err_size) {
        va_list args;
        va_start(args, format);
        vsnprintf(err + used, err_size - (size_t)used, format, args);
        va_end(args);
    }
    return -1;
}

/* The file's frames mixed to mono, checked for finite values. */
static float *read_mono(SNDFILE *file, const SF_INFO *info, const char *path, char *err,
                        size_t err_size)
{
    size_t frames = (size_t)info->frames, channels = (size_t)info->channels;
    float *all = malloc(sizeof(float) * frames * channels);
    float *mono = malloc(sizeof(float) * frames);
    if (!all || !mono) {
        free(all);
        free(mono);
        fail(err, err_size, path, "out of memory for %zu frames", frames);
        return NULL;
    }
    sf_count_t got = sf_readf_float(file, all, (sf_count_t)frames);
    if (got != (sf_count_t)frames) {
        fail(err, err_size, path, "read only %lld frames of the %zu it declares", (long long)got,
             frames);
        free(all);
        free(mono);
        return NULL;
    }
    for (size_t f = 0; f < frames; f++) {
        double sum = 0.0;
        for (size_t c = 0; c < channels; c++) {
            float v = all[f * channels + c];
            if (!isfinite(v)) {
                fail(err, err_size, path, "frame %zu is not a finite number", f);
                free(all);
                free(mono);
                return NULL;
            }
            sum += v;
        }
        mono[f] = (float)(sum / (double)channels);
    }
    free(all);
    return mono;
}

int fire_training_read(const char *path, double rate_hz, fire_training *out, char *err,
                       size_t err_size)
{
    memset(out, 0, sizeof *out);
    if (!(rate_hz >= MIN_RATE_HZ && rate_hz <= MAX_RATE_HZ))
        return fail(err, err_size, path, "the synthesis rate %g Hz is outside 8000-384000 Hz",
                    rate_hz);
    FILE *in = fopen(path, "rb");
    if (!in)
        return fail(err, err_size, path, "cannot open it: %s", strerror(errno));
    wav_file file;
    if (wav_open(&file, in, path, err, err_size) != 0) {
        fclose(in);
        return -1;
    }
    const SF_INFO info = file.info;
    double rate = info.samplerate, seconds = rate > 0 ? (double)info.frames / rate : 0.0;
    int bad = 0;
    if (info.frames <= 0 || info.channels <= 0)
        bad = fail(err, err_size, path, "holds no frames");
    else if (rate < MIN_RATE_HZ || rate > MAX_RATE_HZ)
        bad = fail(err, err_size, path, "sample rate %.0f Hz is outside 8000-384000 Hz", rate);
    else if (seconds < FG_FIRE_TRAINING_MIN_S)
        bad = fail(err, err_size, path, "is %.3g s long; a training clip needs at least 1 s",
                   seconds);
    else if (seconds > FG_FIRE_TRAINING_MAX_S)
        bad = fail(err, err_size, path, "is %.0f s long; a training clip may be 600 s at most",
                   seconds);
    float *mono = bad ? NULL : read_mono(file.sndfile, &info, path, err, err_size);
    wav_close(&file);
    fclose(in);
    if (!mono)
        return -1;
    size_t frames = (size_t)info.frames;
    out->file_rate_hz = rate;
    out->file_channels = info.channels;
    if (rate == rate_hz) {
        out->samples = mono;
        out->frames = frames;
        return 0;
    }
    double ratio = rate_hz / rate;
    size_t capacity = (size_t)ceil((double)frames * ratio) + 16;
    float *converted = malloc(sizeof(float) * capacity);
    if (!converted) {
        free(mono);
        memset(out, 0, sizeof *out);
        return fail(err, err_size, path, "out of memory for %zu frames", capacity);
    }
    SRC_DATA src = {.data_in = mono, .input_frames = (long)frames, .data_out = converted,
                    .output_frames = (long)capacity, .src_ratio = ratio};
    int e = src_simple(&src, SRC_SINC_BEST_QUALITY, 1);
    free(mono);
    if (e != 0) {
        free(converted);
        memset(out, 0, sizeof *out);
        return fail(err, err_size, path, "converting %.0f Hz to %.0f Hz failed: %s", rate, rate_hz,
                    src_strerror(e));
    }
    out->samples = converted;
    out->frames = (size_t)src.output_frames_gen;
    out->resampled = 1;
    return 0;
}

void fire_training_free(fire_training *t)
{
    free(t->samples);
    memset(t, 0, sizeof *t);
}
