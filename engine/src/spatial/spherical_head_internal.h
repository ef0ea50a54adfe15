/* The stereo layout's head: two ears at the ends of a rigid sphere's
 * diameter (the ear spacing, fg_engine_config.ear_spacing_m; its default
 * 0.175 m is the radius a = 8.75 cm of Woodworth's and Brown & Duda's
 * head).
 *
 * Delay. Sound reaches an ear the source can see along the straight line;
 * an ear on the far side along the tangent from the source to the sphere
 * and then the great-circle arc to the ear: for a source r from the
 * centre, at angle phi from the ear's outward axis,
 *   L = sqrt(r^2 - a^2) + a (phi - acos(a / r))   when cos phi < a / r.
 * Far away this is Woodworth's interaural time difference,
 *   ITD = (a / c) (theta + sin theta),  theta the lateral angle
 * (Woodworth & Schlosberg 1954; Brown & Duda 1998 eq. 1): 0.656 ms at 90
 * degrees for a = 8.75 cm, c = 343 m/s. fg_head_excess_m gives L minus the
 * straight ear distance (0 for a visible ear), which the source models add
 * to their travel.
 *
 * Shadow (Brown & Duda 1998, "A structural model for binaural sound
 * synthesis", IEEE Trans. Speech Audio Proc. 6(5), eqs. 2-3): each ear
 * hears the source through the one-pole, one-zero filter
 *   H(w, theta) = (1 + j alpha w / (2 w0)) / (1 + j w / (2 w0)),  w0 = c / a,
 *   alpha(theta) = (1 + alpha_min / 2) + (1 - alpha_min / 2) cos(theta / theta_min pi),
 * alpha_min = 0.1, theta_min = 150 degrees, theta the angle between the
 * ear's outward axis and the direction from the head's centre to the
 * source: +6 dB at high frequencies facing the ear, -20 dB at 150 degrees,
 * -11 dB straight opposite (an ILD of 17 dB at high frequencies for a
 * source at the side). Since H = 1 + (alpha - 1) HP with HP(s) = s / (s +
 * 2 w0), a wave goes to the plain bus with weight 1 and to the bus's
 * shadowed twin, whose filter is HP, with weight alpha - 1: the filter
 * costs per bus, never per wave. HP is mapped by the bilinear transform
 * pre-warped at its corner 2 w0 / (2 pi) = c / (pi a) (1.25 kHz for the
 * default head), capped at 0.45 fs for a very small head.
 * H also delays low frequencies: the near ear (alpha = 2) by -a / (2 c),
 * the far one by (1 - alpha) a / (2 c), so with the shadow on the
 * low-frequency ITD at 90 degrees exceeds Woodworth's (measured in
 * tests/test_stereo_head.c, docs/spatial.md). */
#ifndef FULGUR_SPHERICAL_HEAD_INTERNAL_H
#define FULGUR_SPHERICAL_HEAD_INTERNAL_H

#include "air/iir_internal.h"

#define FG_HEAD_ALPHA_MIN 0.1
#define FG_HEAD_THETA_MIN_DEG 150.0

/* How much longer than the straight line the path from source to the ear
 * at centre + a u is around the sphere of radius a (u unit): 0 while the
 * ear is visible, a <= 0, or the source lies inside the sphere. With the
 * source still, the centre moving at centre_vel and u turning at u_rate
 * (1/s), *rate_m_s (may be NULL) receives the excess's time derivative. */
double fg_head_excess_m(const double source[3], const double centre[3], const double u[3],
                        double a, const double centre_vel[3], const double u_rate[3],
                        double *rate_m_s);

/* Brown & Duda's alpha for an ear with outward axis ear_axis and a source
 * in direction to_source from the head's centre (neither need be unit;
 * either zero gives 1, no shadow). */
double fg_head_alpha(const double ear_axis[3], const double to_source[3]);

/* The twin buses' filter HP for a head of radius a_m (> 0) at fs_hz and
 * c_m_s: one first-order section (b2 = a2 = 0). */
fg_biquad fg_head_highpass(double a_m, double fs_hz, double c_m_s);

#endif
