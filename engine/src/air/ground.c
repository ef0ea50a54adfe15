#include <math.h>

#include "air/ground_internal.h"

void fg_ground_mirror(const double p[3], double out[3])
{
    out[0] = p[0];
    out[1] = p[1];
    out[2] = -p[2];
}

static double distance(const double a[3], const double b[3])
{
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

double fg_ground_extra_path_m(const double src[3], const double ear[3])
{
    double image[3];
    fg_ground_mirror(src, image);
    return distance(image, ear) - distance(src, ear);
}
