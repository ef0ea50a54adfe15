/* fulgur — the flame simulation (Chadwick & James 2011, section 7: a
 * Pyro-style combustion model stepped at 360 Hz), whose flame front's flux
 * I(t) feeds fg_fire_sound (fulgur/fire.h). docs/fire-sound.md gives the
 * equations as built, the grid sizes this machine runs and their cost.
 *
 * The model, on the engine's incompressible fluid core (MAC grid, MacCormack
 * advection, cut-cell projection by multigrid-preconditioned CG):
 *   - advected cell fields: fuel F (the volume fraction of unburnt fuel-air
 *     mixture, dimensionless) and temperature T (K);
 *   - fuel burns where T > ignition_k at burn_rate_1_s: in a step of dt a
 *     burning cell loses F (1 - exp(-burn_rate dt)); the burn field B is
 *     that loss per second (1/s), the volume of mixture burnt per volume
 *     per second;
 *   - the burn heats the gas by heat_k per unit of F burnt, and the gas
 *     cools towards ambient_k at cooling_1_s;
 *   - combustion expands the gas: the projection makes div u = phi with
 *     phi = expansion * B (1/s), so the flow leaves each step's burning
 *     region at expansion * (volume burnt per second);
 *   - buoyancy: the gas is lighter by (T - T_a) / T (ideal gas at constant
 *     pressure) and rises at buoyancy * g times that (m/s^2), along +z;
 *   - the flame front is the iso_level surface of B (fg_flame_front), and
 *     each step returns its flux I = integral over the front of u . n dS.
 *
 * Axes: +z is up (gravity along -z). Units: metres, seconds, kelvin; fuel
 * volumes in m^3 of mixture.
 *
 * Threads: one fg_flame_sim is used by one thread at a time, [sim-thread]
 * or an offline tool; nothing here runs on the audio thread.
 */
#ifndef FULGUR_FLAME_H
#define FULGUR_FLAME_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/fire.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FG_FLAME_SIM_MIN_CELLS 8
#define FG_FLAME_SIM_MAX_CELLS 512
#define FG_FLAME_MAX_EMITTERS 8
/* A step is split into at most this many substeps to keep the advection's
 * CFL number at or below 1 (a faster flow is refused: FG_ERR_NOT_FINITE). */
#define FG_FLAME_MAX_SUBSTEPS 8
/* The default refusal limit for the simulation's memory (fluid and front). */
#define FG_FLAME_SIM_DEFAULT_MAX_BYTES ((size_t)1 << 30)

typedef enum fg_flame_emitter_kind {
    FG_FLAME_EMITTER_OFF = 0,  /* the slot releases nothing */
    /* Fuel released inside the shape, the gas left to rise by itself: a
     * campfire (a flat box on the floor), a torch's head (a small sphere). */
    FG_FLAME_EMITTER_SOURCE = 1,
    /* Fuel released inside the shape, with jet_velocity_m_s blended into
     * the gas's velocity there as far as the shape covers each face: a
     * flame thrower, a dragon's breath. */
    FG_FLAME_EMITTER_JET = 2,
    /* A burning object: fuel released in the one-cell layer just outside
     * the shape's surface (the shape itself is not an obstacle to the flow). */
    FG_FLAME_EMITTER_OBJECT = 3
} fg_flame_emitter_kind;

typedef enum fg_flame_shape {
    FG_FLAME_SPHERE = 0,  /* radius_m about centre_m */
    FG_FLAME_BOX = 1      /* half_size_m about centre_m, axis-aligned */
} fg_flame_shape;

/* One emitter. Its fuel goes to the cells it covers, in proportion to how
 * much of each it covers (as the share of the cell-wide interval of signed
 * distances about the cell centre's that is inside the shape, or inside
 * the object's layer), which changes smoothly as the emitter moves; a
 * shape covering less than a cell in all releases into the 8 cells around
 * centre_m with trilinear weights. Every cell it covers is heated to at
 * least temperature_k. */
typedef struct fg_flame_emitter {
    fg_flame_emitter_kind kind;
    fg_flame_shape shape;
    double centre_m[3];
    double radius_m;          /* FG_FLAME_SPHERE: >= 0 */
    double half_size_m[3];    /* FG_FLAME_BOX: each >= 0 */
    double fuel_m3_s;         /* mixture released per second, >= 0 (1e-3, a litre a
                                 second, is a torch of about 2.3 kW with the defaults;
                                 heat release = rho_a c_p heat_k fuel_m3_s) */
    double temperature_k;     /* the released gas is heated to at least this: above
                                 ignition_k it burns; 0 means 1200 K (lit) */
    double jet_velocity_m_s[3]; /* FG_FLAME_EMITTER_JET: the gas velocity in the
                                   shape (direction times speed), not all zero */
} fg_flame_emitter;

/* Zero in any field means the default in its comment. */
typedef struct fg_flame_sim_config {
    int cells[3];             /* per axis, FG_FLAME_SIM_MIN_CELLS .. FG_FLAME_SIM_MAX_CELLS;
                                 0 means 32 */
    double cell_m;            /* h: 0.02 (a 32^3 grid is 0.64 m across); > 0 */
    double origin_m[3];       /* the box's low corner */
    double step_rate_hz;      /* steps per simulated second: 360 (the paper's);
                                 10 .. 10000 */
    double ambient_k;         /* 293.15 */
    double ignition_k;        /* fuel burns above this temperature: 700 K */
    double burn_rate_1_s;     /* 20 */
    double heat_k;            /* temperature rise per unit of F burnt: 1900 K (about
                                 the adiabatic rise of a hydrocarbon-air flame) */
    double expansion;         /* divergence per unit burn, phi / B: heat_k / ambient_k
                                 (6.5 with the defaults: the gas's volume grows as
                                 its temperature at constant pressure) */
    double cooling_1_s;       /* T - T_a decays at this rate: 3 */
    double buoyancy;          /* multiplies g = 9.81 m/s^2: 1 */
    double iso_level;         /* B on the flame front, 1/s: burn_rate / 1000 (the
                                 front then encloses the expansion to a few %) */
    int open_floor;           /* 0: the low z face is the ground (a wall); 1: open
                                 (a flame in mid-air). The other five faces are open. */
    int front_subdivision;    /* marching-cubes samples per cell edge, 1 .. 4: 1 */
    int emitters;             /* 0 .. FG_FLAME_MAX_EMITTERS */
    fg_flame_emitter emitter[FG_FLAME_MAX_EMITTERS];
    size_t max_bytes;         /* refuse configurations needing more memory; 0 means
                                 FG_FLAME_SIM_DEFAULT_MAX_BYTES */
} fg_flame_sim_config;

/* Counters and the last step's figures. Volumes in m^3 of mixture. */
typedef struct fg_flame_sim_stats {
    uint64_t steps;
    uint64_t substeps;          /* fluid steps taken (>= steps) */
    uint64_t not_converged;     /* substeps whose projection stopped short of 1e-6 */
    double time_s;              /* simulated */
    fg_flame_flux flux;         /* the last step's front and flux */
    double expansion_m3_s;      /* the last step's integral of phi over the grid, the
                                   flux a front enclosing every burning cell would see */
    double burning_m3_s;        /* the last step's integral of B: mixture burnt per second */
    double fuel_emitted_m3;     /* since create */
    double fuel_burnt_m3;
    double fuel_present_m3;     /* integral of F over the grid now */
    double max_speed_m_s;
    double max_temperature_k;
    double projection_residual; /* the last projection's ||r|| / ||rhs|| */
    int projection_iterations;
} fg_flame_sim_stats;

/* The cell fields a viewer may read. */
typedef enum fg_flame_field {
    FG_FLAME_FIELD_BURN = 0,        /* B, 1/s */
    FG_FLAME_FIELD_TEMPERATURE = 1, /* T, K */
    FG_FLAME_FIELD_FUEL = 2         /* F */
} fg_flame_field;

/* A read-only view of one cell field: cell (i, j, k) is
 * data[i + grid.size[0] * (j + grid.size[1] * k)], its centre at
 * grid.origin_m + (i + 1/2, j + 1/2, k + 1/2) grid.cell_m. */
typedef struct fg_flame_field_view {
    const double *data;
    fg_flame_grid grid;
} fg_flame_field_view;

typedef struct fg_flame_sim fg_flame_sim;

/* The bytes a simulation of this configuration allocates (defaults filled
 * in; the flame front's triangle list, 144 bytes a triangle, comes on top),
 * or 0 if the grid is outside its limits. [any-thread] */
FG_API size_t fg_flame_sim_memory_bytes(const fg_flame_sim_config *config);

/* Creates a simulation at rest, at ambient temperature, without fuel. *out
 * is the caller's until fg_flame_sim_destroy; config is copied.
 * [main-thread] or [sim-thread]
 * Errors: FG_ERR_NULL config or out; FG_ERR_NOT_FINITE any parameter or
 * emitter value; FG_ERR_ARGUMENT a cell count outside FG_FLAME_SIM_MIN_CELLS
 * .. FG_FLAME_SIM_MAX_CELLS, a negative parameter, step_rate_hz outside
 * 10 .. 10000, ignition_k not above ambient_k, front_subdivision outside
 * 0 .. 4, emitters outside 0 .. FG_FLAME_MAX_EMITTERS, an emitter that is
 * invalid (fg_flame_sim_set_emitter); FG_ERR_CAPACITY the simulation would
 * need more than max_bytes (fg_flame_sim_memory_bytes says how much;
 * refused before anything is allocated); FG_ERR_NO_MEMORY. *out is written
 * only on success. */
FG_API FG_NODISCARD fg_result fg_flame_sim_create(const fg_flame_sim_config *config,
                                                  fg_flame_sim **out);

/* Frees the simulation; NULL is a no-op. [main-thread] or [sim-thread] */
FG_API void fg_flame_sim_destroy(fg_flame_sim *sim);

/* The configuration in use, defaults filled in (emitters as last set).
 * [sim-thread] */
FG_API void fg_flame_sim_get_config(const fg_flame_sim *sim, fg_flame_sim_config *out);

/* Advances one step, 1 / step_rate_hz (in substeps where the flow is fast:
 * CFL <= 1), and writes the flame front's flux for the state reached to
 * *out (NULL: not wanted). The front uses the velocity of the step's end.
 * [sim-thread]: allocates only when a front has more triangles than any
 * before it.
 * Errors: FG_ERR_NULL sim; FG_ERR_NOT_FINITE the flow blew up or would need
 * more than FG_FLAME_MAX_SUBSTEPS substeps (the simulation is then
 * unusable and every later step answers the same); FG_ERR_NO_MEMORY the
 * front's triangles (the step is taken, *out unchanged). */
FG_API FG_NODISCARD fg_result fg_flame_sim_step(fg_flame_sim *sim, fg_flame_flux *out);

/* Replaces emitter `index` (0 .. config.emitters - 1) from the next step
 * on: move a torch, turn a jet, put a fire out (kind OFF). [sim-thread]
 * Errors: FG_ERR_NULL sim or emitter; FG_ERR_ARGUMENT index out of range,
 * an unknown kind or shape, a negative size or fuel rate, a jet with zero
 * velocity, a temperature below 0 K, a shape reaching outside the grid's
 * box; FG_ERR_NOT_FINITE a value. Nothing changes on error. */
FG_API FG_NODISCARD fg_result fg_flame_sim_set_emitter(fg_flame_sim *sim, int index,
                                                       const fg_flame_emitter *emitter);

/* [sim-thread] */
FG_API void fg_flame_sim_get_stats(const fg_flame_sim *sim, fg_flame_sim_stats *out);

/* A view of one cell field for a viewer (which copies it on this thread),
 * valid until the next fg_flame_sim_step or destroy. [sim-thread]
 * Errors: FG_ERR_NULL sim or out; FG_ERR_ARGUMENT an unknown field. */
FG_API FG_NODISCARD fg_result fg_flame_sim_field(const fg_flame_sim *sim, fg_flame_field field,
                                                 fg_flame_field_view *out);

/* The velocity at the last step's end, FG_VELOCITY_MAC over the grid of
 * fg_flame_sim_field (m/s; the pointers are the simulation's, valid until
 * the next fg_flame_sim_step or destroy). [sim-thread]
 * Errors: FG_ERR_NULL sim or out. */
FG_API FG_NODISCARD fg_result fg_flame_sim_velocity(const fg_flame_sim *sim,
                                                    fg_flame_velocity *out);

/* The last step's flame front: 9 doubles per triangle, as
 * fg_flame_front_triangles, valid until the next step or destroy.
 * [sim-thread]
 * Errors: FG_ERR_NULL an argument. */
FG_API FG_NODISCARD fg_result fg_flame_sim_triangles(const fg_flame_sim *sim,
                                                     const double **xyz_m, size_t *triangles);

#ifdef __cplusplus
}
#endif

#endif
