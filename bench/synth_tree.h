/* A benchmark fixture: a lightning-like tree with exactly the number of
 * segments asked for. A tortuous main channel falls from the cloud base to
 * the ground in steps of 2 l; the rest of the segments form branches that
 * leave random nodes and wander downwards. Seeded, so every run of a
 * benchmark times the same trees. Not a physical generator: the engine's
 * generators are in engine/; this only gives trees of any size. */
#ifndef FULGUR_BENCH_SYNTH_TREE_H
#define FULGUR_BENCH_SYNTH_TREE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/tree.h"

/* Fills nodes[0..segments] (segments + 1 nodes): root at height_m above
 * the origin, steps of step_m. */
void synth_tree(fg_node *nodes, size_t segments, double height_m, double step_m, uint64_t seed);

/* A 5 km bolt of that many segments in 3 m steps (seed 5) whose ground
 * point lies 3 km ahead (+y) of the origin: segments + 1 nodes, malloc'd
 * (the caller frees), NULL when out of memory. */
fg_node *synth_far_bolt(size_t segments);

#endif
