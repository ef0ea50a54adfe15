/* fulgur run's audio drivers: where the rendered blocks go.
 *   null    nowhere; the audio thread paces itself like a sound card
 *   wav     a 32-bit float WAV through libsndfile (audio_file.h), written
 *           under a temporary name and renamed when the run ends well
 *   raw     interleaved float32, native byte order, to stdout:
 *           fulgur run SCENE --audio raw:- | aplay -f FLOAT_LE -c2 -r48000
 * Samples are pascals times the scene's gain, as fulgur render writes. */
#ifndef HOST_RUN_DRIVER_H
#define HOST_RUN_DRIVER_H

#include <sndfile.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "temp_file.h"

typedef enum run_audio_kind { RUN_AUDIO_NULL, RUN_AUDIO_WAV, RUN_AUDIO_RAW } run_audio_kind;

typedef struct run_driver {
    run_audio_kind kind;
    uint32_t channels;
    float gain;
    float *interleaved; /* one block */
    temp_file file;     /* wav */
    SNDFILE *wav;
} run_driver;

/* Reads "null", "wav:FILE" or "raw:-" (the --audio of run and view);
 * *wav_path points into text. Returns 0, or -1 (nothing written). */
int run_driver_parse(const char *text, run_audio_kind *kind, const char **wav_path);

/* Starts the driver for blocks of up to block_frames; path is the WAV's.
 * Returns 0, or -1 with a message in err (nothing is left open).
 * [main-thread] */
int run_driver_start(run_driver *d, run_audio_kind kind, const char *path, double rate_hz,
                     uint32_t channels, uint32_t block_frames, float gain, char *err,
                     size_t err_size);

/* Writes one block of planar samples. Returns 0, or -1 with a message.
 * [audio-thread] of the lock-step modes; the null driver does nothing. */
int run_driver_write(run_driver *d, float *const *planes, uint32_t frames, char *err,
                     size_t err_size);

/* Stops the driver: keep non-zero commits the WAV to its name, else it is
 * removed. Returns 0, or -1 with a message. [main-thread] */
int run_driver_stop(run_driver *d, bool keep, char *err, size_t err_size);

#endif
