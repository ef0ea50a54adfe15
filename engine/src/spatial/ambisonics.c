#include "ambisonics_internal.h"

void fg_ambisonic_gains(const double dir[3], unsigned order, double *g)
{
    const double x = dir[0], y = dir[1], z = dir[2];
    g[0] = 1.0;
    g[1] = y;
    g[2] = z;
    g[3] = x;
    if (order < 2)
        return;
    const double s3 = 1.7320508075688772; /* sqrt(3) */
    g[4] = s3 * x * y;
    g[5] = s3 * y * z;
    g[6] = 0.5 * (3.0 * z * z - 1.0);
    g[7] = s3 * x * z;
    g[8] = 0.5 * s3 * (x * x - y * y);
    if (order < 3)
        return;
    const double s58 = 0.79056941504209483;  /* sqrt(5/8) */
    const double s15 = 3.8729833462074170;   /* sqrt(15) */
    const double s38 = 0.61237243569579452;  /* sqrt(3/8) */
    g[9] = s58 * y * (3.0 * x * x - y * y);
    g[10] = s15 * x * y * z;
    g[11] = s38 * y * (5.0 * z * z - 1.0);
    g[12] = 0.5 * z * (5.0 * z * z - 3.0);
    g[13] = s38 * x * (5.0 * z * z - 1.0);
    g[14] = 0.5 * s15 * z * (x * x - y * y);
    g[15] = s58 * x * (x * x - 3.0 * y * y);
}
