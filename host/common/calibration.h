/* The level a WAV's samples are at: how many pascals full scale (a sample
 * of 1.0) stands for, written into the file so that its pressure can be
 * read back whatever gain made it listenable.
 *
 * Where it is kept: the WAV's LIST/INFO chunk, as its comment (ICMT,
 * libsndfile's SF_STR_COMMENT), in the words
 *     fulgur calibration: full scale = 496.2 Pa
 * with the number printed to 9 significant digits. A file without it is
 * in pascals (full scale = 1 Pa), as `fulgur render` writes by default.
 * Players show the comment; `fulgur analyze` reads it. */
#ifndef HOST_COMMON_CALIBRATION_H
#define HOST_COMMON_CALIBRATION_H

#include <sndfile.h>
#include <stdbool.h>
#include <stddef.h>

#include "audio_file.h"

/* The full scale of a file that carries no calibration. */
#define CALIBRATION_DEFAULT_PA 1.0

/* Writes the calibration into wav (open for writing, before its first
 * samples): the file is then libsndfile's (audio_wav_comment).
 * full_scale_pa must be finite and > 0. Returns 0, or -1 with libsndfile's
 * message in err. [main-thread] */
int calibration_write(audio_wav *wav, double full_scale_pa, char *err, size_t err_size);

/* The calibration of wav (open for reading): true with *full_scale_pa set,
 * or false when the file carries none (*full_scale_pa is then
 * CALIBRATION_DEFAULT_PA). */
bool calibration_read(SNDFILE *wav, double *full_scale_pa);

/* Parses a comment as calibration_write writes it; false when it is not
 * one (or its number is not finite and positive). */
bool calibration_parse(const char *comment, double *full_scale_pa);

/* A level in dB re full scale; -INFINITY for 0. */
double calibration_dbfs(double peak);

#endif
