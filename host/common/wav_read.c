/* Reading a sound file whole for analysis (wav_read.h). */
#include "wav_read.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calibration.h"

/* Bytes per sample of the fixed-width encodings a WAV's data size can be
 * counted in; 0 for the others (compressed: the size says nothing simple). */
static unsigned sample_bytes(int format)
{
    switch (format & SF_FORMAT_SUBMASK) {
    case SF_FORMAT_PCM_S8:
    case SF_FORMAT_PCM_U8:
    case SF_FORMAT_ULAW:
    case SF_FORMAT_ALAW:
        return 1;
    case SF_FORMAT_PCM_16:
        return 2;
    case SF_FORMAT_PCM_24:
        return 3;
    case SF_FORMAT_PCM_32:
    case SF_FORMAT_FLOAT:
        return 4;
    case SF_FORMAT_DOUBLE:
        return 8;
    default:
        return 0;
    }
}

/* The frames the header declares, where the encoding's width says: never
 * fewer than frames. */
static uint64_t declared_frames(const wav_file *w, uint64_t frames)
{
    unsigned width = sample_bytes(w->info.format);
    if (width == 0)
        return frames;
    uint64_t declared = w->declared_bytes / ((uint64_t)width * (uint64_t)w->info.channels);
    return declared > frames ? declared : frames;
}

int wav_read(const wav_file *w, const char *name, wav_audio *out, char *err, size_t err_size)
{
    SNDFILE *f = w->sndfile;
    const SF_INFO *info = &w->info;
    memset(out, 0, sizeof *out);
    if (info->samplerate < 1 || info->samplerate > WAV_READ_MAX_RATE_HZ) {
        snprintf(err, err_size, "%s: a sample rate of %d Hz, outside 1..%d", name,
                 info->samplerate, WAV_READ_MAX_RATE_HZ);
        return -1;
    }
    if (info->channels < 1 || info->frames < 0) {
        snprintf(err, err_size, "%s: %d channels, %lld frames", name, info->channels,
                 (long long)info->frames);
        return -1;
    }
    size_t channels = (size_t)info->channels;
    if ((uint64_t)info->frames > SIZE_MAX / sizeof(float) / channels) {
        snprintf(err, err_size, "%s: %lld frames of %d channels do not fit in memory", name,
                 (long long)info->frames, info->channels);
        return -1;
    }
    size_t frames = (size_t)info->frames;
    float *samples = malloc((frames ? frames : 1) * channels * sizeof *samples);
    if (!samples) {
        snprintf(err, err_size, "%s: no memory for %zu frames", name, frames);
        return -1;
    }
    if (sf_readf_float(f, samples, info->frames) != info->frames) {
        snprintf(err, err_size, "%s: cannot read %zu frames", name, frames);
        free(samples);
        return -1;
    }
    out->samples = samples;
    out->frames = frames;
    out->declared_frames = declared_frames(w, frames);
    out->channels = info->channels;
    out->rate_hz = info->samplerate;
    out->calibrated = calibration_read(f, &out->full_scale_pa);
    return 0;
}
