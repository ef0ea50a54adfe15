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

/* Opens fd (not closed by sf_close) for 32-bit float WAV; no PEAK chunk, so
 * equal samples give equal bytes. Returns NULL with a message naming
 * path in err. */
SNDFILE *audio_wav_open(int fd, const char *path, double rate_hz, uint32_t channels, char *err,
                        size_t err_size);

#endif
