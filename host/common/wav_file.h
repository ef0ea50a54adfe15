/* Opening a WAV (RIFF, RIFX or RF64) for reading with libsndfile, which
 * never sees the file's own header. libsndfile 1.2's header parser loops
 * forever or for minutes on chunks it misreads (a LIST sub-chunk's size
 * read as a step backwards, after the samples as well as before them; an
 * RF64 LIST claiming 0xFFFFFFFF bytes; found by fulgur_fuzz_wav), so
 * wav_open walks the chunks itself, each step moving on by at least 8
 * bytes, and shows libsndfile a header it wrote: the file's kind, its fmt
 * chunk as it is, a LIST/INFO holding only its comment (ICMT: where a
 * render keeps its calibration), a ds64 chunk for RF64, and data's header;
 * then the file's samples, read through from where they lie. Every other
 * chunk is left unread. */
#ifndef HOST_COMMON_WAV_FILE_H
#define HOST_COMMON_WAV_FILE_H

#include <sndfile.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* The largest fmt chunk taken: WAVE_FORMAT_EXTENSIBLE is 40 bytes, MS
 * ADPCM with its seven coefficients 50. */
#define WAV_FILE_MAX_FMT_BYTES 1024u
/* The longest comment carried: libsndfile reads a LIST/INFO string into
 * 2048 bytes, its size rounded up to even and below 2048. */
#define WAV_FILE_MAX_COMMENT 2044u
/* RIFF and WAVE, ds64, fmt, LIST/INFO/ICMT and the comment's NUL and pad, data */
#define WAV_FILE_HEADER_BYTES                                                                      \
    (12u + 36u + 8u + WAV_FILE_MAX_FMT_BYTES + 20u + WAV_FILE_MAX_COMMENT + 2u + 8u)

typedef struct wav_file {
    SNDFILE *sndfile;        /* open for reading after wav_open; NULL before */
    SF_INFO info;            /* as sf_open_virtual filled it */
    uint64_t declared_bytes; /* the sample bytes the header declares (the bytes held
                              * where it says "not known": 0xFFFFFFFF) */
    uint64_t held_bytes;     /* the sample bytes the file holds, at most declared_bytes */
    /* what libsndfile reads: header, then the file's held_bytes from data_at */
    FILE *in;
    unsigned char header[WAV_FILE_HEADER_BYTES];
    size_t header_bytes;
    uint64_t data_at;
    uint64_t at;
} wav_file;

/* Walks the chunks of in (a seekable file; the caller closes it after
 * wav_close) and opens it with libsndfile as above; name is the file's
 * name for messages. Refused, with a message naming name and the fault: a
 * file that is not RIFF, RIFX or RF64 WAVE; a chunk claiming more bytes
 * than the file holds before both fmt and data are found (after them the
 * walk stops there, the samples whole); no fmt chunk, or one outside
 * 16..WAV_FILE_MAX_FMT_BYTES bytes; no data chunk; what libsndfile then
 * refuses. A data chunk claiming more than the file holds is a file cut
 * short: held_bytes < declared_bytes. w must stay where it is until
 * wav_close. Returns 0, or -1 with w->sndfile NULL. [main-thread] */
int wav_open(wav_file *w, FILE *in, const char *name, char *err, size_t err_size);

/* Closes what wav_open opened; nothing when it failed. [main-thread] */
void wav_close(wav_file *w);

#endif
