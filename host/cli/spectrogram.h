/* A short-time Fourier spectrogram for plotting on a log-frequency axis:
 * Hann-windowed frames (FFTW r2c) of one channel, bins grouped into bands
 * of at least 1/24 octave, each band's level in dB re 20 uPa. */
#ifndef HOST_CLI_SPECTROGRAM_H
#define HOST_CLI_SPECTROGRAM_H

#include <stddef.h>
#include <stdio.h>

/* Writes "time_s freq_hz level_db" rows, a blank line after each time
 * slice (gnuplot's grid format), for channel `channel` of interleaved
 * samples. Returns 0, or -1 on a write or allocation error. */
int spectrogram_write(FILE *out, const float *samples, size_t frames, int channels, int channel,
                      double rate_hz);

#endif
