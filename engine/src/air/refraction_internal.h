/* Refraction (Glassner, after Few): sound speed falls with height, so rays
 * bend upward along circular arcs of radius R, about 80 km in still air
 * and 55 km in a thunderstorm (range 20-200 km). R = 0 or infinity means
 * straight rays.
 *
 * Travel: the ray from a source to the ear is the arc of radius R through
 * both; its length is 2 R asin(L / 2R) for the chord L (>= L, -> L as R
 * grows; excess ~ L^3 / 24 R^2). Chords longer than 2R, beyond 40 km even
 * for R = 20 km, take the half circle pi R.
 *
 * Shadow zone: the arc that grazes the ground runs up on both sides of
 * its touching point. The one through an ear at height z_e touches the
 * ground sqrt(2 R z_e) from the ear and, in the parabolic approximation,
 * stands h = (D - sqrt(2 R z_e))^2 / 2R above the ground at horizontal
 * distance D from the ear (0 nearer than the touching point): D = 3 km,
 * R = 55 km, z_e = 1.7 m gives 59.9 m (81.8 m for an ear on the ground).
 * A source at height z_s below it is in the shadow, x = D - sqrt(2 R z_e)
 * - sqrt(2 R z_s) metres beyond the farthest point its own grazing ray
 * reaches.
 *
 * Into the shadow the sound is the creeping wave that the curved rays
 * diffract along the ground (the same problem as diffraction around a
 * sphere of radius R, Fock's; for sound in a refracting atmosphere Pierce,
 * Acoustics, 1981, ch. 9, and Berry & Daigle, JASA 83, 1988). With the
 * effective wavenumber linear in height, k^2(z) = k^2 (1 + 2z / R), the
 * height modes are Airy functions; over a rigid ground the first one,
 * which decays slowest, has the horizontal wavenumber
 * k + tau_1 (k / 2R^2)^(1/3), tau_1 = |a_1'| e^(i pi / 3), a_1' = -1.01879
 * the first zero of Ai'. So its level falls by
 *     beta = 20 log10(e) |a_1'| sin(pi / 3) (k / 2R^2)^(1/3)  dB per metre
 * of x: 4.1 dB/km at 50 Hz for R = 55 km, growing as f^(1/3). The engine
 * applies beta x at FG_SHADOW_REFERENCE_HZ, thunder's spectral maximum
 * (Holmes et al. 1971, ~50 Hz), to every frequency: the gain is 1 on the
 * lit side, continuous at the boundary, and falls without bound into the
 * shadow (-41 dB 10 km in at R = 55 km). Not modelled: the higher
 * frequencies' faster decay (f^(1/3): 1.6 times beta at 200 Hz) and the
 * turbulent scattering that, near the ground upwind, keeps measured shadow
 * zones within 20-30 dB of free field (Wiener & Keast, JASA 31, 1959). */
#ifndef FULGUR_REFRACTION_INTERNAL_H
#define FULGUR_REFRACTION_INTERNAL_H


/* Travel time from src to ear along the arc, seconds, at speed c_m_s. */
double fg_refraction_travel_s(const double src[3], const double ear[3], double radius_m,
                              double c_m_s);

/* How fast the arc lengthens with the chord: d(arc)/d(chord) =
 * 1 / sqrt(1 - (L / 2R)^2) (1 for straight rays; the half circle, beyond
 * 2R, no longer lengthens). A moving ear's travel time changes by this
 * times its speed along the chord, over c. */
double fg_refraction_path_slope(double chord_m, double radius_m);

/* The frequency the shadow's decay is evaluated at, Hz. */
#define FG_SHADOW_REFERENCE_HZ 50.0

/* Top of the shadow zone at horizontal distance horizontal_m from an ear
 * ear_z_m above the ground (negative heights count as 0), metres (0 for
 * straight rays). */
double fg_shadow_height_m(double horizontal_m, double ear_z_m, double radius_m);

/* How far a source at height source_z_m lies horizontally inside the
 * shadow of an ear at height ear_z_m, horizontal_m away: metres, 0 on the
 * lit side and for straight rays. */
double fg_shadow_depth_m(double source_z_m, double ear_z_m, double horizontal_m,
                         double radius_m);

/* The creeping wave's decay beta at f_hz for sound speed c_m_s, dB per
 * metre of shadow depth (0 for straight rays). */
double fg_shadow_decay_db_m(double f_hz, double c_m_s, double radius_m);

/* The gain of that source: 10^(-beta x / 20) with beta at
 * FG_SHADOW_REFERENCE_HZ; 1 on the lit side, in (0, 1] inside (0 once it
 * is below 10^-12, 240 dB down). */
double fg_shadow_gain(double source_z_m, double ear_z_m, double horizontal_m, double radius_m,
                      double c_m_s);

#endif
