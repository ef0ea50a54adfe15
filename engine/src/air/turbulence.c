#include <math.h>

#include "fg_rng.h"
#include "turbulence_internal.h"

static double lattice(uint64_t seed, int64_t i, int64_t j, int64_t k)
{
    uint64_t h = fg_splitmix64_mix(
        seed ^ fg_splitmix64_mix((uint64_t)i * FG_SPLITMIX64_GAMMA ^
                                 fg_splitmix64_mix((uint64_t)j * 0xc2b2ae3d27d4eb4full ^
                                                   fg_splitmix64_mix((uint64_t)k * 0x165667b19e3779f9ull))));
    return (double)(h >> 11) * (2.0 / 9007199254740992.0) - 1.0; /* 53 bits -> [-1, 1) */
}

static double fade(double t)
{
    return t * t * t * (t * (6.0 * t - 15.0) + 10.0);
}

static double lerp(double a, double b, double t)
{
    return a + (b - a) * t;
}

double fg_value_noise3(uint64_t seed, double x, double y, double z)
{
    double fx = floor(x), fy = floor(y), fz = floor(z);
    int64_t i = (int64_t)fx, j = (int64_t)fy, k = (int64_t)fz;
    double u = fade(x - fx), v = fade(y - fy), w = fade(z - fz);
    double c[2][2];
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++)
            c[a][b] = lerp(lattice(seed, i, j + a, k + b), lattice(seed, i + 1, j + a, k + b), u);
    return lerp(lerp(c[0][0], c[1][0], v), lerp(c[0][1], c[1][1], v), w);
}

double fg_turbulence_offset_s(const fg_turbulence *t, const double p[3])
{
    double s = 1.0 / t->correlation_m;
    return t->amplitude_s * fg_value_noise3(t->seed, p[0] * s, p[1] * s, p[2] * s);
}
