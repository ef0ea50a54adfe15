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

double fg_refraction_travel_s(const double src[3], const double ear[3], double radius_m,
                              double c_m_s)
{
    double dx = src[0] - ear[0], dy = src[1] - ear[1], dz = src[2] - ear[2];
    return path_m(sqrt(dx * dx + dy * dy + dz * dz), radius_m) / c_m_s;
}

double fg_shadow_height_m(double horizontal_m, double radius_m)
{
    if (straight(radius_m))
        return 0.0;
    return horizontal_m * horizontal_m / (2.0 * radius_m);
}

double fg_shadow_gain(double source_z_m, double horizontal_m, double radius_m)
{
    double top = fg_shadow_height_m(horizontal_m, radius_m);
    if (source_z_m >= top)
        return 1.0;
    double x = source_z_m <= 0.0 ? 0.0 : source_z_m / top;
    return x * x * (3.0 - 2.0 * x);
}
