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
 * Shadow zone: the arc that grazes the ground at a ground listener rises
 * to h = D^2 / 2R at horizontal distance D (parabolic approximation; the
 * ear's own height is neglected). Sources below it are in the shadow: D =
 * 3 km, R = 55 km gives 81.8 m. Following Glassner, they are faded in over
 * the height of the zone rather than cut: gain = smoothstep(h / h_shadow)
 * = 3x^2 - 2x^3 with x clamped to [0, 1]: 0 at the ground, 1/2 halfway,
 * 1 at and above the zone's top. */
#ifndef FULGUR_REFRACTION_INTERNAL_H
#define FULGUR_REFRACTION_INTERNAL_H


/* Travel time from src to ear along the arc, seconds, at speed c_m_s. */
double fg_refraction_travel_s(const double src[3], const double ear[3], double radius_m,
                              double c_m_s);

/* Top of the shadow zone at horizontal distance horizontal_m, metres
 * (0 for straight rays). */
double fg_shadow_height_m(double horizontal_m, double radius_m);

/* The fade-in gain of a source at height source_z_m whose horizontal
 * distance from the listener is horizontal_m: in [0, 1]. */
double fg_shadow_gain(double source_z_m, double horizontal_m, double radius_m);

#endif
