#include <math.h>

#include "fg_math.h"
#include "spherical_head_internal.h"

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double fg_head_excess_m(const double source[3], const double centre[3], const double u[3],
                        double a, const double centre_vel[3], const double u_rate[3],
                        double *rate_m_s)
{
    if (rate_m_s)
        *rate_m_s = 0.0;
    double v[3], w[3];
    for (int k = 0; k < 3; k++) {
        v[k] = source[k] - centre[k];
        w[k] = v[k] - a * u[k]; /* source - ear */
    }
    double r = sqrt(dot3(v, v));
    if (!(a > 0.0) || !(r > a))
        return 0.0;
    double cos_phi = dot3(v, u) / r;
    if (cos_phi >= a / r)
        return 0.0; /* the ear sees the source */
    cos_phi = cos_phi < -1.0 ? -1.0 : cos_phi;
    double phi = acos(cos_phi), tangent = sqrt(r * r - a * a), straight = sqrt(dot3(w, w));
    double excess = tangent + a * (phi - acos(a / r)) - straight;
    if (rate_m_s) {
        /* dL/dr = tangent / r, dL/dphi = a; the straight line's rate from
         * the ear's velocity centre_vel + a u_rate */
        double dr = -dot3(v, centre_vel) / r;
        double dcos = (-dot3(centre_vel, u) + dot3(v, u_rate)) / r - cos_phi * dr / r;
        double sin_phi = sqrt(fmax(0.0, 1.0 - cos_phi * cos_phi));
        double dphi = sin_phi > 1e-9 ? -dcos / sin_phi : 0.0;
        double ear_vel[3];
        for (int k = 0; k < 3; k++)
            ear_vel[k] = centre_vel[k] + a * u_rate[k];
        double dstraight = straight > 0.0 ? -dot3(w, ear_vel) / straight : 0.0;
        *rate_m_s = tangent / r * dr + a * dphi - dstraight;
    }
    return excess;
}

double fg_head_alpha(const double ear_axis[3], const double to_source[3])
{
    double na = dot3(ear_axis, ear_axis), ns = dot3(to_source, to_source);
    if (na == 0.0 || ns == 0.0)
        return 1.0;
    double c = dot3(ear_axis, to_source) / sqrt(na * ns);
    double theta = acos(c > 1.0 ? 1.0 : c < -1.0 ? -1.0 : c);
    return (1.0 + 0.5 * FG_HEAD_ALPHA_MIN) +
           (1.0 - 0.5 * FG_HEAD_ALPHA_MIN) * cos(theta / (FG_HEAD_THETA_MIN_DEG / 180.0));
}

fg_biquad fg_head_highpass(double a_m, double fs_hz, double c_m_s)
{
    double corner = fmin(c_m_s / (FG_PI * a_m), 0.45 * fs_hz);
    double k = tan(FG_PI * corner / fs_hz);
    return (fg_biquad){1.0 / (1.0 + k), -1.0 / (1.0 + k), 0.0, (k - 1.0) / (k + 1.0), 0.0};
}
