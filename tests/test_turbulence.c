/* Turbulence: the offset is bounded by its amplitude, continuous (3 m
 * apart with a 100 m correlation length: within the noise's slope bound,
 * and small on average), deterministic for a seed, different between
 * seeds, and of mean near zero over many correlation lengths. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "fg_rng.h"
#include "air/turbulence_internal.h"

#define POINTS 40000
#define AMP 0.02

static void random_point(fg_rng *rng, double span_m, double p[3])
{
    for (int k = 0; k < 3; k++)
        p[k] = fg_rng_range(rng, -span_m, span_m);
}

static void test_bounded_and_centred(void **state)
{
    (void)state;
    fg_turbulence t = {1234, AMP, 100.0};
    fg_rng rng;
    fg_rng_seed(&rng, 1);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < POINTS; i++) {
        double p[3];
        random_point(&rng, 50e3, p);
        double o = fg_turbulence_offset_s(&t, p);
        assert_true(fabs(o) <= AMP);
        sum += o;
        sum2 += o * o;
    }
    double mean = sum / POINTS, rms = sqrt(sum2 / POINTS);
    /* trilinear blending of uniform values: rms about 0.4 of the amplitude */
    assert_true(rms > 0.2 * AMP && rms < 0.5 * AMP);
    assert_true(fabs(mean) < 0.02 * AMP);
}

static void test_continuous(void **state)
{
    (void)state;
    fg_turbulence t = {99, AMP, 100.0};
    fg_rng rng;
    fg_rng_seed(&rng, 2);
    double worst = 0.0, mean_diff = 0.0;
    for (int i = 0; i < POINTS; i++) {
        double p[3], q[3], dir[3], norm = 0.0, l1 = 0.0;
        random_point(&rng, 5e3, p);
        for (int k = 0; k < 3; k++) {
            dir[k] = fg_rng_range(&rng, -1.0, 1.0);
            norm += dir[k] * dir[k];
        }
        for (int k = 0; k < 3; k++) {
            q[k] = p[k] + 3.0 * dir[k] / sqrt(norm);
            l1 += fabs(q[k] - p[k]);
        }
        double diff = fabs(fg_turbulence_offset_s(&t, p) - fg_turbulence_offset_s(&t, q));
        /* the slope bound, in seconds */
        assert_true(diff <= FG_NOISE_MAX_SLOPE * AMP * l1 / 100.0 + 1e-15);
        worst = fmax(worst, diff);
        mean_diff += diff / POINTS;
    }
    assert_true(worst < 0.2 * AMP);
    assert_true(mean_diff < 0.03 * AMP);
}

static void test_seeded(void **state)
{
    (void)state;
    fg_turbulence a = {5, AMP, 100.0}, a2 = {5, AMP, 100.0}, b = {6, AMP, 100.0};
    fg_rng rng;
    fg_rng_seed(&rng, 3);
    double differ = 0.0;
    for (int i = 0; i < 1000; i++) {
        double p[3];
        random_point(&rng, 20e3, p);
        assert_true(fg_turbulence_offset_s(&a, p) == fg_turbulence_offset_s(&a2, p));
        differ += fabs(fg_turbulence_offset_s(&a, p) - fg_turbulence_offset_s(&b, p)) / 1000;
    }
    assert_true(differ > 0.15 * AMP);
}

/* On the lattice the noise is the hashed value itself; halfway between two
 * lattice points on an edge it is their mean. */
static void test_lattice(void **state)
{
    (void)state;
    double a = fg_value_noise3(7, 3.0, -2.0, 5.0), b = fg_value_noise3(7, 4.0, -2.0, 5.0);
    assert_true(fabs(fg_value_noise3(7, 3.5, -2.0, 5.0) - 0.5 * (a + b)) < 1e-15);
    assert_true(a != b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bounded_and_centred),
        cmocka_unit_test(test_continuous),
        cmocka_unit_test(test_seeded),
        cmocka_unit_test(test_lattice),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
