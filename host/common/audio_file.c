/* Interleaving and the WAV writer's settings. */
#include <math.h>
#include <stdio.h>

#include "audio_file.h"

void audio_interleave(float *const *planes, uint32_t channels, uint32_t frames, float gain,
                      float *out)
{
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

SNDFILE *audio_wav_open(int fd, const char *path, double rate_hz, uint32_t channels,
                        uint64_t max_frames, char *err, size_t err_size)
{
    int rf64 = audio_needs_rf64(max_frames, channels);
    SF_INFO info = {
        .samplerate = (int)rate_hz,
        .channels = (int)channels,
        .format = (rf64 ? SF_FORMAT_RF64 : SF_FORMAT_WAV) | SF_FORMAT_FLOAT,
    };
    SNDFILE *wav = sf_open_fd(fd, SFM_WRITE, &info, SF_FALSE);
    if (!wav) {
        snprintf(err, err_size, "%s: %s", path, sf_strerror(NULL));
        return NULL;
    }
    if (max_frames == AUDIO_FRAMES_UNBOUNDED)
        sf_command(wav, SFC_RF64_AUTO_DOWNGRADE, NULL, SF_TRUE);
    /* the PEAK chunk carries a timestamp: without it equal renders are
     * byte-identical */
    sf_command(wav, SFC_SET_ADD_PEAK_CHUNK, NULL, SF_FALSE);
    return wav;
}
