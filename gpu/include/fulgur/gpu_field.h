/* fulgur gpu/ — Laplace's equation solved by compute shaders.
 *
 * A GPU field mirrors a CPU fg_field: the same grid, the same shapes and
 * labels (read from the CPU field with fg_field_get_labels and
 * fg_field_get_potential, so there is one definition of the boundary), the
 * same finite-volume 7-point operator with Neumann box faces. The potential
 * lives on the GPU as an R32F 3-D image, relaxed in place in red-black
 * order; warm-started multigrid V-cycles solve it, with multigrid-
 * preconditioned conjugate gradient as the safety net when the residual
 * grows. Only the values a growth model asks for come back (a gather
 * kernel), never the whole grid per step.
 *
 * Precision: the potential is single precision on the GPU. A relative
 * residual of 1e-5 (the default) leaves errors up to about 1e-4 at 65^3
 * (maximum absolute, normalised units); 1e-6 agrees with a tightly solved
 * CPU field to about 1e-5. Single precision reaches about 5e-7.
 *
 * The fallback: a V-cycle that does not halve the residual (a thin
 * Dirichlet tree the coarse levels cannot see, small electrodes) hands phi
 * to MGPCG, which continues from it with the same cycle as preconditioner.
 * See docs/gpu-field.md. */
#ifndef FULGUR_GPU_FIELD_H
#define FULGUR_GPU_FIELD_H

#include <stddef.h>

#include "fulgur/field.h"
#include "fulgur/gpu_context.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fgg_field fgg_field;

typedef struct fgg_solve_config {
    double tolerance;     /* relative residual to reach; 0 means 1e-5 */
    int max_cycles;       /* V-cycles (or CG iterations) at most; 0 means 100 */
    int cold;             /* nonzero: free nodes start from 0, not the last solution */
    int vcycles_only;     /* nonzero: no MGPCG fallback (to compare; may not converge) */
} fgg_solve_config;

typedef struct fgg_solve_report {
    int cycles;              /* V-cycles run */
    int cg_iterations;       /* MGPCG iterations after a fallback, else 0 */
    double residual;         /* final ||b - A phi|| / ||b|| on the free nodes */
    double initial_residual;
} fgg_solve_report;

/* Creates a GPU field with the grid, labels and potential of description
 * (which keeps belonging to the caller; it is only read here). [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_ARGUMENT description has no shapes yet;
 * FG_ERR_CAPACITY the GPU cannot hold the grid; FG_ERR_GPU a shader or GL
 * failure (see fgg_error_message); FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fgg_field_create(fgg_context *context, const fg_field *description,
                                               fgg_field **out);

/* Frees the field's GPU objects; NULL is a no-op. [gpu-thread] */
FG_API void fgg_field_destroy(fgg_field *field);

/* Takes description's labels and Dirichlet values again (after
 * fg_field_set_shapes on it); free nodes keep their GPU values, so the next
 * solve starts warm. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_ARGUMENT a grid of another size or box;
 * FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_field_update(fgg_field *field, const fg_field *description);

/* Solves for phi on the free nodes. config may be NULL (defaults), report
 * may be NULL. [gpu-thread]
 * Errors: FG_ERR_NULL field; FG_ERR_ARGUMENT tolerance not in [0, 1) or
 * negative cycles; FG_ERR_NOT_CONVERGED the cycles ran out (phi holds the
 * last iterate); FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_field_solve(fgg_field *field, const fgg_solve_config *config,
                                              fgg_solve_report *report);

/* phi at n points (xyz triples, metres), trilinear, as fg_field_sample
 * computes it from the same node values (in double precision, so equal node
 * values give equal samples to the bit). [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE a coordinate; FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_field_sample(fgg_field *field, const double *points_m, size_t n,
                                               double *out);

/* Reads the whole potential back into phi[0..fg_field_node_count) — for
 * tests, export and warm-starting a CPU field (fg_field_set_potential); not
 * for every growth step. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_field_read_potential(fgg_field *field, double *phi);

/* A field source for the growth models: phi from the GPU (the gather
 * kernel), regions and origin sites from description, which must describe
 * the same shapes. Valid while both live and are not being updated.
 * [gpu-thread] */
FG_API void fgg_field_source_init(fgg_field *field, fg_field *description, fg_field_source *out);

#ifdef __cplusplus
}
#endif

#endif
