/* Abe et al.'s fixed distant-thunder filter: an FIR low-pass, cut-off
 * 200 Hz, order 51 (52 taps).
 *
 * At audio rates 52 taps span about a millisecond, far too short to
 * resolve 200 Hz (a 52-tap window's main lobe at 48 kHz is ~3 kHz wide).
 * So the 52-tap filter is realised as an interpolated FIR (Neuvo, Dong &
 * Mitra 1984): the model filter is designed at the rate fs / M, with M =
 * floor(fs / 2400 Hz), and run at fs with its taps M samples apart; its
 * images around multiples of fs / M are removed by two cascaded M-sample
 * moving averages, whose nulls fall exactly on those multiples. The whole
 * is linear phase, with a delay of (51 M / 2 + M - 1) samples.
 *
 * Model filter: windowed sinc with a Hamming window, cut-off 200 Hz
 * defined as the half-amplitude point (-6 dB) of the model, taps scaled to
 * unit DC gain. The whole filter is -6.2 dB at 200 Hz (the moving
 * averages add -0.2 dB), -0.02 dB at 100 Hz, below -65 dB at 1 kHz, and
 * at least 46 dB down everywhere above 600 Hz, images included (44.1, 48
 * and 96 kHz).
 *
 * Cost per sample: 52 multiply-adds, plus four adds and two divisions for
 * the moving averages, whose running sums are re-added exactly once per M
 * samples (at fixed sample positions, so block splitting never changes the
 * output); about 60 ns per sample here. State: about 35 KB. */
#ifndef FULGUR_ABE_LOWPASS_INTERNAL_H
#define FULGUR_ABE_LOWPASS_INTERNAL_H

#include <stddef.h>

#include "fulgur/result.h"

#define FG_ABE_FIR_TAPS 52
#define FG_ABE_FIR_CUTOFF_HZ 200.0
#define FG_ABE_FIR_MODEL_MIN_HZ 2400.0
#define FG_ABE_FIR_MAX_STRIDE 160 /* 384 kHz / 2400 Hz */
#define FG_ABE_FIR_HISTORY 8192   /* power of two > 51 * FG_ABE_FIR_MAX_STRIDE */

typedef struct fg_abe_fir {
    double h[FG_ABE_FIR_TAPS];
    unsigned stride;                          /* M */
    double box[2][FG_ABE_FIR_MAX_STRIDE];     /* the two moving averages' inputs */
    double box_sum[2];
    unsigned box_pos;
    float hist[FG_ABE_FIR_HISTORY];           /* smoothed input, ring */
    unsigned pos;
} fg_abe_fir;

/* Designs the filter for fs_hz and clears its state.
 * Errors: FG_ERR_SAMPLE_RATE for fs_hz outside 8 kHz - 384 kHz (f is then
 * unchanged). */
fg_result fg_abe_fir_init(fg_abe_fir *f, double fs_hz);

/* Clears the state (silence before the first sample). */
void fg_abe_fir_reset(fg_abe_fir *f);

/* Filters buf[0..n) in place; the state carries over to the next call.
 * [audio-thread]: bounded, no allocation. */
void fg_abe_fir_process(fg_abe_fir *f, float *buf, size_t n);

#endif
