/* fulgur — leader growth in the field of point charges (Sosorbaram; Abe et
 * al. §4.1).
 *
 * The potential is that of the given point charges in free space,
 *   Phi(x) = sum_i q_i / (4 pi eps0 |x - x_i|),
 * evaluated exactly where needed (Abe samples it on a grid; no grid is
 * needed for point charges). Growth, one round at a time:
 *   1. Around every active tip i, M candidate points at distance d in
 *      uniformly random directions.
 *   2. Each candidate k gets the field strength E_k = |Phi_k - Phi_i| / d and
 *      the probability P_k = E_k / sum_j E_j (Abe eq. 2).
 *   3. Up to N candidates are drawn one after another with these
 *      probabilities (without replacement); a candidate within R of one
 *      already chosen is skipped. The first drawn continues the tip, the
 *      others start branches.
 *   4. Stop when a tip reaches the target: the ground (z <= 0) or, when
 *      target_radius_m > 0, the sphere around target_m (an intracloud
 *      discharge; candidates below the ground then get E = 0).
 * Choices of ours, where Abe's text leaves room:
 *   - Abe takes "the N most probable" candidates; with our random candidate
 *     directions we draw them instead, so that P_k is the probability of
 *     being chosen first, as eq. 2 says.
 *   - A candidate that goes back up the potential (toward the origin's side:
 *     sign(Phi_k - Phi_i) opposite to sign(Phi_target - Phi_root)) gets
 *     E_k = 0; with |.| alone a uniform field would send the leader back as
 *     often as forward. A tip whose M candidates all go back draws a new
 *     set, up to 16 times, before it stops.
 *   - Every chosen candidate becomes a tip, so tips would multiply as N^rounds;
 *     at most max_tips stay active, those of strongest E; the others stop
 *     (the dead ends of the real stepped leader).
 * The root is start_m. The nodes on the path from the root to the node that
 * reached the target carry FG_NODE_MAIN.
 */
#ifndef FULGUR_CHARGES_H
#define FULGUR_CHARGES_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/result.h"
#include "fulgur/tree.h"

/* Vacuum permittivity, F/m. */
#define FG_EPSILON0 8.8541878128e-12

typedef struct fg_point_charge {
    double position_m[3];
    double charge_c;  /* coulombs; cloud regions hold some tens of C */
} fg_point_charge;

/* Zero in any field means the default given in its comment. */
typedef struct fg_charges_config {
    const fg_point_charge *charges; /* borrowed for the call; at least one */
    size_t charge_count;
    double start_m[3];       /* the leader's origin (root); z > 0 for a ground target */
    double step_m;           /* d, candidate distance: 3 m (twice the lightning preset's l) */
    uint32_t candidates;     /* M: 8; at most 4096 */
    uint32_t chosen;         /* N: 2; must be <= M */
    double exclusion_m;      /* R: 0.75 d; must be < 2 d */
    uint32_t max_tips;       /* tips kept active per round: 4; at most 4096 */
    double target_m[3];      /* centre of the target sphere (used when its radius > 0) */
    double target_radius_m;  /* 0: the target is the ground z <= 0 */
    uint32_t max_nodes;      /* give up after this many nodes: 200000 */
    uint64_t seed;           /* same seed, same tree */
} fg_charges_config;

/* The potential of the charges at p, volts. Reads only. [any-thread]
 * A point on a charge is taken 1 nm from it (finite, very large). */
FG_API double fg_charges_potential(const fg_point_charge *charges, size_t count,
                                   const double p[3]);

/* Copies *in to *out with every zero field replaced by its default.
 * [any-thread]
 * Errors: FG_ERR_NULL in or out, or charges NULL with charge_count > 0;
 * FG_ERR_NOT_FINITE a NaN/inf position, charge, step or radius;
 * FG_ERR_ARGUMENT no charges, a negative step or radius, candidates or
 * max_tips > 4096, chosen > candidates, exclusion >= 2 step, a start on or
 * below the ground (z <= 0) with a ground target, or a start already inside
 * the target sphere. *out is written only on success. */
FG_API FG_NODISCARD fg_result fg_charges_config_resolve(const fg_charges_config *in,
                                                        fg_charges_config *out);

/* Grows a leader from start_m until it reaches the target and appends it to
 * out, which must be empty; the root is node 0. out stays owned by the
 * caller. Deterministic for a given seed. [sim-thread]
 * Errors: those of fg_charges_config_resolve; FG_ERR_NULL out;
 * FG_ERR_ARGUMENT out is not empty; FG_ERR_UNREACHABLE no tip can go
 * forward, or max_nodes were used without reaching the target;
 * FG_ERR_NO_MEMORY. On any error out is left empty. */
FG_API FG_NODISCARD fg_result fg_charges_grow(const fg_charges_config *config, fg_tree *out);

#endif
