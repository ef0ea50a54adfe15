/* From the simulation rate to the audio rate (eqs. 10-11) and the 30 Hz
 * high-pass: the Mitchell-Netravali kernel (B = C = 1/3) has its published
 * values, sums to one and reproduces lines and parabolas (B + 2C = 1); a
 * linear flux gives p = its slope to 1e-12 at every audio sample, at
 * integer and non-integer rate ratios and with a large mean; a parabola
 * gives p = its derivative; the stream hands each sample out as soon as
 * the 2 steps it needs are in; the high-pass is a 2nd-order Butterworth
 * (-3.01 dB at 30 Hz, -12.3 dB an octave below, flat above). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "fire/highpass_internal.h"
#include "fire/mitchell_internal.h"
#include "fg_math.h"
#include "filter_reference.h"

static void test_kernel(void **state)
{
    (void)state;
    /* Mitchell & Netravali: k(0) = (6 - 2B)/6, k(1) = B/6, k(2) = 0 */
    assert_true(fabs(fg_mn_kernel(0.0) - 16.0 / 18.0) < 1e-15);
    assert_true(fabs(fg_mn_kernel(1.0) - 1.0 / 18.0) < 1e-15);
    assert_true(fabs(fg_mn_kernel(-1.0) - 1.0 / 18.0) < 1e-15);
    assert_true(fg_mn_kernel(2.0) == 0.0 && fg_mn_kernel(-2.5) == 0.0);
    for (double x = -1.999; x < 2.0; x += 0.0137) {
        /* continuity of k and k' against finite differences */
        double d = (fg_mn_kernel(x + 1e-6) - fg_mn_kernel(x - 1e-6)) / 2e-6;
        assert_true(fabs(d - fg_mn_kernel_derivative(x)) < 1e-6);
    }
    double second_moment = 0.0;
    for (double x = 0.0; x < 1.0; x += 0.0731) {
        double s0 = 0.0, s1 = 0.0, s2 = 0.0, d0 = 0.0, d1 = 0.0, d2 = 0.0;
        for (int i = -3; i <= 4; i++) {
            double k = fg_mn_kernel(x - i), kd = fg_mn_kernel_derivative(x - i);
            s0 += k;
            s1 += i * k;
            s2 += (x - i) * (x - i) * k;
            d0 += kd;
            d1 += i * kd;
            d2 += i * (double)i * kd;
        }
        assert_true(fabs(s0 - 1.0) < 1e-14);
        assert_true(fabs(s1 - x) < 1e-14);
        assert_true(fabs(d0) < 1e-14);
        assert_true(fabs(d1 - 1.0) < 1e-14);
        /* sum (x - i)^2 k(x - i) is the same for every x, so sum i^2 k'
         * = 2x: parabolas are differentiated exactly too */
        if (x == 0.0)
            second_moment = s2;
        assert_true(fabs(s2 - second_moment) < 1e-14);
        assert_true(fabs(d2 - 2.0 * x) < 1e-13);
    }
}

/* The stream on I_i = mean + step i (+ curve t_i^2): every sample after
 * the held start, p(t) = step sim_hz + 2 curve t. With mean an integer and
 * step a power of two the flux values are exact in double, so the only
 * rounding left is the filter's. */
static double worst_error(double sim_hz, double fs, double mean, double step, double curve,
                          size_t steps, size_t *frames)
{
    double slope = step * sim_hz;
    fg_mn_stream s;
    fg_mn_init(&s, sim_hz, fs);
    double *p = malloc(sizeof(double) * fg_mn_max_frames_per_step(&s));
    double worst = 0.0;
    size_t made = 0;
    for (size_t i = 0; i < steps; i++) {
        double t = (double)i / sim_hz;
        size_t n = fg_mn_push(&s, mean + step * (double)i + curve * t * t, p);
        assert_true(n <= fg_mn_max_frames_per_step(&s));
        for (size_t k = 0; k < n; k++, made++) {
            double tf = (double)made / fs;
            /* sample made needs flux up to index floor(tf sim) + 2 = i */
            assert_int_equal((size_t)floor(tf * sim_hz + 1e-9) + 2, i);
            if (tf < 2.0 / sim_hz)
                continue; /* the start, where the flux is held */
            double want = slope + 2.0 * curve * tf;
            worst = fmax(worst, fabs(p[k] - want) / fabs(want));
        }
    }
    free(p);
    *frames = made;
    return worst;
}

static void test_linear_flux_gives_its_slope(void **state)
{
    (void)state;
    const double rates[][2] = {{360, 48000}, {360, 44100}, {240, 96000}, {500, 8000}, {360, 384000}};
    for (size_t r = 0; r < sizeof rates / sizeof rates[0]; r++) {
        size_t frames;
        double e = worst_error(rates[r][0], rates[r][1], 0.0, 0x1p-10, 0.0, 3000, &frames);
        assert_true(frames > 2900 * (size_t)(rates[r][1] / rates[r][0]));
        assert_true(e <= 1e-12);
        /* a large mean flux costs no precision */
        double e_mean = worst_error(rates[r][0], rates[r][1], 1e4, -0x1p-12, 0.0, 3000, &frames);
        assert_true(e_mean <= 1e-12);
        print_message("%g Hz -> %g Hz: worst relative error of p %.1e (mean 1e4: %.1e)\n",
                      rates[r][0], rates[r][1], e, e_mean);
    }
    size_t frames;
    double e = worst_error(360, 44100, 0.5, 0x1p-9, 0.3, 3000, &frames);
    print_message("parabola: worst relative error of p %.1e\n", e);
    assert_true(e <= 1e-11);
}

static void test_highpass(void **state)
{
    (void)state;
    fg_iir f;
    for (double fs = 8000; fs <= 384000; fs *= 2) {
        fg_fire_highpass_design(&f, 30.0, fs);
        double at = fg_iir_db(&f, 2 * FG_PI * 30.0 / fs);
        double below = fg_iir_db(&f, 2 * FG_PI * 15.0 / fs);
        double above = fg_iir_db(&f, 2 * FG_PI * 300.0 / fs);
        assert_true(fabs(at + 10.0 * log10(2.0)) < 0.005);
        assert_true(fabs(below - 10.0 * log10(1.0 / 17.0)) < 0.02); /* (1/2)^4 / (1 + (1/2)^4) */
        assert_true(fabs(above) < 0.001);
        assert_true(ref_quadratic_root_radius(f.sec[0].a1, f.sec[0].a2) < 1.0);
    }
    /* a constant is removed, and once it stops the tail ends in exact zeros */
    fg_fire_highpass_design(&f, 30.0, 48000.0);
    float x[4800];
    for (int block = 0; block < 5; block++) {
        for (int i = 0; i < 4800; i++)
            x[i] = 1.0f;
        fg_iir_process(&f, x, 4800);
    }
    assert_true(fabs(x[4799]) < 1e-6);
    for (int block = 0; block < 20; block++) {
        for (int i = 0; i < 4800; i++)
            x[i] = 0.0f;
        fg_iir_process(&f, x, 4800);
    }
    assert_true(x[4799] == 0.0f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kernel),
        cmocka_unit_test(test_linear_flux_gives_its_slope),
        cmocka_unit_test(test_highpass),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
