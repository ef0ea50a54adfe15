/* Min/max envelope: keeps every peak visible however long the file. */
#include <math.h>

#include "envelope.h"

int envelope_write(FILE *out, const float *samples, size_t frames, int channels, double rate_hz,
                   size_t points)
{
    size_t bucket = points ? (frames + points - 1) / points : frames;
    if (bucket == 0)
        bucket = 1;
    fprintf(out, "# time_s");
    for (int ch = 0; ch < channels; ch++)
        fprintf(out, " min%d_pa max%d_pa", ch, ch);
    fprintf(out, "\n");
    for (size_t start = 0; start < frames; start += bucket) {
        size_t end = start + bucket < frames ? start + bucket : frames;
        fprintf(out, "%.6f", (double)start / rate_hz);
        for (int ch = 0; ch < channels; ch++) {
            float lo = INFINITY, hi = -INFINITY;
            for (size_t f = start; f < end; f++) {
                float v = samples[f * (size_t)channels + (size_t)ch];
                lo = fminf(lo, v);
                hi = fmaxf(hi, v);
            }
            fprintf(out, " %.6g %.6g", lo, hi);
        }
        fprintf(out, "\n");
    }
    return ferror(out) ? -1 : 0;
}
