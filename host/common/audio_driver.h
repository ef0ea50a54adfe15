/* The audio drivers of fulgur run and fulgur view: where the rendered
 * blocks go.
 *   null    nowhere; the audio thread paces itself like a sound card
 *   wav     a 32-bit float WAV (audio_file.h), written
 *           under a temporary name and renamed when the run ends well
 *   raw     interleaved float32, native byte order, to stdout:
 *           fulgur run SCENE --audio raw:- | aplay -f FLOAT_LE -c2 -r48000
 *   jack, portaudio
 *           live devices (common/live_audio.h): the device's callback pulls
 *           the blocks, so these have no write; the command opens them
 * Samples are pascals times the scene's gain, as fulgur render writes. */
#ifndef HOST_COMMON_AUDIO_DRIVER_H
#define HOST_COMMON_AUDIO_DRIVER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "audio_file.h"
#include "options.h"
#include "temp_file.h"

typedef enum audio_driver_kind {
    AUDIO_DRIVER_NULL,
    AUDIO_DRIVER_WAV,
    AUDIO_DRIVER_RAW,
    AUDIO_DRIVER_JACK,
    AUDIO_DRIVER_PORTAUDIO,
    AUDIO_DRIVER_AUTO      /* fulgur view: JACK if a server runs, else PortAudio's default, else null */
} audio_driver_kind;

typedef struct audio_driver {
    audio_driver_kind kind;
    uint32_t channels;
    float gain;
    float *interleaved; /* one block */
    temp_file file;     /* wav */
    audio_wav *wav;
} audio_driver;

/* Where a command's sound goes: the --audio of run and view. */
typedef struct audio_output {
    audio_driver_kind kind;
    const char *wav_path; /* AUDIO_DRIVER_WAV: the file; JACK: the server, PortAudio:
                             the device (NULL: the default) */
} audio_output;

/* Reads "null", "wav:FILE", "raw:-", "jack[:SERVER]" or
 * "portaudio[:DEVICE]" into *(audio_output *)output, whose wav_path then
 * points into text: the option_parse_fn of --audio (common/options.h).
 * Returns 0, or -1 with what it expects in why (*output unchanged). */
int audio_output_parse(const char *text, void *output, char *why, size_t why_size);

/* The --audio option of run and view, read into *out, with its help. */
option audio_output_option(audio_output *out, const char *help);

/* Whether the output is a live device (jack, portaudio, auto). */
bool audio_output_is_live(const audio_output *out);

/* "null", "wav", "raw", "jack", "portaudio" or "auto". */
const char *audio_driver_name(audio_driver_kind kind);

/* Starts the driver of out for blocks of up to block_frames and at most
 * max_frames in all (AUDIO_FRAMES_UNBOUNDED when not known: a WAV's format
 * follows, audio_wav_open); a live kind is opened by the command, here it
 * is as null. Returns 0, or -1 with a message in err (nothing is left
 * open). [main-thread] */
int audio_driver_start(audio_driver *d, const audio_output *out, double rate_hz,
                       uint32_t channels, uint32_t block_frames, uint64_t max_frames, float gain,
                       char *err, size_t err_size);

/* Writes one block of planar samples. Returns 0, or -1 with a message.
 * [audio-thread] of the lock-step modes; the null driver does nothing. */
int audio_driver_write(audio_driver *d, float *const *planes, uint32_t frames, char *err,
                       size_t err_size);

/* Stops the driver: keep non-zero commits the WAV to its name, else it is
 * removed. Returns 0, or -1 with a message. [main-thread] */
int audio_driver_stop(audio_driver *d, bool keep, char *err, size_t err_size);

#endif
