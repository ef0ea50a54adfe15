/* The binaural convolver's AVX2 transforms of 128 and 256 points
 * (engine/src/dsp/fft_avx2) against the engine's double one (fg_fft): 64
 * signals of noise, each with a spike in a different place; the packed
 * spectrum within 1e-6 of the spectrum's peak (float rounding through a
 * four-step transform, the 256-point one's radix-2 step and the split: it
 * measures about 1e-7), every bin checked (a transposed pair of columns,
 * a wrong twiddle, a swapped even and odd half or a misplaced X[n/2] is
 * off by the bin's whole size), and inverse(forward(x)) back to x within
 * 1e-6 of its peak, split (the inverse's layout). Skipped on a CPU
 * without AVX2 and FMA, where the convolver does not choose them; other
 * sizes are refused. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "dsp/fft_avx2_internal.h"
#include "dsp/fft_internal.h"
#include "fg_rng.h"

#define N_MAX 256
#define SIGNALS 64

static void matches_double_transform(size_t N)
{
#ifdef FG_FFT_AVX2
    if (!fg_fft_avx2_available())
        skip();
    fg_fft_avx2 f;
    assert_true(fg_fft_avx2_init(&f, N));
    fg_fft plain;
    assert_true(fg_fft_init(&plain, N));
    fg_rng rng;
    fg_rng_seed(&rng, 5);
    double worst = 0.0, back = 0.0;
    for (size_t s = 0; s < SIGNALS; s++) {
        float window[N_MAX], x[N_MAX], orig[N_MAX];
        double d[N_MAX + 2];
        for (size_t t = 0; t < N; t++) {
            float v = (float)fg_rng_range(&rng, -1.0, 1.0) +
                      (t == (N / SIGNALS) * s + s % 2 ? 4.0f : 0.0f);
            window[t] = v;
            orig[t % 2 ? N / 2 + t / 2 : t / 2] = v; /* split: x[2k] re, x[2k+1] im */
            d[t] = v;
        }
        fg_fft_avx2_forward(&f, window, x);
        fg_fft_forward(&plain, d, d);
        double peak = 0.0, err = 0.0;
        for (size_t k = 0; k <= N / 2; k++) {
            double re = k < N / 2 ? x[k] : x[N / 2];
            double im = k == 0 || k == N / 2 ? 0.0 : x[N / 2 + k];
            peak = fmax(peak, hypot(d[2 * k], d[2 * k + 1]));
            err = fmax(err, hypot(re - d[2 * k], im - d[2 * k + 1]));
        }
        worst = fmax(worst, err / peak);
        fg_fft_avx2_inverse(&f, x);
        double xpeak = 0.0, off = 0.0;
        for (size_t e = 0; e < N; e++) {
            xpeak = fmax(xpeak, fabs(orig[e]));
            off = fmax(off, fabs(x[e] - orig[e]));
        }
        back = fmax(back, off / xpeak);
    }
    print_message("%zu points: forward %.1e of the peak, inverse %.1e\n", N, worst, back);
    assert_true(worst < 1e-6);
    assert_true(back < 1e-6);
    fg_fft_deinit(&plain);
#else
    (void)N;
    skip();
#endif
}

static void points_128(void **state)
{
    (void)state;
    matches_double_transform(128);
}

static void points_256(void **state)
{
    (void)state;
    matches_double_transform(256);
}

static void other_sizes_refused(void **state)
{
    (void)state;
    fg_fft_avx2 f;
    assert_false(fg_fft_avx2_init(&f, 64));
    assert_false(fg_fft_avx2_init(&f, 512));
    assert_false(fg_fft_avx2_init(&f, 192));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(points_128),
        cmocka_unit_test(points_256),
        cmocka_unit_test(other_sizes_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
