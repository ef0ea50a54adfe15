/* Ground reflection: the ground is the plane z = 0 and reflects like a
 * mirror with a pressure reflection coefficient Q in [0, 1] (about 0.8-1
 * for thunder's low frequencies over open ground). The reflected sound is
 * that of the image source below the ground.
 *
 * Mirroring the ear instead of the source gives the same distance, the
 * same angle to every segment and so the same WM-wave: the image of a
 * segment as heard by an ear equals the segment itself as heard by the
 * mirrored ear, scaled by Q. The path is longer by the extra length below. */
#ifndef FULGUR_GROUND_INTERNAL_H
#define FULGUR_GROUND_INTERNAL_H

/* out = p mirrored in z = 0 (out may alias p). */
void fg_ground_mirror(const double p[3], double out[3]);

/* How much longer the reflected path from src to ear is than the direct
 * one, metres (>= 0 for points above the ground). */
double fg_ground_extra_path_m(const double src[3], const double ear[3]);

#endif
