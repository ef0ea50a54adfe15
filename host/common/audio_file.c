/* Interleaving and the WAV writer. */
#define _DEFAULT_SOURCE /* pwrite */
#include <errno.h>
#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "audio_file.h"

void audio_interleave(float *const *planes, uint32_t channels, uint32_t frames, float gain,
                      float *out)
{
    if (channels == 2) {
        /* both planes in one loop, which the compiler vectorises (the
         * strided loop below it does not): the same products */
        const float *left = planes[0], *right = planes[1];
        for (uint32_t f = 0; f < frames; f++) {
            out[2 * (size_t)f] = left[f] * gain;
            out[2 * (size_t)f + 1] = right[f] * gain;
        }
        return;
    }
    /* a plane at a time: a plain loop over the frames, out written with a stride */
    for (uint32_t ch = 0; ch < channels; ch++) {
        const float *in = planes[ch];
        float *to = out + ch;
        for (uint32_t f = 0; f < frames; f++)
            to[(size_t)f * channels] = in[f] * gain;
    }
}

/* Lanes of audio_peak: running maxima that do not wait on each other. */
#define PEAK_LANES 8

float audio_peak(const float *samples, size_t count, float peak)
{
    float lane[PEAK_LANES];
    for (int k = 0; k < PEAK_LANES; k++)
        lane[k] = peak;
    size_t i = 0;
    for (; i + PEAK_LANES <= count; i += PEAK_LANES)
        for (int k = 0; k < PEAK_LANES; k++) {
            float a = fabsf(samples[i + k]);
            lane[k] = a > lane[k] ? a : lane[k];
        }
    for (; i < count; i++)
        if (fabsf(samples[i]) > peak)
            peak = fabsf(samples[i]);
    for (int k = 0; k < PEAK_LANES; k++)
        peak = lane[k] > peak ? lane[k] : peak;
    return peak;
}

/* Room for the header chunks within a RIFF's 32-bit size. */
#define RIFF_HEADER_ROOM 4096u

int audio_needs_rf64(uint64_t max_frames, uint32_t channels)
{
    uint64_t limit = (UINT32_MAX - RIFF_HEADER_ROOM) / (4u * (uint64_t)channels);
    return max_frames > limit;
}

/* A plain WAV's header as libsndfile writes it (no PEAK chunk): RIFF,
 * fmt (IEEE float), fact (the frames), a PAD chunk of zeros where it kept
 * room for a PEAK chunk (16 bytes and 8 a channel) before it was told to
 * leave that out, and data's header; the samples follow. */
#define PLAIN_PAD_AT 48u
#define PLAIN_PAD_BYTES(channels) (8u + 8u * (channels))
#define PLAIN_HEADER_BYTES(channels) (PLAIN_PAD_AT + 8u + PLAIN_PAD_BYTES(channels) + 8u)
#define WAVE_FORMAT_IEEE_FLOAT 3u

/* The samples are written as they lie in memory: a plain WAV here only
 * where that is little-endian, as WAV is. */
#define PLAIN_NATIVE (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__)

struct audio_wav {
    SNDFILE *sndfile; /* RF64 or a comment: libsndfile's file; NULL: plain */
    int fd;
    uint32_t rate_hz, channels;
    uint64_t frames;        /* written, plain */
    int header_written;     /* plain: the header's room taken */
    unsigned char header[]; /* plain: PLAIN_HEADER_BYTES(channels) */
};

static void put_u16(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
}

static void put_u32(unsigned char *p, uint32_t v)
{
    put_u16(p, v & 0xFFFFu);
    put_u16(p + 2, v >> 16);
}

/* w->header for a plain WAV of w->frames frames; its size. */
static size_t plain_header(audio_wav *w)
{
    unsigned char *h = w->header;
    uint32_t frame_bytes = 4u * w->channels, pad = PLAIN_PAD_BYTES(w->channels);
    uint32_t size = PLAIN_HEADER_BYTES(w->channels);
    uint32_t data_bytes = (uint32_t)(w->frames * frame_bytes);
    memset(h, 0, size);
    memcpy(h, "RIFF", 4);
    put_u32(h + 4, size - 8u + data_bytes);
    memcpy(h + 8, "WAVEfmt ", 8);
    put_u32(h + 16, 16);
    put_u16(h + 20, WAVE_FORMAT_IEEE_FLOAT);
    put_u16(h + 22, w->channels);
    put_u32(h + 24, w->rate_hz);
    put_u32(h + 28, w->rate_hz * frame_bytes);
    put_u16(h + 32, frame_bytes);
    put_u16(h + 34, 32);
    memcpy(h + 36, "fact", 4);
    put_u32(h + 40, 4);
    put_u32(h + 44, (uint32_t)w->frames);
    memcpy(h + PLAIN_PAD_AT, "PAD ", 4);
    put_u32(h + PLAIN_PAD_AT + 4, pad);
    memcpy(h + size - 8u, "data", 4);
    put_u32(h + size - 4u, data_bytes);
    return size;
}

/* size bytes at offset (pwrite) or, offset < 0, at the file's position
 * (write), through short writes and signals; 0 or -1 with errno. */
static int write_all(int fd, const void *bytes, size_t size, off_t offset)
{
    const char *p = bytes;
    while (size > 0) {
        ssize_t n = offset < 0 ? write(fd, p, size) : pwrite(fd, p, size, offset);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return -1;
        p += n;
        size -= (size_t)n;
        offset += offset < 0 ? 0 : n;
    }
    return 0;
}

/* libsndfile's file on w->fd, rf64 or a plain WAV; -1 with a message. */
static int open_sndfile(audio_wav *w, int rf64, uint64_t max_frames, char *err, size_t err_size)
{
    SF_INFO info = {
        .samplerate = (int)w->rate_hz,
        .channels = (int)w->channels,
        .format = (rf64 ? SF_FORMAT_RF64 : SF_FORMAT_WAV) | SF_FORMAT_FLOAT,
    };
    w->sndfile = sf_open_fd(w->fd, SFM_WRITE, &info, SF_FALSE);
    if (!w->sndfile) {
        snprintf(err, err_size, "%s", sf_strerror(NULL));
        return -1;
    }
    if (max_frames == AUDIO_FRAMES_UNBOUNDED)
        sf_command(w->sndfile, SFC_RF64_AUTO_DOWNGRADE, NULL, SF_TRUE);
    /* the PEAK chunk carries a timestamp: without it equal renders are
     * byte-identical */
    sf_command(w->sndfile, SFC_SET_ADD_PEAK_CHUNK, NULL, SF_FALSE);
    return 0;
}

audio_wav *audio_wav_open(int fd, const char *path, double rate_hz, uint32_t channels,
                          uint64_t max_frames, char *err, size_t err_size)
{
    audio_wav *w = calloc(1, sizeof *w + PLAIN_HEADER_BYTES(channels));
    if (!w) {
        snprintf(err, err_size, "%s: out of memory", path);
        return NULL;
    }
    *w = (audio_wav){.fd = fd, .rate_hz = (uint32_t)rate_hz, .channels = channels};
    int rf64 = audio_needs_rf64(max_frames, channels);
    char why[256];
    if ((rf64 || !PLAIN_NATIVE) && open_sndfile(w, rf64, max_frames, why, sizeof why) != 0) {
        snprintf(err, err_size, "%s: %s", path, why);
        free(w);
        return NULL;
    }
    return w;
}

int audio_wav_comment(audio_wav *w, const char *text, char *err, size_t err_size)
{
    /* a plain WAV with a comment is libsndfile's, whose layout of the
     * LIST chunk this writer does not repeat */
    if (!w->sndfile && open_sndfile(w, 0, 0, err, err_size) != 0)
        return -1;
    if (sf_set_string(w->sndfile, SF_STR_COMMENT, text) != 0) {
        snprintf(err, err_size, "%s", sf_strerror(w->sndfile));
        return -1;
    }
    return 0;
}

int audio_wav_write(audio_wav *w, const float *interleaved, uint64_t frames, char *err,
                    size_t err_size)
{
    if (w->sndfile) {
        if (sf_writef_float(w->sndfile, interleaved, (sf_count_t)frames) != (sf_count_t)frames) {
            snprintf(err, err_size, "writing the WAV: %s", sf_strerror(w->sndfile));
            return -1;
        }
        return 0;
    }
    if (!w->header_written) {
        if (write_all(w->fd, w->header, plain_header(w), -1) != 0) {
            snprintf(err, err_size, "writing the WAV: %s", strerror(errno));
            return -1;
        }
        w->header_written = 1;
    }
    if (write_all(w->fd, interleaved, (size_t)(frames * w->channels * sizeof(float)), -1) != 0) {
        snprintf(err, err_size, "writing the WAV: %s", strerror(errno));
        return -1;
    }
    w->frames += frames;
    return 0;
}

int audio_wav_close(audio_wav *w)
{
    if (!w)
        return 0;
    int rc;
    if (w->sndfile) {
        rc = sf_close(w->sndfile) == 0 ? 0 : -1;
    } else {
        rc = write_all(w->fd, w->header, plain_header(w), 0);
    }
    free(w);
    return rc;
}
