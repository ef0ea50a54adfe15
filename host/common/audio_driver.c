/* The null, WAV and raw drivers. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "audio_driver.h"
#include "audio_file.h"
#include "calibration.h"

int audio_output_parse(const char *text, void *output, char *why, size_t why_size)
{
    audio_output *out = output;
    if (strcmp(text, "null") == 0) {
        *out = (audio_output){AUDIO_DRIVER_NULL, NULL};
    } else if (strcmp(text, "raw:-") == 0) {
        *out = (audio_output){AUDIO_DRIVER_RAW, NULL};
    } else if (strncmp(text, "wav:", 4) == 0 && text[4]) {
        *out = (audio_output){AUDIO_DRIVER_WAV, text + 4};
    } else if (strcmp(text, "jack") == 0 || (strncmp(text, "jack:", 5) == 0 && text[5])) {
        *out = (audio_output){AUDIO_DRIVER_JACK, text[4] ? text + 5 : NULL};
    } else if (strcmp(text, "portaudio") == 0 || (strncmp(text, "portaudio:", 10) == 0 && text[10])) {
        *out = (audio_output){AUDIO_DRIVER_PORTAUDIO, text[9] ? text + 10 : NULL};
    } else {
        snprintf(why, why_size, "expected null, wav:FILE, raw:-, jack[:SERVER] or portaudio[:DEVICE]");
        return -1;
    }
    return 0;
}

bool audio_output_is_live(const audio_output *out)
{
    return out->kind == AUDIO_DRIVER_JACK || out->kind == AUDIO_DRIVER_PORTAUDIO ||
           out->kind == AUDIO_DRIVER_AUTO;
}

option audio_output_option(audio_output *out, const char *help)
{
    return (option){"--audio", OPTION_PARSED, out, "null|wav:FILE|raw:-|jack[:SERVER]|portaudio[:DEV]",
                    .help = help,
                    .parse = audio_output_parse};
}

const char *audio_driver_name(audio_driver_kind kind)
{
    static const char *const names[] = {"null", "wav", "raw", "jack", "portaudio", "auto"};
    return names[kind];
}

int audio_driver_start(audio_driver *d, const audio_output *out, double rate_hz,
                       uint32_t channels, uint32_t block_frames, uint64_t max_frames, float gain,
                       char *err, size_t err_size)
{
    audio_driver_kind kind = out->kind;
    const char *path = out->wav_path;
    *d = (audio_driver){.kind = kind, .channels = channels, .gain = gain};
    if (kind == AUDIO_DRIVER_NULL || audio_output_is_live(out))
        return 0;
    d->interleaved = malloc((size_t)block_frames * channels * sizeof(float));
    if (!d->interleaved) {
        snprintf(err, err_size, "out of memory");
        return -1;
    }
    if (kind == AUDIO_DRIVER_RAW) {
        /* a reader that goes away is an error to report, not a silent
         * death by SIGPIPE (exit 141) */
        signal(SIGPIPE, SIG_IGN);
        return 0;
    }
    if (temp_file_open(&d->file, path, err, err_size) != 0)
        goto fail;
    d->wav = audio_wav_open(d->file.fd, path, rate_hz, channels, max_frames, err, err_size);
    if (!d->wav) {
        temp_file_abort(&d->file);
        goto fail;
    }
    /* not in pascals: the file says what full scale is */
    if (gain != 1.0f && calibration_write(d->wav, 1.0 / gain, err, err_size) != 0) {
        audio_wav_close(d->wav);
        temp_file_abort(&d->file);
        goto fail;
    }
    return 0;
fail:
    free(d->interleaved);
    d->interleaved = NULL;
    return -1;
}

int audio_driver_write(audio_driver *d, float *const *planes, uint32_t frames, char *err,
                       size_t err_size)
{
    if (d->kind != AUDIO_DRIVER_WAV && d->kind != AUDIO_DRIVER_RAW)
        return 0;
    audio_interleave(planes, d->channels, frames, d->gain, d->interleaved);
    if (d->kind == AUDIO_DRIVER_RAW) {
        if (fwrite(d->interleaved, sizeof(float) * d->channels, frames, stdout) != frames) {
            if (errno == EPIPE)
                snprintf(err, err_size, "raw:-: the program reading stdout closed the pipe "
                                        "(for | aplay, Debian's alsa-utils; aplay -l lists the "
                                        "sound cards)");
            else
                snprintf(err, err_size, "writing raw samples to stdout failed: %s",
                         strerror(errno));
            return -1;
        }
        return 0;
    }
    return audio_wav_write(d->wav, d->interleaved, frames, err, err_size);
}

int audio_driver_stop(audio_driver *d, bool keep, char *err, size_t err_size)
{
    int rc = 0;
    if (d->kind == AUDIO_DRIVER_RAW && fflush(stdout) != 0) {
        snprintf(err, err_size, "writing raw samples to stdout failed");
        rc = -1;
    }
    if (d->kind == AUDIO_DRIVER_WAV) {
        if (audio_wav_close(d->wav) != 0 && keep) {
            snprintf(err, err_size, "%s: closing the WAV failed", d->file.path);
            keep = false;
            rc = -1;
        }
        if (keep)
            rc = temp_file_commit(&d->file, err, err_size);
        else
            temp_file_abort(&d->file);
    }
    free(d->interleaved);
    memset(d, 0, sizeof *d);
    return rc;
}
