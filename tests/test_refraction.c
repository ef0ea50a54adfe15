/* Refraction: the shadow zone's tangent-ray height (D = 3 km, R = 55 km:
 * 81.8 m for an ear on the ground, 59.9 m for a 1.7 m ear), the depth into
 * it, the creeping wave's decay against its closed form and the gain, and arc travel times against
 * the straight line and their large-R limit. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "fulgur/propagation.h"
#include "air/refraction_internal.h"
#include "fg_math.h"

static void test_shadow_height(void **state)
{
    (void)state;
    const double r = FG_REFRACTION_STORM_M;
    /* an ear on the ground: D^2 / 2R, 81.8 m at 3 km */
    double h0 = fg_shadow_height_m(3000.0, 0.0, r);
    assert_true(fabs(h0 - 9.0e6 / 110000.0) < 1e-9);
    /* a 1.7 m ear: its grazing ray touches down sqrt(2 R 1.7) = 432.4 m
     * away, (3000 - 432.4)^2 / 110 km = 59.9 m */
    double h = fg_shadow_height_m(3000.0, 1.7, r);
    double reach = sqrt(2.0 * r * 1.7);
    assert_true(fabs(h - (3000.0 - reach) * (3000.0 - reach) / (2.0 * r)) < 1e-9);
    assert_true(h > 59.8 && h < 60.0);
    /* nearer than the touching point nothing is in the shadow */
    assert_true(fg_shadow_height_m(400.0, 1.7, r) == 0.0);
    /* a negative ear height is the ground */
    assert_true(fg_shadow_height_m(3000.0, -2.0, r) == h0);
    assert_true(fg_shadow_height_m(3000.0, 1.7, 0.0) == 0.0);
    assert_true(fg_shadow_height_m(3000.0, 1.7, INFINITY) == 0.0);
    /* still air, 80 km, ear on the ground: 56.25 m */
    assert_true(fabs(fg_shadow_height_m(3000.0, 0.0, 80000.0) - 56.25) < 1e-9);
}

/* A source exactly on the tangent ray is at depth 0; the depth is the
 * horizontal distance beyond the two grazing reaches. */
static void test_shadow_depth(void **state)
{
    (void)state;
    const double r = FG_REFRACTION_STORM_M, ze = 1.7, d = 3000.0;
    double top = fg_shadow_height_m(d, ze, r);
    assert_true(fabs(fg_shadow_depth_m(top, ze, d, r)) < 1e-6);
    assert_true(fg_shadow_depth_m(top + 1.0, ze, d, r) == 0.0);
    double want = d - sqrt(2.0 * r * ze) - sqrt(2.0 * r * 20.0);
    assert_true(fabs(fg_shadow_depth_m(20.0, ze, d, r) - want) < 1e-9);
    /* a source on the ground: everything beyond the ear's reach */
    assert_true(fabs(fg_shadow_depth_m(0.0, ze, d, r) - (d - sqrt(2.0 * r * ze))) < 1e-9);
    /* a 5 km-high channel top is lit out to 432 m + 23.45 km */
    assert_true(fg_shadow_depth_m(5000.0, ze, 23800.0, r) == 0.0);
    assert_true(fabs(fg_shadow_depth_m(5000.0, ze, 30000.0, r) -
                     (30000.0 - sqrt(2.0 * r * ze) - sqrt(2.0 * r * 5000.0))) < 1e-6);
    assert_true(fg_shadow_depth_m(0.0, ze, d, 0.0) == 0.0);
}

/* beta = 8.686 |a_1'| sin 60 (k / 2R^2)^(1/3): computed here from the first
 * zero of Ai' (Abramowitz & Stegun table 10.13: a_1' = -1.018792972). */
static void test_shadow_decay(void **state)
{
    (void)state;
    const double c = 343.0, r = FG_REFRACTION_STORM_M;
    const double im = 1.018792972 * sqrt(3.0) / 2.0;
    double k = 2.0 * FG_PI * 50.0 / c;
    double want = 20.0 * log10(exp(1.0)) * im * pow(k / (2.0 * r * r), 1.0 / 3.0);
    double got = fg_shadow_decay_db_m(50.0, c, r);
    assert_true(fabs(got - want) < 1e-9 * want);
    assert_true(got > 4.0e-3 && got < 4.2e-3); /* 4.1 dB/km */
    /* f^(1/3) and R^(-2/3) */
    assert_true(fabs(fg_shadow_decay_db_m(400.0, c, r) / got - 2.0) < 1e-9);
    assert_true(fabs(fg_shadow_decay_db_m(50.0, c, 8.0 * r) / got - 0.25) < 1e-9);
    assert_true(fg_shadow_decay_db_m(50.0, c, 0.0) == 0.0);
}

static void test_shadow_gain(void **state)
{
    (void)state;
    const double d = 3000.0, r = FG_REFRACTION_STORM_M, ze = 1.7, c = 343.0;
    const double top = fg_shadow_height_m(d, ze, r);
    const double beta = fg_shadow_decay_db_m(FG_SHADOW_REFERENCE_HZ, c, r);
    /* lit: 1; on the boundary: 1; inside: 10^(-beta x / 20) */
    assert_true(fg_shadow_gain(top + 0.5, ze, d, r, c) == 1.0);
    assert_true(fabs(fg_shadow_gain(top, ze, d, r, c) - 1.0) < 1e-6);
    static const double heights[] = {0.0, 5.0, 20.0, 40.0};
    for (size_t i = 0; i < sizeof heights / sizeof heights[0]; i++) {
        double x = d - sqrt(2.0 * r * ze) - sqrt(2.0 * r * heights[i]);
        double want = pow(10.0, -beta * x / 20.0);
        double g = fg_shadow_gain(heights[i], ze, d, r, c);
        if (fabs(g - want) > 1e-12)
            fail_msg("z = %g m: gain %.9f, want %.9f", heights[i], g, want);
    }
    /* a source on the ground 3 km away: 2.57 km deep, -10.5 dB */
    double db = 20.0 * log10(fg_shadow_gain(0.0, ze, d, r, c));
    assert_true(db < -10.0 && db > -11.0);
    /* deep shadow reaches deep attenuation: a 1 km-high segment 30 km
     * away is 19 km in, below -75 dB; 200 km away it is silent */
    assert_true(20.0 * log10(fg_shadow_gain(1000.0, ze, 30000.0, r, c)) < -75.0);
    assert_true(fg_shadow_gain(1000.0, ze, 200000.0, r, c) == 0.0);
    /* straight rays: no shadow, even at the ground */
    assert_true(fg_shadow_gain(0.0, ze, d, 0.0, c) == 1.0);
    /* continuous and rising with height */
    double prev = 0.0;
    for (int k = 0; k <= 100; k++) {
        double g = fg_shadow_gain(top * k / 100.0, ze, d, r, c);
        assert_true(g >= prev);
        prev = g;
    }
    assert_true(fabs(prev - 1.0) < 1e-6);
}

static void test_travel(void **state)
{
    (void)state;
    const double c = 343.0;
    const double ear[3] = {0.0, 0.0, 1.7};
    const double src[3] = {3000.0, 400.0, 5000.0};
    double chord = sqrt(3000.0 * 3000.0 + 400.0 * 400.0 + 4998.3 * 4998.3);
    double straight = chord / c;
    assert_true(fabs(fg_refraction_travel_s(src, ear, 0.0, c) - straight) < 1e-12);
    assert_true(fabs(fg_refraction_travel_s(src, ear, INFINITY, c) - straight) < 1e-12);
    static const double radii[] = {20e3, 55e3, 80e3, 200e3, 2e6, 2e7};
    double prev_excess = INFINITY;
    for (size_t i = 0; i < sizeof radii / sizeof radii[0]; i++) {
        double t = fg_refraction_travel_s(src, ear, radii[i], c);
        double excess = t - straight;
        assert_true(excess > 0.0 && excess < prev_excess);
        /* small-angle series: chord^3 / (24 R^2 c), to second order */
        double series = chord * chord * chord / (24.0 * radii[i] * radii[i] * c);
        assert_true(fabs(excess - series) < 0.05 * series);
        prev_excess = excess;
    }
    /* 5.84 km at R = 55 km: about 8 ms longer (2.7 m of path) */
    double t55 = fg_refraction_travel_s(src, ear, 55e3, c);
    assert_true(t55 - straight > 7.5e-3 && t55 - straight < 8.5e-3);
    /* a chord beyond the diameter takes the half circle */
    double far_src[3] = {50e3, 0, 1.7};
    assert_true(fabs(fg_refraction_travel_s(far_src, ear, 20e3, c) - FG_PI * 20e3 / c) < 1e-9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shadow_height),
        cmocka_unit_test(test_shadow_depth),
        cmocka_unit_test(test_shadow_decay),
        cmocka_unit_test(test_shadow_gain),
        cmocka_unit_test(test_travel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
