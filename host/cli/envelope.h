/* A waveform decimated for plotting: per bucket of frames, the time of its
 * first frame and the minimum and maximum of each channel. */
#ifndef HOST_CLI_ENVELOPE_H
#define HOST_CLI_ENVELOPE_H

#include <stddef.h>
#include <stdio.h>

/* Writes "time_s min_0 max_0 [min_1 max_1]" rows, at most `points` of them,
 * for interleaved samples. Returns 0, or -1 on a write error. */
int envelope_write(FILE *out, const float *samples, size_t frames, int channels, double rate_hz,
                   size_t points);

#endif
