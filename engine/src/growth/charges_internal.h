/* The candidate rule of the point-charge growth, exposed for the tests. */
#ifndef FULGUR_CHARGES_INTERNAL_H
#define FULGUR_CHARGES_INTERNAL_H

#include <stddef.h>

#include "fulgur/charges.h"
#include "fg_rng.h"
#include "fg_vec3.h"

/* Fills e[k] = |Phi(cand[k]) - phi_tip| / d for the m candidates, or 0 where
 * sign * (Phi(cand[k]) - phi_tip) <= 0 (a step back up the potential). */
void fg_charges_field(const fg_point_charge *charges, size_t count, double phi_tip,
                      double sign, const fg_vec3 *cand, size_t m, double d, double *e);

/* Draws up to n distinct candidates, each with probability e[k] / sum e
 * among those still eligible; after each draw, candidates within r of the
 * drawn one become ineligible. e is scratch (zeroed as candidates drop out).
 * Writes the indices to chosen in draw order and returns how many. */
size_t fg_charges_choose(fg_rng *rng, const fg_vec3 *cand, double *e, size_t m, size_t n,
                         double r, size_t *chosen);

#endif
