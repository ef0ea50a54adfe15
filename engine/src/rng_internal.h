/* A small seeded generator: xoshiro256** state filled by splitmix64.
 * Deterministic across platforms; not for cryptography. */
#ifndef FULGUR_RNG_INTERNAL_H
#define FULGUR_RNG_INTERNAL_H

#include <stdint.h>

typedef struct fg_rng {
    uint64_t s[4];
} fg_rng;

void fg_rng_seed(fg_rng *rng, uint64_t seed);
uint64_t fg_rng_next(fg_rng *rng);
/* Uniform in [0, 1), 53 bits. */
double fg_rng_uniform(fg_rng *rng);
/* Uniform in [lo, hi). */
double fg_rng_range(fg_rng *rng, double lo, double hi);

#endif
