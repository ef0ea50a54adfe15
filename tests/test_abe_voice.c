/* Abe's voice model: non-silent and deterministic, identical in any block
 * split, its span where the arrival and duration put it, its dominant
 * frequency falling over time (zero crossings against the phase law), the
 * height law, energy ~ 1/r^2, attenuation growing as f^2, and parameter
 * checks. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "sound/abe_voice_internal.h"

#define FS 48000.0
#define N 96000 /* 2 s */
#define C 343.0

static float a[N], b[N];
static const double ear[3] = {0.0, 0.0, 1.5};

static double energy(const float *x, size_t n)
{
    double e = 0.0;
    for (size_t i = 0; i < n; i++)
        e += (double)x[i] * x[i];
    return e;
}

static int crossings(const float *x, size_t from, size_t to)
{
    int c = 0;
    for (size_t i = from + 1; i < to; i++)
        c += (x[i - 1] < 0.0f) != (x[i] < 0.0f);
    return c;
}

static void test_deterministic_and_split(void **state)
{
    (void)state;
    fg_abe_config p = fg_abe_defaults;
    const double src[3] = {60.0, 80.0, 300.0}; /* r ~ 316 m: arrives at ~0.93 s */
    fg_abe_wave w, w2;
    fg_abe_wave_init(&w, &p, src, ear, 0.05, C);
    fg_abe_wave_init(&w2, &p, src, ear, 0.05, C);
    memset(a, 0, sizeof a);
    memset(b, 0, sizeof b);
    fg_abe_wave_render(&w, FS, 0, a, N);
    assert_true(energy(a, N) > 1e-3);
    size_t pos = 0, k = 0;
    static const size_t sizes[] = {1, 511, 64, 4096, 7};
    while (pos < N) {
        size_t n = sizes[k++ % 5];
        n = n > N - pos ? N - pos : n;
        fg_abe_wave_render(&w2, FS, (int64_t)pos, b + pos, n);
        pos += n;
    }
    assert_memory_equal(a, b, sizeof a);

    int64_t first, last;
    fg_abe_wave_span(&w, FS, &first, &last);
    double r = sqrt(60.0 * 60.0 + 80.0 * 80.0 + 298.5 * 298.5);
    assert_int_equal(first, (int64_t)ceil((0.05 + r / C) * FS));
    assert_int_equal(last, (int64_t)floor((0.05 + r / C + 0.12 * log(1000.0)) * FS));
    for (int64_t i = 0; i < N; i++)
        if (i < first || i > last)
            assert_true(a[i] == 0.0f);
    assert_true(a[first] > 0.0f); /* the N-wave opens with its overpressure */
}

static void test_frequency_falls(void **state)
{
    (void)state;
    fg_abe_config p = fg_abe_defaults;
    p.amp_decay_s = 0.5; /* long enough to count late crossings */
    const double src[3] = {0.0, 0.0, 1.5 + 1.0};
    fg_abe_wave w;
    fg_abe_wave_init(&w, &p, src, ear, -1.0 / C, C); /* arrives at t = 0 */
    memset(a, 0, sizeof a);
    fg_abe_wave_render(&w, FS, 0, a, N);
    /* two crossings per cycle; cycles from the phase law */
    double f0 = w.f0_hz, tf = p.freq_decay_s;
    double early = 2.0 * f0 * tf * (1.0 - exp(-0.2 / tf));
    double late = 2.0 * f0 * tf * (exp(-0.5 / tf) - exp(-0.7 / tf));
    int ce = crossings(a, 0, (size_t)(0.2 * FS)), cl = crossings(a, (size_t)(0.5 * FS), (size_t)(0.7 * FS));
    if (fabs(ce - early) > 2.0 || fabs(cl - late) > 2.0)
        fail_msg("crossings %d and %d, phase law %.1f and %.1f", ce, cl, early, late);
    assert_true(cl < 0.5 * ce);
}

static void test_height_law(void **state)
{
    (void)state;
    fg_abe_config p = fg_abe_defaults;
    assert_true(fabs(fg_abe_fundamental_hz(&p, 0.0) - 80.0) < 1e-12);
    double want = 80.0 * (331.5 + 0.6 * (20.0 - 32.5)) / (331.5 + 0.6 * 20.0);
    assert_true(fabs(fg_abe_fundamental_hz(&p, 5000.0) - want) < 1e-9);
    assert_true(fg_abe_fundamental_hz(&p, 2000.0) < fg_abe_fundamental_hz(&p, 1000.0));
    fg_abe_wave w;
    const double src[3] = {100.0, 0.0, 5001.5};
    fg_abe_wave_init(&w, &p, src, ear, 0.0, C);
    assert_true(fabs(w.f0_hz - want) < 1e-9);
}

static void test_inverse_square_energy(void **state)
{
    (void)state;
    fg_abe_config p = fg_abe_defaults;
    p.atten_db_m_hz2 = 0.0;
    const double near[3] = {300.0, 0.0, 400.0}, far[3] = {-600.0, 0.0, 400.0};
    /* same height, so the same fundamental */
    double rn = sqrt(300.0 * 300.0 + 398.5 * 398.5), rf = sqrt(600.0 * 600.0 + 398.5 * 398.5);
    fg_abe_wave wn, wf;
    fg_abe_wave_init(&wn, &p, near, ear, 0.1 - rn / C, C); /* both arrive at 0.1 s */
    fg_abe_wave_init(&wf, &p, far, ear, 0.1 - rf / C, C);
    memset(a, 0, sizeof a);
    memset(b, 0, sizeof b);
    fg_abe_wave_render(&wn, FS, 0, a, N);
    fg_abe_wave_render(&wf, FS, 0, b, N);
    double ratio = energy(a, N) / energy(b, N), want = (rf * rf) / (rn * rn);
    if (fabs(ratio / want - 1.0) > 1e-5)
        fail_msg("energy ratio %.4f, 1/r^2 gives %.4f", ratio, want);
}

/* One harmonic at a steady frequency: its level drops by k r f^2 dB. */
static void test_attenuation_f_squared(void **state)
{
    (void)state;
    static const double f0[] = {100.0, 200.0};
    const double k = 2.5e-7, r = 2000.0;
    for (int i = 0; i < 2; i++) {
        fg_abe_config p = fg_abe_defaults;
        p.harmonics = 1;
        p.freq_decay_s = 1e9;
        p.amp_decay_s = 1e9;
        p.f_ground_hz = f0[i];
        const double src[3] = {r, 0.0, 1.5};
        fg_abe_wave plain, damped;
        p.atten_db_m_hz2 = 0.0;
        fg_abe_wave_init(&plain, &p, src, ear, -r / C, C);
        p.atten_db_m_hz2 = k;
        fg_abe_wave_init(&damped, &p, src, ear, -r / C, C);
        memset(a, 0, sizeof a);
        memset(b, 0, sizeof b);
        fg_abe_wave_render(&plain, FS, 0, a, 48000);
        fg_abe_wave_render(&damped, FS, 0, b, 48000);
        double db = 10.0 * log10(energy(b, 48000) / energy(a, 48000));
        double want = -k * r * f0[i] * f0[i];
        if (fabs(db - want) > 1e-6)
            fail_msg("%g Hz: %.6f dB, want %.6f", f0[i], db, want);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_deterministic_and_split),
        cmocka_unit_test(test_frequency_falls),
        cmocka_unit_test(test_height_law),
        cmocka_unit_test(test_inverse_square_energy),
        cmocka_unit_test(test_attenuation_f_squared),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
