/* Sound out of the engine into files and streams: the planes interleaved
 * with the scene's gain, and a 32-bit float WAV writer whose bytes depend
 * only on the samples. Shared by fulgur render and fulgur run. */
#ifndef HOST_COMMON_AUDIO_FILE_H
#define HOST_COMMON_AUDIO_FILE_H

#include <sndfile.h>
#include <stddef.h>
#include <stdint.h>

/* out[f * channels + ch] = planes[ch][f] * gain for f < frames. */
void audio_interleave(float *const *planes, uint32_t channels, uint32_t frames, float gain,
                      float *out);

/* The larger of peak and the largest |samples[i]|, i < count. */
float audio_peak(const float *samples, size_t count, float peak);
/* max_frames for an output whose length is not known in advance. */
#define AUDIO_FRAMES_UNBOUNDED UINT64_MAX

/* Whether max_frames of 32-bit float samples in channels may pass the
 * 4 GiB a RIFF WAV's 32-bit sizes can state. */
int audio_needs_rf64(uint64_t max_frames, uint32_t channels);

/* Opens fd (not closed by sf_close) for 32-bit float WAV; no PEAK chunk, so
 * equal samples give equal bytes. max_frames is the most frames the file
 * may get: when they may pass 4 GiB the file is RF64 (EBU Tech 3306, read
 * by libsndfile and most tools) rather than a WAV whose sizes would wrap;
 * AUDIO_FRAMES_UNBOUNDED gives RF64 that libsndfile turns back into a WAV
 * at close when it stayed under 4 GiB. Returns NULL with a message naming
 * path in err. */
SNDFILE *audio_wav_open(int fd, const char *path, double rate_hz, uint32_t channels,
                        uint64_t max_frames, char *err, size_t err_size);

#endif
