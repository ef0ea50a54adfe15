/* The biquad cascade: its processing matches its stated response (steady
 * sine amplitude), a block-split run equals the one-shot run bit for bit,
 * and a decaying tail ends in exact zeros. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "fg_math.h"
#include "filter_reference.h"
#include "air/iir_internal.h"

#define FS 48000.0
#define N 9600

/* A resonant low-pass, a first-order shelf and a notch-ish section. */
static fg_iir example(void)
{
    fg_iir f = {.sections = 3};
    f.sec[0] = (fg_biquad){0.02, 0.04, 0.02, -1.6, 0.7};
    f.sec[1] = (fg_biquad){0.8, -0.5, 0.0, -0.7, 0.0};
    f.sec[2] = (fg_biquad){1.0, 1.2, 0.5, 0.3, 0.2};
    fg_iir_reset(&f);
    return f;
}

static void test_sine_amplitude(void **state)
{
    (void)state;
    static const double hz[] = {50.0, 750.0, 3000.0, 8000.0}; /* whole periods */
    static float buf[N];
    for (size_t k = 0; k < sizeof hz / sizeof hz[0]; k++) {
        fg_iir f = example();
        double w = 2.0 * FG_PI * hz[k] / FS;
        for (int i = 0; i < N; i++)
            buf[i] = (float)sin(w * i);
        fg_iir_process(&f, buf, N);
        /* after the transient: amplitude from the last two periods' energy */
        int period = (int)lround(FS / hz[k]);
        double e = 0.0;
        int span = 2 * period;
        for (int i = N - span; i < N; i++)
            e += (double)buf[i] * buf[i];
        double got_db = 10.0 * log10(2.0 * e / span);
        double want_db = fg_iir_db(&f, w);
        if (fabs(got_db - want_db) > 0.02)
            fail_msg("%.0f Hz: measured %.3f dB, response %.3f dB", hz[k], got_db, want_db);
    }
}

static void test_block_split_exact(void **state)
{
    (void)state;
    static float one[N], split[N];
    for (int i = 0; i < N; i++)
        one[i] = split[i] = (float)(sin(0.01 * i) + 0.3 * sin(1.3 * i) + (i % 97 == 0));
    fg_iir a = example(), b = example();
    fg_iir_process(&a, one, N);
    static const size_t sizes[] = {1, 7, 64, 300, 1, 2048};
    size_t pos = 0, k = 0;
    while (pos < N) {
        size_t n = sizes[k++ % 6];
        if (n > N - pos)
            n = N - pos;
        fg_iir_process(&b, split + pos, n);
        pos += n;
    }
    assert_memory_equal(one, split, sizeof one);
}

/* fg_iir_process_lanes: 1 to 4 lanes of 1 to 4 sections, each lane with
 * its own coefficients, state and signal, give exactly what
 * fg_iir_process gives each, and leave the same state (a second call
 * continues it); the signals end in silence long enough for the tails to
 * snap to zero. (With AVX2, 3 and 4 lanes run as vectors, sections in
 * skewed pairs over 64-frame chunks: calls of 300 and 9300 frames end
 * mid-chunk.) */
static void test_lanes_exact(void **state)
{
    (void)state;
    enum { M = N, SOUND = 1000 };
    static float alone[FG_IIR_LANES][M], lanes[FG_IIR_LANES][M];
    for (unsigned sections = 1; sections <= FG_IIR_MAX_SECTIONS; sections++) {
        for (unsigned count = 1; count <= FG_IIR_LANES; count++) {
            fg_iir a[FG_IIR_LANES], b[FG_IIR_LANES];
            fg_iir *pb[FG_IIR_LANES];
            float *buf[FG_IIR_LANES];
            for (unsigned j = 0; j < count; j++) {
                a[j] = example();
                a[j].sec[3] = (fg_biquad){0.5, 0.2, 0.1, -0.9, 0.3};
                a[j].sections = sections;
                a[j].sec[0].b0 *= 1.0 + 0.1 * j; /* each lane its own filter */
                a[j].z[0][1] = 0.01 * j;         /* and state */
                b[j] = a[j];
                pb[j] = &b[j];
                buf[j] = lanes[j];
                for (int i = 0; i < M; i++)
                    alone[j][i] = lanes[j][i] =
                        i < SOUND ? (float)(sin(0.02 * (j + 1) * i) + (i % 61 == (int)j)) : 0.0f;
            }
            for (unsigned j = 0; j < count; j++) {
                fg_iir_process(&a[j], alone[j], 300);
                fg_iir_process(&a[j], alone[j] + 300, M - 300);
            }
            fg_iir_process_lanes(pb, buf, count, 300);
            for (unsigned j = 0; j < count; j++)
                buf[j] = lanes[j] + 300;
            fg_iir_process_lanes(pb, buf, count, M - 300);
            for (unsigned j = 0; j < count; j++) {
                assert_memory_equal(alone[j], lanes[j], sizeof alone[j]);
                assert_memory_equal(a[j].z, b[j].z, sizeof a[j].z);
                assert_true(lanes[j][M - 1] == 0.0f && b[j].z[0][0] == 0.0);
                assert_true(lanes[j][SOUND / 2] != 0.0f);
            }
        }
    }
}

static void test_tail_snaps_to_zero(void **state)
{
    (void)state;
    static float buf[N];
    fg_iir f = example();
    buf[0] = 1.0f;
    fg_iir_process(&f, buf, N);
    for (unsigned k = 0; k < f.sections; k++) {
        assert_true(f.z[k][0] == 0.0);
        assert_true(f.z[k][1] == 0.0);
    }
    assert_true(buf[N - 1] == 0.0f);
    assert_true(buf[1] != 0.0f);
}

static void test_root_radius(void **state)
{
    (void)state;
    /* (x - 0.5)(x + 0.9): c1 = 0.4, c2 = -0.45 */
    assert_true(fabs(ref_quadratic_root_radius(0.4, -0.45) - 0.9) < 1e-12);
    /* complex pair of modulus 0.8 */
    assert_true(fabs(ref_quadratic_root_radius(-2.0 * 0.8 * cos(1.0), 0.64) - 0.8) < 1e-12);
    /* first order: root -c1 */
    assert_true(fabs(ref_quadratic_root_radius(-0.7, 0.0) - 0.7) < 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sine_amplitude),
        cmocka_unit_test(test_block_split_exact),
        cmocka_unit_test(test_lanes_exact),
        cmocka_unit_test(test_tail_snaps_to_zero),
        cmocka_unit_test(test_root_radius),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
