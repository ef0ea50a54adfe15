/* Head shadow: the gain law over angle, and the shelf's response against
 * its analog prototype through the bilinear map, with the stated figures
 * (-1.9 dB at 500 Hz, -9.4 dB at 5 kHz when fully shadowed). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "fg_math.h"
#include "air/head_shadow_internal.h"

#define FS 48000.0
#define C 343.0

static void test_gain_law(void **state)
{
    (void)state;
    const double right[3] = {0.0, 1.0, 0.0};
    static const struct {
        double dir[3], db;
    } cases[] = {
        {{0, 5, 0}, 0.0},       /* facing the ear */
        {{3, 0, 0}, -2.5},      /* ahead: at the side of the ear */
        {{0, -1, 0}, -10.0},    /* opposite */
        {{1, 1, 0}, -0.21446609406726214}, /* -10 ((1 - cos 45 deg) / 2)^2 */
        {{0, 0, 0}, 0.0},       /* no direction */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double db = fg_head_shadow_db(right, cases[i].dir);
        if (fabs(db - cases[i].db) > 1e-12)
            fail_msg("case %zu: %.6f dB, want %.6f", i, db, cases[i].db);
    }
}

static double analog_db(double hf_db, double hz)
{
    double f0 = C / (2.0 * FG_PI * FG_HEAD_RADIUS_M);
    double x = tan(FG_PI * hz / FS) / tan(FG_PI * f0 / FS), g = pow(10.0, hf_db / 20.0);
    return 10.0 * log10((g * g * x * x + 1.0) / (x * x + 1.0));
}

static void test_shelf_response(void **state)
{
    (void)state;
    static const double gains[] = {0.0, -2.5, -6.0, -10.0};
    for (size_t k = 0; k < 4; k++) {
        fg_iir f = {.sections = 1};
        f.sec[0] = fg_head_shelf(gains[k], FS, C);
        assert_true(fabs(fg_iir_db(&f, 0.0)) < 1e-12);
        assert_true(fabs(fg_iir_db(&f, FG_PI) - gains[k]) < 1e-9);
        for (double hz = 20.0; hz < 0.5 * FS; hz *= 1.1)
            assert_true(fabs(fg_iir_db(&f, 2.0 * FG_PI * hz / FS) - analog_db(gains[k], hz)) <
                        1e-9);
        /* minimum phase and stable */
        assert_true(fabs(f.sec[0].a1) < 1.0);
        assert_true(fabs(f.sec[0].b1 / f.sec[0].b0) < 1.0);
    }
    fg_iir f = {.sections = 1};
    f.sec[0] = fg_head_shelf(FG_HEAD_SHADOW_DB, FS, C);
    double at100 = fg_iir_db(&f, 2.0 * FG_PI * 100.0 / FS);
    double at500 = fg_iir_db(&f, 2.0 * FG_PI * 500.0 / FS);
    double at5k = fg_iir_db(&f, 2.0 * FG_PI * 5000.0 / FS);
    double at10k = fg_iir_db(&f, 2.0 * FG_PI * 10000.0 / FS);
    assert_true(at100 > -0.3);
    assert_true(fabs(at500 + 1.9) < 0.1);
    assert_true(fabs(at5k + 9.4) < 0.1);
    assert_true(at10k < -9.8);
    /* facing: the zero cancels the pole, a wire */
    fg_biquad wire = fg_head_shelf(0.0, FS, C);
    assert_true(fabs(wire.b0 - 1.0) < 1e-15 && fabs(wire.b1 - wire.a1) < 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gain_law),
        cmocka_unit_test(test_shelf_response),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
