/* Abe's 52-tap, 200 Hz FIR (as an interpolated FIR): unit DC gain, -6 dB
 * near 200 Hz, strong stop band, processing that matches the stated
 * response, a symmetric impulse response centred on the stated delay, and
 * block-split output equal to one-shot output. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "air/abe_lowpass_internal.h"
#include "fg_math.h"
#include "filter_reference.h"
#include "fg_rng.h"

#define N 48000

static fg_abe_fir fir; /* large: keep off the stack */
static float buf[N], other[N];

/* Steady-state level of a sine at hz through a fresh filter, dB. The last
 * 0.25 s hold a whole number of periods for the rates and tones used. */
static double measured_db(double fs, double hz)
{
    assert_int_equal(fg_abe_fir_init(&fir, fs), FG_OK);
    size_t n = (size_t)fs / 2;
    for (size_t i = 0; i < n; i++)
        buf[i] = (float)sin(2.0 * FG_PI * hz * i / fs);
    fg_abe_fir_process(&fir, buf, n);
    double e = 0.0;
    size_t span = n / 2;
    for (size_t i = n - span; i < n; i++)
        e += (double)buf[i] * buf[i];
    return 10.0 * log10(2.0 * e / span);
}

static void test_response(void **state)
{
    (void)state;
    static const double rates[] = {8000.0, 44100.0, 48000.0, 96000.0, 384000.0};
    for (size_t r = 0; r < sizeof rates / sizeof rates[0]; r++) {
        double fs = rates[r];
        assert_int_equal(fg_abe_fir_init(&fir, fs), FG_OK);
        assert_true(fabs(ref_abe_fir_db(&fir, 0.0, fs)) < 1e-9);
        double at200 = ref_abe_fir_db(&fir, 200.0, fs);
        if (fabs(at200 + 6.0) > 0.5)
            fail_msg("fs %g: %.2f dB at 200 Hz", fs, at200);
        assert_true(ref_abe_fir_db(&fir, 100.0, fs) > -1.5);
        assert_true(ref_abe_fir_db(&fir, 1000.0, fs) < -45.0);
        /* the whole band above 600 Hz, images included (2000 points) */
        for (double hz = 600.0; hz < 0.5 * fs; hz += fs / 4000.0)
            if (ref_abe_fir_db(&fir, hz, fs) > -35.0)
                fail_msg("fs %g: %.2f dB at %.0f Hz", fs, ref_abe_fir_db(&fir, hz, fs), hz);
    }
}

static void test_processing_matches_response(void **state)
{
    (void)state;
    static const double tones[] = {40.0, 200.0, 400.0, 1000.0};
    for (size_t t = 0; t < 4; t++) {
        double got = measured_db(48000.0, tones[t]);
        double want = ref_abe_fir_db(&fir, tones[t], 48000.0);
        if (fabs(got - want) > 0.1)
            fail_msg("%.0f Hz: measured %.2f dB, response %.2f dB", tones[t], got, want);
    }
}

static void test_dc_and_impulse(void **state)
{
    (void)state;
    assert_int_equal(fg_abe_fir_init(&fir, 48000.0), FG_OK);
    for (size_t i = 0; i < N; i++)
        buf[i] = i == 0 ? 1.0f : 0.0f;
    fg_abe_fir_process(&fir, buf, N);
    double delay = ref_abe_fir_delay_frames(&fir);
    assert_true(delay == 25.5 * 20 + 19);
    size_t len = (size_t)(2.0 * delay) + 1; /* 51 M + 2 (M - 1) + 1 taps */
    double sum = 0.0, moment = 0.0;
    for (size_t i = 0; i < len; i++) {
        sum += buf[i];
        moment += i * (double)buf[i];
        assert_true(fabs(buf[i] - buf[len - 1 - i]) < 1e-7);
    }
    /* after it: rounding residue of the running sums only, then exact
     * zeros once the sums have been re-added */
    for (size_t i = len; i < N; i++)
        assert_true(fabs(buf[i]) < 1e-12);
    assert_true(buf[N - 1] == 0.0f);
    assert_true(fabs(sum - 1.0) < 1e-5);
    assert_true(fabs(moment / sum - delay) < 1e-3);

    assert_int_equal(fg_abe_fir_init(&fir, 48000.0), FG_OK);
    for (size_t i = 0; i < N; i++)
        buf[i] = 0.25f;
    fg_abe_fir_process(&fir, buf, N);
    assert_true(fabs(buf[N - 1] - 0.25) < 1e-6);
}

static void test_block_split_exact(void **state)
{
    (void)state;
    fg_rng rng;
    fg_rng_seed(&rng, 7);
    for (size_t i = 0; i < N; i++)
        buf[i] = other[i] = (float)fg_rng_range(&rng, -0.5, 0.5);
    assert_int_equal(fg_abe_fir_init(&fir, 44100.0), FG_OK);
    fg_abe_fir_process(&fir, buf, N);
    assert_int_equal(fg_abe_fir_init(&fir, 44100.0), FG_OK);
    size_t pos = 0, k = 0;
    static const size_t sizes[] = {1, 17, 256, 3, 1000, 64};
    while (pos < N) {
        size_t n = sizes[k++ % 6];
        n = n > N - pos ? N - pos : n;
        fg_abe_fir_process(&fir, other + pos, n);
        pos += n;
    }
    assert_memory_equal(buf, other, sizeof buf);
}

static void test_bad_rate(void **state)
{
    (void)state;
    assert_int_equal(fg_abe_fir_init(&fir, 48000.0), FG_OK);
    unsigned stride = fir.stride;
    assert_int_equal(fg_abe_fir_init(&fir, 4000.0), FG_ERR_SAMPLE_RATE);
    assert_int_equal(fg_abe_fir_init(&fir, 500000.0), FG_ERR_SAMPLE_RATE);
    assert_int_equal(fg_abe_fir_init(&fir, NAN), FG_ERR_SAMPLE_RATE);
    assert_int_equal(fir.stride, stride);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_response),        cmocka_unit_test(test_processing_matches_response),
        cmocka_unit_test(test_dc_and_impulse),  cmocka_unit_test(test_block_split_exact),
        cmocka_unit_test(test_bad_rate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
