/* The convolver's float transform of FG_VF_LANES signals at once
 * (engine/src/dsp/fft_lanes) against the engine's double one (fg_fft) at
 * every length from 4 to 2^14 (radix-2 only, radix 4 only and both): a
 * different signal in each lane, the packed spectrum within 1e-6 of the
 * spectrum's peak (float rounding through up to 13 stages: it measures
 * 0.5-2e-7), inverse(forward(x)) back to x within 1e-6 of its peak, and a
 * bad length refused. The single-signal path gives each lane's floats bit
 * for bit, forward and inverse, at every length it serves. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "dsp/fft_internal.h"
#include "dsp/fft_lanes_internal.h"
#include "fg_rng.h"

#define V FG_VF_LANES

static void matches_double_transform(void **state)
{
    (void)state;
    fg_rng rng;
    fg_rng_seed(&rng, 7);
    for (size_t n = 4; n <= 16384; n *= 2) {
        const size_t m = n / 2;
        float *x = malloc(sizeof(float) * n * V), *w = malloc(sizeof(float) * n * V);
        float *orig = malloc(sizeof(float) * n * V);
        double *d = malloc(sizeof(double) * (n + 2));
        assert_non_null(x);
        assert_non_null(w);
        assert_non_null(orig);
        assert_non_null(d);
        fg_fft_lanes f;
        fg_fft plain;
        assert_true(fg_fft_lanes_init(&f, n));
        assert_true(fg_fft_init(&plain, n));
        for (unsigned l = 0; l < V; l++)
            for (size_t t = 0; t < n; t++) { /* split: x[2k] re, x[2k+1] im */
                float v = (float)fg_rng_range(&rng, -1.0, 1.0) + (t == n / 3 + l ? 4.0f : 0.0f);
                size_t e = t % 2 ? m + t / 2 : t / 2;
                x[e * V + l] = v;
                orig[e * V + l] = v;
            }
        fg_fft_lanes_forward(&f, x, w);
        double worst = 0.0, peak = 0.0;
        for (unsigned l = 0; l < V; l++) {
            for (size_t t = 0; t < n; t++)
                d[t] = orig[(t % 2 ? m + t / 2 : t / 2) * V + l];
            fg_fft_forward(&plain, d, d);
            for (size_t k = 0; k <= m; k++) {
                double re = k < m ? x[k * V + l] : x[m * V + l];
                double im = k == 0 || k == m ? 0.0 : x[(m + k) * V + l];
                peak = fmax(peak, hypot(d[2 * k], d[2 * k + 1]));
                worst = fmax(worst, hypot(re - d[2 * k], im - d[2 * k + 1]));
            }
        }
        fg_fft_lanes_inverse(&f, x, w);
        double back = 0.0, xpeak = 0.0;
        for (size_t e = 0; e < n * V; e++) {
            xpeak = fmax(xpeak, fabs(orig[e]));
            back = fmax(back, fabs(x[e] - orig[e]));
        }
        print_message("n %5zu: forward %.1e of the peak, inverse %.1e\n", n, worst / peak,
                      back / xpeak);
        assert_true(worst < 1e-6 * peak);
        assert_true(back < 1e-6 * xpeak);
        fg_fft_lanes_deinit(&f);
        fg_fft_deinit(&plain);
        free(x);
        free(w);
        free(orig);
        free(d);
    }
}

static void one_signal_same_as_its_lane(void **state)
{
    (void)state;
    fg_rng rng;
    fg_rng_seed(&rng, 11);
    size_t served = 0;
    for (size_t n = 4; n <= 16384; n *= 2) {
        fg_fft_lanes f;
        assert_true(fg_fft_lanes_init(&f, n));
        if (!f.one) {
            assert_true(n / 8 < V); /* it serves every length with N/2 >= 4 V */
            fg_fft_lanes_deinit(&f);
            continue;
        }
        served++;
        float *x = malloc(sizeof(float) * n * V), *w = malloc(sizeof(float) * n * V);
        float *one = malloc(sizeof(float) * n), *wone = malloc(sizeof(float) * n);
        assert_non_null(x);
        assert_non_null(w);
        assert_non_null(one);
        assert_non_null(wone);
        for (size_t e = 0; e < n * V; e++)
            x[e] = (float)fg_rng_range(&rng, -1.0, 1.0);
        for (unsigned l = 0; l < V; l++) {
            for (size_t e = 0; e < n; e++)
                one[e] = x[e * V + l];
            float *lanes = malloc(sizeof(float) * n * V);
            assert_non_null(lanes);
            memcpy(lanes, x, sizeof(float) * n * V);
            fg_fft_lanes_forward(&f, lanes, w);
            fg_fft_lanes_forward_one(&f, one, wone);
            for (size_t e = 0; e < n; e++)
                assert_memory_equal(&one[e], &lanes[e * V + l], sizeof(float));
            fg_fft_lanes_inverse(&f, lanes, w);
            fg_fft_lanes_inverse_one(&f, one, wone);
            for (size_t e = 0; e < n; e++)
                assert_memory_equal(&one[e], &lanes[e * V + l], sizeof(float));
            free(lanes);
        }
        fg_fft_lanes_deinit(&f);
        free(x);
        free(w);
        free(one);
        free(wone);
    }
    assert_true(served >= 9); /* 32 .. 16384 points with four lanes */
}

static void bad_lengths_refused(void **state)
{
    (void)state;
    fg_fft_lanes f;
    assert_false(fg_fft_lanes_init(&f, 2));
    assert_false(fg_fft_lanes_init(&f, 96));
    assert_false(fg_fft_lanes_init(&f, FG_FFT_MAX_SIZE * 2));
    assert_null(f.twiddle);
    fg_fft_lanes_deinit(&f); /* zeroed: a no-op */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matches_double_transform),
        cmocka_unit_test(one_signal_same_as_its_lane),
        cmocka_unit_test(bad_lengths_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
