/* The stereo layout's spherical head (spatial/spherical_head_internal.h):
 * the way around the sphere against Woodworth's far-field formula and its
 * exact time derivative, Brown & Duda's alpha at the angles their paper
 * names, and the plain bus plus alpha - 1 times the twin's high-pass
 * against their analog head-shadow filter through the bilinear map. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "fg_math.h"
#include "spatial/spherical_head_internal.h"

#define FS 48000.0
#define C 343.0
#define A 0.0875

static const double zero[3] = {0, 0, 0};

/* Far away, the far ear's excess plus the near ear's shortening is
 * Woodworth's a (theta + sin theta): the interaural path difference. */
static void far_field_is_woodworth(void **state)
{
    (void)state;
    const double right[3] = {1, 0, 0}, left[3] = {-1, 0, 0}, centre[3] = {0, 0, 0};
    const double r = 1e5;
    for (double deg = 0.0; deg <= 90.0; deg += 15.0) {
        double th = deg * FG_PI / 180.0;
        /* ahead is +y, the source theta towards the right ear */
        double src[3] = {r * sin(th), r * cos(th), 0.0};
        double ear_r[3] = {A, 0, 0}, ear_l[3] = {-A, 0, 0};
        double dr = 0, dl = 0;
        for (int k = 0; k < 3; k++) {
            dr += (src[k] - ear_r[k]) * (src[k] - ear_r[k]);
            dl += (src[k] - ear_l[k]) * (src[k] - ear_l[k]);
        }
        double far = sqrt(dl) + fg_head_excess_m(src, centre, left, A, zero, zero, NULL);
        double near = sqrt(dr) + fg_head_excess_m(src, centre, right, A, zero, zero, NULL);
        double want = A * (th + sin(th));
        if (fabs((far - near) - want) > 1e-7)
            fail_msg("%.0f deg: path difference %.9f m, Woodworth %.9f m", deg, far - near, want);
        /* the near ear sees the source (from straight ahead neither does,
         * by a hair: the tangent point lies just short of 90 degrees) */
        if (deg > 0.0)
            assert_true(fg_head_excess_m(src, centre, right, A, zero, zero, NULL) == 0.0);
    }
    /* 90 degrees: 0.656 ms */
    assert_true(fabs(A * (FG_PI / 2 + 1) / C - 655.9e-6) < 0.1e-6);
}

/* Near the head, the tangent and the arc: a source 0.5 m out on the
 * left, the right ear's way is sqrt(r^2 - a^2) + a (pi - acos(a / r)). */
static void near_field_tangent_and_arc(void **state)
{
    (void)state;
    const double right[3] = {1, 0, 0}, centre[3] = {0, 0, 0}, src[3] = {-0.5, 0, 0};
    double r = 0.5, want = sqrt(r * r - A * A) + A * (FG_PI - acos(A / r)) - (r + A);
    assert_true(fabs(fg_head_excess_m(src, centre, right, A, zero, zero, NULL) - want) < 1e-12);
    /* no head, or a source inside it: nothing */
    assert_true(fg_head_excess_m(src, centre, right, 0.0, zero, zero, NULL) == 0.0);
    const double inside[3] = {-0.05, 0, 0};
    assert_true(fg_head_excess_m(inside, centre, right, A, zero, zero, NULL) == 0.0);
}

/* The rate against a centred difference of the excess along a moving,
 * turning head. */
static void rate_is_the_derivative(void **state)
{
    (void)state;
    const double src[3] = {-3.0, 1.0, 0.4};
    const double vc[3] = {0.7, -0.3, 0.2};
    const double w = 2.0; /* rad/s about z */
    const double h = 1e-6;
    for (double t = 0.0; t < 1.5; t += 0.25) {
        double c[3], u[3], du[3];
        for (int k = 0; k < 3; k++)
            c[k] = vc[k] * t;
        u[0] = cos(w * t), u[1] = sin(w * t), u[2] = 0;
        du[0] = -w * sin(w * t), du[1] = w * cos(w * t), du[2] = 0;
        double rate;
        double e0 = fg_head_excess_m(src, c, u, A, vc, du, &rate);
        double cp[3], cm[3], up[3] = {cos(w * (t + h)), sin(w * (t + h)), 0},
               um[3] = {cos(w * (t - h)), sin(w * (t - h)), 0};
        for (int k = 0; k < 3; k++) {
            cp[k] = vc[k] * (t + h);
            cm[k] = vc[k] * (t - h);
        }
        double ep = fg_head_excess_m(src, cp, up, A, zero, zero, NULL);
        double em = fg_head_excess_m(src, cm, um, A, zero, zero, NULL);
        if (e0 > 0 && ep > 0 && em > 0 && fabs(rate - (ep - em) / (2 * h)) > 1e-6)
            fail_msg("t %.2f: rate %.9f, difference %.9f", t, rate, (ep - em) / (2 * h));
    }
}

/* Brown & Duda's alpha: 2 facing the ear, alpha_min at theta_min = 150
 * degrees, 1 + a_min/2 + (1 - a_min/2) cos(216 deg) opposite. */
static void alpha_at_the_named_angles(void **state)
{
    (void)state;
    const double axis[3] = {0, 3, 0};
    static const struct {
        double deg, alpha;
    } cases[] = {{0.0, 2.0}, {150.0, 0.1}, {180.0, 1.05 + 0.95 * -0.80901699437494745},
                 {75.0, 1.05}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double th = cases[i].deg * FG_PI / 180.0;
        double dir[3] = {sin(th), cos(th), 0};
        double a = fg_head_alpha(axis, dir);
        if (fabs(a - cases[i].alpha) > 1e-12)
            fail_msg("%.0f deg: alpha %.12f, want %.12f", cases[i].deg, a, cases[i].alpha);
    }
    assert_true(fg_head_alpha(axis, zero) == 1.0);
}

/* |1 + (alpha - 1) HP| against the analog (1 + j alpha w/2w0) / (1 + j
 * w/2w0) at the pre-warped frequency. */
static void plain_plus_twin_is_brown_duda(void **state)
{
    (void)state;
    fg_biquad hp = fg_head_highpass(A, FS, C);
    double corner = C / (FG_PI * A);
    static const double alphas[] = {2.0, 1.05, 0.28, 0.1};
    for (size_t i = 0; i < 4; i++) {
        double al = alphas[i];
        for (double hz = 20.0; hz < 0.5 * FS; hz *= 1.1) {
            double w = 2.0 * FG_PI * hz / FS;
            /* HP(e^jw) */
            double cr = cos(w), ci = -sin(w);
            double nr = hp.b0 + hp.b1 * cr, ni = hp.b1 * ci;
            double dr = 1.0 + hp.a1 * cr, di = hp.a1 * ci;
            double den = dr * dr + di * di;
            double hr = (nr * dr + ni * di) / den, hi = (ni * dr - nr * di) / den;
            double gr = 1.0 + (al - 1.0) * hr, gi = (al - 1.0) * hi;
            double got = 10.0 * log10(gr * gr + gi * gi);
            double x = tan(FG_PI * hz / FS) / tan(FG_PI * corner / FS);
            double want = 10.0 * log10((1.0 + al * al * x * x) / (1.0 + x * x));
            if (fabs(got - want) > 1e-9)
                fail_msg("alpha %.2f, %.0f Hz: %.6f dB, want %.6f", al, hz, got, want);
        }
    }
    /* the corner: c / (pi a) = 1.248 kHz; HP is stable */
    assert_true(fabs(corner - 1247.8) < 0.1);
    assert_true(fabs(hp.a1) < 1.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(far_field_is_woodworth),
        cmocka_unit_test(near_field_tangent_and_arc),
        cmocka_unit_test(rate_is_the_derivative),
        cmocka_unit_test(alpha_at_the_named_angles),
        cmocka_unit_test(plain_plus_twin_is_brown_duda),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
