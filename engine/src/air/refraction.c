#include <math.h>

#include "fg_math.h"
#include "refraction_internal.h"

static int straight(double radius_m)
{
    return radius_m <= 0.0 || isinf(radius_m);
}

/* Arc length for a chord chord_m; radius_m 0 or infinite: the chord. */
static double path_m(double chord_m, double radius_m)
{
    if (straight(radius_m))
        return chord_m;
    if (chord_m >= 2.0 * radius_m)
        return FG_PI * radius_m;
    return 2.0 * radius_m * asin(chord_m / (2.0 * radius_m));
}

double fg_refraction_path_slope(double chord_m, double radius_m)
{
    if (straight(radius_m))
        return 1.0;
    if (chord_m >= 2.0 * radius_m)
        return 0.0;
    double x = chord_m / (2.0 * radius_m);
    return 1.0 / sqrt(1.0 - x * x);
}

double fg_refraction_travel_s(const double src[3], const double ear[3], double radius_m,
                              double c_m_s)
{
    double dx = src[0] - ear[0], dy = src[1] - ear[1], dz = src[2] - ear[2];
    return path_m(sqrt(dx * dx + dy * dy + dz * dz), radius_m) / c_m_s;
}

/* The horizontal reach of the arc that grazes the ground below a point
 * z_m high: sqrt(2 R z). */
static double grazing_reach_m(double z_m, double radius_m)
{
    return sqrt(2.0 * radius_m * fmax(z_m, 0.0));
}

double fg_shadow_height_m(double horizontal_m, double ear_z_m, double radius_m)
{
    if (straight(radius_m))
        return 0.0;
    double beyond = fmax(horizontal_m - grazing_reach_m(ear_z_m, radius_m), 0.0);
    return beyond * beyond / (2.0 * radius_m);
}

double fg_shadow_depth_m(double source_z_m, double ear_z_m, double horizontal_m,
                         double radius_m)
{
    if (straight(radius_m))
        return 0.0;
    double reach = grazing_reach_m(ear_z_m, radius_m) + grazing_reach_m(source_z_m, radius_m);
    return fmax(horizontal_m - reach, 0.0);
}

/* |a_1'| sin(pi / 3): the imaginary part of the first rigid-ground mode's
 * tau_1, a_1' = -1.018792971647471 the first zero of Ai'. */
#define FIRST_MODE_IM 0.8823005946

double fg_shadow_decay_db_m(double f_hz, double c_m_s, double radius_m)
{
    if (straight(radius_m))
        return 0.0;
    double k = 2.0 * FG_PI * f_hz / c_m_s;
    return 20.0 / log(10.0) * FIRST_MODE_IM * cbrt(k / (2.0 * radius_m * radius_m));
}

/* Deeper than this the shadow is silence. */
#define SHADOW_SILENT_DB 240.0

double fg_shadow_gain(double source_z_m, double ear_z_m, double horizontal_m, double radius_m,
                      double c_m_s)
{
    double x = fg_shadow_depth_m(source_z_m, ear_z_m, horizontal_m, radius_m);
    if (x == 0.0)
        return 1.0;
    double db = fg_shadow_decay_db_m(FG_SHADOW_REFERENCE_HZ, c_m_s, radius_m) * x;
    return db >= SHADOW_SILENT_DB ? 0.0 : pow(10.0, -db / 20.0);
}
