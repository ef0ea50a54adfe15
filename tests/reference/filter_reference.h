/* Properties of the air's filters computed from their coefficients, for
 * the tests to compare with the published responses. Test code only. */
#ifndef FULGUR_TEST_FILTER_REFERENCE_H
#define FULGUR_TEST_FILTER_REFERENCE_H

#include "air/abe_lowpass_internal.h"

/* The roots of 1 + c1 x^-1 + c2 x^-2 (poles with a1, a2; zeros, scaled by
 * b0, with b1, b2): the larger modulus of the pair. A first-order section
 * has one root, -c1. */
double ref_quadratic_root_radius(double c1, double c2);

/* The interpolated FIR's magnitude response at f_hz in decibels: the model
 * taps M samples apart times the two M-sample moving averages. */
double ref_abe_fir_db(const fg_abe_fir *f, double f_hz, double fs_hz);

/* Its group delay (linear phase), samples: 51 M / 2 + M - 1. */
double ref_abe_fir_delay_frames(const fg_abe_fir *f);

#endif
