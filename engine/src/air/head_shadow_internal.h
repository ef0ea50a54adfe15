/* Head shadow: an interaural level difference at high frequencies, on top
 * of the per-ear delays the geometry already gives.
 *
 * Model (ours, after the spherical-head scale of Brown & Duda 1998): each
 * ear gets a first-order low shelf, DC gain 1, high-frequency gain g.
 * Analog prototype H(s) = (g s + w0) / (s + w0) with w0 = c / a, a = 8.75
 * cm the head radius (f0 = 624 Hz at 343 m/s: the wavelength equals the
 * head's circumference); mapped by the bilinear transform pre-warped at
 * f0. So |H|^2 = (g^2 x^2 + 1) / (x^2 + 1) with x = tan(pi f / fs) /
 * tan(pi f0 / fs): fully shadowed (g = -10 dB) it is -1.9 dB at 500 Hz,
 * -9.4 dB at 5 kHz and -9.9 dB at 10 kHz (48 kHz).
 *
 * Gain law: with theta the angle between the ear's outward axis and the
 * direction from the head's centre to the source,
 * g_dB = FG_HEAD_SHADOW_DB ((1 - cos theta) / 2)^2: 0 dB facing the ear,
 * -2.5 dB at the side (a source straight ahead), -10 dB opposite. The
 * square keeps the near half nearly flat. */
#ifndef FULGUR_HEAD_SHADOW_INTERNAL_H
#define FULGUR_HEAD_SHADOW_INTERNAL_H

#include "iir_internal.h"

#define FG_HEAD_SHADOW_DB (-10.0)
#define FG_HEAD_RADIUS_M 0.0875

/* High-frequency gain in dB for an ear with outward axis ear_axis (need
 * not be unit) and a source in direction to_source (need not be unit;
 * zero means no shadow). */
double fg_head_shadow_db(const double ear_axis[3], const double to_source[3]);

/* The shelf with high-frequency gain hf_db (<= 0) at sample rate fs_hz
 * for sound speed c_m_s: one first-order section (b2 = a2 = 0). */
fg_biquad fg_head_shelf(double hf_db, double fs_hz, double c_m_s);

#endif
