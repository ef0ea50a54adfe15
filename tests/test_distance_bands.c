/* Distance bands: log-spaced centres, the mapping distance -> band with
 * edges at geometric means, the neighbour pair and its weight, and bad
 * arguments leaving the plan unchanged. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "air/distance_bands_internal.h"

static void test_centres(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 100.0, 25600.0, 9), FG_OK);
    /* ratio (256)^(1/8) = 2: 100, 200, ..., 25600 */
    for (unsigned k = 0; k < 9; k++)
        assert_true(fabs(p.centre_m[k] - 100.0 * ldexp(1.0, (int)k)) < 1e-9 * p.centre_m[k]);
}

static void test_nearest(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 100.0, 25600.0, 9), FG_OK);
    static const struct {
        double r;
        unsigned band;
    } cases[] = {
        {1.0, 0}, {100.0, 0}, {141.0, 0}, {142.0, 1},  /* edge sqrt(2) * 100 = 141.4 */
        {3000.0, 5}, {4500.0, 5}, {4550.0, 6},         /* edge 3200 sqrt 2 = 4525 */
        {25600.0, 8}, {1e6, 8},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (fg_band_nearest(&p, cases[i].r) != cases[i].band)
            fail_msg("%g m: band %u, want %u", cases[i].r, fg_band_nearest(&p, cases[i].r),
                     cases[i].band);
}

static void test_locate(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 100.0, 25600.0, 9), FG_OK);
    unsigned lo;
    double w;
    fg_band_locate(&p, 400.0 * sqrt(2.0), &lo, &w); /* halfway in log between 400 and 800 */
    assert_int_equal(lo, 2);
    assert_true(fabs(w - 0.5) < 1e-12);
    fg_band_locate(&p, 800.0, &lo, &w); /* on centre 3: (3, 0) or (2, 1 - eps) */
    assert_true(fabs(lo + w - 3.0) < 1e-12);
    fg_band_locate(&p, 50000.0, &lo, &w);
    assert_int_equal(lo, 8);
    assert_true(w == 0.0);
    fg_band_locate(&p, 10.0, &lo, &w);
    assert_int_equal(lo, 0);
    assert_true(w == 0.0);
}

static void test_single_band(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 500.0, 500.0, 1), FG_OK);
    assert_int_equal(fg_band_nearest(&p, 3.0), 0);
    assert_int_equal(fg_band_nearest(&p, 3e4), 0);
    assert_true(p.centre_m[0] == 500.0);
}

static void test_bad_arguments(void **state)
{
    (void)state;
    fg_band_plan p, before;
    memset(&p, 0x5a, sizeof p);
    before = p;
    assert_int_equal(fg_band_plan_init(&p, 0.0, 10.0, 4), FG_ERR_ARGUMENT);
    assert_int_equal(fg_band_plan_init(&p, 10.0, 5.0, 4), FG_ERR_ARGUMENT);
    assert_int_equal(fg_band_plan_init(&p, 10.0, 50.0, 0), FG_ERR_ARGUMENT);
    assert_int_equal(fg_band_plan_init(&p, 10.0, 50.0, FG_BANDS_MAX + 1), FG_ERR_ARGUMENT);
    assert_int_equal(fg_band_plan_init(&p, NAN, 50.0, 4), FG_ERR_NOT_FINITE);
    assert_int_equal(fg_band_plan_init(&p, 10.0, INFINITY, 4), FG_ERR_NOT_FINITE);
    assert_memory_equal(&p, &before, sizeof p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_centres),       cmocka_unit_test(test_nearest),
        cmocka_unit_test(test_locate),        cmocka_unit_test(test_single_band),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
