/* Drawing one item with probability proportional to its weight: eq. 2's
 * choice among a leader's candidates and Abe's Ek / sum(Ej). */
#ifndef FULGUR_PICK_INTERNAL_H
#define FULGUR_PICK_INTERNAL_H

/* Index i with probability w[i] / sum(w), u uniform in [0, 1); -1 if the
 * sum is not positive. Weights <= 0 are never drawn. */
int fg_pick(const double *w, int n, double u);

#endif
