/* The presets: Matsuyama's table 1 kept exactly (spark_balls, plasma_ball,
 * lightning_table1), the lightning preset calibrated to measured thunder
 * (docs/sound-model.md), the names both ways, and the calibrated preset's
 * N-wave against the published thunder spectrum through eq. 4. The levels
 * and spectra of whole bolts through the air are bench_validate --check. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "fg_math.h"
#include "fulgur/sound.h"

/* Matsuyama, Fujimoto & Chiba, table 1: path, l, r0, T0; Wright's sigma0. */
static const struct {
    fg_preset preset;
    const char *name;
    double path_m, half_step_m, r0_m, t0_s;
} table1[] = {
    {FG_PRESET_SPARK_BALLS, "spark_balls", 0.02, 0.001, 0.05, 30e-6},
    {FG_PRESET_PLASMA_BALL, "plasma_ball", 0.20, 0.01, 0.10, 40e-6},
    {FG_PRESET_LIGHTNING_TABLE1, "lightning_table1", 5000.0, 1.5, 10.0, 500e-6},
};

static void test_table1_kept(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof table1 / sizeof table1[0]; i++) {
        fg_sound_config p;
        fg_preset_scale scale;
        assert_int_equal(fg_preset_sound(table1[i].preset, &p), FG_OK);
        assert_int_equal(fg_preset_get_scale(table1[i].preset, &scale), FG_OK);
        assert_string_equal(fg_preset_name(table1[i].preset), table1[i].name);
        assert_true(p.t0_s == table1[i].t0_s && p.r0_m == table1[i].r0_m);
        assert_true(p.sigma0 == 0.524 && p.ref_half_len_m == table1[i].half_step_m);
        assert_true(scale.path_m == table1[i].path_m && scale.half_step_m == table1[i].half_step_m);
        assert_int_equal(fg_sound_config_check(&p), FG_OK);
    }
}

/* The calibrated bolt: table 1's geometry, r0 and ps0, only T0 moved. */
static void test_lightning_calibrated(void **state)
{
    (void)state;
    fg_sound_config cal, t1;
    fg_preset_scale s_cal, s_t1;
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &cal), FG_OK);
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING_TABLE1, &t1), FG_OK);
    assert_int_equal(fg_preset_get_scale(FG_PRESET_LIGHTNING, &s_cal), FG_OK);
    assert_int_equal(fg_preset_get_scale(FG_PRESET_LIGHTNING_TABLE1, &s_t1), FG_OK);
    assert_string_equal(fg_preset_name(FG_PRESET_LIGHTNING), "lightning");
    assert_true(cal.t0_s == 2.5e-3 && cal.r0_m == 10.0 && cal.ps0_pa == 500.0);
    assert_true(cal.sigma0 == t1.sigma0 && cal.ps0_pa == t1.ps0_pa && cal.r0_m == t1.r0_m);
    assert_true(s_cal.path_m == s_t1.path_m && s_cal.half_step_m == s_t1.half_step_m);
    assert_int_equal(fg_sound_config_check(&cal), FG_OK);

    /* eq. 4 at 3 km, then the energy peak of one N-wave, f = 0.33 / T
     * (2 pi f T = 2.08): Holmes et al. 1971 put thunder's maximum near
     * 50 Hz, below 100 Hz; table 1's T0 lands above 150 Hz */
    double stretch = sqrt(1 + cal.sigma0 * log(3000.0 / cal.r0_m));
    double f_cal = 2.08 / (2 * FG_PI * cal.t0_s * stretch);
    double f_t1 = 2.08 / (2 * FG_PI * t1.t0_s * stretch);
    assert_true(f_cal > 40.0 && f_cal < 100.0);
    assert_true(f_t1 > 150.0);
    /* Few's relaxation radius for that peak, f = 0.63 c / R0: a few metres */
    double r0_few = 0.63 * 343.0 / f_cal;
    assert_true(r0_few > 2.0 && r0_few < 6.0);
    /* close strikes brighter: T at 300 m shorter than at 3 km by > 15 % */
    double near = sqrt(1 + cal.sigma0 * log(300.0 / cal.r0_m));
    assert_true(near / stretch < 0.85);
}

static void test_names(void **state)
{
    (void)state;
    for (int p = 0; p < FG_PRESET_COUNT; p++) {
        fg_preset back;
        assert_non_null(fg_preset_name((fg_preset)p));
        assert_int_equal(fg_preset_from_name(fg_preset_name((fg_preset)p), &back), FG_OK);
        assert_int_equal(back, p);
    }
    /* the existing values keep their numbers; the new preset comes last */
    assert_int_equal(FG_PRESET_SPARK_BALLS, 0);
    assert_int_equal(FG_PRESET_PLASMA_BALL, 1);
    assert_int_equal(FG_PRESET_LIGHTNING, 2);
    assert_int_equal(FG_PRESET_LIGHTNING_TABLE1, 3);
    assert_int_equal(FG_PRESET_COUNT, 4);
    fg_preset out;
    assert_int_equal(fg_preset_from_name("lightning_table", &out), FG_ERR_ARGUMENT);
    assert_int_equal(fg_preset_from_name("Lightning", &out), FG_ERR_ARGUMENT);
    assert_null(fg_preset_name(FG_PRESET_COUNT));
    fg_sound_config p;
    assert_int_equal(fg_preset_sound(FG_PRESET_COUNT, &p), FG_ERR_ARGUMENT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table1_kept),
        cmocka_unit_test(test_lightning_calibrated),
        cmocka_unit_test(test_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
