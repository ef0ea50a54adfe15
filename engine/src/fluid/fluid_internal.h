/* The incompressible fluid core: a MAC grid in 2-D or 3-D, MacCormack
 * advection, implicit viscosity, a multigrid-preconditioned pressure
 * projection, and solids as an immersed boundary with the force on them.
 *
 * [sim-thread] or an offline tool; never the audio thread. One fg_fluid is
 * used by one thread at a time; separate fg_fluid objects are independent.
 * Pure C11, no I/O. Units are SI throughout (m, s, kg/m^3, m^2/s, Pa); a 2-D
 * grid is a slab of unit depth, so its forces are per metre of span.
 *
 * Discretisation (engine/src/fluid/README.md, docs/fluid-solver.md):
 * - cells of side h; velocity component a lives on the faces normal to a
 *   (array size n + e_a), pressure and scalars at cell centres;
 * - advection: semi-Lagrangian with an RK2 back-trace along the velocity
 *   extrapolated to mid-step, and the MacCormack correction, clamped to the
 *   values the back-trace interpolated from (Selle et al. 2008);
 * - the pressure gradient shared between the trajectory's departure point
 *   (0.45) and its arrival (the projection), fluid_step.c;
 * - viscosity: Crank-Nicolson, solved by Gauss-Seidel; a velocity node
 *   next to a solid sees the wall at its true distance (Shortley-Weller);
 * - projection: cut-cell face fractions (the variational projection of
 *   Batty, Bertails & Bridson 2007 / Ng, Min & Gibou 2009), solved by
 *   conjugate gradient preconditioned with a cell-centred multigrid V-cycle;
 *   the divergence target phi (1/s) allows expanding flows (combustion);
 * - the force on the solids is the momentum the discrete scheme exchanges
 *   with them: the pressure on the cut faces and the wall shear of the
 *   viscous step. */
#ifndef FULGUR_FLUID_INTERNAL_H
#define FULGUR_FLUID_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/result.h"

#define FG_FLUID_MAX_SCALARS 8

/* Air at 20 degrees C and 1 atm. */
#define FG_AIR_KINEMATIC_VISCOSITY 1.5e-5 /* m^2/s */
#define FG_AIR_DENSITY 1.204              /* kg/m^3 */

typedef struct fg_fluid fg_fluid;

/* What a face of the domain box is. */
typedef enum fg_fluid_boundary {
    FG_FLUID_WALL = 0, /* no-slip wall at rest */
    FG_FLUID_SLIP,     /* free-slip wall: no flow through, no shear */
    FG_FLUID_INFLOW,   /* the velocity is config.inflow_m_s; scalars are inflow_scalar */
    FG_FLUID_OPEN      /* p = 0 outside, zero normal gradient of velocity and scalars:
                          outflow, or entrainment where the flow comes in */
} fg_fluid_boundary;

typedef struct fg_fluid_config {
    int dims;                 /* 2 or 3 */
    int cells[3];             /* per axis, >= 4; cells[2] is ignored in 2-D */
    double cell_m;            /* h, > 0 */
    double origin_m[3];       /* the lower corner of the box */
    double viscosity_m2_s;    /* kinematic; 0 = air (1.5e-5); < 0 = inviscid */
    double density_kg_m3;     /* 0 = air (1.204) */
    /* boundary[axis][0] is the low face, [1] the high face (0 = WALL) */
    fg_fluid_boundary boundary[3][2];
    double inflow_m_s[3];     /* velocity at every INFLOW face */
    int scalars;              /* advected cell fields, 0..FG_FLUID_MAX_SCALARS */
    double inflow_scalar[FG_FLUID_MAX_SCALARS];
    double tolerance;         /* projection: ||residual|| / ||rhs|| (rhs floored at 1e-3 of
                                 the fluxes it is made of), 0 = 1e-6 */
    int max_iterations;       /* projection CG iterations, 0 = 200 */
    int semi_lagrangian;      /* 1: first-order advection (no MacCormack step) */
} fg_fluid_config;

/* One array of the grid: element (i, j, k) is data[i*stride[0] + j*stride[1]
 * + k*stride[2]] and sits at origin_m + cell_m * (i, j, k) + offset. */
typedef struct fg_fluid_array {
    double *data;
    int size[3];
    size_t stride[3];
    double origin_m[3]; /* the position of element (0, 0, 0) */
    double cell_m;
} fg_fluid_array;

/* The solid as a signed distance (m, negative inside) at a point; called
 * from fg_fluid_set_solid only, on the calling thread. */
typedef double (*fg_fluid_sdf_fn)(const double x_m[3], void *user);

/* Optional calls inside fg_fluid_step, on its thread. */
typedef struct fg_fluid_hooks {
    /* After advection, before viscosity and projection: add dt * force /
     * density to the velocity arrays (fg_fluid_velocity), e.g. buoyancy from
     * a temperature scalar, or change the scalars (reaction). */
    void (*forces)(fg_fluid *f, double dt_s, void *user);
    /* Before the projection: fill phi (1/s, one per cell, zeroed before the
     * call, layout of fg_fluid_scalar) with the divergence the flow must
     * have, e.g. the expansion of burning gas. */
    void (*divergence)(fg_fluid *f, double dt_s, double *phi, void *user);
    void *user;
} fg_fluid_hooks;

/* The last projection. */
typedef struct fg_fluid_report {
    int iterations;
    double residual;         /* ||r|| / ||rhs|| reached */
    double initial_residual; /* the same before the first iteration (warm start) */
} fg_fluid_report;

/* Force on the solids from the last step: N in 3-D, N per metre of span in 2-D. */
typedef struct fg_fluid_force {
    double pressure_n[3];
    double viscous_n[3];
} fg_fluid_force;

/* Creates a grid at rest (u = 0, scalars 0, no solid). Errors: NULL (c or
 * out), ARGUMENT (dims not 2 or 3, fewer than 4 cells on an axis, more than
 * 2^28 cells, h not > 0, an unknown boundary, scalars out of range, tolerance
 * not in [0, 1), negative max_iterations), NOT_FINITE (a NaN or infinite
 * value), NO_MEMORY. *out is written only on success. */
FG_NODISCARD fg_result fg_fluid_create(const fg_fluid_config *c, fg_fluid **out);
/* NULL is a no-op. */
void fg_fluid_destroy(fg_fluid *f);
/* The bytes fg_fluid_create allocates for c (a solid adds its cut cells and
 * wall links on top), or 0 if c is refused by fg_fluid_create. */
size_t fg_fluid_memory_bytes(const fg_fluid_config *c);
/* The configuration with its defaults filled in. */
const fg_fluid_config *fg_fluid_get_config(const fg_fluid *f);

/* Replaces the solid by {x : sdf(x) < 0} (sdf NULL: no solid). The velocity
 * inside is set to the solid's. Errors: NULL (f), NOT_FINITE (sdf returned
 * a NaN or infinite value; the old solid is kept). */
FG_NODISCARD fg_result fg_fluid_set_solid(fg_fluid *f, fg_fluid_sdf_fn sdf, void *user);
/* The solid's surface moves rigidly: u_s(x) = v + omega x (x - centre)
 * (the geometry itself stays where set_solid put it). All NULL: at rest.
 * Errors: NULL (f), NOT_FINITE. */
FG_NODISCARD fg_result fg_fluid_set_solid_motion(fg_fluid *f, const double v_m_s[3],
                                                 const double omega_rad_s[3],
                                                 const double centre_m[3]);

/* Advances by dt: scalars and velocity advected, hooks->forces, viscosity,
 * hooks->divergence, projection, forces on the solid. hooks may be NULL.
 * The advection extrapolates the velocity from this step's start and the
 * last one's (dt may change between steps); after setting the velocity by
 * hand between steps, call fg_fluid_forget_history.
 * Errors: NULL (f), ARGUMENT (dt not > 0), NOT_CONVERGED (the projection
 * stopped short of its tolerance: the step is still taken with the best
 * pressure found), NOT_FINITE (the velocity blew up: dt too large for the
 * hooks' forces; the state is then unusable). */
FG_NODISCARD fg_result fg_fluid_step(fg_fluid *f, double dt_s, const fg_fluid_hooks *hooks);

/* The next step takes the velocity as it is, without extrapolating from
 * the last step's (as the first step does). */
void fg_fluid_forget_history(fg_fluid *f);

/* Moves the scalars through the current velocity, held fixed over dt_s
 * (inside fg_fluid_step they ride the velocity extrapolated to mid-step):
 * for scalars in a flow the caller prescribes. */
void fg_fluid_advect_scalars(fg_fluid *f, double dt_s);
/* Makes the current velocity divergence-free (div u = phi, phi per cell in
 * 1/s, NULL = 0) by a whole projection, and sets the pressure from it, as
 * if the velocity had come out of a step of dt_s. Errors: NOT_CONVERGED. */
FG_NODISCARD fg_result fg_fluid_project(fg_fluid *f, double dt_s, const double *phi);

/* Views of the state, valid until fg_fluid_destroy; writable between calls
 * of fg_fluid_step (and from its hooks). axis 0..dims-1, k < scalars. */
fg_fluid_array fg_fluid_velocity(fg_fluid *f, int axis);
fg_fluid_array fg_fluid_scalar(fg_fluid *f, int k);
/* Pressure of the last projection, Pa (0 in solid cells). */
fg_fluid_array fg_fluid_pressure(fg_fluid *f);

/* Trilinear samples at any point (clamped into the box). */
void fg_fluid_sample_velocity(const fg_fluid *f, const double x_m[3], double out_m_s[3]);
double fg_fluid_sample_scalar(const fg_fluid *f, int k, const double x_m[3]);

/* Force on the part of the solid whose surface elements lie in the box
 * [lo, hi] (NULL, NULL: all of it), from the last step. */
void fg_fluid_solid_force(const fg_fluid *f, const double lo_m[3], const double hi_m[3],
                          fg_fluid_force *out);

/* Diagnostics. */
const fg_fluid_report *fg_fluid_last_report(const fg_fluid *f);
double fg_fluid_time_s(const fg_fluid *f);
/* Largest |u| component on any face (m/s), for a CFL time step. */
double fg_fluid_max_speed(const fg_fluid *f);
/* max over fluid cells of |div u - phi| * h (m/s): a velocity scale of
 * the discrete divergence left by the last projection. */
double fg_fluid_divergence_error(const fg_fluid *f, const double *phi);
/* Kinetic energy of the fluid, J (J/m in 2-D). */
double fg_fluid_kinetic_energy(const fg_fluid *f);

#endif
