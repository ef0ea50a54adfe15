/* Shared by the growth models: the node buffer a tree is grown in, the
 * configuration with defaults filled in, and eq. 2's choice. */
#ifndef FULGUR_GROWTH_INTERNAL_H
#define FULGUR_GROWTH_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/growth.h"
#include "pick_internal.h"
#include "fg_rng.h"
#include "tree_internal.h"

typedef struct fg_nodebuf {
    fg_node *v;
    size_t count, cap;
} fg_nodebuf;

/* growth_tree.c */
fg_result fg_nodebuf_push(fg_nodebuf *b, const double x[3], int32_t parent, size_t *index);
void fg_nodebuf_free(fg_nodebuf *b);
/* Clears out and copies the nodes into it. */
fg_result fg_nodebuf_emit(const fg_nodebuf *b, fg_tree *out);

/* growth_choice.c (and fg_growth_config_resolve, public) */
/* n unit directions (xyz triples) uniform over the spherical cap of half
 * angle half_rad around the unit vector axis. */
void fg_cone_directions(fg_rng *rng, const double axis[3], double half_rad, int n, double *dirs);
/* Eq. 2's weight: max(phi, 0)^exponent. */
double fg_eq2_weight(double phi, double exponent);
/* The unit gradient of phi at x (central differences one cell apart) into
 * dir; dir is left as it was where the gradient vanishes. */
fg_result fg_field_direction(const fg_field_source *src, const double x[3], double dir[3]);
/* The root: an origin site drawn by phi^exponent; its first direction, the
 * normalised gradient of phi there (+z where it vanishes). */
fg_result fg_growth_root(const fg_field_source *src, double exponent, fg_rng *rng,
                         double root[3], double dir[3]);

/* growth_matsuyama.c — eq. 2's weights of the n candidates tip + step *
 * dirs[i]: 0 for a blocked one (its point or midpoint in an obstacle or
 * outside the box). *hit is the first candidate in the target (its point
 * or its midpoint), or -1. */
fg_result fg_matsuyama_weigh(const fg_field_source *src, const double tip[3],
                             const double *dirs, int n, double step_m, double gamma, double *w,
                             int *hit);

#endif
