#include <math.h>

#include "fg_math.h"
#include "head_shadow_internal.h"

double fg_head_shadow_db(const double ear_axis[3], const double to_source[3])
{
    double dot = 0.0, na = 0.0, ns = 0.0;
    for (int k = 0; k < 3; k++) {
        dot += ear_axis[k] * to_source[k];
        na += ear_axis[k] * ear_axis[k];
        ns += to_source[k] * to_source[k];
    }
    if (na == 0.0 || ns == 0.0)
        return 0.0;
    double shadow = 0.5 * (1.0 - dot / sqrt(na * ns));
    return FG_HEAD_SHADOW_DB * shadow * shadow;
}

fg_biquad fg_head_shelf(double hf_db, double fs_hz, double c_m_s)
{
    double f0 = c_m_s / (2.0 * FG_PI * FG_HEAD_RADIUS_M);
    double k = tan(FG_PI * f0 / fs_hz), g = pow(10.0, hf_db / 20.0);
    return (fg_biquad){(g + k) / (1.0 + k), (k - g) / (1.0 + k), 0.0, (k - 1.0) / (1.0 + k), 0.0};
}
