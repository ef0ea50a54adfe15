/* A cascade of up to four biquads, run in transposed direct form II with
 * double state. Coefficients and state live in one fixed-size struct;
 * processing never allocates and keeps its state across blocks, so a
 * signal split into blocks anywhere gives exactly the one-shot output. */
#ifndef FULGUR_IIR_INTERNAL_H
#define FULGUR_IIR_INTERNAL_H

#include <stddef.h>

#define FG_IIR_MAX_SECTIONS 4

/* H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2). A first-order
 * section has b2 = a2 = 0. */
typedef struct fg_biquad {
    double b0, b1, b2, a1, a2;
} fg_biquad;

typedef struct fg_iir {
    fg_biquad sec[FG_IIR_MAX_SECTIONS];
    unsigned sections;
    double z[FG_IIR_MAX_SECTIONS][2];
} fg_iir;

/* Clears the state (silence before the first sample). */
void fg_iir_reset(fg_iir *f);

/* Filters buf[0..n) in place. [audio-thread]: bounded, no allocation.
 * State magnitudes below 1e-30 are snapped to zero on every sample, so a
 * decaying tail ends in exact zeros and never becomes denormal, whatever
 * the floating-point environment. */
void fg_iir_process(fg_iir *f, float *buf, size_t n);

/* Filters up to FG_IIR_LANES signals at once, f[j] on buf[j][0..n) for j
 * < count, every filter with the same number of sections: each lane gives
 * exactly what fg_iir_process gives it (the same operations in the same
 * order), but the lanes' recurrences run side by side instead of one
 * after the other, which hides the latency of each. On an x86 processor
 * with AVX2 (checked per call), three or four lanes run as one vector of
 * doubles over 64-frame chunks held in double, each section a sample
 * behind the one before it so that their recurrences overlap (four
 * sections at once, else pairs): the same operations per lane without
 * FMA, so the same samples, 1.6x faster here for four lanes of the four
 * sections an absorption filter has. [audio-thread] */
#define FG_IIR_LANES 4
void fg_iir_process_lanes(fg_iir *const *f, float *const *buf, unsigned count, size_t n);

/* e^{-jw} and e^{-2jw}, for evaluating many responses at one frequency. */
typedef struct fg_phasor {
    double c1, s1, c2, s2;
} fg_phasor;

fg_phasor fg_phasor_at(double w);

/* |H(e^{jw})| of the cascade in decibels, w = 2 pi f / fs rad/sample. */
double fg_iir_db(const fg_iir *f, double w);

#endif
