/* Distance bands: log-spaced centres, the neighbour pair around a
 * distance and its level-matched weight, the split's accuracy, and bad
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

/* The pair around r: the nearer centre below r in log distance. */
static void test_pair(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 100.0, 25600.0, 9), FG_OK);
    static const struct {
        double r;
        unsigned lo;
    } cases[] = {
        {1.0, 0}, {100.0, 0}, {141.0, 0}, {199.0, 0}, {201.0, 1},
        {3000.0, 4}, {3300.0, 5}, {25600.0, 8}, {1e6, 8},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        unsigned lo;
        double w;
        fg_band_locate(&p, cases[i].r, &lo, &w);
        if (lo != cases[i].lo)
            fail_msg("%g m: band %u, want %u", cases[i].r, lo, cases[i].lo);
    }
}

/* The weight mixes the two bands' magnitudes to exactly the source's own
 * at FG_BAND_MATCH_DB: (1 - w) a + w a^q = a^(q^u), a the lower band's
 * magnitude there; 0 and 1 at the centres, rising in between. */
static void test_locate(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 100.0, 25600.0, 9), FG_OK);
    const double a = pow(10.0, -FG_BAND_MATCH_DB / 20.0);
    double prev = -1.0;
    for (int i = 0; i <= 100; i++) {
        double u = i / 100.0, r = 400.0 * pow(2.0, u);
        unsigned lo;
        double w;
        fg_band_locate(&p, r, &lo, &w);
        if (i == 0 || i == 100) {
            /* on a centre k: (k, 0) or (k - 1, 1 - eps) */
            assert_true(fabs(lo + w - 2.0 - u) < 1e-9);
            continue;
        }
        assert_int_equal(lo, 2);
        double mix = (1.0 - w) * a + w * pow(a, 2.0);
        double want = pow(a, pow(2.0, u));
        assert_true(fabs(mix - want) < 1e-12 * want);
        assert_true(w >= 0.0 && w <= 1.0 && w > prev);
        prev = w;
    }
    unsigned lo;
    double w;
    fg_band_locate(&p, 1600.0, &lo, &w);
    assert_true(fabs(lo + w - 4.0) < 1e-9);
    fg_band_locate(&p, 50000.0, &lo, &w);
    assert_int_equal(lo, 8);
    assert_true(w == 0.0);
    fg_band_locate(&p, 10.0, &lo, &w);
    assert_int_equal(lo, 0);
    assert_true(w == 0.0);
}

/* The engine's plan (45 bands, 10 m - 30 km, q = 1.1996): the split mix is
 * within 0.52 dB of alpha d at every attenuation up to 80 dB, at least
 * 80 dB down beyond (magnitudes), over a fine grid of distances. */
static void test_split_accuracy(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 10.0, 30000.0, 45), FG_OK);
    assert_true(fabs(p.q - 1.1996) < 1e-4);
    double worst = 0.0;
    for (double r = 100.0; r <= 20000.0; r *= 1.003) {
        unsigned lo;
        double w;
        fg_band_locate(&p, r, &lo, &w);
        for (double db_per_m = 1e-5; db_per_m < 1.0; db_per_m *= 1.02) {
            double want = db_per_m * r;
            double mix = (1.0 - w) * pow(10.0, -db_per_m * p.centre_m[lo] / 20.0) +
                         w * pow(10.0, -db_per_m * p.centre_m[lo + 1] / 20.0);
            double got = -20.0 * log10(mix);
            double err = want <= 80.0 ? fabs(got - want) : fmax(0.0, 80.0 - got);
            worst = fmax(worst, err);
        }
    }
    if (worst > 0.52)
        fail_msg("worst %.3f dB", worst);
}

static void test_single_band(void **state)
{
    (void)state;
    fg_band_plan p;
    assert_int_equal(fg_band_plan_init(&p, 500.0, 500.0, 1), FG_OK);
    unsigned lo;
    double w;
    fg_band_locate(&p, 3.0, &lo, &w);
    assert_true(lo == 0 && w == 0.0);
    fg_band_locate(&p, 3e4, &lo, &w);
    assert_true(lo == 0 && w == 0.0);
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
        cmocka_unit_test(test_centres),        cmocka_unit_test(test_pair),
        cmocka_unit_test(test_locate),         cmocka_unit_test(test_split_accuracy),
        cmocka_unit_test(test_single_band),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
