/* A training clip for fire texture synthesis (fulgur/fire.h,
 * fg_fire_texture_create) from a WAV the user supplies (RIFF, RIFX or
 * RF64; wav_open shows libsndfile a header of its own, and libsndfile
 * decodes the samples), mixed to mono by averaging its channels, checked
 * (length, rate, finite samples) and, at another rate
 * than the synthesis rate, converted with libsamplerate's best sinc
 * converter. The project ships no recording; without a file the engine's
 * procedural clip (fg_fire_texture_create_default) is what there is.
 * [main-thread] (it reads a file). */
#ifndef HOST_COMMON_FIRE_TRAINING_H
#define HOST_COMMON_FIRE_TRAINING_H

#include <stddef.h>

typedef struct fire_training {
    float *samples;       /* mono at the asked rate; the caller frees with fire_training_free */
    size_t frames;
    double file_rate_hz;  /* the file's own rate */
    int file_channels;
    int resampled;        /* 1 when converted from file_rate_hz */
} fire_training;

/* Reads path into *out at rate_hz (8000 .. 384000). Returns 0, or -1 with
 * a message naming path and what is wrong in err: unreadable, not a WAV
 * or one wav_open refuses, no frames, a rate outside 8000 .. 384000 Hz, shorter than
 * FG_FIRE_TRAINING_MIN_S or longer than FG_FIRE_TRAINING_MAX_S, a frame
 * that is not a finite number, a failed conversion. On error *out is
 * zeroed and nothing is held. */
int fire_training_read(const char *path, double rate_hz, fire_training *out, char *err,
                       size_t err_size);

/* Frees the samples and zeroes *t; a zeroed one is a no-op. */
void fire_training_free(fire_training *t);

#endif
