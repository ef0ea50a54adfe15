/* Rotations as rotation vectors: the axis times the angle in radians,
 * the exponential map's coordinates. A turn at a steady angular velocity
 * w for a time h is the rotation vector w h, so a path of rotations
 * exp(phi(t)) R0 interpolated on phi turns at exactly w when phi is
 * linear in t (core/trajectory.c). The angular velocity of such a path
 * is J(phi) dphi/dt, J the left Jacobian of SO(3) (T. D. Barfoot, State
 * Estimation for Robotics, Cambridge University Press 2017, section 7.1:
 * the Jacobian and its inverse in the closed forms below). */
#ifndef FG_ROTATION_H
#define FG_ROTATION_H

#include <math.h>

#include "fg_vec3.h"

/* Below this angle the Jacobians' coefficients are their series (the
 * first dropped term is under 1e-16 of the kept ones). */
#define FG_ROT_SERIES_RAD 1e-2

/* v turned by the rotation phi (Rodrigues' formula); v itself, bit for
 * bit, when phi is zero. */
static inline fg_vec3 fg_rot_apply(fg_vec3 phi, fg_vec3 v)
{
    double theta = fg_v3_len(phi);
    if (theta == 0.0)
        return v;
    fg_vec3 n = fg_v3_scale(phi, 1.0 / theta);
    double c = cos(theta), s = sin(theta);
    return fg_v3_add(fg_v3_add(fg_v3_scale(v, c), fg_v3_scale(fg_v3_cross(n, v), s)),
                     fg_v3_scale(n, fg_v3_dot(n, v) * (1.0 - c)));
}

/* J(phi) x = x + (1 - cos a) / a^2 phi x x + (a - sin a) / a^3 phi x (phi x x), a = |phi|. */
static inline fg_vec3 fg_rot_jacobian(fg_vec3 phi, fg_vec3 x)
{
    double a2 = fg_v3_dot(phi, phi), a = sqrt(a2), c1, c2;
    if (a < FG_ROT_SERIES_RAD) {
        c1 = 0.5 - a2 / 24.0 + a2 * a2 / 720.0;
        c2 = 1.0 / 6.0 - a2 / 120.0 + a2 * a2 / 5040.0;
    } else {
        c1 = (1.0 - cos(a)) / a2;
        c2 = (a - sin(a)) / (a2 * a);
    }
    fg_vec3 px = fg_v3_cross(phi, x);
    return fg_v3_add(fg_v3_add(x, fg_v3_scale(px, c1)), fg_v3_scale(fg_v3_cross(phi, px), c2));
}

/* J(phi)^-1 x = x - phi x x / 2 + (1 - (a/2) cot(a/2)) / a^2 phi x (phi x x),
 * for |phi| = a <= pi (finite there: 1 / pi^2). */
static inline fg_vec3 fg_rot_jacobian_inverse(fg_vec3 phi, fg_vec3 x)
{
    double a2 = fg_v3_dot(phi, phi), a = sqrt(a2), c2;
    if (a < FG_ROT_SERIES_RAD)
        c2 = 1.0 / 12.0 + a2 / 720.0 + a2 * a2 / 30240.0;
    else
        c2 = (1.0 - 0.5 * a * cos(0.5 * a) / sin(0.5 * a)) / a2;
    fg_vec3 px = fg_v3_cross(phi, x);
    return fg_v3_add(fg_v3_sub(x, fg_v3_scale(px, 0.5)), fg_v3_scale(fg_v3_cross(phi, px), c2));
}

/* The rotation vector (angle in [0, pi]) of the rotation taking the
 * orthonormal right-handed frame a[0..2] onto b[0..2]: R = sum b_k a_k^T,
 * through its unit quaternion (Shepperd's choice of the largest pivot, so
 * it is accurate at every angle). Zero, exactly, for equal frames. */
static inline fg_vec3 fg_rot_between(const fg_vec3 a[3], const fg_vec3 b[3])
{
    double fa[3][3], fb[3][3], r[3][3];
    for (int k = 0; k < 3; k++) {
        fg_v3_store(a[k], fa[k]);
        fg_v3_store(b[k], fb[k]);
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[i][j] = fb[0][i] * fa[0][j] + fb[1][i] * fa[1][j] + fb[2][i] * fa[2][j];
    double tr = r[0][0] + r[1][1] + r[2][2], w, x, y, z;
    if (tr >= r[0][0] && tr >= r[1][1] && tr >= r[2][2]) {
        w = 0.5 * sqrt(1.0 + tr);
        x = (r[2][1] - r[1][2]) / (4.0 * w);
        y = (r[0][2] - r[2][0]) / (4.0 * w);
        z = (r[1][0] - r[0][1]) / (4.0 * w);
    } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
        x = 0.5 * sqrt(fmax(1.0 + r[0][0] - r[1][1] - r[2][2], 0.0));
        w = (r[2][1] - r[1][2]) / (4.0 * x);
        y = (r[0][1] + r[1][0]) / (4.0 * x);
        z = (r[0][2] + r[2][0]) / (4.0 * x);
    } else if (r[1][1] >= r[2][2]) {
        y = 0.5 * sqrt(fmax(1.0 - r[0][0] + r[1][1] - r[2][2], 0.0));
        w = (r[0][2] - r[2][0]) / (4.0 * y);
        x = (r[0][1] + r[1][0]) / (4.0 * y);
        z = (r[1][2] + r[2][1]) / (4.0 * y);
    } else {
        z = 0.5 * sqrt(fmax(1.0 - r[0][0] - r[1][1] + r[2][2], 0.0));
        w = (r[1][0] - r[0][1]) / (4.0 * z);
        x = (r[0][2] + r[2][0]) / (4.0 * z);
        y = (r[1][2] + r[2][1]) / (4.0 * z);
    }
    fg_vec3 q = w < 0.0 ? fg_v3(-x, -y, -z) : fg_v3(x, y, z);
    double s = fg_v3_len(q);
    if (s == 0.0)
        return fg_v3(0.0, 0.0, 0.0);
    return fg_v3_scale(q, 2.0 * atan2(s, fabs(w)) / s);
}

#endif
