/* 1-D Gaussian pyramids (Burt & Adelson 1983): level l + 1 is level l
 * smoothed by the 5-tap generating kernel (1, 4, 6, 4, 1) / 16 (their
 * a = 3/8) and decimated by two,
 *     g_{l+1}[m] = sum_{k=-2}^{2} w_k g_l[2m + k],
 * so sample m of level l + 1 sits at sample 2m of level l: the levels stay
 * aligned in time. Level 1 is the sound itself. [sim-thread] */
#ifndef FULGUR_FIRE_PYRAMID_INTERNAL_H
#define FULGUR_FIRE_PYRAMID_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

/* Samples of the next level for n of this one: floor((n - 1) / 2) + 1. */
static inline size_t fg_pyramid_reduced_length(size_t n)
{
    return (n - 1) / 2 + 1;
}

/* out[0 .. reduced_length(n)) from in[0 .. n), n >= 1, mirroring at both
 * ends (in[-k] = in[k], in[n - 1 + k] = in[n - 1 - k]). */
void fg_pyramid_reduce(const double *in, size_t n, double *out);

/* The same filter, streamed: zero before the first sample. */
typedef struct fg_reducer {
    double history[5];  /* the last 5 inputs, oldest first */
    uint64_t taken;
} fg_reducer;

void fg_reducer_reset(fg_reducer *r);
/* Takes one sample; returns 1 and sets *out when it completes an output
 * sample (every second input from the third on), else 0. Output m needs
 * input 2m + 2, so it lags by 2 input samples. */
int fg_reducer_push(fg_reducer *r, double x, double *out);

#endif
