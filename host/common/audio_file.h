/* Sound out of the engine into files and streams: the planes interleaved
 * with the scene's gain, and a 32-bit float WAV writer whose bytes depend
 * only on the samples. Shared by fulgur render and fulgur run. */
#ifndef HOST_COMMON_AUDIO_FILE_H
#define HOST_COMMON_AUDIO_FILE_H

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

/* A 32-bit float WAV being written (audio_wav_open). */
typedef struct audio_wav audio_wav;

/* Opens fd (left open by audio_wav_close) for a 32-bit float WAV whose
 * bytes depend only on the samples (no PEAK chunk and its timestamp).
 * max_frames is the most frames the file may get: when they may pass
 * 4 GiB the file is RF64 (EBU Tech 3306, read by libsndfile and most
 * tools) rather than a WAV whose sizes would wrap; AUDIO_FRAMES_UNBOUNDED
 * gives RF64 that libsndfile turns back into a WAV at close when it
 * stayed under 4 GiB. A plain WAV (no RF64, no comment) is written here,
 * byte for byte as libsndfile writes it; the others through libsndfile,
 * which the fulgur program then opens (lazy_library.h). Returns NULL with
 * a message naming path in err. [main-thread] */
audio_wav *audio_wav_open(int fd, const char *path, double rate_hz, uint32_t channels,
                          uint64_t max_frames, char *err, size_t err_size);

/* Gives the file text as its comment (a LIST/INFO ICMT chunk, libsndfile's
 * SF_STR_COMMENT), before the first audio_wav_write. Returns 0, or -1 with
 * libsndfile's reason in err. */
int audio_wav_comment(audio_wav *w, const char *text, char *err, size_t err_size);

/* Appends frames of interleaved samples. Returns 0, or -1 with a message
 * in err ("writing the WAV: ..."). */
int audio_wav_write(audio_wav *w, const float *interleaved, uint64_t frames, char *err,
                    size_t err_size);

/* Completes the file's sizes and frees w (NULL: nothing). Returns 0, or -1
 * when that failed. */
int audio_wav_close(audio_wav *w);

#endif
