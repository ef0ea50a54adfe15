/* fulgur — growing a discharge tree in a field.
 *
 * Matsuyama (eq. 2): from a tip, n candidates one step away inside the cone
 * of total angle rho around the tip's propagation direction (ours: the
 * bisector of the tip's last step and the field direction grad phi, so a
 * leader neither turns back on itself nor wanders off the field); candidate i is taken with
 * probability phi_i^gamma / sum_j phi_j^gamma (phi by trilinear
 * interpolation, negative phi counted as 0). Candidates inside an ORIGIN or
 * FIXED region, outside the box, or whose midpoint is, are never taken, so
 * no node lies in an obstacle. A candidate in the TARGET region connects the
 * leader: its node is put on the target's surface (to within step / 256).
 *
 * The root is a free grid node next to the origin, drawn with probability
 * phi^gamma (DBM: phi^eta) among all such nodes; its first direction is the
 * gradient of phi.
 *
 * Branching rule (ours; the paper does not give one). The leader keeps a set
 * of active tips, each stepped once per round, in order. After a tip steps,
 * with probability branch_probability (and while fewer than max_tips are
 * active) a second candidate, drawn by eq. 2 from the others, starts a new
 * tip at the same parent. A branch tip dies once it has grown
 * branch_length_m; the first tip (the leader) never does. A tip whose
 * candidates are all blocked retries with the cone widened by rho/2 per
 * try, and dies after five tries; when the leader dies, the next tip in
 * order becomes the leader. Growth ends when a
 * tip reaches the target (or, with all_tips_connect, when every tip has
 * reached the target or died). The path root -> the first node that reached
 * the target carries FG_NODE_MAIN.
 *
 * DBM (Niemeyer, Pietronero & Wiesmann 1984): the channel is a set of grid
 * nodes held at phi = 0; every step adds one free node that touches the
 * channel (26-neighbourhood), with probability phi^eta / sum phi^eta over
 * all of them, and updates the field: Gauss-Seidel sweeps in a box around
 * the new node every step, two warm multigrid iterations (fg_field_solve)
 * every dbm_global_every steps, and a full solve (to 1e-5) whenever a cycle ends
 * with a larger residual than the cycle before it. The lattice path is then resampled so that segments are
 * about step_m long (branch points and ends kept).
 */
#ifndef FULGUR_GROWTH_H
#define FULGUR_GROWTH_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/field.h"
#include "fulgur/result.h"
#include "fulgur/tree.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FG_GROWTH_MAX_CANDIDATES 64
/* The relative residual (fg_solve_config.tolerance) a field needs for
 * Matsuyama growth: five V-cycles from a cold start at 65^3 instead of the
 * solver's default 1e-5 and six. phi then differs from the converged field
 * by at most 3e-3 of itself at the candidates the presets' trees sample
 * (6e-4 at 1e-5; 200 seeds each), so a candidate's probability
 * phi_i^gamma / sum_j phi_j^gamma moves by at most a factor (1 +- 3e-3)^(2
 * gamma), 1.5 % at gamma 2.5: the trees differ, their statistics over seeds
 * do not (test_growth's tolerance_keeps_statistics). */
#define FG_GROWTH_FIELD_TOLERANCE 5e-5

typedef struct fg_growth_config {
    double step_m;             /* segment length, metres; required (> 0), no default */
    uint64_t seed;             /* the same seed and field give the same tree */
    double gamma;              /* Matsuyama exponent; 0 means 2.5 */
    int candidates;            /* Matsuyama n, 1..64; 0 means 8 */
    double cone_rad;           /* total cone angle rho, (0, pi]; 0 means pi/2 */
    double branch_probability; /* per tip and step, [0, 1]; 0 means 0.1 */
    int max_tips;              /* active tips at most; 0 means 16; 1 disables branching */
    double branch_length_m;    /* a branch dies after growing this much; 0 means 6 steps */
    int all_tips_connect;      /* nonzero: go on until every tip has connected or died */
    int max_steps;             /* steps of all tips together before giving up; 0 means 4096 */
    double eta;                /* DBM exponent; 0 means 2 */
    int dbm_global_every;      /* DBM steps between global cycles; 0 means 8 */
    int dbm_relax_radius;      /* DBM local relaxation box half-width, nodes; 0 means 3 */
} fg_growth_config;

typedef struct fg_growth_report {
    size_t nodes;              /* nodes in the tree */
    size_t main_nodes;         /* nodes carrying FG_NODE_MAIN */
    int steps;                 /* growth steps taken (DBM: lattice nodes added) */
    int solves;                /* DBM: global cycles and full solves run */
    int solver_iterations;     /* DBM: CG iterations over all of them */
} fg_growth_report;

/* Copies *in to *out with every zero field replaced by its default (the
 * values fg_grow_matsuyama and fg_grow_dbm use). *out is written only on
 * success. [any-thread]
 * Errors: FG_ERR_NULL in or out; FG_ERR_NOT_FINITE a parameter;
 * FG_ERR_ARGUMENT step_m <= 0 or another parameter out of its range. */
FG_API FG_NODISCARD fg_result fg_growth_config_resolve(const fg_growth_config *in,
                                                       fg_growth_config *out);

/* Grows a Matsuyama leader in the field that source reads (not modified)
 * and writes it into out, which is cleared first. report may be NULL.
 * [sim-thread]
 * Errors: FG_ERR_NULL source, one of its functions, config or out;
 * FG_ERR_NOT_FINITE a parameter; FG_ERR_ARGUMENT step_m <= 0 or another
 * parameter out of its range, or the field has no free node next to the
 * origin; FG_ERR_UNREACHABLE max_steps ran out or every tip died before one
 * reached the target (e.g. an enclosed origin); FG_ERR_NO_MEMORY. On every
 * error but FG_ERR_NO_MEMORY, out is unchanged. */
FG_API FG_NODISCARD fg_result fg_grow_matsuyama(const fg_field_source *source,
                                                const fg_growth_config *config, fg_tree *out,
                                                fg_growth_report *report);

/* Grows a DBM channel in field (which must have been solved) and writes it
 * into out, which is cleared first. The channel's nodes are Dirichlet only
 * during the call: on return the field has its shapes' labels again and phi
 * holds the last field of the growth (solve again before sampling it).
 * report may be NULL. [sim-thread]
 * Errors: as fg_grow_matsuyama, with field for source. */
FG_API FG_NODISCARD fg_result fg_grow_dbm(fg_field *field, const fg_growth_config *config,
                                          fg_tree *out, fg_growth_report *report);

#ifdef __cplusplus
}
#endif

#endif
