/* The binaural convolver's 128-point transform (engine/src/dsp/fft128)
 * against the engine's double one (fg_fft): 64 signals of noise, each with
 * a spike in a different place, in the split layout; the packed spectrum
 * within 1e-6 of the spectrum's peak (float rounding through a four-step
 * transform and the split: it measures about 1e-7), every bin checked
 * (a transposed pair of columns, a wrong twiddle or a misplaced X[64]
 * is off by the bin's whole size), and inverse(forward(x)) back to x
 * within 1e-6 of its peak, split (the inverse's layout). Skipped on a CPU without AVX2 and FMA,
 * where the convolver does not choose it. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "dsp/fft128_internal.h"
#include "dsp/fft_internal.h"
#include "fg_rng.h"

#define N 128
#define SIGNALS 64

static void matches_double_transform(void **state)
{
    (void)state;
#ifdef FG_FFT128_AVX2
    if (!fg_fft128_avx2_available())
        skip();
    fg_fft128 f;
    fg_fft128_init(&f);
    fg_fft plain;
    assert_true(fg_fft_init(&plain, N));
    fg_rng rng;
    fg_rng_seed(&rng, 5);
    double worst = 0.0, back = 0.0;
    for (int s = 0; s < SIGNALS; s++) {
        float window[N], x[N], orig[N];
        double d[N + 2];
        for (int t = 0; t < N; t++) {
            float v = (float)fg_rng_range(&rng, -1.0, 1.0) + (t == 2 * s + s % 2 ? 4.0f : 0.0f);
            window[t] = v;
            orig[t % 2 ? N / 2 + t / 2 : t / 2] = v; /* split: x[2k] re, x[2k+1] im */
            d[t] = v;
        }
        fg_fft128_forward_avx2(&f, window, x);
        fg_fft_forward(&plain, d, d);
        double peak = 0.0, err = 0.0;
        for (int k = 0; k <= N / 2; k++) {
            double re = k < N / 2 ? x[k] : x[N / 2];
            double im = k == 0 || k == N / 2 ? 0.0 : x[N / 2 + k];
            peak = fmax(peak, hypot(d[2 * k], d[2 * k + 1]));
            err = fmax(err, hypot(re - d[2 * k], im - d[2 * k + 1]));
        }
        worst = fmax(worst, err / peak);
        fg_fft128_inverse_avx2(&f, x);
        double xpeak = 0.0, off = 0.0;
        for (int e = 0; e < N; e++) {
            xpeak = fmax(xpeak, fabs(orig[e]));
            off = fmax(off, fabs(x[e] - orig[e]));
        }
        back = fmax(back, off / xpeak);
    }
    print_message("forward %.1e of the peak, inverse %.1e\n", worst, back);
    assert_true(worst < 1e-6);
    assert_true(back < 1e-6);
    fg_fft_deinit(&plain);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(matches_double_transform),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
