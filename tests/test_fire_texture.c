/* Sound texture synthesis (Chadwick & James section 5): trained on a clip
 * X and given X itself (so its coarsest level G_X(L) is the input), the
 * octave-band levels 1-16 kHz are X's within 3 dB; ten times the input
 * gives ten times the output, the same training windows chosen; silence
 * gives exact silence; the latency the dry run states is the one the
 * stream has; blocks of any size give the same samples; bad training
 * clips are refused with nothing made. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <fftw3.h>

#include "fire/texture_synth_internal.h"
#include "fire_signal.h"
#include "fulgur/fire.h"

#define FS 44100.0

static float *clip(uint64_t seed, double seconds, size_t *frames)
{
    *frames = (size_t)(seconds * FS);
    float *x = malloc(sizeof(float) * *frames);
    assert_int_equal(fg_fire_training_clip(FS, seed, x, *frames), FG_OK);
    return x;
}

static fg_fire_texture *train(const float *x, size_t frames)
{
    fg_fire_texture_config c = {.samples = x, .frames = frames, .sample_rate_hz = FS};
    fg_fire_texture *t;
    assert_int_equal(fg_fire_texture_create(&c, &t), FG_OK);
    return t;
}

/* A procedural clip and a texture trained on it. */
static fg_fire_texture *clip_texture(uint64_t seed, double seconds, float **x, size_t *frames)
{
    *x = clip(seed, seconds, frames);
    return train(*x, *frames);
}

/* Output of a fresh stream for x[0 .. n) (and its stats). */
static float *synthesise(const fg_fire_texture *t, const float *x, size_t n, size_t *made,
                         fg_texture_synth_stats *stats)
{
    fg_texture_synth s;
    assert_true(fg_texture_synth_init(&s, t, 10.0));
    float *y = malloc(sizeof(float) * (n + fg_texture_synth_latency(&s)));
    *made = fg_texture_synth_push(&s, x, n, y);
    if (stats)
        *stats = s.stats;
    fg_texture_synth_deinit(&s);
    return y;
}

/* Octave-band energy (dB) of x[0 .. n) at centre fc, from one FFT. */
static double octave_db(const float *x, size_t n, double fc)
{
    double *buf = fftw_malloc(sizeof(double) * n);
    fftw_complex *spec = fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1));
    fftw_plan p = fftw_plan_dft_r2c_1d((int)n, buf, spec, FFTW_ESTIMATE);
    for (size_t i = 0; i < n; i++)
        buf[i] = x[i];
    fftw_execute(p);
    double e = 0.0;
    for (size_t k = 0; k <= n / 2; k++) {
        double f = (double)k * FS / (double)n;
        if (f >= fc / sqrt(2.0) && f < fc * sqrt(2.0))
            e += spec[k][0] * spec[k][0] + spec[k][1] * spec[k][1];
    }
    fftw_destroy_plan(p);
    fftw_free(buf);
    fftw_free(spec);
    return 10.0 * log10(e);
}

static void test_octave_levels(void **state)
{
    (void)state;
    size_t n;
    float *x;
    fg_fire_texture *t = clip_texture(2, 6.0, &x, &n);
    size_t made;
    float *y = synthesise(t, x, n, &made, NULL);
    assert_true(made + 2000 > n);
    for (double fc = 1000.0; fc <= 16000.0; fc *= 2.0) {
        double d = octave_db(y, made, fc) - octave_db(x, made, fc);
        print_message("octave %5.0f Hz: output - X %+.2f dB\n", fc, d);
        assert_true(fabs(d) <= 3.0);
    }
    free(y);
    free(x);
    fg_fire_texture_destroy(t);
}

/* The simulated low band: a made-up flame's p (LOW_ONLY), rounded to
 * multiples of 2^-8 so that ten times it is exact in float. */
static float *low_band(size_t *n)
{
    size_t steps = 360 * 3 / 2;
    double *flux = malloc(sizeof(double) * steps);
    fire_test_flux(360.0, steps, 4, flux);
    fg_fire_sound_config c = {.sample_rate_hz = FS, .extension = FG_FIRE_LOW_ONLY};
    fg_fire_sound *s;
    assert_int_equal(fg_fire_sound_create(&c, &s), FG_OK);
    size_t cap = fg_fire_sound_max_frames(s, steps);
    float *p = malloc(sizeof(float) * cap);
    assert_int_equal(fg_fire_sound_process(s, flux, steps, p, cap, n), FG_OK);
    for (size_t i = 0; i < *n; i++)
        p[i] = (float)(round(p[i] * 256.0) / 256.0);
    fg_fire_sound_destroy(s);
    free(flux);
    return p;
}

static void test_scaling_and_silence(void **state)
{
    (void)state;
    size_t n;
    float *x;
    fg_fire_texture *t = clip_texture(3, 2.0, &x, &n);
    size_t np;
    float *p = low_band(&np), *p10 = malloc(sizeof(float) * np);
    double level = 0.0;
    for (size_t i = 0; i < np; i++) {
        p10[i] = 10.0f * p[i];
        assert_true(p10[i] == 10.0 * (double)p[i]); /* exact */
        level = fmax(level, fabs(p[i]));
    }
    assert_true(level > 1.0);
    size_t m1, m10;
    fg_texture_synth_stats s1, s10;
    float *y1 = synthesise(t, p, np, &m1, &s1), *y10 = synthesise(t, p10, np, &m10, &s10);
    assert_int_equal(m1, m10);
    assert_true(s1.queries > 30000);
    assert_int_equal(s1.queries, s10.queries);
    assert_true(s1.choices == s10.choices); /* the same windows, in order */
    double worst = 0.0, energy = 0.0;
    for (size_t i = 0; i < m1; i++) {
        double want = 10.0 * (double)y1[i];
        /* float rounding of the two products, no more */
        assert_true(fabs((double)y10[i] - want) <= 2.5e-7 * fabs(want));
        if (want != 0.0)
            worst = fmax(worst, fabs((double)y10[i] - want) / fabs(want));
        energy += (double)y1[i] * y1[i];
    }
    assert_true(energy > 0.0);
    print_message("x10 in: worst relative deviation from x10 out %.2e\n", worst);

    /* silence in, silence out: every sample exactly 0 */
    float *zero = calloc(np, sizeof(float));
    fg_texture_synth_stats sz;
    size_t mz;
    float *yz = synthesise(t, zero, np, &mz, &sz);
    assert_true(mz > np / 2);
    for (size_t i = 0; i < mz; i++)
        assert_true(yz[i] == 0.0f);
    assert_true(sz.silent > 0);
    free(yz);
    free(zero);
    free(y1);
    free(y10);
    free(p);
    free(p10);
    free(x);
    fg_fire_texture_destroy(t);
}

/* The latency from the dry run is the lag the real stream shows, and any
 * block sizes give the same samples. */
static void test_latency_and_blocks(void **state)
{
    (void)state;
    size_t n;
    float *x;
    fg_fire_texture *t = clip_texture(4, 2.0, &x, &n);
    fg_texture_synth a, b;
    assert_true(fg_texture_synth_init(&a, t, 10.0));
    assert_true(fg_texture_synth_init(&b, t, 10.0));
    size_t latency = fg_texture_synth_latency(&a);
    print_message("texture latency %zu samples (%.1f ms)\n", latency, 1e3 * (double)latency / FS);
    assert_true(latency > 500 && latency < 2000);
    float *ya = malloc(sizeof(float) * (n + latency)), *yb = malloc(sizeof(float) * (n + latency));
    size_t made_a = 0, made_b = 0, worst = 0;
    for (size_t i = 0; i < n; i++) {
        made_a += fg_texture_synth_push(&a, x + i, 1, ya + made_a);
        size_t lag = i + 1 - made_a;
        worst = lag > worst ? lag : worst;
    }
    assert_int_equal(worst, latency);
    for (size_t i = 0, block = 1; i < n; i += block, block = block * 7 % 1013 + 1) {
        size_t k = block < n - i ? block : n - i;
        size_t got = fg_texture_synth_push(&b, x + i, k, yb + made_b);
        assert_true(got <= k + latency);
        made_b += got;
    }
    assert_int_equal(made_a, made_b);
    assert_memory_equal(ya, yb, sizeof(float) * made_a);
    fg_texture_synth_deinit(&a);
    fg_texture_synth_deinit(&b);
    free(ya);
    free(yb);
    free(x);
    fg_fire_texture_destroy(t);
}

static void test_bad_training(void **state)
{
    (void)state;
    size_t n;
    float *x = clip(5, 2.0, &n);
    fg_fire_texture *t = (fg_fire_texture *)x; /* must become NULL */
    fg_fire_texture_config c = {.samples = x, .frames = n, .sample_rate_hz = FS};
    assert_int_equal(fg_fire_texture_create(NULL, &t), FG_ERR_NULL);
    assert_int_equal(fg_fire_texture_create(&c, NULL), FG_ERR_NULL);
    struct {
        fg_fire_texture_config c;
        fg_result want;
    } bad[] = {
        {{.samples = NULL, .frames = n, .sample_rate_hz = FS}, FG_ERR_NULL},
        {{.samples = x, .frames = (size_t)(0.9 * FS), .sample_rate_hz = FS}, FG_ERR_ARGUMENT},
        {{.samples = x, .frames = n, .sample_rate_hz = 4000.0}, FG_ERR_SAMPLE_RATE},
        {{.samples = x, .frames = n, .sample_rate_hz = NAN}, FG_ERR_NOT_FINITE},
        {{.samples = x, .frames = n, .sample_rate_hz = FS, .levels = 9}, FG_ERR_ARGUMENT},
        {{.samples = x, .frames = n, .sample_rate_hz = FS, .half_width = 17}, FG_ERR_ARGUMENT},
        {{.samples = x, .frames = n, .sample_rate_hz = FS, .feature_multiplier = -1},
         FG_ERR_ARGUMENT},
        {{.samples = x, .frames = n, .sample_rate_hz = FS, .max_bytes = 1000000}, FG_ERR_CAPACITY},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        t = (fg_fire_texture *)x;
        assert_int_equal(fg_fire_texture_create(&bad[i].c, &t), bad[i].want);
        assert_null(t);
    }
    /* a NaN anywhere, and a silent clip */
    x[n / 2] = NAN;
    assert_int_equal(fg_fire_texture_create(&c, &t), FG_ERR_NOT_FINITE);
    assert_null(t);
    memset(x, 0, sizeof(float) * n);
    assert_int_equal(fg_fire_texture_create(&c, &t), FG_ERR_ARGUMENT);
    assert_null(t);
    /* a texture of another rate is refused by the stream */
    assert_int_equal(fg_fire_training_clip(FS, 5, x, n), FG_OK);
    t = train(x, n);
    fg_fire_sound_config sc = {.sample_rate_hz = 48000.0, .extension = FG_FIRE_TEXTURE,
                               .texture = t};
    fg_fire_sound *s = (fg_fire_sound *)x;
    assert_int_equal(fg_fire_sound_create(&sc, &s), FG_ERR_ARGUMENT);
    assert_null(s);
    sc.texture = NULL;
    assert_int_equal(fg_fire_sound_create(&sc, &s), FG_ERR_ARGUMENT);
    fg_fire_texture_info info;
    fg_fire_texture_get_info(t, &info);
    assert_int_equal(info.feature_dims, 46);
    assert_int_equal(info.config.levels, 6);
    assert_int_equal(info.config.half_width, 4);
    assert_int_equal(info.config.feature_multiplier, 3);
    assert_true(info.config.epsilon == 1.0);
    assert_true(info.dictionary[0] > n / 4 - 100 && info.dictionary[0] <= n / 4);
    fg_fire_texture_destroy(t);
    fg_fire_texture_destroy(NULL);
    free(x);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_octave_levels),
        cmocka_unit_test(test_scaling_and_silence),
        cmocka_unit_test(test_latency_and_blocks),
        cmocka_unit_test(test_bad_training),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
