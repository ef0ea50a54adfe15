/* The flux-series stream (fulgur/fire.h): its defaults are table 1's,
 * scaled with the simulation rate; p = dI/dt in m^3/s^2 (a 100 Hz flux
 * sine comes out at 2 pi f A times the filter's response); frames come
 * out exactly when the stated latency allows; any split of the flux gives
 * the same samples; a NaN, a short buffer, a drained stream change
 * nothing; draining returns every frame up to the last flux sample. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fg_math.h"
#include "fire/mitchell_internal.h"
#include "fire_signal.h"
#include "fulgur/fire.h"


static fg_fire_texture *small_texture(double fs)
{
    size_t n = (size_t)(1.5 * fs);
    float *x = malloc(sizeof(float) * n);
    assert_int_equal(fg_fire_training_clip(fs, 9, x, n), FG_OK);
    fg_fire_texture_config c = {.samples = x, .frames = n, .sample_rate_hz = fs};
    fg_fire_texture *t;
    assert_int_equal(fg_fire_texture_create(&c, &t), FG_OK);
    free(x);
    return t;
}

static fg_fire_sound *make(fg_fire_extension ext, double fs, const fg_fire_texture *t)
{
    fg_fire_sound_config c = {.sample_rate_hz = fs, .extension = ext, .texture = t};
    fg_fire_sound *s;
    assert_int_equal(fg_fire_sound_create(&c, &s), FG_OK);
    return s;
}

static void test_defaults(void **state)
{
    (void)state;
    fg_fire_sound *s = make(FG_FIRE_BANDWIDTH_EXTENSION, 0.0, NULL);
    fg_fire_sound_config c;
    fg_fire_sound_get_config(s, &c);
    assert_true(c.sample_rate_hz == 48000.0 && c.sim_rate_hz == 360.0 && c.highpass_hz == 30.0);
    assert_true(c.bwe.alpha == 3.0 && c.bwe.f_cut_hz == 180.0 && c.bwe.sigma_cut_hz == 10.0);
    assert_true(c.bwe.blend_low_hz == 165.0 && c.bwe.blend_high_hz == 195.0);
    assert_int_equal(c.bwe.half_window_frames, 544); /* 500 at 44.1 kHz */
    assert_int_equal(c.bwe.beta_half_window_frames, 4800); /* fs / sigma_cut */
    /* 2 steps of Mitchell-Netravali + M/2 + A - 1 (M = 4096) */
    assert_true(fabs(fg_fire_sound_latency_s(s) - (2.0 / 360.0 + (2048.0 + 4799.0) / 48000.0)) <
                1e-12);
    fg_fire_sound_destroy(s);
    fg_fire_sound_config d = {.sample_rate_hz = 44100.0, .sim_rate_hz = 240.0};
    assert_int_equal(fg_fire_sound_create(&d, &s), FG_OK);
    fg_fire_sound_get_config(s, &c);
    assert_true(c.bwe.f_cut_hz == 120.0 && c.bwe.blend_low_hz == 110.0 &&
                c.bwe.blend_high_hz == 130.0);
    assert_int_equal(c.bwe.half_window_frames, 500);
    assert_int_equal(c.bwe.beta_half_window_frames, 6615); /* sigma_cut 20/3 Hz */
    assert_true(fabs(fg_fire_sound_latency_s(s) - (2.0 / 240.0 + 8662.0 / 44100.0)) < 1e-12);
    fg_fire_sound_destroy(s);
    /* table 1's own analysis window: 58 ms less */
    fg_fire_sound_config literal = {.sample_rate_hz = 44100.0,
                                    .bwe = {.beta_half_window_frames = 500}};
    assert_int_equal(fg_fire_sound_create(&literal, &s), FG_OK);
    assert_true(fabs(fg_fire_sound_latency_s(s) - (2.0 / 360.0 + 2547.0 / 44100.0)) < 1e-12);
    fg_fire_sound_destroy(s);
    fg_fire_sound_destroy(NULL);
}

/* The Mitchell-Netravali filter's response at nu cycles per step. */
static double mn_response(double nu)
{
    double sum = 0.0, dx = 1e-4;
    for (double x = -2.0 + dx / 2; x < 2.0; x += dx)
        sum += fg_mn_kernel(x) * cos(2.0 * FG_PI * nu * x) * dx;
    return sum;
}

static void test_units_of_p(void **state)
{
    (void)state;
    double fs = 48000.0, f = 100.0, amp = 1e-3;
    size_t steps = 3600;
    double *flux = malloc(sizeof(double) * steps);
    for (size_t i = 0; i < steps; i++)
        flux[i] = 0.05 + amp * sin(2.0 * FG_PI * f * (double)i / 360.0);
    fg_fire_sound *s = make(FG_FIRE_LOW_ONLY, fs, NULL);
    size_t cap = fg_fire_sound_max_frames(s, steps), n;
    float *p = malloc(sizeof(float) * cap);
    assert_int_equal(fg_fire_sound_process(s, flux, steps, p, cap, &n), FG_OK);
    /* the 100 Hz component over whole periods from 1 s on */
    double c = 0.0, q = 0.0;
    size_t start = 48000, len = 48000 * 8;
    assert_true(n >= start + len);
    for (size_t k = start; k < start + len; k++) {
        double t = (double)k / fs;
        c += p[k] * cos(2.0 * FG_PI * f * t) * 2.0 / (double)len;
        q += p[k] * sin(2.0 * FG_PI * f * t) * 2.0 / (double)len;
    }
    double r = 100.0 / 30.0, hp = r * r / sqrt(1.0 + r * r * r * r);
    double want = 2.0 * FG_PI * f * amp * mn_response(f / 360.0) * hp;
    print_message("100 Hz flux sine: |p| = %.6f, 2 pi f A K(f) |H_hp(f)| = %.6f (K = %.4f)\n",
                  hypot(c, q), want, mn_response(f / 360.0));
    assert_true(fabs(hypot(c, q) / want - 1.0) < 1e-3);
    fg_fire_sound_destroy(s);
    free(p);
    free(flux);
}

/* Every frame is out by the time the flux reaches its time plus the
 * latency, and none more than a step and an extension window sooner;
 * splits change nothing. */
static void check_stream(fg_fire_extension ext, double fs, const fg_fire_texture *t)
{
    size_t steps = 360 * 3 / 2;
    double *flux = malloc(sizeof(double) * steps);
    fire_test_flux(360.0, steps, 21, flux);
    fg_fire_sound *whole = make(ext, fs, t), *parts = make(ext, fs, t);
    double latency = fg_fire_sound_latency_s(whole);
    fg_fire_sound_config c;
    fg_fire_sound_get_config(whole, &c);
    double window = ext == FG_FIRE_BANDWIDTH_EXTENSION ? c.bwe.half_window_frames / fs
                    : ext == FG_FIRE_TEXTURE ? 4.0 * 32.0 / fs : 0.0;
    size_t cap = fg_fire_sound_max_frames(whole, steps) + fg_fire_sound_drain_frames(whole);
    float *a = malloc(sizeof(float) * cap), *b = malloc(sizeof(float) * cap);
    size_t na = 0, nb = 0, n;
    for (size_t i = 0; i < steps; i++) {
        assert_int_equal(fg_fire_sound_process(whole, flux + i, 1, a + na, cap - na, &n), FG_OK);
        assert_true(n <= fg_fire_sound_max_frames(whole, 1));
        na += n;
        double known = (double)i / 360.0; /* the flux is known up to here */
        /* frame na is not out yet: its time + latency is beyond the flux */
        assert_true((double)na / fs + latency > known - 1e-9);
        if (na > 0)
            assert_true((double)(na - 1) / fs + latency <= known + 1.0 / 360.0 + window + 1e-9);
    }
    for (size_t i = 0, k = 1; i < steps; i += k, k = k * 5 % 97 + 1) {
        size_t m = k < steps - i ? k : steps - i;
        assert_int_equal(fg_fire_sound_process(parts, flux + i, m, b + nb, cap - nb, &n), FG_OK);
        nb += n;
    }
    assert_int_equal(na, nb);
    assert_memory_equal(a, b, sizeof(float) * na);
    /* drain: every frame up to the last flux sample's time */
    assert_int_equal(fg_fire_sound_drain(whole, a + na, cap - na, &n), FG_OK);
    na += n;
    assert_int_equal(na, (size_t)floor((double)(steps - 1) / 360.0 * fs) + 1);
    assert_int_equal(fg_fire_sound_drain(whole, a + na, cap - na, &n), FG_ERR_ARGUMENT);
    assert_int_equal(fg_fire_sound_process(whole, flux, 1, a, cap, &n), FG_ERR_ARGUMENT);
    fg_fire_sound_stats st;
    fg_fire_sound_get_stats(whole, &st);
    assert_int_equal(st.flux_steps, steps);
    assert_int_equal(st.frames, na);
    /* reset: the same samples again */
    fg_fire_sound_reset(whole);
    assert_int_equal(fg_fire_sound_process(whole, flux, steps, a, cap, &n), FG_OK);
    assert_int_equal(n, nb);
    assert_memory_equal(a, b, sizeof(float) * n);
    double energy = 0.0;
    for (size_t i = 0; i < n; i++)
        energy += (double)a[i] * a[i];
    assert_true(energy > 0.0);
    fg_fire_sound_destroy(whole);
    fg_fire_sound_destroy(parts);
    free(a);
    free(b);
    free(flux);
}

static void test_stream_timing_and_splits(void **state)
{
    (void)state;
    check_stream(FG_FIRE_LOW_ONLY, 48000.0, NULL);
    check_stream(FG_FIRE_BANDWIDTH_EXTENSION, 44100.0, NULL);
    check_stream(FG_FIRE_BANDWIDTH_EXTENSION, 96000.0, NULL);
    fg_fire_texture *t = small_texture(44100.0);
    check_stream(FG_FIRE_TEXTURE, 44100.0, t);
    fg_fire_texture_destroy(t);
}

/* A bad call takes nothing: the stream goes on as if it had not been. */
static void test_bad_calls(void **state)
{
    (void)state;
    size_t steps = 200;
    double *flux = malloc(sizeof(double) * steps);
    fire_test_flux(360.0, steps, 3, flux);
    fg_fire_sound *clean = make(FG_FIRE_BANDWIDTH_EXTENSION, 48000.0, NULL);
    fg_fire_sound *s = make(FG_FIRE_BANDWIDTH_EXTENSION, 48000.0, NULL);
    size_t cap = fg_fire_sound_max_frames(s, steps), n = 99, m;
    float *a = malloc(sizeof(float) * cap), *b = malloc(sizeof(float) * cap);
    double poisoned[3] = {0.02, NAN, 0.02};
    assert_int_equal(fg_fire_sound_process(s, poisoned, 3, a, cap, &n), FG_ERR_NOT_FINITE);
    assert_int_equal(n, 0);
    poisoned[1] = INFINITY;
    assert_int_equal(fg_fire_sound_process(s, poisoned, 3, a, cap, &n), FG_ERR_NOT_FINITE);
    poisoned[1] = -2e12; /* beyond FG_FIRE_MAX_FLUX_M3_S */
    assert_int_equal(fg_fire_sound_process(s, poisoned, 3, a, cap, &n), FG_ERR_ARGUMENT);
    assert_int_equal(fg_fire_sound_process(s, flux, steps, a, cap - 1, &n), FG_ERR_CAPACITY);
    assert_int_equal(fg_fire_sound_process(s, NULL, 1, a, cap, &n), FG_ERR_NULL);
    assert_int_equal(fg_fire_sound_process(s, flux, 1, NULL, cap, &n), FG_ERR_NULL);
    assert_int_equal(fg_fire_sound_process(s, flux, 1, a, cap, NULL), FG_ERR_NULL);
    assert_int_equal(fg_fire_sound_process(NULL, flux, 1, a, cap, &n), FG_ERR_NULL);
    assert_int_equal(fg_fire_sound_drain(s, a, 1, &n), FG_ERR_CAPACITY);
    fg_fire_sound_stats st;
    fg_fire_sound_get_stats(s, &st);
    assert_int_equal(st.flux_steps, 0);
    assert_true(fg_fire_sound_max_frames(s, SIZE_MAX / 2) == SIZE_MAX);
    assert_int_equal(fg_fire_sound_process(s, flux, steps, a, cap, &n), FG_OK);
    assert_int_equal(fg_fire_sound_process(clean, flux, steps, b, cap, &m), FG_OK);
    assert_int_equal(n, m);
    assert_memory_equal(a, b, sizeof(float) * n);
    fg_fire_sound_destroy(clean);
    fg_fire_sound_destroy(s);
    free(a);
    free(b);
    free(flux);
}

static void test_bad_configs(void **state)
{
    (void)state;
    struct {
        fg_fire_sound_config c;
        fg_result want;
    } bad[] = {
        {{.sample_rate_hz = 4000.0}, FG_ERR_SAMPLE_RATE},
        {{.sample_rate_hz = 500000.0}, FG_ERR_SAMPLE_RATE},
        {{.sample_rate_hz = NAN}, FG_ERR_NOT_FINITE},
        {{.sim_rate_hz = 5.0}, FG_ERR_ARGUMENT},
        {{.sim_rate_hz = 20000.0}, FG_ERR_ARGUMENT},
        {{.sim_rate_hz = INFINITY}, FG_ERR_NOT_FINITE},
        {{.highpass_hz = 30000.0}, FG_ERR_ARGUMENT},
        {{.extension = (fg_fire_extension)9}, FG_ERR_ARGUMENT},
        {{.bwe = {.alpha = 0.1}}, FG_ERR_ARGUMENT},
        {{.bwe = {.alpha = 7.0}}, FG_ERR_ARGUMENT},
        {{.bwe = {.f_cut_hz = 100.0}}, FG_ERR_ARGUMENT},     /* below blend_low 165 */
        {{.bwe = {.blend_high_hz = 170.0}}, FG_ERR_ARGUMENT}, /* below f_cut */
        {{.bwe = {.sigma_cut_hz = -1.0}}, FG_ERR_ARGUMENT},
        {{.bwe = {.half_window_frames = 8}}, FG_ERR_ARGUMENT},
        {{.bwe = {.beta_half_window_frames = 100}}, FG_ERR_ARGUMENT}, /* below w_H */
        {{.bwe = {.beta_half_window_frames = 600000}}, FG_ERR_ARGUMENT},
        {{.bwe = {.alpha = NAN}}, FG_ERR_NOT_FINITE},
        {{.level_history_s = -1.0}, FG_ERR_ARGUMENT},
        {{.level_history_s = 1e300}, FG_ERR_ARGUMENT},
        {{.extension = FG_FIRE_TEXTURE}, FG_ERR_ARGUMENT},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fg_fire_sound *s = (fg_fire_sound *)bad;
        assert_int_equal(fg_fire_sound_create(&bad[i].c, &s), bad[i].want);
        assert_null(s);
    }
    fg_fire_sound *s;
    assert_int_equal(fg_fire_sound_create(NULL, &s), FG_ERR_NULL);
    assert_int_equal(fg_fire_sound_create(&bad[0].c, NULL), FG_ERR_NULL);
    /* no high-pass at all: negative */
    fg_fire_sound_config none = {.highpass_hz = -1.0, .extension = FG_FIRE_LOW_ONLY};
    assert_int_equal(fg_fire_sound_create(&none, &s), FG_OK);
    fg_fire_sound_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_units_of_p),
        cmocka_unit_test(test_stream_timing_and_splits),
        cmocka_unit_test(test_bad_calls),
        cmocka_unit_test(test_bad_configs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
