/* The stereo layout through the engine: a spark at the listener's side
 * heard on the spherical head. Its interaural time difference, by
 * cross-correlation below 1.5 kHz, is Woodworth's (a / c)(theta + sin
 * theta) within 20 us (with the shadow's filters, Kuhn's low-frequency
 * 3 (a / c) sin theta within 30 us); with the head shadow on, its level difference in
 * the 8 kHz octave is at least 15 dB and that of Brown & Duda's filter
 * pair within 1 dB. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "ear_measure.h"
#include "engine_fixture.h"
#include "fulgur/fulgur.h"

#define FS 48000.0
#define C 343.0
#define A 0.0875 /* the default head: ear spacing 0.175 m */
#define PI 3.14159265358979323846
#define FRAMES 9600

/* Renders a spark 10 m away at azimuth az_deg (clockwise from ahead,
 * towards the right ear) on the horizontal plane. */
static void render_spark(double az_deg, int shadow, float *left, float *right)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .speed_of_sound_m_s = C,
                            .max_block_frames = 256};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_engine_config used;
    fg_engine_get_config(e, &used);
    assert_true(used.ear_spacing_m == 2 * A);
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    double th = az_deg * PI / 180.0;
    fg_node nodes[2];
    fx_segment(nodes, (double[]){10.0 * sin(th), 10.0 * cos(th), 1.7}, (double[]){0, 0, 1}, 1e-3);
    fg_discharge d = {.nodes = nodes, .node_count = 2, .strokes = 1, .seed = 3,
                      .propagation = {.head_shadow = shadow}};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    d.sound.t0_jitter = 0;
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    fx_render(e, (float *[]){left, right}, 2, FRAMES, 256);
    fg_engine_destroy(e);
}

static void itd_is_woodworth(void **state)
{
    (void)state;
    float *l = calloc(FRAMES, sizeof *l), *r = calloc(FRAMES, sizeof *r);
    static const double azimuths[] = {90.0, 30.0, -60.0};
    for (size_t i = 0; i < 3; i++) {
        render_spark(azimuths[i], 0, l, r);
        double th = azimuths[i] * PI / 180.0;
        double want = A / C * (th + sin(th));
        double got = em_itd_s(l, r, FRAMES, FS, 1500.0, 1.5e-3);
        print_message("azimuth %+.0f deg: ITD %.1f us, Woodworth %.1f us\n", azimuths[i],
                      got * 1e6, want * 1e6);
        if (fabs(got - want) > 20e-6)
            fail_msg("azimuth %.0f: ITD %.1f us, Woodworth %.1f us", azimuths[i], got * 1e6,
                     want * 1e6);
    }
    /* at 90 degrees the head model's 656 us, against 525 us of two point
     * ears 0.18 m apart: the two are told apart */
    render_spark(90.0, 0, l, r);
    assert_true(em_itd_s(l, r, FRAMES, FS, 1500.0, 1.5e-3) > 600e-6);
    /* with the shadow's filters their low-frequency group delay adds:
     * towards Kuhn's low-frequency limit for a rigid sphere, 3 (a / c) sin
     * theta (Kuhn 1977, JASA 62(1)): 765 us at 90 degrees */
    render_spark(90.0, 1, l, r);
    double shaded = em_itd_s(l, r, FRAMES, FS, 1500.0, 1.5e-3);
    print_message("azimuth +90 deg, head shadow on: ITD below 1.5 kHz %.1f us, Kuhn %.1f us\n",
                  shaded * 1e6, 3.0 * A / C * 1e6);
    assert_true(fabs(shaded - 3.0 * A / C) < 30e-6);
    free(l);
    free(r);
}

/* Brown & Duda's |H|^2 at hz for alpha, the bilinear map pre-warped at the
 * corner c / (pi a). */
static double model_db(double alpha, double hz)
{
    double x = tan(PI * hz / FS) / tan(PI * (C / (PI * A)) / FS);
    return 10.0 * log10((1.0 + alpha * alpha * x * x) / (1.0 + x * x));
}

static void ild_at_8k(void **state)
{
    (void)state;
    float *l = calloc(FRAMES, sizeof *l), *r = calloc(FRAMES, sizeof *r);
    render_spark(90.0, 1, l, r);
    double lo = 8000.0 / sqrt(2.0), hi = 8000.0 * sqrt(2.0);
    double ild = 10.0 * log10(em_band_energy(r, FRAMES, FS, lo, hi) /
                              em_band_energy(l, FRAMES, FS, lo, hi));
    /* near ear theta = 0 (alpha 2), far ear theta = 180 (alpha 0.2814),
     * and the 1/r of 10 -+ a m */
    double far_alpha = 1.05 + 0.95 * cos(PI / (150.0 / 180.0));
    double want = model_db(2.0, 8000.0) - model_db(far_alpha, 8000.0) +
                  20.0 * log10((10.0 + A) / (10.0 - A));
    print_message("azimuth +90 deg: ILD in the 8 kHz octave %.2f dB, model %.2f dB\n", ild, want);
    assert_true(ild >= 15.0);
    assert_true(fabs(ild - want) < 1.0);
    /* and without the shadow only the 1/r: under 0.2 dB */
    render_spark(90.0, 0, l, r);
    double open = 10.0 * log10(em_band_energy(r, FRAMES, FS, lo, hi) /
                               em_band_energy(l, FRAMES, FS, lo, hi));
    assert_true(fabs(open) < 0.2);
    free(l);
    free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(itd_is_woodworth),
        cmocka_unit_test(ild_at_8k),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
