/* fulgur.lv2's worker, through liblilv: a note-on in run() becomes a
 * request; the tree is grown and posted only when the worker runs it; its
 * response reaches the plugin before the next run(), which reports it on the
 * "discharges" output. Notes the engine cannot take come back as
 * failures, one each. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "lv2_fixture.h"

#define RATE_HZ 48000.0
#define BLOCK 512

static float block_peak(const float *l, const float *r)
{
    float m = 0;
    for (int i = 0; i < BLOCK; i++)
        m = fmaxf(m, fmaxf(fabsf(l[i]), fabsf(r[i])));
    return m;
}

static void run_block(lv2_host *h, float *peak)
{
    float l[BLOCK], r[BLOCK];
    assert_int_equal(lv2_run_guarded(h, BLOCK, l, r), 0);
    if (peak)
        *peak = block_peak(l, r);
}

static void test_response_in_later_run(void **state)
{
    (void)state;
    lv2_host *h = lv2_host_create(RATE_HZ);
    assert_non_null(h);
    lv2_host_set(h, "gain", 0);
    lv2_host_set(h, "distance", 1);
    float peak;
    lv2_host_midi(h, 10, 0x90, 60, 100);
    run_block(h, &peak);
    /* scheduled, not yet worked: nothing posted, nothing heard */
    assert_int_equal(lv2_host_work_calls(h), 0);
    assert_true(lv2_host_get(h, "discharges") == 0);
    assert_true(peak == 0);
    assert_int_equal(lv2_work_on_thread(h, NULL), 1);
    /* worked; the response waits for the next run */
    assert_int_equal(lv2_host_responses(h), 0);
    assert_true(lv2_host_get(h, "discharges") == 0);
    run_block(h, &peak);
    assert_int_equal(lv2_host_responses(h), 1);
    assert_true(lv2_host_get(h, "discharges") == 1);
    /* 1 m away: 2.9 ms, inside this block */
    assert_true(peak > 0.01f);
    /* a spark's note-off is worked but has nothing to answer */
    lv2_host_midi(h, 0, 0x80, 60, 0);
    run_block(h, NULL);
    assert_int_equal(lv2_work_on_thread(h, NULL), 1);
    run_block(h, NULL);
    assert_int_equal(lv2_host_responses(h), 1);

    /* a held plasma ball: sounds in every 50 ms until note-off, which the
     * worker answers with the engine's stop */
    lv2_host_set(h, "preset", 1);
    lv2_host_midi(h, 0, 0x90, 64, 127);
    run_block(h, NULL);
    lv2_work_on_thread(h, NULL);
    int blocks_with_sound = 0, blocks = (int)(0.5 * RATE_HZ / BLOCK);
    for (int b = 0; b < blocks; b++) {
        run_block(h, &peak);
        blocks_with_sound += peak > 1e-4f;
    }
    /* repeats come every 10-50 ms and a block lasts 10.7 ms */
    assert_true(blocks_with_sound >= blocks / 5);
    lv2_host_midi(h, 0, 0x80, 64, 0);
    run_block(h, NULL);
    assert_int_equal(lv2_work_on_thread(h, NULL), 1);
    run_block(h, NULL);
    assert_int_equal(lv2_host_responses(h), 3);
    assert_true(lv2_host_get(h, "discharges") == 2);
    assert_true(lv2_host_get(h, "failures") == 0);
    for (int b = 0; b < (int)(0.2 * RATE_HZ / BLOCK); b++)
        run_block(h, NULL);
    run_block(h, &peak);
    assert_true(peak < 1e-6f);
    lv2_host_destroy(h);
}

/* Twenty bolts in one block hold more segments than the engine's 131072:
 * the ones it refuses are counted as failures, and every note is one or
 * the other. */
static void test_refused_notes_are_failures(void **state)
{
    (void)state;
    lv2_host *h = lv2_host_create(RATE_HZ);
    assert_non_null(h);
    lv2_host_set(h, "preset", 2);
    for (uint8_t k = 0; k < 20; k++)
        lv2_host_midi(h, k, 0x90, 40 + k, 100);
    run_block(h, NULL);
    assert_int_equal(lv2_work_on_thread(h, NULL), 20);
    run_block(h, NULL);
    float played = lv2_host_get(h, "discharges"), failed = lv2_host_get(h, "failures");
    assert_true(played + failed == 20);
    assert_true(played >= 8);
    assert_true(failed >= 1);
    lv2_host_destroy(h);
}

/* Controls out of range or NaN are clamped: a preset of -5 is the spark
 * balls, a distance of 1e9 m is 20 km (58 s away: silent for the second
 * run here), NaN reads as the minimum (0.1 m: heard in the next block). */
static void test_controls_clamped(void **state)
{
    (void)state;
    lv2_host *h = lv2_host_create(RATE_HZ);
    assert_non_null(h);
    lv2_host_set(h, "gain", 0);
    lv2_host_set(h, "preset", -5);
    lv2_host_set(h, "distance", 1e9f);
    lv2_host_set(h, "t0_scale", NAN);
    lv2_host_set(h, "strokes", 99);
    lv2_host_set(h, "seed", -1);
    lv2_host_midi(h, 0, 0x90, 60, 127);
    float peak, loudest = 0;
    for (int b = 0; b < (int)(RATE_HZ / BLOCK); b++) {
        run_block(h, &peak);
        lv2_work_on_thread(h, NULL);
        loudest = fmaxf(loudest, peak);
    }
    assert_true(lv2_host_get(h, "discharges") == 1);
    assert_true(lv2_host_get(h, "failures") == 0);
    assert_true(loudest == 0);
    lv2_host_set(h, "distance", NAN);
    lv2_host_midi(h, 0, 0x90, 60, 127);
    run_block(h, NULL);
    lv2_work_on_thread(h, NULL);
    run_block(h, &peak);
    assert_true(lv2_host_get(h, "discharges") == 2);
    assert_true(peak > 1.0f);
    lv2_host_destroy(h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_response_in_later_run),
        cmocka_unit_test(test_refused_notes_are_failures),
        cmocka_unit_test(test_controls_clamped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
