/* Ground reflection: the image's extra delay equals the geometric
 * prediction sqrt(D^2 + (hs + hl)^2) - sqrt(D^2 + (hs - hl)^2), and
 * mirroring the ear is equivalent to mirroring the source. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "air/ground_internal.h"

static void test_extra_delay(void **state)
{
    (void)state;
    const double c = 343.0;
    static const struct {
        double d, hs, hl;
    } cases[] = {{3000.0, 2000.0, 1.7}, {10.0, 5.0, 1.7}, {0.0, 100.0, 2.0}, {500.0, 0.0, 1.7}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double src[3] = {cases[i].d * 0.6, cases[i].d * 0.8, cases[i].hs};
        double ear[3] = {0.0, 0.0, cases[i].hl};
        double want = (sqrt(cases[i].d * cases[i].d + pow(cases[i].hs + cases[i].hl, 2)) -
                       sqrt(cases[i].d * cases[i].d + pow(cases[i].hs - cases[i].hl, 2))) / c;
        double got = fg_ground_extra_path_m(src, ear) / c;
        assert_true(fabs(got - want) < 1e-12);
    }
    /* straight above: the path is longer by twice the ear's height */
    double src[3] = {0, 0, 100}, ear[3] = {0, 0, 2};
    assert_true(fabs(fg_ground_extra_path_m(src, ear) - 4.0) < 1e-12);
    /* a source on the ground has no separate image */
    double low[3] = {40, 30, 0};
    assert_true(fabs(fg_ground_extra_path_m(low, ear)) < 1e-12);
}

static void test_mirror_ear_equivalent(void **state)
{
    (void)state;
    double src[3] = {120.0, -40.0, 35.0}, ear[3] = {1.0, 2.0, 1.7};
    double ear_m[3], src_m[3];
    fg_ground_mirror(ear, ear_m);
    fg_ground_mirror(src, src_m);
    assert_true(ear_m[0] == 1.0 && ear_m[1] == 2.0 && ear_m[2] == -1.7);
    double d1 = 0.0, d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        d1 += (src[k] - ear_m[k]) * (src[k] - ear_m[k]);
        d2 += (src_m[k] - ear[k]) * (src_m[k] - ear[k]);
    }
    assert_true(fabs(d1 - d2) < 1e-9);
    fg_ground_mirror(src, src); /* in place */
    assert_true(src[2] == -35.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_extra_delay),
        cmocka_unit_test(test_mirror_ear_equivalent),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
