/* The engine's partitioned convolution (engine/src/dsp/convolver) against
 * the direct sum y_o[t] = sum_i sum_k h_io[k] x_i[t - B - k], in three
 * shapes: three inputs to two outputs through 300 taps in partitions of
 * 128 (3, the last one partial: the binaural shape) and of 64 (5), two
 * inputs to three
 * outputs (an odd count) through 37 taps in partitions of 4, and five
 * inputs to one output through 9 taps in partitions of 2 (blocks shorter
 * than a vector: the plain loops). The inputs sound in bursts with
 * stretches of silence longer than the responses (the path that skips a
 * quiet input), or as isolated clicks far fewer blocks apart than the
 * partitions (the history slots of silent blocks skipped among sounding
 * ones), and are rendered in calls of 1 to 200 frames, through the
 * multiply-add kernel and transform init chose for this CPU and through
 * the portable ones (dsp/spectrum_mac_internal.h; at 128 and 64 frames a
 * partition the AVX2 transforms of dsp/fft_avx2_internal.h against
 * fft_lanes.c's), and
 * with every call's silent input
 * given as NULL (zeros the convolver need not read), which must give the
 * same output bit for bit. Every output sample is within 2e-6
 * of the output's peak: the convolver runs in float (rounding 6e-8), and
 * its spectra, transforms and sums over the partitions each round, which
 * measures 1.2-2.3e-7 of the peak; one bin's sum off by 1e-4 of itself
 * (X[B] of one output) already fails it, a stale history slot by 0.9 of
 * the peak. Bad sizes are refused. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "dsp/convolver_internal.h"
#include "fg_rng.h"

#define IN_MAX 5
#define OUT_MAX 3
#define TAPS_MAX 300
#define FRAMES 6000

typedef struct shape {
    unsigned in, out;
    size_t taps, block, partitions;
} shape;

/* Runs the shape through the direct-sum check; its outputs into y. */
static void check_shape(const shape *sh, uint64_t seed, bool plain, bool nulls,
                        float y[OUT_MAX][FRAMES])
{
    fg_rng rng;
    fg_rng_seed(&rng, seed);
    static double h[IN_MAX * OUT_MAX * TAPS_MAX];
    const size_t taps = sh->taps, B = sh->block;
    for (size_t k = 0; k < sh->in * sh->out * taps; k++)
        h[k] = fg_rng_range(&rng, -1.0, 1.0) * exp(-(double)(k % taps) / (0.27 * (double)taps));
    static float x[IN_MAX][FRAMES];
    for (unsigned i = 0; i < sh->in; i++)
        for (size_t t = 0; t < FRAMES; t++) {
            bool on;
            if (i % 3 == 1) /* a click every 2.5 blocks */
                on = t % (5 * B / 2) == 3;
            else /* bursts, silent for 1000 frames between */
                on = (t / 1000 + i) % 2 == 0 && !(i % 3 == 2 && t > 2000);
            x[i][t] = on ? (float)fg_rng_range(&rng, -1.0, 1.0) : 0.0f;
        }
    fg_convolver c;
    assert_true(fg_convolver_init(&c, sh->in, sh->out, taps, B, h));
    assert_int_equal(c.partitions, sh->partitions);
    if (plain) { /* the portable kernel and transform where init chose AVX2 */
        c.mac = fg_spectrum_mac_plain;
        c.fft_avx2 = false;
    }
    size_t t = 0;
    while (t < FRAMES) {
        size_t n = 1 + (size_t)fg_rng_range(&rng, 0.0, 199.999);
        if (n > FRAMES - t)
            n = FRAMES - t;
        const float *in[IN_MAX];
        float *out[OUT_MAX];
        for (unsigned i = 0; i < sh->in; i++) {
            bool silent = true;
            for (size_t k = 0; k < n && silent; k++)
                silent = x[i][t + k] == 0.0f;
            in[i] = nulls && silent ? NULL : x[i] + t;
        }
        for (unsigned o = 0; o < sh->out; o++)
            out[o] = y[o] + t;
        fg_convolver_process(&c, in, out, n);
        t += n;
    }
    fg_convolver_deinit(&c);
    for (unsigned o = 0; o < sh->out; o++) {
        double peak = 0.0, worst = 0.0;
        for (size_t s = 0; s < FRAMES; s++) {
            double want = 0.0;
            for (unsigned i = 0; i < sh->in; i++)
                for (size_t k = 0; k < taps; k++)
                    if (s >= B + k)
                        want += h[(i * sh->out + o) * taps + k] * x[i][s - B - k];
            peak = fmax(peak, fabs(want));
            worst = fmax(worst, fabs(want - y[o][s]));
        }
        print_message("%u -> %u, %zu taps, B %zu, %s kernel%s, output %u: worst error %.2e of "
                      "the peak %.2f\n",
                      sh->in, sh->out, taps, B, plain ? "portable" : "chosen",
                      nulls ? ", silence as NULL" : "", o, worst / peak, peak);
        assert_true(peak > 0.5);
        assert_true(worst < 2e-6 * peak);
    }
}

static void matches_direct_convolution(void **state)
{
    (void)state;
    static const shape shapes[] = {
        {3, 2, 300, 128, 3},
        {3, 2, 300, 64, 5},
        {2, 3, 37, 4, 10},
        {5, 1, 9, 2, 5},
    };
    static float given[OUT_MAX][FRAMES], null[OUT_MAX][FRAMES];
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; s++) {
        check_shape(&shapes[s], 11 + s, false, false, given);
        check_shape(&shapes[s], 11 + s, true, false, given);
        check_shape(&shapes[s], 11 + s, false, false, given);
        check_shape(&shapes[s], 11 + s, false, true, null);
        assert_memory_equal(given, null, sizeof given);
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
