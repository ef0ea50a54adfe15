/* The diffuse-field equalization of a measured HRIR set, with its low end
 * made flat: what turns a SOFA file's responses, which carry the
 * measurement's own chain (the loudspeaker and microphone: the MIT KEMAR
 * set is 10 dB down at 150 Hz-1 kHz and 30 dB down at 30-50 Hz against
 * its 2 kHz), into responses calibrated in pressure like the stereo
 * layout's ears, so that thunder's 50 Hz is as loud through them.
 *
 *   1. D(f)^2, the power of every response (each direction, both ears)
 *      averaged: the diffuse-field response, the part all directions
 *      share.
 *   2. Each response times the minimum-phase filter of 1 / D(f), D held
 *      at its value at HRIR_EQ_CROSSOVER_HZ below it and at 0.9 of the
 *      file's Nyquist frequency above: the set's diffuse-field average
 *      is then 0 dB, its interaural differences unchanged (one filter
 *      for both ears).
 *   3. Below the crossover, where a head is small against the wavelength
 *      and its response tends to 1 with a pure delay, each response is
 *      replaced by a unit impulse delayed to its phase at the crossover
 *      (the delay nearest the response's onset),
 *      through a fourth-order Linkwitz-Riley crossover (Linkwitz 1976):
 *      low and high parts sum to one all-pass, the same for every
 *      response, so the set's interaural time and level differences are
 *      kept.
 *
 * The responses keep their length (their last 5 % faded out). Host code:
 * FFTW. [main-thread] */
#ifndef HOST_COMMON_HRIR_EQUALIZE_H
#define HOST_COMMON_HRIR_EQUALIZE_H

#include <stddef.h>

#include "fulgur/engine.h"

/* The crossover below which a response is made a flat, delayed one. */
#define HRIR_EQ_CROSSOVER_HZ 250.0

/* Equalizes the set's left and right responses in place (count x length
 * each, at set->sample_rate_hz; file_rate_hz the rate they were measured
 * at, whose Nyquist frequency bounds the equalizer). Returns 0, or -1 with
 * why (out of memory, or a set with no energy to equalize). */
int hrir_equalize(const fg_hrir_set *set, float *left, float *right, double file_rate_hz,
                  char *why, size_t why_size);

#endif
