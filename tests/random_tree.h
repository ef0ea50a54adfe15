/* Seeded random discharge trees for the tests that need many of them. */
#ifndef FULGUR_TESTS_RANDOM_TREE_H
#define FULGUR_TESTS_RANDOM_TREE_H

#include <stddef.h>

#include "fulgur/tree.h"
#include "fg_rng.h"

/* Fills nodes[0..count) with a branching walk from root: node i continues
 * from node i-1, or, with probability branch, from a random earlier node;
 * each step is step_m long, in a random direction pulled towards drift (a
 * vector whose length sets how strong the pull is against a unit random
 * one). Flags are 0. The result passes fg_tree_check. */
void random_tree(fg_rng *rng, fg_node *nodes, size_t count, const double root[3], double step_m,
                 const double drift[3], double branch);

#endif
