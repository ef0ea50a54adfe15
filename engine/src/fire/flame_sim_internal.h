/* The flame simulation's emitters (flame_emitter.c), shared with its step
 * (flame_sim.c). */
#ifndef FULGUR_FLAME_SIM_INTERNAL_H
#define FULGUR_FLAME_SIM_INTERNAL_H

#include "fulgur/flame.h"
#include "fluid/fluid_internal.h"

/* The advected cell fields of the simulation's fluid. */
enum { FG_FLAME_FUEL = 0, FG_FLAME_TEMPERATURE = 1, FG_FLAME_SCALARS = 2 };

/* The default temperature of a released gas (lit: above the default
 * ignition temperature). */
#define FG_FLAME_EMITTER_DEFAULT_K 1200.0

/* Checks an emitter against the box [lo, hi] of a grid of cell h, and
 * writes it with its defaults filled in to *out (only when valid).
 * Errors: as fg_flame_sim_set_emitter. */
fg_result fg_flame_emitter_prepare(const fg_flame_emitter *e, const double lo_m[3],
                                   const double hi_m[3], double cell_m, fg_flame_emitter *out);

/* Releases dt's fuel into the fuel field of f over the cells the emitter
 * covers (in proportion to their coverage), heats them to at least its
 * temperature and, for a jet, blends its velocity into the faces it
 * covers. Returns the volume of mixture released (m^3). */
double fg_flame_emitter_release(const fg_flame_emitter *e, fg_fluid *f, double dt_s);

#endif
