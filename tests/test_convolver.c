/* The engine's partitioned convolution (engine/src/dsp/convolver) against
 * the direct sum y_o[t] = sum_i sum_k h_io[k] x_i[t - B - k]: three inputs
 * to two outputs, responses of 300 taps (5 partitions of 64, the last one
 * partial), inputs with stretches of silence longer than the responses
 * (the path that skips a quiet input), rendered in calls of 1 to 200
 * frames: every output sample within 1e-5 of the output's peak. Bad sizes
 * are refused. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "dsp/convolver_internal.h"
#include "fg_rng.h"

#define IN 3
#define OUT 2
#define TAPS 300
#define B 64
#define FRAMES 6000

static void matches_direct_convolution(void **state)
{
    (void)state;
    fg_rng rng;
    fg_rng_seed(&rng, 11);
    static double h[IN * OUT * TAPS];
    for (size_t k = 0; k < IN * OUT * TAPS; k++)
        h[k] = fg_rng_range(&rng, -1.0, 1.0) * exp(-(double)(k % TAPS) / 80.0);
    static float x[IN][FRAMES], y[OUT][FRAMES];
    for (int i = 0; i < IN; i++)
        for (size_t t = 0; t < FRAMES; t++) {
            /* input i sounds in bursts, silent for 1000 frames between */
            bool on = (t / 1000 + (size_t)i) % 2 == 0 && !(i == 2 && t > 2000);
            x[i][t] = on ? (float)fg_rng_range(&rng, -1.0, 1.0) : 0.0f;
        }
    fg_convolver c;
    assert_true(fg_convolver_init(&c, IN, OUT, TAPS, B, h));
    assert_int_equal(c.partitions, 5);
    size_t t = 0;
    while (t < FRAMES) {
        size_t n = 1 + (size_t)fg_rng_range(&rng, 0.0, 199.999);
        if (n > FRAMES - t)
            n = FRAMES - t;
        const float *in[IN] = {x[0] + t, x[1] + t, x[2] + t};
        float *out[OUT] = {y[0] + t, y[1] + t};
        fg_convolver_process(&c, in, out, n);
        t += n;
    }
    fg_convolver_deinit(&c);
    for (int o = 0; o < OUT; o++) {
        double peak = 0.0, worst = 0.0;
        for (size_t s = 0; s < FRAMES; s++) {
            double want = 0.0;
            for (int i = 0; i < IN; i++)
                for (size_t k = 0; k < TAPS; k++)
                    if (s >= B + k)
                        want += h[(i * OUT + o) * TAPS + k] * x[i][s - B - k];
            peak = fmax(peak, fabs(want));
            worst = fmax(worst, fabs(want - y[o][s]));
        }
        print_message("output %d: worst error %.2e of a peak %.2f\n", o, worst, peak);
        assert_true(peak > 1.0);
        assert_true(worst < 1e-5 * peak);
    }
}

static void bad_sizes_refused(void **state)
{
    (void)state;
    double h[4] = {1, 0, 0, 0};
    fg_convolver c;
    assert_false(fg_convolver_init(&c, 0, 1, 4, 64, h));
    assert_false(fg_convolver_init(&c, 1, 0, 4, 64, h));
    assert_false(fg_convolver_init(&c, 1, 1, 0, 64, h));
    assert_false(fg_convolver_init(&c, 1, 1, 4, 48, h));
    assert_false(fg_convolver_init(&c, 1, 1, 4, 1, h));
    assert_false(fg_convolver_init(&c, 1, 1, 4, 64, NULL));
    assert_null(c.filter);
    fg_convolver_deinit(&c); /* zeroed: a no-op */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matches_direct_convolution),
        cmocka_unit_test(bad_sizes_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
