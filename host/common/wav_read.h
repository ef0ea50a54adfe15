/* Reading a sound file whole for analysis (fulgur analyze): its samples as
 * floats, its rate checked, its calibration, and whether it holds fewer
 * frames than its header declares (a file cut short in a copy or a crash). */
#ifndef HOST_COMMON_WAV_READ_H
#define HOST_COMMON_WAV_READ_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "wav_file.h"

/* Twice the highest rate of any audio interface or format in use (384 kHz):
 * the header's rate sizes analysis windows, so a rate no audio file has
 * (2 147 483 647 Hz in 844 bytes took 8.3 GB) is refused. */
#define WAV_READ_MAX_RATE_HZ 768000

typedef struct wav_audio {
    float *samples;         /* frames * channels, interleaved, as stored; free() it */
    size_t frames;          /* the frames the file holds */
    uint64_t declared_frames; /* the frames its header declares (= frames when it
                               * cannot say: compressed formats, a size "not known") */
    int channels;
    double rate_hz;
    double full_scale_pa;   /* what a sample of 1.0 stands for */
    bool calibrated;        /* the file said so (else CALIBRATION_DEFAULT_PA) */
} wav_audio;

/* Reads every frame of w (wav_open opened it); name is the file's name
 * for messages. A WAV whose data chunk declares more frames than the file
 * holds is read as far as it goes, with declared_frames > frames. Returns
 * 0, or -1 with a message naming name in err (a rate outside
 * 1..WAV_READ_MAX_RATE_HZ, no channel, no memory, a read that stopped
 * short); w stays open either way. [main-thread] */
int wav_read(const wav_file *w, const char *name, wav_audio *out, char *err, size_t err_size);

#endif
