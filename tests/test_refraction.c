/* Refraction: the shadow zone's height (Glassner: D = 3 km, R = 55 km ->
 * ~82 m), the fade at and inside its bounds, and arc travel times against
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
    double h = fg_shadow_height_m(3000.0, FG_REFRACTION_STORM_M);
    assert_true(fabs(h - 9.0e6 / 110000.0) < 1e-9);
    assert_true(h > 81.0 && h < 83.0);
    assert_true(fg_shadow_height_m(3000.0, 0.0) == 0.0);
    assert_true(fg_shadow_height_m(3000.0, INFINITY) == 0.0);
    /* still air, 80 km: 56.25 m */
    assert_true(fabs(fg_shadow_height_m(3000.0, 80000.0) - 56.25) < 1e-9);
}

static void test_shadow_gain(void **state)
{
    (void)state;
    const double d = 3000.0, r = FG_REFRACTION_STORM_M;
    const double top = fg_shadow_height_m(d, r);
    static const struct {
        double fraction, gain;
    } cases[] = {
        {-0.5, 0.0}, {0.0, 0.0}, {0.25, 0.15625}, {0.5, 0.5}, {0.75, 0.84375}, {1.0, 1.0},
        {3.0, 1.0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double g = fg_shadow_gain(cases[i].fraction * top, d, r);
        if (fabs(g - cases[i].gain) > 1e-12)
            fail_msg("h = %g top: gain %.6f, want %.6f", cases[i].fraction, g, cases[i].gain);
    }
    /* straight rays: no shadow, even at the ground */
    assert_true(fg_shadow_gain(0.0, d, 0.0) == 1.0);
    /* continuous and rising through the zone */
    double prev = 0.0;
    for (int k = 1; k <= 100; k++) {
        double g = fg_shadow_gain(top * k / 100.0, d, r);
        assert_true(g >= prev && g - prev < 0.016);
        prev = g;
    }
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
        cmocka_unit_test(test_shadow_gain),
        cmocka_unit_test(test_travel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
