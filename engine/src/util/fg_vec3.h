/* 3-vectors of doubles, by value. fg_v3_load and fg_v3_store convert from
 * and to the double[3] of the public structs. */
#ifndef FG_VEC3_H
#define FG_VEC3_H

#include <math.h>

#include "fg_math.h"
#include "fg_rng.h"

typedef struct fg_vec3 {
    double x, y, z;
} fg_vec3;

static inline fg_vec3 fg_v3(double x, double y, double z)
{
    return (fg_vec3){x, y, z};
}
static inline fg_vec3 fg_v3_load(const double p[3])
{
    return fg_v3(p[0], p[1], p[2]);
}
static inline void fg_v3_store(fg_vec3 a, double out[3])
{
    out[0] = a.x;
    out[1] = a.y;
    out[2] = a.z;
}
static inline fg_vec3 fg_v3_add(fg_vec3 a, fg_vec3 b)
{
    return fg_v3(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline fg_vec3 fg_v3_sub(fg_vec3 a, fg_vec3 b)
{
    return fg_v3(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline fg_vec3 fg_v3_scale(fg_vec3 a, double s)
{
    return fg_v3(a.x * s, a.y * s, a.z * s);
}
/* a / s, component by component (not a times 1/s: the same bits as
 * dividing each coordinate). */
static inline fg_vec3 fg_v3_div(fg_vec3 a, double s)
{
    return fg_v3(a.x / s, a.y / s, a.z / s);
}
static inline double fg_v3_dot(fg_vec3 a, fg_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline fg_vec3 fg_v3_cross(fg_vec3 a, fg_vec3 b)
{
    return fg_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double fg_v3_len(fg_vec3 a)
{
    return sqrt(fg_v3_dot(a, a));
}
/* a / |a|; a must not be zero. */
static inline fg_vec3 fg_v3_unit(fg_vec3 a)
{
    return fg_v3_scale(a, 1.0 / fg_v3_len(a));
}
/* A unit vector perpendicular to the unit vector a. */
static inline fg_vec3 fg_v3_perp(fg_vec3 a)
{
    fg_vec3 t = fabs(a.x) < 0.9 ? fg_v3(1, 0, 0) : fg_v3(0, 1, 0);
    return fg_v3_unit(fg_v3_cross(a, t));
}
/* Angle between two unit vectors, radians, robust near 0 and pi. */
static inline double fg_v3_angle(fg_vec3 a, fg_vec3 b)
{
    return atan2(fg_v3_len(fg_v3_cross(a, b)), fg_v3_dot(a, b));
}
/* The unit vector a turned by angle theta toward azimuth phi (measured
 * around a from an arbitrary fixed perpendicular). */
static inline fg_vec3 fg_v3_turn(fg_vec3 a, double theta, double phi)
{
    fg_vec3 u = fg_v3_perp(a), v = fg_v3_cross(a, u);
    fg_vec3 side = fg_v3_add(fg_v3_scale(u, cos(phi)), fg_v3_scale(v, sin(phi)));
    return fg_v3_add(fg_v3_scale(a, cos(theta)), fg_v3_scale(side, sin(theta)));
}
/* A direction uniform on the unit sphere. */
static inline fg_vec3 fg_v3_random_unit(fg_rng *rng)
{
    double z = 2.0 * fg_rng_uniform(rng) - 1.0;
    double phi = 2.0 * FG_PI * fg_rng_uniform(rng);
    double s = sqrt(1.0 - z * z);
    return fg_v3(s * cos(phi), s * sin(phi), z);
}

#endif
