/* Spectral bandwidth extension (Chadwick & James section 4, Algorithm 1)
 * on a made-up simulated flame's flux at 360 Hz, through the public
 * stream, measured with FFTW: the spectral slope over 400 Hz - 8 kHz
 * (1/3-octave means of a Welch spectrum, least squares in log-log) is
 * -alpha within 0.15; the band power under the Gaussian g^2 of eq. 13 at
 * f_cut is the input's within 1 dB, in every one of 4 flux seeds, and
 * closer than with table 1's own analysis window (A = w_H); 30-150 Hz is
 * the input's to -30 dB; the 50 ms envelope above 500 Hz follows the low
 * band (correlation >= 0.4); beta satisfies eq. 13 to 1e-9 on both
 * analysis windows, and in every case of its quadratic. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <fftw3.h>

#include "fire/bwe_internal.h"
#include "fire_signal.h"
#include "fulgur/fire.h"

#define FS 44100.0
#define SIM 360.0
#define SECONDS 12
#define STEPS ((size_t)(SECONDS * SIM))
#define SEG 8192

typedef struct run {
    float *out;
    size_t frames;
} run;

/* The whole flux series through a stream of the given extension. */
static run render_with(fg_fire_extension ext, double alpha, uint64_t seed, int beta_half_window,
                       const double *flux, size_t steps)
{
    fg_fire_sound_config c = {.sample_rate_hz = FS, .sim_rate_hz = SIM, .extension = ext,
                              .bwe = {.alpha = alpha, .seed = seed,
                                      .beta_half_window_frames = beta_half_window}};
    fg_fire_sound *s;
    assert_int_equal(fg_fire_sound_create(&c, &s), FG_OK);
    size_t cap = fg_fire_sound_max_frames(s, steps) + fg_fire_sound_drain_frames(s);
    run r = {.out = malloc(sizeof(float) * cap)};
    size_t n;
    assert_int_equal(fg_fire_sound_process(s, flux, steps, r.out, cap, &n), FG_OK);
    r.frames = n;
    assert_int_equal(fg_fire_sound_drain(s, r.out + n, cap - n, &n), FG_OK);
    r.frames += n;
    fg_fire_sound_stats st;
    fg_fire_sound_get_stats(s, &st);
    if (ext == FG_FIRE_BANDWIDTH_EXTENSION) {
        assert_true(st.windows > 1000);
        assert_int_equal(st.beta_degenerate, 0);
        assert_int_equal(st.beta_no_root, 0);
    }
    fg_fire_sound_destroy(s);
    return r;
}

static run render(fg_fire_extension ext, double alpha, uint64_t seed, const double *flux,
                  size_t steps)
{
    return render_with(ext, alpha, seed, 0, flux, steps);
}

static double *test_flux(uint64_t seed)
{
    double *flux = malloc(sizeof(double) * STEPS);
    fire_test_flux(SIM, STEPS, seed, flux);
    return flux;
}

static void check_slope(double alpha)
{
    double *flux = test_flux(11);
    run y = render(FG_FIRE_BANDWIDTH_EXTENSION, alpha, 7, flux, STEPS);
    double *psd = malloc(sizeof(double) * (SEG / 2 + 1));
    fire_welch(y.out, y.frames, FS, SEG, psd);
    double lf[16], lp[16];
    size_t bands = 0;
    for (double f = 400.0; f * 1.12 <= 8000.0 * 1.001; f *= pow(2.0, 1.0 / 3.0)) {
        double lo = f / pow(2.0, 1.0 / 6.0), hi = f * pow(2.0, 1.0 / 6.0);
        lf[bands] = log10(f);
        lp[bands] = log10(fire_band_mean(psd, SEG, FS, lo, hi));
        bands++;
    }
    double slope = fire_slope(lf, lp, bands);
    print_message("alpha %.2f: slope over 400 Hz - 8 kHz %.3f (%zu bands)\n", alpha, slope, bands);
    assert_true(fabs(slope + alpha) <= 0.15);
    free(psd);
    free(y.out);
    free(flux);
}

static void test_slope_alpha_3(void **state)
{
    (void)state;
    check_slope(3.0);
}

static void test_slope_alpha_2_5(void **state)
{
    (void)state;
    check_slope(2.5);
}

/* Output minus input power under g^2 at f_cut, dB (Welch spectra). */
static double band_db(const run *x, const run *y)
{
    double *px = malloc(sizeof(double) * (SEG / 2 + 1)), *py = malloc(sizeof(double) * (SEG / 2 + 1));
    fire_welch(x->out, x->frames, FS, SEG, px);
    fire_welch(y->out, x->frames, FS, SEG, py);
    double gx = 0.0, gy = 0.0;
    for (size_t k = 0; k <= SEG / 2; k++) {
        double z = ((double)k * FS / SEG - 180.0) / 10.0, g2 = exp(-z * z);
        gx += g2 * px[k];
        gy += g2 * py[k];
    }
    free(px);
    free(py);
    return 10.0 * log10(gy / gx);
}

/* Band power under g^2 at f_cut, the low band, and the envelope, for one
 * flux and noise seed; returns |band error| with the default analysis
 * window, and in *literal that with table 1's (A = w_H). */
static double check_band_and_envelope(uint64_t seed, double *literal)
{
    double *flux = test_flux(seed);
    run x = render(FG_FIRE_LOW_ONLY, 3.0, 0, flux, STEPS);
    run y = render(FG_FIRE_BANDWIDTH_EXTENSION, 3.0, seed + 100, flux, STEPS);
    run l = render_with(FG_FIRE_BANDWIDTH_EXTENSION, 3.0, seed + 100, 500, flux, STEPS);
    assert_int_equal(x.frames, y.frames);
    assert_int_equal(x.frames, l.frames);
    size_t n = x.frames;
    double band = band_db(&x, &y);
    *literal = fabs(band_db(&x, &l));
    print_message("seed %d: power under g^2 at f_cut: output - input %+.3f dB (A = w_H: %.3f)\n",
                  (int)seed, band, *literal);
    assert_true(fabs(band) <= 1.0);

    /* 30-150 Hz: the simulated signal itself */
    double *bx = malloc(sizeof(double) * n), *by = malloc(sizeof(double) * n);
    fire_band_pass(x.out, n, FS, 30.0, 150.0, bx);
    fire_band_pass(y.out, n, FS, 30.0, 150.0, by);
    double err = 0.0, ref = 0.0;
    for (size_t i = 0; i < n; i++) {
        err += (by[i] - bx[i]) * (by[i] - bx[i]);
        ref += bx[i] * bx[i];
    }
    double low_db = 10.0 * log10(err / ref);
    print_message("30-150 Hz error %.1f dB\n", low_db);
    assert_true(low_db <= -30.0);

    /* 50 ms envelopes: the output above 500 Hz against the low band */
    double *hy = malloc(sizeof(double) * n);
    fire_band_pass(y.out, n, FS, 500.0, FS / 2.0 + 1.0, hy);
    size_t frame = (size_t)(0.05 * FS), frames = n / frame;
    double *ex = malloc(sizeof(double) * frames), *ey = malloc(sizeof(double) * frames);
    fire_frame_rms(bx, n, frame, ex);
    fire_frame_rms(hy, n, frame, ey);
    double r = fire_correlation(ex, ey, frames);
    print_message("envelope correlation %.3f over %zu frames\n", r, frames);
    assert_true(r >= 0.4);

    free(hy);
    free(ex);
    free(ey);
    free(bx);
    free(by);
    free(x.out);
    free(y.out);
    free(l.out);
    free(flux);
    return fabs(band);
}

static void test_band_and_envelope(void **state)
{
    (void)state;
    double mean = 0.0, mean_literal = 0.0;
    for (uint64_t seed = 11; seed <= 14; seed++) {
        double literal;
        mean += check_band_and_envelope(seed, &literal) / 4.0;
        mean_literal += literal / 4.0;
    }
    print_message("mean |band error|: %.3f dB; with A = w_H %.3f dB\n", mean, mean_literal);
    assert_true(mean < mean_literal);
}

/* Table 1's blend and weight, written out here again. */
static double f_low(double f)
{
    return f <= 165.0 ? 1.0 : f >= 195.0 ? 0.0 : (195.0 - f) / 30.0;
}

static double g2_at(double f)
{
    double z = (f - 180.0) / 10.0;
    return exp(-z * z);
}

/* Windows of the simulated signal and their noise, of half-width w_H and
 * of the default A: beta from the engine's transform and fg_bwe_beta
 * satisfies eq. 13 on FFTW's spectra of the same windows with the weights
 * above, and fg_bwe_blend returns the inverse transform of eq. 12. */
static void test_beta_solves_eq13(void **state)
{
    (void)state;
    double *flux = test_flux(5);
    run x = render(FG_FIRE_LOW_ONLY, 3.0, 0, flux, STEPS);
    fg_bwe_params p = {.sample_rate_hz = FS, .alpha = 3.0, .f_cut_hz = 180.0,
                       .sigma_cut_hz = 10.0, .blend_low_hz = 165.0, .blend_high_hz = 195.0,
                       .half_window = 500, .beta_half_window = 4410, .seed = 3};
    fg_bwe b;
    assert_true(fg_bwe_init(&b, &p));
    assert_int_equal(b.m, 4096);
    assert_int_equal(b.ma, 16384);
    for (int pass = 0; pass < 2; pass++) {
        int half = pass ? 4410 : 500;
        size_t m = pass ? b.ma : b.m, bins = m / 2 + 1;
        const fg_fft *fft = pass ? &b.fft_beta : &b.fft;
        const fg_bwe_weights *weights = pass ? &b.weights_beta : &b.weights;
        double *P = calloc(m + 2, sizeof(double)), *Q = calloc(m + 2, sizeof(double));
        double *pw0 = fftw_malloc(sizeof(double) * m), *nw0 = fftw_malloc(sizeof(double) * m);
        fftw_complex *PF = fftw_malloc(sizeof(fftw_complex) * bins);
        fftw_complex *QF = fftw_malloc(sizeof(fftw_complex) * bins);
        fftw_plan fp = fftw_plan_dft_r2c_1d((int)m, pw0, PF, FFTW_ESTIMATE);
        fftw_plan fq = fftw_plan_dft_r2c_1d((int)m, nw0, QF, FFTW_ESTIMATE);
        double worst = 0.0, worst_y = 0.0;
        int windows = 0;
        for (int64_t c = 40000; c + half < (int64_t)x.frames && windows < 60; c += 7001, windows++) {
            for (size_t k = 0; k < m; k++)
                pw0[k] = nw0[k] = 0.0;
            for (int64_t d = 1 - half; d < half; d++) {
                double w = 1.0 - fabs((double)d) / half, v = w * x.out[c + d];
                pw0[(int64_t)m / 2 + d] = v;
                nw0[(int64_t)m / 2 + d] = fabs(v) * fg_noise_next(&b.noise);
            }
            fg_fft_forward(fft, pw0, P);
            fg_fft_forward(fft, nw0, Q);
            fg_beta_case how;
            double beta = fg_bwe_beta(weights, P, Q, &how);
            assert_int_equal(how, FG_BETA_ROOT);
            assert_true(beta > 0.0);
            fftw_execute(fp);
            fftw_execute(fq);
            double lhs = 0.0, rhs = 0.0;
            for (size_t k = 0; k < bins; k++) {
                double f = (double)k * FS / (double)m, lo = f_low(f), hi = 1.0 - lo, g2 = g2_at(f);
                double br = lo * PF[k][0] + beta * hi * QF[k][0];
                double bi = lo * PF[k][1] + beta * hi * QF[k][1];
                lhs += g2 * (br * br + bi * bi);
                rhs += g2 * (PF[k][0] * PF[k][0] + PF[k][1] * PF[k][1]);
            }
            worst = fmax(worst, fabs(lhs - rhs) / rhs);
            if (!pass) {
                /* eq. 12 on the synthesis window: FFT(y) = F_low P + beta F_high Q */
                double *y = fftw_malloc(sizeof(double) * m);
                fftw_complex *Y = fftw_malloc(sizeof(fftw_complex) * bins);
                fftw_plan fy = fftw_plan_dft_r2c_1d((int)m, y, Y, FFTW_ESTIMATE);
                fg_bwe_blend(&b, P, Q, beta, y);
                fftw_execute(fy);
                double ydiff = 0.0, ynorm = 0.0;
                for (size_t k = 0; k < bins; k++) {
                    double f = (double)k * FS / (double)m, lo = f_low(f), hi = 1.0 - lo;
                    double br = lo * PF[k][0] + beta * hi * QF[k][0];
                    double bi = lo * PF[k][1] + beta * hi * QF[k][1];
                    ydiff += hypot(Y[k][0] - br, Y[k][1] - bi);
                    ynorm += hypot(br, bi);
                }
                worst_y = fmax(worst_y, ydiff / ynorm);
                fftw_destroy_plan(fy);
                fftw_free(y);
                fftw_free(Y);
            }
        }
        print_message("eq. 13 on %d windows of half-width %d: worst relative residual %.2e%s",
                      windows, half, worst, pass ? "\n" : "");
        if (!pass)
            print_message("; eq. 12 output %.2e\n", worst_y);
        assert_true(worst <= 1e-9);
        assert_true(worst_y <= 1e-12);
        fftw_destroy_plan(fp);
        fftw_destroy_plan(fq);
        fftw_free(pw0);
        fftw_free(nw0);
        fftw_free(PF);
        fftw_free(QF);
        free(P);
        free(Q);
    }
    fg_bwe_deinit(&b);
    free(x.out);
    free(flux);
}

/* The quadratic's cases, on two hand-made bins: a = sum g2 hi^2 |Q|^2,
 * b = 2 sum g2 lo hi Re(P conj Q), c = sum g2 (lo^2 - 1) |P|^2. */
static double beta_of(const double lo[2], const double p[2], const double q[2], fg_beta_case *how)
{
    double hi[2] = {lo[0] == 2.0 ? 1.0 : 1.0 - lo[0], 1.0 - lo[1]}, g2[2] = {1.0, 1.0};
    fg_bwe_weights w = {.bins = 2, .f_low = (double *)lo, .f_high = hi, .g2 = g2};
    double P[4] = {p[0], 0.0, p[1], 0.0}, Q[4] = {q[0], 0.0, q[1], 0.0};
    return fg_bwe_beta(&w, P, Q, how);
}

static void test_beta_cases(void **state)
{
    (void)state;
    fg_beta_case how;
    /* no noise under g: degenerate, beta = 0 */
    assert_true(beta_of((double[]){0.5, 0.5}, (double[]){1.0, 2.0}, (double[]){0.0, 0.0}, &how) ==
                0.0);
    assert_int_equal(how, FG_BETA_DEGENERATE);
    /* a = 1, b = -2, c = 3.75 (lo = 2 on bin 0 makes c > 0): no real root;
     * beta = -b / 2a = 1, where the residual is least */
    double beta = beta_of((double[]){2.0, 0.5}, (double[]){1.5, -2.0}, (double[]){0.0, 2.0}, &how);
    assert_int_equal(how, FG_BETA_NO_ROOT);
    assert_true(fabs(beta - 1.0) < 1e-15);
    /* a = 1, b = 2, c = 0.63: real roots, both negative: beta = 0 */
    beta = beta_of((double[]){2.0, 0.5}, (double[]){1.1, 2.0}, (double[]){0.0, 2.0}, &how);
    assert_int_equal(how, FG_BETA_NO_ROOT);
    assert_true(beta == 0.0);
    /* b >> |c|, b > 0: the root -c/b-ish without cancellation; the
     * residual a beta^2 + b beta + c is zero to rounding of c */
    beta = beta_of((double[]){0.5, 0.5}, (double[]){1e-4, 1e4}, (double[]){0.0, 2.0}, &how);
    assert_int_equal(how, FG_BETA_ROOT);
    double a = 1.0, b = 0.5 * 1e4 * 2.0, c = -0.75 * (1e-8 + 1e8);
    assert_true(fabs(a * beta * beta + b * beta + c) <= 1e-12 * fabs(c));
    /* the ordinary case: P and Q alike, c < 0 */
    beta = beta_of((double[]){0.5, 0.25}, (double[]){1.0, 1.0}, (double[]){1.0, -1.0}, &how);
    assert_int_equal(how, FG_BETA_ROOT);
    assert_true(beta > 0.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_slope_alpha_3),
        cmocka_unit_test(test_slope_alpha_2_5),
        cmocka_unit_test(test_band_and_envelope),
        cmocka_unit_test(test_beta_solves_eq13),
        cmocka_unit_test(test_beta_cases),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
