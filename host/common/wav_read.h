/* Reading a sound file whole for analysis (fulgur analyze): its samples as
 * floats, its rate checked, its calibration, and whether it holds fewer
 * frames than its header declares (a file cut short in a copy or a crash). */
#ifndef HOST_COMMON_WAV_READ_H
#define HOST_COMMON_WAV_READ_H

#include <sndfile.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Twice the highest rate of any audio interface or format in use (384 kHz):
 * the header's rate sizes analysis windows, so a rate no audio file has
 * (2 147 483 647 Hz in 844 bytes took 8.3 GB) is refused. */
#define WAV_READ_MAX_RATE_HZ 768000

typedef struct wav_audio {
    float *samples;         /* frames * channels, interleaved, as stored; free() it */
    size_t frames;          /* the frames the file holds */
    uint64_t declared_frames; /* the frames its header declares (= frames when it
                               * cannot say: RF64, compressed formats) */
    int channels;
    double rate_hz;
    double full_scale_pa;   /* what a sample of 1.0 stands for */
    bool calibrated;        /* the file said so (else CALIBRATION_DEFAULT_PA) */
} wav_audio;

/* Walks the chunks of a RIFF, RIFX or RF64 file in (from its start; its
 * position is left anywhere) and refuses one whose chunk other than "data"
 * claims more bytes than the file holds, or whose LIST chunk holds a
 * sub-chunk claiming more than the list: libsndfile 1.2's header parser
 * can loop for minutes on such a chunk (a LIST claiming 4 GB in a 240-byte
 * file) or forever on such a sub-chunk (a 98-byte file; both found by
 * fulgur_fuzz_wav), so this runs before sf_open. A data
 * chunk cut short is the truncated file wav_read reports; other files are
 * not walked. Returns 0, or -1 with a message naming name in err.
 * [main-thread] */
int wav_check_chunks(FILE *in, const char *name, char *err, size_t err_size);

/* Reads every frame of f (open for reading, info as sf_open filled it);
 * name is the file's name for messages. A WAV whose data chunk declares
 * more frames than the file holds is read as far as it goes, with
 * declared_frames > frames. Returns 0, or -1 with a message naming name in
 * err (a rate outside 1..WAV_READ_MAX_RATE_HZ, no channel, no memory, a
 * read that stopped short); f stays open either way. [main-thread] */
int wav_read(SNDFILE *f, const SF_INFO *info, const char *name, wav_audio *out, char *err,
             size_t err_size);

#endif
