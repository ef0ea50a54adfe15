/* The per-process band filter designs (engine/src/air/band_filters.c): a
 * kept design is, bit for bit, what designing again gives, for the inputs
 * it was kept for and no others. The reference is the fit itself,
 * absorb_filter_internal.h, chained band to band as the engine does. */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "air/absorb_filter_internal.h"
#include "air/band_filters_internal.h"
#include "air/distance_bands_internal.h"

#define BANDS 3

static void direct_design(const fg_air *air, const fg_band_plan *plan, double fs_hz, fg_iir *out)
{
    fg_absorb_fit fit = {.valid = false};
    for (unsigned k = 0; k < plan->count; k++) {
        fg_absorb_design(&out[k], air, plan->centre_m[k], fs_hz, &fit);
        fg_iir_reset(&out[k]);
    }
}

/* Coefficients, section count and state, bit for bit (not the padding). */
static void expect_same_filters(const fg_iir *a, const fg_iir *b, unsigned count)
{
    for (unsigned k = 0; k < count; k++) {
        assert_int_equal(a[k].sections, b[k].sections);
        assert_memory_equal(a[k].sec, b[k].sec, sizeof a[k].sec);
        assert_memory_equal(a[k].z, b[k].z, sizeof a[k].z);
    }
}

static void expect_design(const fg_air *air, const fg_band_plan *plan, double fs_hz)
{
    fg_iir kept[BANDS], direct[BANDS];
    fg_band_filters_design(air, plan->centre_m, plan->count, fs_hz, kept);
    direct_design(air, plan, fs_hz, direct);
    expect_same_filters(kept, direct, BANDS);
}

static void kept_designs_are_the_designs(void **state)
{
    (void)state;
    fg_band_plan plan, other_plan;
    assert_int_equal(fg_band_plan_init(&plan, 200.0, 8000.0, BANDS), FG_OK);
    assert_int_equal(fg_band_plan_init(&other_plan, 250.0, 8000.0, BANDS), FG_OK);
    const fg_air air = FG_AIR_DEFAULT, humid = {20.0, 90.0, 101.325};
    const fg_air cold = {-10.0, 70.0, 101.325}, thin = {20.0, 70.0, 80.0};
    /* new, then kept, then each input changed alone: no stale design */
    expect_design(&air, &plan, 48000.0);
    expect_design(&air, &plan, 48000.0);
    expect_design(&air, &plan, 44100.0);
    expect_design(&humid, &plan, 48000.0);
    expect_design(&cold, &plan, 48000.0);
    expect_design(&thin, &plan, 48000.0);
    expect_design(&air, &other_plan, 48000.0);
    /* more inputs than FG_BAND_FILTERS_KEPT: the first was replaced, and
     * is designed again */
    expect_design(&air, &plan, 48000.0);
    expect_design(&air, &plan, 44100.0);
    /* the two designs differ, so the comparison above can tell them apart */
    fg_iir a[BANDS], b[BANDS];
    fg_band_filters_design(&air, plan.centre_m, BANDS, 48000.0, a);
    fg_band_filters_design(&humid, plan.centre_m, BANDS, 48000.0, b);
    assert_memory_not_equal(a[0].sec, b[0].sec, sizeof a[0].sec);
}

typedef struct designer {
    fg_band_plan plan;
    fg_air air;
    fg_iir out[BANDS];
} designer;

static void *design_on_thread(void *arg)
{
    designer *d = arg;
    fg_band_filters_design(&d->air, d->plan.centre_m, BANDS, 96000.0, d->out);
    return NULL;
}

/* Engines on several sim threads design at once: each gets the design
 * (ThreadSanitizer checks the kept designs' lock in its stage). */
static void concurrent_designs_agree(void **state)
{
    (void)state;
    designer d[3];
    pthread_t t[3];
    for (int i = 0; i < 3; i++) {
        assert_int_equal(fg_band_plan_init(&d[i].plan, 300.0, 9000.0, BANDS), FG_OK);
        d[i].air = (fg_air){15.0, 50.0 + 10.0 * (i % 2), 101.325};
        assert_int_equal(pthread_create(&t[i], NULL, design_on_thread, &d[i]), 0);
    }
    for (int i = 0; i < 3; i++)
        assert_int_equal(pthread_join(t[i], NULL), 0);
    for (int i = 0; i < 3; i++) {
        fg_iir direct[BANDS];
        direct_design(&d[i].air, &d[i].plan, 96000.0, direct);
        expect_same_filters(d[i].out, direct, BANDS);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(kept_designs_are_the_designs),
        cmocka_unit_test(concurrent_designs_agree),
    };
    return cmocka_run_group_tests(tests, 0, NULL);
}
