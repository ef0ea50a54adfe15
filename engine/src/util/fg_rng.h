/* Seeded random numbers: splitmix64 (Steele, Lea & Flood 2014) and
 * xoshiro256** (Blackman & Vigna 2018) on the caller's state. Deterministic
 * across platforms; not for cryptography. */
#ifndef FG_RNG_H
#define FG_RNG_H

#include <math.h>
#include <stdint.h>

#include "fg_math.h"

/* splitmix64's increment: 2^64 / the golden ratio, odd. */
#define FG_SPLITMIX64_GAMMA 0x9e3779b97f4a7c15u

/* splitmix64's finaliser: a bijective mix of 64 bits. */
static inline uint64_t fg_splitmix64_mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* The next splitmix64 output; advances *state. */
static inline uint64_t fg_splitmix64_next(uint64_t *state)
{
    return fg_splitmix64_mix(*state += FG_SPLITMIX64_GAMMA);
}

/* The top 53 bits of x as a double uniform in [0, 1). */
static inline double fg_unit_from_bits(uint64_t x)
{
    return (double)(x >> 11) * 0x1.0p-53;
}

/* The next splitmix64 output as a double uniform in [0, 1); advances
 * *state. For a stream that needs nothing more than one word of state. */
static inline double fg_splitmix64_uniform(uint64_t *state)
{
    return fg_unit_from_bits(fg_splitmix64_next(state));
}

/* xoshiro256**, its state filled from the seed by splitmix64. */
typedef struct fg_rng {
    uint64_t s[4];
} fg_rng;

static inline void fg_rng_seed(fg_rng *rng, uint64_t seed)
{
    for (int i = 0; i < 4; i++)
        rng->s[i] = fg_splitmix64_next(&seed);
}

static inline uint64_t fg_rng_rotl(uint64_t x, int k)
{
    return (x << k) | (x >> (64 - k));
}

static inline uint64_t fg_rng_next(fg_rng *rng)
{
    uint64_t *s = rng->s;
    uint64_t out = fg_rng_rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = fg_rng_rotl(s[3], 45);
    return out;
}

/* Uniform in [0, 1), 53 bits. */
static inline double fg_rng_uniform(fg_rng *rng)
{
    return fg_unit_from_bits(fg_rng_next(rng));
}

/* Uniform in [lo, hi). */
static inline double fg_rng_range(fg_rng *rng, double lo, double hi)
{
    return lo + (hi - lo) * fg_rng_uniform(rng);
}

/* A standard normal deviate (Box-Muller, one of the pair): two uniforms,
 * always exactly two, so a stream's later draws do not depend on it. */
static inline double fg_rng_gaussian(fg_rng *rng)
{
    double u1 = fg_rng_uniform(rng), u2 = fg_rng_uniform(rng);
    return sqrt(-2.0 * log(1.0 - u1)) * cos(2.0 * FG_PI * u2);
}

#endif
