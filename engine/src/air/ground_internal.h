/* Ground reflection: the ground is the plane z = 0 and reflects like a
 * mirror with a pressure reflection coefficient Q in [0, 1] (about 0.8-1
 * for thunder's low frequencies over open ground). The reflected sound is
 * that of the image source below the ground.
 *
 * The engine mirrors each source segment: the image's midpoint and
 * direction are the segment's mirrored in z = 0, its gain is Q, and it
 * emits when the segment does (sound/discharge_prepare.c); from there on
 * it is an event like any other, with its own distance, angle, arrival and
 * bus for every ear. Its path is longer than the direct one by
 * sqrt(D^2 + (hs + hl)^2) - sqrt(D^2 + (hs - hl)^2) for a source at height
 * hs, an ear at hl and a horizontal distance D (test_propagation checks
 * the engine's delays against this). */
#ifndef FULGUR_GROUND_INTERNAL_H
#define FULGUR_GROUND_INTERNAL_H

/* out = p mirrored in z = 0 (out may alias p). */
void fg_ground_mirror(const double p[3], double out[3]);

#endif
