/* fulgur.lv2's levels, through liblilv as a host loads it: at the default
 * controls every preset (spark balls, plasma ball, both lightning presets,
 * each at the default distance) peaks below 0 dBFS for a note 60 at velocity 127, over
 * several seeds; every preset of the bundle (pset:Preset, read by lilv)
 * loads, sets what it says, and plays below 0 dBFS too. The output is
 * pascals times the gain control, so these are the engine's levels: a
 * change of the sound model that makes the defaults clip fails here. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fulgur/sound.h"
#include "lilv_host.h"

#define RATE_HZ 48000.0
#define BLOCK 256
#define SEEDS 6
#define HOLD_S 1.0 /* the note's length: a held plasma ball sounds this long */

/* The peak of both ears over seconds after a note 60 at velocity 127, and
 * the control values as they were. */
static float play(lv2_host *h, double seconds)
{
    float left[BLOCK], right[BLOCK], peak = 0;
    size_t blocks = (size_t)(seconds * RATE_HZ / BLOCK), off = (size_t)(HOLD_S * RATE_HZ / BLOCK);
    for (size_t b = 0; b < blocks; b++) {
        if (b == 0)
            assert_int_equal(lv2_host_midi(h, 0, 0x90, 60, 127), 0);
        if (b == off)
            assert_int_equal(lv2_host_midi(h, 0, 0x80, 60, 0), 0);
        lv2_host_run(h, BLOCK, left, right);
        lv2_host_work(h); /* between blocks, as an offline host may */
        for (int i = 0; i < BLOCK; i++)
            peak = fmaxf(peak, fmaxf(fabsf(left[i]), fabsf(right[i])));
    }
    assert_true(lv2_host_get(h, "discharges") == 1.0f);
    assert_true(lv2_host_get(h, "failures") == 0.0f);
    return peak;
}

/* Long enough for the whole sound: the farthest part of a 5 km channel
 * arrives about 15 s after the nearest. */
static double seconds_for(float distance_m)
{
    return HOLD_S + (distance_m + 6000.0) / 343.0 + 1.0;
}

static void test_default_controls(void **state)
{
    (void)state;
    static const char *const names[] = {"spark balls", "plasma ball", "lightning",
                                        "lightning (table 1)"};
    for (int preset = 0; preset < FG_PRESET_COUNT; preset++) {
        float worst = 0;
        for (int seed = 1; seed <= SEEDS; seed++) {
            lv2_host *h = lv2_host_create(RATE_HZ);
            assert_non_null(h);
            /* only the preset and the seed change: the rest at its default */
            assert_int_equal(lv2_host_set(h, "preset", (float)preset), 0);
            assert_int_equal(lv2_host_set(h, "seed", (float)seed), 0);
            int bolt = preset == FG_PRESET_LIGHTNING || preset == FG_PRESET_LIGHTNING_TABLE1;
            float peak = play(h, bolt ? seconds_for(lv2_host_get(h, "distance")) : 2.0);
            lv2_host_destroy(h);
            assert_true(peak > 0);
            worst = fmaxf(worst, peak);
        }
        printf("default controls, %-19s: worst peak of %d seeds %+.1f dBFS\n", names[preset],
               SEEDS, 20 * log10f(worst));
        assert_true(worst < 1.0f);
    }
}

static void test_bundle_presets(void **state)
{
    (void)state;
    static const char *const labels[] = {"Spark balls",   "Plasma ball",  "Lightning",
                                         "Lightning (table 1)", "Distant storm",
                                         "Close strike",  "Tesla coil"};
    const unsigned count = sizeof labels / sizeof labels[0];
    lv2_host *none = lv2_host_create(RATE_HZ);
    assert_non_null(none);
    assert_int_equal(lv2_host_preset_apply(none, "no such preset"), -1);
    lv2_host_destroy(none);
    lv2_host *probe = lv2_host_create(RATE_HZ);
    assert_non_null(probe);
    char found[8][LV2_HOST_LABEL_BYTES];
    assert_int_equal(lv2_host_presets(probe, found, 8), count);
    lv2_host_destroy(probe);
    for (unsigned k = 0; k < count; k++) {
        unsigned seen = 0;
        for (unsigned i = 0; i < count; i++)
            seen += strcmp(found[i], labels[k]) == 0;
        assert_int_equal(seen, 1); /* each label once */
    }
    for (unsigned k = 0; k < count; k++) {
        float worst = 0;
        for (int seed = 1; seed <= SEEDS / 2; seed++) {
            lv2_host *h = lv2_host_create(RATE_HZ);
            assert_non_null(h);
            lv2_host_set(h, "gain", 99); /* a preset sets it: this must go */
            assert_int_equal(lv2_host_preset_apply(h, labels[k]), 0);
            assert_true(lv2_host_get(h, "gain") < 20);
            assert_int_equal(lv2_host_set(h, "seed", (float)seed), 0);
            float peak = play(h, seconds_for(lv2_host_get(h, "distance")));
            lv2_host_destroy(h);
            assert_true(peak > 0);
            worst = fmaxf(worst, peak);
        }
        printf("preset %-19s: worst peak of %d seeds %+.1f dBFS\n", labels[k], SEEDS / 2,
               20 * log10f(worst));
        assert_true(worst < 1.0f);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_controls),
        cmocka_unit_test(test_bundle_presets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
