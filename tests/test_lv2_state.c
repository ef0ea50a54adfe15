/* fulgur.lv2's state, through liblilv: a snapshot taken after some notes,
 * restored into a fresh instance whose controls were set otherwise, makes
 * the same MIDI give the same output, sample for sample; without the
 * restore the same controls give other trees. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "lv2_fixture.h"

#define RATE_HZ 48000.0
#define BLOCK 256
#define BEFORE_BLOCKS 94  /* 0.5 s played before the snapshot */
#define AFTER_BLOCKS 188  /* 1 s compared after it */

/* Runs blocks, playing a spark on note key, key + 1, ... every 20 blocks
 * from block 1 (none if key is 0), and the worker after each block; out
 * (may be NULL) gets both ears. */
static void play(lv2_host *h, int blocks, uint8_t key, float *out)
{
    float l[BLOCK], r[BLOCK];
    for (int b = 0; b < blocks; b++) {
        if (key && b % 20 == 1)
            lv2_host_midi(h, 7, 0x90, key + (uint8_t)(b / 20), 100);
        assert_int_equal(lv2_run_guarded(h, BLOCK, l, r), 0);
        lv2_work_on_thread(h, NULL);
        if (out) {
            memcpy(out + (size_t)b * 2 * BLOCK, l, sizeof l);
            memcpy(out + (size_t)b * 2 * BLOCK + BLOCK, r, sizeof r);
        }
    }
}

static void set_controls(lv2_host *h, float seed, float distance, float azimuth, float t0_scale)
{
    lv2_host_set(h, "seed", seed);
    lv2_host_set(h, "distance", distance);
    lv2_host_set(h, "azimuth", azimuth);
    lv2_host_set(h, "t0_scale", t0_scale);
    lv2_host_set(h, "strokes", 1);
}

static double energy(const float *x, size_t n)
{
    double e = 0;
    for (size_t i = 0; i < n; i++)
        e += (double)x[i] * x[i];
    return e;
}

static void test_restore_replays(void **state)
{
    (void)state;
    size_t n = (size_t)AFTER_BLOCKS * 2 * BLOCK;
    float *a = calloc(n, sizeof *a), *b = calloc(n, sizeof *b), *c = calloc(n, sizeof *c);

    lv2_host *first = lv2_host_create(RATE_HZ);
    assert_non_null(first);
    set_controls(first, 7, 3, 30, 1.5f);
    play(first, BEFORE_BLOCKS, 50, NULL);
    LilvState *snap = lv2_host_save(first);
    assert_non_null(snap);
    play(first, AFTER_BLOCKS, 60, a);

    /* other controls, then the snapshot: its port values and seed stream */
    lv2_host *second = lv2_host_create(RATE_HZ);
    assert_non_null(second);
    set_controls(second, 99, 40, -60, 1);
    lv2_host_restore(second, snap);
    assert_true(lv2_host_get(second, "seed") == 7);
    assert_true(lv2_host_get(second, "distance") == 3);
    assert_true(lv2_host_get(second, "azimuth") == 30);
    assert_true(lv2_host_get(second, "t0_scale") == 1.5f);
    /* the same engine clock as the first had at the snapshot */
    play(second, BEFORE_BLOCKS, 0, NULL);
    play(second, AFTER_BLOCKS, 60, b);
    /* the same controls without the snapshot: the seed stream starts over */
    lv2_host *third = lv2_host_create(RATE_HZ);
    assert_non_null(third);
    set_controls(third, 7, 3, 30, 1.5f);
    play(third, BEFORE_BLOCKS, 0, NULL);
    play(third, AFTER_BLOCKS, 60, c);

    assert_true(energy(a, n) > 1e-3);
    assert_memory_equal(a, b, n * sizeof *a);
    assert_true(memcmp(a, c, n * sizeof *a) != 0);
    lilv_state_free(snap);
    lv2_host_destroy(first);
    lv2_host_destroy(second);
    lv2_host_destroy(third);
    free(a);
    free(b);
    free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_restore_replays),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
