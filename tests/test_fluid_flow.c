/* The fluid core in motion: the Taylor-Green vortex decaying at the viscous
 * rate, in 2-D and embedded in 3-D, and a scalar carried round a solid-body
 * rotation (its mass, its extrema, its shape).
 *
 * Taylor-Green: u = sin x cos y, v = -cos x sin y on [0, pi]^2 is an exact
 * Navier-Stokes solution whose velocity decays as exp(-2 nu t) (energy
 * exp(-4 nu t)); its velocity has no flow through and no shear on the box
 * faces, so free-slip walls hold it exactly (Taylor & Green 1937). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "fluid/fluid_internal.h"
#include "fg_math.h"


/* Energy decay rate over t = 2 divided by 4 nu, and the largest velocity
 * error against exp(-2 nu t) sin x cos y. dims 3: the same field, uniform
 * along z, in a slab of depth cells. */
static void taylor_green(int dims, int n, double nu, double cfl, double *ratio, double *error)
{
    double h = FG_PI / n, T = 2.0;
    fg_fluid_config c = {.dims = dims,
                         .cells = {n, n, 4},
                         .cell_m = h,
                         .viscosity_m2_s = nu,
                         .density_kg_m3 = 1.0,
                         .boundary = {{FG_FLUID_SLIP, FG_FLUID_SLIP},
                                      {FG_FLUID_SLIP, FG_FLUID_SLIP},
                                      {FG_FLUID_SLIP, FG_FLUID_SLIP}}};
    fg_fluid *f = NULL;
    assert_int_equal(fg_fluid_create(&c, &f), FG_OK);
    for (int a = 0; a < 2; a++) {
        fg_fluid_array u = fg_fluid_velocity(f, a);
        for (int k = 0; k < u.size[2]; k++)
            for (int j = 0; j < u.size[1]; j++)
                for (int i = 0; i < u.size[0]; i++) {
                    double x = u.origin_m[0] + h * i, y = u.origin_m[1] + h * j;
                    u.data[i + u.stride[1] * j + u.stride[2] * k] =
                        a == 0 ? sin(x) * cos(y) : -cos(x) * sin(y);
                }
    }
    double e0 = fg_fluid_kinetic_energy(f);
    int steps = (int)ceil(T / (cfl * h));
    for (int s = 0; s < steps; s++)
        assert_int_equal(fg_fluid_step(f, T / steps, NULL), FG_OK);
    *ratio = -log(fg_fluid_kinetic_energy(f) / e0) / T / (4.0 * nu);
    double decay = exp(-2.0 * nu * T), worst = 0.0;
    fg_fluid_array u = fg_fluid_velocity(f, 0);
    for (int j = 0; j < u.size[1]; j++)
        for (int i = 0; i < u.size[0]; i++) {
            double x = u.origin_m[0] + h * i, y = u.origin_m[1] + h * j;
            worst = fmax(worst, fabs(u.data[i + u.stride[1] * j] - decay * sin(x) * cos(y)));
        }
    *error = worst;
    if (dims == 3) { /* and (next to) nothing along z */
        fg_fluid_array w = fg_fluid_velocity(f, 2);
        size_t m = (size_t)w.size[0] * w.size[1] * w.size[2];
        double most = 0.0;
        for (size_t i = 0; i < m; i++)
            most = fmax(most, fabs(w.data[i]));
        print_message("3-D: largest w %.2e\n", most);
        assert_true(most < 1e-7); /* measured 2.2e-9: the projection's tolerance */
    }
    fg_fluid_destroy(f);
}

/* The decay rate is the viscous one within 5 % at 64^2 (measured 3.1 %),
 * closer at 128^2 (1.5 %), and the velocity error halves with h at a
 * fixed Courant number. */
static void taylor_green_decay(void **state)
{
    (void)state;
    static const struct {
        int dims, n;
        double most_ratio;
    } cases[] = {{2, 32, 1.08}, {2, 64, 1.05}, {2, 128, 1.025}, {3, 32, 1.08}};
    double err[4];
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double ratio;
        taylor_green(cases[k].dims, cases[k].n, 0.01, 0.5, &ratio, &err[k]);
        print_message("dims %d, %d^2: decay %.4f x the viscous rate, max error %.3e\n",
                      cases[k].dims, cases[k].n, ratio, err[k]);
        assert_true(ratio > 0.995 && ratio < cases[k].most_ratio);
    }
    assert_true(err[1] < 0.6 * err[0] && err[2] < 0.6 * err[1]);
    assert_true(fabs(err[3] / err[0] - 1.0) < 0.05); /* 3-D slab = 2-D */
}

/* A Gaussian blob (sigma 0.08, 10 cells) carried once round a solid-body
 * rotation by the scalar advection alone, 400 steps. MacCormack keeps the
 * peak (measured 0.984), adds no new extrema (the clamp), keeps the mass
 * (measured +0.024 %; the scheme is not conservative, so this is a bound,
 * asserted 0.5 %) and the shape (L1 error 0.038 of the mass);
 * first-order semi-Lagrangian keeps 0.58 of the peak, L1 error 0.40. */
static double rotate_blob(int semi_lagrangian, double *peak, double *mass_change, double *l1,
                          double *lowest)
{
    int n = 128;
    double h = 1.0 / n;
    fg_fluid_config c = {.dims = 2, .cells = {n, n, 1}, .cell_m = h, .origin_m = {-0.5, -0.5, 0},
                         .scalars = 1, .semi_lagrangian = semi_lagrangian,
                         .boundary = {{FG_FLUID_OPEN, FG_FLUID_OPEN}, {FG_FLUID_OPEN, FG_FLUID_OPEN}}};
    fg_fluid *f = NULL;
    assert_int_equal(fg_fluid_create(&c, &f), FG_OK);
    double omega = 2.0 * FG_PI; /* one turn a second */
    for (int a = 0; a < 2; a++) {
        fg_fluid_array u = fg_fluid_velocity(f, a);
        for (int j = 0; j < u.size[1]; j++)
            for (int i = 0; i < u.size[0]; i++) {
                double x = u.origin_m[0] + h * i, y = u.origin_m[1] + h * j;
                u.data[i + u.stride[1] * j] = a == 0 ? -omega * y : omega * x;
            }
    }
    fg_fluid_array s = fg_fluid_scalar(f, 0);
    static double start[128 * 128];
    double m0 = 0.0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double x = s.origin_m[0] + h * i - 0.25, y = s.origin_m[1] + h * j;
            double v = exp(-(x * x + y * y) / (2 * 0.08 * 0.08));
            start[i + n * j] = s.data[i + s.stride[1] * j] = v;
            m0 += v;
        }
    int steps = 400; /* CFL 0.8 at the blob's centre */
    for (int k = 0; k < steps; k++)
        fg_fluid_advect_scalars(f, 1.0 / steps);
    double m = 0.0, top = -1.0, low = 1.0, diff = 0.0;
    for (int i = 0; i < n * n; i++) {
        double v = s.data[i];
        m += v;
        top = fmax(top, v);
        low = fmin(low, v);
        diff += fabs(v - start[i]);
    }
    *peak = top;
    *mass_change = m / m0 - 1.0;
    *l1 = diff / m0;
    *lowest = low;
    fg_fluid_destroy(f);
    return top;
}

static void scalar_rotation(void **state)
{
    (void)state;
    double peak, dm, l1, low, peak_sl, dm_sl, l1_sl, low_sl;
    rotate_blob(0, &peak, &dm, &l1, &low);
    rotate_blob(1, &peak_sl, &dm_sl, &l1_sl, &low_sl);
    print_message("MacCormack: peak %.4f, mass %+.4f %%, L1 %.4f, min %.2e\n", peak, 100 * dm, l1,
                  low);
    print_message("semi-Lagrangian: peak %.4f, mass %+.4f %%, L1 %.4f, min %.2e\n", peak_sl,
                  100 * dm_sl, l1_sl, low_sl);
    assert_true(peak > 0.97 && peak <= 1.0);
    assert_true(low >= 0.0);
    assert_true(fabs(dm) < 0.005);
    assert_true(l1 < 0.06);
    assert_true(peak_sl < 0.7 && l1_sl > 5.0 * l1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(taylor_green_decay),
        cmocka_unit_test(scalar_rotation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
