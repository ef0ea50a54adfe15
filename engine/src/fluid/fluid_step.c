/* One time step: the phases in order, with the caller's hooks between.
 *
 * The pressure gradient is split along the trajectory, as the
 * semi-Lagrangian semi-implicit schemes of weather models do: a share
 * alpha of dt grad p^n / rho is taken at the departure point (before
 * advection, fluid_advect.c), the rest at the arrival point by the
 * projection, whose pressure is then p^(n+1). Advect-then-project
 * (alpha = 0, Chorin's splitting) is first order in dt and dissipates: a
 * Taylor-Green vortex (64^2, nu = 0.001) lost energy 6.8x, 4.0x and 2.5x
 * faster than nu allows at CFL 1, 0.5 and 0.25, and a cylinder's Strouhal
 * number at Re 100 moved 4 % between CFL 1 and 0.5. Centred (alpha = 1/2)
 * the decay was 1.15x at CFL 1, but a pressure perturbation then flips
 * sign each step without decaying (the lift rang at the Nyquist rate, 16 %
 * of the shedding peak in the drag spectrum); alpha = 0.45 damps it by
 * 0.82 a step and keeps most of the gain (1.33x at CFL 0.5; St within
 * 0.5 % between CFL 0.5 and 0.25). The carrier velocity is extrapolated to
 * mid-step (fluid_advect.c) and viscosity is Crank-Nicolson. */
#include <math.h>
#include <string.h>

#include "fluid_state_internal.h"
#include "core/fp_env_internal.h"

fg_result fg_fluid_step(fg_fluid *f, double dt, const fg_fluid_hooks *hooks)
{
    if (!f)
        return FG_ERR_NULL;
    if (!(dt > 0.0) || !isfinite(dt))
        return FG_ERR_ARGUMENT;
    /* slow flow near walls decays into denormals */
    fg_fp_env env = fg_fp_env_flush_denormals();
    fg_fluid_advect(f, dt);
    if (hooks && hooks->forces) {
        hooks->forces(f, dt, hooks->user);
        fg_fluid_impose_box(f);
        fg_fluid_impose_solid(f);
    }
    fg_fluid_apply_viscosity(f, dt);
    double *phi = NULL;
    if (hooks && hooks->divergence) {
        phi = f->phi;
        memset(phi, 0, f->cells * sizeof(double));
        hooks->divergence(f, dt, phi, hooks->user);
    }
    fg_result r = fg_fluid_solve_pressure(f, dt, phi, 1.0 - FG_FLUID_DEPARTURE_SHARE);
    f->time += dt;
    fg_fp_env_restore(env);
    if (!isfinite(fg_fluid_max_speed(f)))
        return FG_ERR_NOT_FINITE;
    return r;
}
