#include "ground_internal.h"

void fg_ground_mirror(const double p[3], double out[3])
{
    out[0] = p[0];
    out[1] = p[1];
    out[2] = -p[2];
}
