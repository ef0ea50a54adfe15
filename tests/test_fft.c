/* The engine's real FFT (engine/src/util/) against FFTW at every length
 * from 4 to 2^16: forward to 1e-14 of the spectrum's peak, inverse back to
 * the input to 1e-14; in place as well as out of place; bad lengths
 * refused. */
#include <fftw3.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "fg_rng.h"
#include "dsp/fft_internal.h"

static void test_against_fftw(void **state)
{
    (void)state;
    fg_rng rng;
    fg_rng_seed(&rng, 4);
    for (size_t n = 4; n <= 65536; n *= 2) {
        double *x = fftw_malloc(sizeof(double) * n), *y = malloc(sizeof(double) * (n + 2));
        double *z = malloc(sizeof(double) * (n + 2));
        fftw_complex *X = fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1));
        fftw_plan p = fftw_plan_dft_r2c_1d((int)n, x, X, FFTW_ESTIMATE);
        for (size_t i = 0; i < n; i++)
            x[i] = fg_rng_range(&rng, -1.0, 1.0) + (i == n / 3 ? 5.0 : 0.0);
        fftw_execute(p);
        fg_fft f;
        assert_true(fg_fft_init(&f, n));
        fg_fft_forward(&f, x, y);
        double err = 0.0, peak = 0.0;
        for (size_t k = 0; k <= n / 2; k++) {
            err = fmax(err, hypot(y[2 * k] - X[k][0], y[2 * k + 1] - X[k][1]));
            peak = fmax(peak, hypot(X[k][0], X[k][1]));
        }
        assert_true(y[1] == 0.0 && y[n + 1] == 0.0);
        assert_true(err <= 1e-14 * peak);
        /* in place */
        for (size_t i = 0; i < n; i++)
            z[i] = x[i];
        fg_fft_forward(&f, z, z);
        for (size_t k = 0; k < n + 2; k++)
            assert_true(z[k] == y[k]);
        fg_fft_inverse(&f, z, z);
        double back = 0.0;
        for (size_t i = 0; i < n; i++)
            back = fmax(back, fabs(z[i] - x[i]));
        assert_true(back <= 1e-14);
        fg_fft_deinit(&f);
        fftw_destroy_plan(p);
        fftw_free(x);
        fftw_free(X);
        free(y);
        free(z);
    }
}

static void test_bad_lengths(void **state)
{
    (void)state;
    fg_fft f;
    assert_false(fg_fft_init(&f, 0));
    assert_false(fg_fft_init(&f, 2));
    assert_false(fg_fft_init(&f, 96));
    assert_false(fg_fft_init(&f, FG_FFT_MAX_SIZE * 2));
    assert_null(f.twiddle);
    fg_fft_deinit(&f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_fftw),
        cmocka_unit_test(test_bad_lengths),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
