/* Reading a sound file whole for analysis (wav_read.h). */
#include "wav_read.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calibration.h"
#include "text_escape.h"

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

/* The frames a WAV's data chunk declares; frames when it cannot say. A
 * size of 0 or 0xFFFFFFFF is what streaming writers leave: "not known". */
static uint64_t declared_frames(SNDFILE *f, const SF_INFO *info, uint64_t frames)
{
    unsigned width = sample_bytes(info->format);
    if ((info->format & SF_FORMAT_TYPEMASK) != SF_FORMAT_WAV || width == 0)
        return frames;
    SF_CHUNK_INFO chunk = {.id = "data", .id_size = 4};
    SF_CHUNK_ITERATOR *it = sf_get_chunk_iterator(f, &chunk);
    if (!it || sf_get_chunk_size(it, &chunk) != SF_ERR_NO_ERROR || chunk.datalen == 0 ||
        chunk.datalen == UINT32_MAX)
        return frames;
    uint64_t declared = chunk.datalen / ((uint64_t)width * (uint64_t)info->channels);
    return declared > frames ? declared : frames;
}

static uint32_t chunk_size(const unsigned char *b, bool big_endian)
{
    return big_endian ? (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3]
                      : (uint32_t)b[3] << 24 | (uint32_t)b[2] << 16 | (uint32_t)b[1] << 8 | b[0];
}

int wav_check_chunks(FILE *in, const char *name, char *err, size_t err_size)
{
    unsigned char head[12];
    if (fseek(in, 0, SEEK_END) != 0)
        return 0;
    const long size = ftell(in);
    if (size < 12 || fseek(in, 0, SEEK_SET) != 0 || fread(head, 1, 12, in) != 12)
        return 0;
    const bool rf64 = memcmp(head, "RF64", 4) == 0, big_endian = memcmp(head, "RIFX", 4) == 0;
    if ((!rf64 && !big_endian && memcmp(head, "RIFF", 4) != 0) || memcmp(head + 8, "WAVE", 4) != 0)
        return 0;
    /* each step moves on by at least 8 bytes: the walk ends */
    for (long at = 12; at + 8 <= size;) {
        unsigned char chunk[8];
        if (fseek(in, at, SEEK_SET) != 0 || fread(chunk, 1, 8, in) != 8)
            return 0;
        const uint32_t bytes = chunk_size(chunk + 4, big_endian);
        if (memcmp(chunk, "data", 4) == 0 || (rf64 && bytes == UINT32_MAX))
            return 0; /* the samples (cut short: wav_read says so), or ds64 sizes */
        if ((uint64_t)bytes > (uint64_t)(size - at - 8)) {
            char raw[5] = {0}, id[4 * 4 + 1];
            memcpy(raw, chunk, 4);
            text_escape(id, sizeof id, raw);
            snprintf(err, err_size, "%s: its '%s' chunk at byte %ld claims %u bytes, past the "
                                    "file's end (%ld bytes)", name, id, at, bytes, size);
            return -1;
        }
        at += 8 + (long)bytes + (long)(bytes & 1u);
    }
    return 0;
}

int wav_read(SNDFILE *f, const SF_INFO *info, const char *name, wav_audio *out, char *err,
             size_t err_size)
{
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
    out->declared_frames = declared_frames(f, info, frames);
    out->channels = info->channels;
    out->rate_hz = info->samplerate;
    out->calibrated = calibration_read(f, &out->full_scale_pa);
    return 0;
}
