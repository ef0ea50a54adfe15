/* The high-pass on p before extension (section 6: "a high-pass filter
 * (with 30Hz cutoff frequency)"; the paper gives no order). Ours is a
 * 2nd-order Butterworth (Q = 1/sqrt 2, -3 dB at the cutoff, -12 dB per
 * octave below it), mapped by the bilinear transform pre-warped at the
 * cutoff, run by the engine's fg_iir. With p = dI/dt already rising at
 * 6 dB per octave, a drift of the mean flux is down 18 dB per octave
 * below 30 Hz. */
#ifndef FULGUR_FIRE_HIGHPASS_INTERNAL_H
#define FULGUR_FIRE_HIGHPASS_INTERNAL_H

#include "air/iir_internal.h"

/* f as a high-pass at cutoff_hz (0 < cutoff_hz < fs / 2), state cleared. */
void fg_fire_highpass_design(fg_iir *f, double cutoff_hz, double sample_rate_hz);

#endif
