/* The air between the discharge and the ear, through the engine: the
 * shadow zone's decay, the ground image's delay and level, turbulence's
 * bounded offsets, absorption routed through the band and FIR buses (equal
 * to filtering the free-air render), the head shadow on both ears, and
 * Abe's voice model. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "air/abe_lowpass_internal.h"
#include "air/absorb_filter_internal.h"
#include "air/distance_bands_internal.h"
#include "engine_fixture.h"
#include "fulgur/fulgur.h"
#include "air/refraction_internal.h"
#include "fg_math.h"

#define FS 48000.0
#define C 343.0

typedef struct render_case {
    fg_node nodes[2];
    fg_propagation_config prop;
    fg_voice_model model;
    uint32_t channels;
    double seconds;
    fg_listener head;
} render_case;

/* A lightning segment 1.5 m long (vertical unless dir says otherwise). */
static void lightning_segment(render_case *rc, double x, double y, double z)
{
    memset(rc, 0, sizeof *rc);
    fx_segment(rc->nodes, (double[]){x, y, z}, (double[]){0, 0, 1}, 1.5);
    rc->channels = 1;
    rc->head = (fg_listener){.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
}

/* Renders rc into a fresh buffer per channel (caller frees). */
static float **render(const render_case *rc, size_t *frames)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .channels = rc->channels,
                            .speed_of_sound_m_s = C, .max_block_frames = 256};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    assert_int_equal(fg_engine_set_listener(e, &rc->head), FG_OK);
    fg_discharge d = {.nodes = rc->nodes, .node_count = 2, .strokes = 1, .seed = 5,
                      .propagation = rc->prop, .model = rc->model};
    /* table 1's short wave: the image's onset and the head shadow's highs
     * stand apart from the direct wave */
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING_TABLE1, &d.sound), FG_OK);
    d.sound.t0_jitter = 0;
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    *frames = (size_t)(rc->seconds * FS);
    float **planes = calloc(rc->channels, sizeof *planes);
    for (uint32_t ch = 0; ch < rc->channels; ch++)
        planes[ch] = calloc(*frames, sizeof **planes);
    fx_render(e, planes, rc->channels, *frames, 256);
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.late_events, 0);
    fg_engine_destroy(e);
    return planes;
}

static void release(float **planes, uint32_t channels)
{
    for (uint32_t ch = 0; ch < channels; ch++)
        free(planes[ch]);
    free(planes);
}

/* Segments below the 1.7 m ear's tangent ray (59.9 m at 3 km) are heard
 * through the creeping wave, weaker by beta x; above it at full level. */
static void shadow_zone_decays_into_the_shadow(void **state)
{
    (void)state;
    static const double heights[] = {0.5, 20.0, 50.0, 200.0};
    for (size_t i = 0; i < sizeof heights / sizeof heights[0]; i++) {
        render_case rc;
        lightning_segment(&rc, 0, 3000, heights[i]);
        rc.seconds = 9.5;
        size_t n;
        float **straight = render(&rc, &n);
        rc.prop.refraction_radius_m = FG_REFRACTION_STORM_M;
        float **bent = render(&rc, &n);
        double depth = 3000.0 - sqrt(2.0 * FG_REFRACTION_STORM_M * 1.7) -
                       sqrt(2.0 * FG_REFRACTION_STORM_M * heights[i]);
        double beta = 20.0 * log10(exp(1.0)) * 1.018792972 * sqrt(3.0) / 2.0 *
                      cbrt(2.0 * FG_PI * 50.0 / C /
                           (2.0 * FG_REFRACTION_STORM_M * FG_REFRACTION_STORM_M));
        double want = depth > 0.0 ? pow(10.0, -beta * depth / 20.0) : 1.0;
        double got = sqrt(fx_energy(bent[0], 0, n) / fx_energy(straight[0], 0, n));
        if (fabs(got - want) > 1e-3 + 1e-3 * want)
            fail_msg("z = %g m: gain %.5f, want %.5f", heights[i], got, want);
        if (heights[i] < 59.9)
            assert_true(want < 0.97);
        /* the arc is longer: the refracted wave comes later, never earlier */
        assert_true(fx_first_nonzero(bent[0], n) >= fx_first_nonzero(straight[0], n));
        release(straight, 1);
        release(bent, 1);
    }
}

/* The image source below z = 0 arrives later by the geometric prediction
 * sqrt(D^2 + (hs + hl)^2) - sqrt(D^2 + (hs - hl)^2) over c, weaker by the
 * coefficient and by eq. 3 at its longer distance. */
static void ground_image_arrives_at_the_geometric_delay(void **state)
{
    (void)state;
    static const struct {
        double d, hs; /* horizontal distance, source height */
    } cases[] = {{300.0, 200.0}, {0.0, 60.0}};
    const double hl = 1.7;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        render_case rc;
        /* horizontal, so both paths see it broadside */
        lightning_segment(&rc, 0, cases[i].d, cases[i].hs);
        fx_segment(rc.nodes, (double[]){0, cases[i].d, cases[i].hs}, (double[]){1, 0, 0}, 1.5);
        rc.seconds = 1.5;
        rc.prop.ground_reflection = 0.8;
        size_t n;
        float **out = render(&rc, &n);
        size_t onsets[4];
        size_t found = fx_onsets(out[0], n, 1e-4f, 100, onsets, 4);
        assert_int_equal(found, 2);
        double d2 = cases[i].d * cases[i].d;
        double direct = sqrt(d2 + (cases[i].hs - hl) * (cases[i].hs - hl));
        double image = sqrt(d2 + (cases[i].hs + hl) * (cases[i].hs + hl));
        double want = (image - direct) / C * FS;
        if (fabs((double)(onsets[1] - onsets[0]) - want) > 1.0)
            fail_msg("case %zu: image %zu samples after, want %.1f", i, onsets[1] - onsets[0], want);
        float p_direct = fx_peak(out[0], onsets[0] + 100);
        float p_image = fx_peak(out[0] + onsets[1], n - onsets[1]);
        double ps_ratio = direct / image *
                          sqrt((1 + 0.524 * log(direct / 10)) / (1 + 0.524 * log(image / 10)));
        if (fabs(p_image / p_direct - 0.8 * ps_ratio) > 0.02)
            fail_msg("case %zu: level ratio %.4f, want %.4f", i, p_image / p_direct,
                     0.8 * ps_ratio);
        release(out, 1);
    }
}

static void turbulence_offsets_are_bounded_and_seeded(void **state)
{
    (void)state;
    double moved = 0;
    for (int seed = 0; seed < 8; seed++) {
        render_case rc;
        lightning_segment(&rc, 0, 600, 300 + 40 * seed);
        rc.seconds = 2.5;
        size_t n;
        float **calm = render(&rc, &n);
        rc.prop.turbulence_s = 0.002;
        float **windy = render(&rc, &n);
        long shift = fx_first_nonzero(windy[0], n) - fx_first_nonzero(calm[0], n);
        assert_true(labs(shift) <= (long)(0.002 * FS) + 1);
        moved = fmax(moved, labs(shift) / FS);
        /* only the timing changes */
        assert_true(fabs(fx_energy(windy[0], 0, n) / fx_energy(calm[0], 0, n) - 1) < 1e-4);
        release(calm, 1);
        release(windy, 1);
    }
    assert_true(moved > 0.2 * 0.002);
}

/* The engine's absorbed render equals the free-air render through the
 * same two band filters, mixed by the split weight, within float
 * rounding. */
static void absorption_equals_filtering_the_free_render(void **state)
{
    (void)state;
    static const double distances[] = {150.0, 1200.0, 4000.0};
    for (size_t i = 0; i < sizeof distances / sizeof distances[0]; i++) {
        render_case rc;
        lightning_segment(&rc, 0, distances[i], 1.7);
        fx_segment(rc.nodes, (double[]){0, distances[i], 1.7}, (double[]){1, 0, 0}, 1.5);
        rc.seconds = distances[i] / C + 0.2;
        size_t n;
        float **dry = render(&rc, &n);
        rc.prop.absorption = FG_ABSORPTION_ISO9613;
        float **wet = render(&rc, &n);

        fg_band_plan plan;
        assert_int_equal(fg_band_plan_init(&plan, 10.0, 30000.0, FG_ABSORPTION_BANDS), FG_OK);
        fg_air air = {293.15 - 273.15, 70.0, 101.325}; /* the engine default */
        unsigned lo;
        double w;
        fg_band_locate(&plan, distances[i], &lo, &w);
        float *near = malloc(n * sizeof *near);
        memcpy(near, dry[0], n * sizeof *near);
        /* the bands are designed in a chain, each from the previous fit */
        fg_iir f[FG_ABSORPTION_BANDS];
        fg_absorb_fit fit = {.valid = false};
        for (unsigned k = 0; k <= lo + 1; k++)
            fg_absorb_design(&f[k], &air, plan.centre_m[k], FS, &fit);
        fg_iir_process(&f[lo], near, n);
        fg_iir_process(&f[lo + 1], dry[0], n);
        /* the source split between its two bands */
        for (size_t k = 0; k < n; k++)
            dry[0][k] = (float)((1.0 - w) * near[k] + w * dry[0][k]);
        free(near);
        double peak = fx_peak(dry[0], n), err = 0;
        for (size_t k = 0; k < n; k++)
            err = fmax(err, fabs(dry[0][k] - wet[0][k]));
        assert_true(peak > 0);
        assert_true(err <= 1e-5 * peak);
        release(dry, 1);
        release(wet, 1);
    }
}

static void abe_fir_filters_only_distant_sources(void **state)
{
    (void)state;
    static const double distances[] = {500.0, 2000.0};
    for (size_t i = 0; i < 2; i++) {
        render_case rc;
        lightning_segment(&rc, 0, distances[i], 1.7);
        rc.seconds = distances[i] / C + 0.3;
        size_t n;
        float **dry = render(&rc, &n);
        rc.prop.absorption = FG_ABSORPTION_ABE_FIR; /* beyond 1 km by default */
        float **wet = render(&rc, &n);
        if (distances[i] < FG_ABE_FIR_DEFAULT_DISTANCE_M) {
            assert_memory_equal(dry[0], wet[0], n * sizeof(float));
        } else {
            fg_abe_fir *f = malloc(sizeof *f);
            assert_int_equal(fg_abe_fir_init(f, FS), FG_OK);
            fg_abe_fir_process(f, dry[0], n);
            double peak = fx_peak(dry[0], n), err = 0;
            for (size_t k = 0; k < n; k++)
                err = fmax(err, fabs(dry[0][k] - wet[0][k]));
            assert_true(peak > 0);
            assert_true(err <= 1e-5 * peak);
            free(f);
        }
        release(dry, 1);
        release(wet, 1);
    }
}

static void head_shadow_brightens_the_near_ear_and_shades_the_far(void **state)
{
    (void)state;
    render_case rc;
    /* 30 m to the listener's right (+x) */
    lightning_segment(&rc, 30, 0, 1.7);
    rc.channels = 2;
    rc.seconds = 0.2;
    size_t n;
    float **open = render(&rc, &n);
    rc.prop.head_shadow = 1;
    float **shaded = render(&rc, &n);
    /* the right ear faces the source: Brown & Duda's alpha 2, up to +6 dB
     * above the head's corner; the left one is shaded (alpha 0.28) */
    double right_open = fx_energy(open[1], 0, n), right_shaded = fx_energy(shaded[1], 0, n);
    assert_true(right_shaded > 1.05 * right_open);
    double left_open = fx_energy(open[0], 0, n), left_shaded = fx_energy(shaded[0], 0, n);
    assert_true(left_shaded < 0.8 * left_open);
    assert_true(left_shaded > 0.05 * left_open);
    release(open, 2);
    release(shaded, 2);
}

static size_t crossings(const float *x, size_t a, size_t b)
{
    size_t count = 0;
    for (size_t k = a + 1; k < b; k++)
        count += (x[k - 1] < 0) != (x[k] < 0);
    return count;
}

static void abe_model_falls_in_pitch(void **state)
{
    (void)state;
    render_case rc;
    lightning_segment(&rc, 0, 500, 100);
    rc.model = FG_MODEL_ABE;
    rc.seconds = 2.5;
    size_t n;
    float **a = render(&rc, &n);
    float **b = render(&rc, &n);
    assert_memory_equal(a[0], b[0], n * sizeof(float));
    long start = fx_first_nonzero(a[0], n);
    assert_true(start > 0);
    double arrival = sqrt(500.0 * 500 + 98.3 * 98.3) / C * FS;
    assert_true(fabs(start - arrival) <= 2.0);
    size_t w = (size_t)(0.1 * FS), s = (size_t)start;
    size_t early = crossings(a[0], s, s + w), late = crossings(a[0], s + 4 * w, s + 5 * w);
    assert_true(early > 0);
    assert_true(late < early);
    release(a, 1);
    release(b, 1);
}

/* The defaults an effect takes once it is on, and only then. */
static void propagation_resolves_its_defaults(void **state)
{
    (void)state;
    fg_propagation_config used;
    fg_propagation_config on = {.turbulence_s = 0.002, .absorption = FG_ABSORPTION_ABE_FIR};
    assert_int_equal(fg_propagation_config_resolve(&on, &used), FG_OK);
    assert_true(used.turbulence_length_m == FG_TURBULENCE_DEFAULT_LENGTH_M);
    assert_true(used.abe_fir_distance_m == FG_ABE_FIR_DEFAULT_DISTANCE_M);
    assert_true(used.turbulence_s == 0.002 && used.absorption == FG_ABSORPTION_ABE_FIR);
    fg_propagation_config given = {.turbulence_s = 0.001, .turbulence_length_m = 20,
                                   .absorption = FG_ABSORPTION_ABE_FIR, .abe_fir_distance_m = 300};
    assert_int_equal(fg_propagation_config_resolve(&given, &used), FG_OK);
    assert_true(used.turbulence_length_m == 20 && used.abe_fir_distance_m == 300);
    fg_propagation_config off = {0};
    assert_int_equal(fg_propagation_config_resolve(&off, &used), FG_OK);
    assert_true(used.turbulence_length_m == 0 && used.abe_fir_distance_m == 0);
    assert_int_equal(fg_propagation_config_resolve(NULL, &used), FG_ERR_NULL);
    assert_int_equal(fg_propagation_config_resolve(&off, NULL), FG_ERR_NULL);
}

static void bad_propagation_is_refused(void **state)
{
    (void)state;
    static const fg_propagation_config bad[] = {
        {.refraction_radius_m = 5000.0},
        {.refraction_radius_m = NAN},
        {.turbulence_s = -1e-3},
        {.turbulence_s = 2.0},
        {.absorption = (fg_absorption)7},
        {.ground_reflection = 1.5},
        {.abe_fir_distance_m = -1.0},
        /* the noise's lattice coordinate p / length once overflowed int64 */
        {.turbulence_s = 0.002, .turbulence_length_m = 1e-300},
        {.turbulence_s = 0.002, .turbulence_length_m = 0.99e-3},
    };
    fg_engine *e;
    assert_int_equal(fg_engine_create(NULL, &e), FG_OK);
    render_case rc;
    lightning_segment(&rc, 0, 100, 10);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fg_discharge d = {.nodes = rc.nodes, .node_count = 2, .propagation = bad[i]};
        assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), FG_OK);
        fg_result r = fg_engine_post(e, &d, NULL);
        assert_true(r == FG_ERR_ARGUMENT || r == FG_ERR_NOT_FINITE);
    }
    fg_propagation_config used = {.turbulence_s = 0.5};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fg_result r = fg_propagation_config_resolve(&bad[i], &used);
        assert_true(r == FG_ERR_ARGUMENT || r == FG_ERR_NOT_FINITE);
        assert_true(used.turbulence_s == 0.5); /* untouched */
    }
    fg_discharge d = {.nodes = rc.nodes, .node_count = 2, .model = (fg_voice_model)9};
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), FG_OK);
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_ERR_ARGUMENT);
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.posted, 0);
    fg_engine_destroy(e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(shadow_zone_decays_into_the_shadow),
        cmocka_unit_test(ground_image_arrives_at_the_geometric_delay),
        cmocka_unit_test(turbulence_offsets_are_bounded_and_seeded),
        cmocka_unit_test(absorption_equals_filtering_the_free_render),
        cmocka_unit_test(abe_fir_filters_only_distant_sources),
        cmocka_unit_test(head_shadow_brightens_the_near_ear_and_shades_the_far),
        cmocka_unit_test(abe_model_falls_in_pitch),
        cmocka_unit_test(propagation_resolves_its_defaults),
        cmocka_unit_test(bad_propagation_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
