/* The ambisonic layout's encoder: a wave arriving from unit direction
 * (x, y, z) in the head's frame (x ahead, y to the left, z up: the AmbiX
 * convention) is added to channel ACN = n^2 + n + m with the real
 * spherical harmonic Y_n^m in SN3D normalisation, without the
 * Condon-Shortley phase (Nachbar, Zotter, Deleflie & Sontacchi 2011,
 * "AmbiX - a suggested ambisonics format", Ambisonics Symposium, Lexington;
 * Chapman et al.'s Cartesian forms). Orders 1 to 3: 4, 9 or 16 channels.
 * SN3D gives every order n a total gain sum_m (Y_n^m)^2 = 1 in every
 * direction, so the encoded energy does not depend on the direction. */
#ifndef FULGUR_AMBISONICS_INTERNAL_H
#define FULGUR_AMBISONICS_INTERNAL_H

#include "fulgur/engine.h"

/* (FG_AMBISONIC_ORDER_MAX + 1)^2 */
#define FG_AMBISONIC_CHANNELS_MAX 16

/* Channels of order n: (n + 1)^2. */
static inline unsigned fg_ambisonic_channels(unsigned order)
{
    return (order + 1) * (order + 1);
}

/* The (order + 1)^2 gains for the unit direction dir (head frame), in ACN
 * order, into gain[]. order in [1, FG_AMBISONIC_ORDER_MAX]. */
void fg_ambisonic_gains(const double dir[3], unsigned order, double *gain);

#endif
