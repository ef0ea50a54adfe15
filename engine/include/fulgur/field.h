/* fulgur — the electric field that discharges grow in.
 *
 * A field is a vertex-centred grid of n[0] x n[1] x n[2] nodes over a box in
 * metres, holding the potential phi of Laplace's equation. Shapes (spheres,
 * boxes, half-spaces, points, the ground z <= 0) make their nodes Dirichlet;
 * every other node, the box faces included, is free with zero normal
 * derivative (Neumann) where it meets the box.
 *
 * Normalisation: each shape has a role. ORIGIN shapes (where the leader
 * starts) are held at phi = 0 and TARGET shapes (what it must reach) at
 * phi = 1. FIXED shapes are held at a value derived from their `potential`:
 *   - if every origin and target shape has potential 0 (the default), FIXED
 *     potentials are read directly in normalised units;
 *   - otherwise all origin shapes must share one voltage Vo and all target
 *     shapes another Vt != Vo, and a FIXED shape of voltage V is held at
 *     phi = (V - Vo) / (Vt - Vo).
 * Where shapes overlap, the later one in the array wins.
 *
 * The discretisation is the finite-volume 7-point Laplacian (each edge
 * weighted by its dual face area over its length), which is symmetric, so
 * the solver can fall back on conjugate gradient. Sizes of the form
 * 2^k + 1 (33, 65, 129, 257) give the multigrid its full hierarchy.
 */
#ifndef FULGUR_FIELD_H
#define FULGUR_FIELD_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/result.h"

#define FG_FIELD_MIN_SIZE 9
#define FG_FIELD_MAX_SIZE 257
#define FG_FIELD_DEFAULT_SIZE 65
#define FG_FIELD_MAX_SHAPES 64
/* The default refusal limit: a 257^3 grid needs about 0.6 GiB. */
#define FG_FIELD_DEFAULT_MAX_BYTES ((size_t)1 << 30)

typedef struct fg_field fg_field;

typedef struct fg_grid_config {
    int size[3];        /* nodes per axis, 9..257; 0 means 65 */
    double min_m[3];    /* box corner, metres */
    double max_m[3];    /* opposite corner; each max_m[a] > min_m[a] */
    size_t max_bytes;   /* refuse grids needing more memory; 0 means FG_FIELD_DEFAULT_MAX_BYTES */
} fg_grid_config;

/* The bytes a field of this configuration would allocate (potential,
 * labels, solver vectors, multigrid levels), with zero fields taken as their
 * defaults; 0 if a size is outside 9..257. [any-thread] */
FG_API size_t fg_field_memory_bytes(const fg_grid_config *config);

/* Creates a field with phi = 0 everywhere and no shapes. *out is owned by
 * the caller until fg_field_destroy. [sim-thread]
 * Errors: FG_ERR_NULL config or out; FG_ERR_NOT_FINITE a corner;
 * FG_ERR_ARGUMENT a size outside 9..257 or max_m <= min_m on an axis;
 * FG_ERR_CAPACITY the arrays would exceed max_bytes; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_field_create(const fg_grid_config *config, fg_field **out);

/* Frees the field; NULL is a no-op. [sim-thread] */
FG_API void fg_field_destroy(fg_field *field);

/* The configuration actually used (defaults filled in). NULL arguments are
 * programmer errors (an assert in debug builds). [sim-thread] */
FG_API void fg_field_get_config(const fg_field *field, fg_grid_config *out);

/* The node spacing on each axis, metres. [sim-thread] */
FG_API void fg_field_cell(const fg_field *field, double out_m[3]);

typedef enum fg_shape_kind {
    FG_SHAPE_SPHERE = 0, /* centre_m, radius_m: nodes with |x - centre| <= radius */
    FG_SHAPE_BOX,        /* box_min_m, box_max_m: nodes inside the axis-aligned box */
    FG_SHAPE_PLANE,      /* centre_m a point on the plane, normal: the half-space
                            dot(x - centre, normal) <= 0 (normal points out of it) */
    FG_SHAPE_POINT,      /* centre_m: the one node nearest to it */
    FG_SHAPE_GROUND      /* the half-space z <= 0 (a plane with normal +z) */
} fg_shape_kind;

typedef enum fg_shape_role {
    FG_ROLE_FIXED = 0,   /* held at its normalised potential (see above) */
    FG_ROLE_ORIGIN,      /* phi = 0: where the leader starts */
    FG_ROLE_TARGET       /* phi = 1: where the leader ends */
} fg_shape_role;

typedef struct fg_shape {
    fg_shape_kind kind;
    fg_shape_role role;
    double potential;    /* volts or normalised units; see the normalisation above */
    double centre_m[3];
    double radius_m;     /* sphere, > 0 */
    double box_min_m[3], box_max_m[3];
    double normal[3];    /* plane; need not be unit length, must not be zero */
    int outside;         /* sphere or box: nonzero makes the outside the Dirichlet
                            region (e.g. the glass of a plasma ball) */
} fg_shape;

/* Replaces the field's shapes with shapes[0..count) (copied; count at most
 * FG_FIELD_MAX_SHAPES): at least one ORIGIN and one TARGET. Dirichlet nodes get their normalised value; free
 * nodes keep their phi, so the next solve starts warm. A sphere smaller than
 * the cell covers the node nearest its centre. On error, *bad_shape (if not
 * NULL) is the index of the offending shape (count if the set as a whole is
 * wrong) and the field is unchanged. [sim-thread]
 * Errors: FG_ERR_NULL field, or shapes with count > 0; FG_ERR_NOT_FINITE a
 * coordinate or potential; FG_ERR_ARGUMENT too many shapes, an unknown kind or role, a
 * radius <= 0, a box with max < min, a zero plane normal, a shape that
 * covers no node of the grid (e.g. lies outside it), no origin or no
 * target, origin (or target) voltages that disagree, or Vo == Vt. */
FG_API FG_NODISCARD fg_result fg_field_set_shapes(fg_field *field, const fg_shape *shapes,
                                                  size_t count, size_t *bad_shape);

typedef enum fg_solver {
    FG_SOLVER_MULTIGRID = 0, /* multigrid V-cycles while each divides the residual by
                                3 or more, then multigrid-preconditioned conjugate
                                gradient (MGPCG) */
    FG_SOLVER_SOR            /* red-black successive over-relaxation (the oracle) */
} fg_solver;

typedef struct fg_solve_config {
    fg_solver solver;
    double tolerance;     /* relative residual to reach; 0 means 1e-5 */
    int max_iterations;   /* 0 means 200 (multigrid) or 100000 sweeps (SOR) */
    double sor_omega;     /* SOR only, in (0, 2); 0 means 2 / (1 + sin(pi / (n - 1))) */
    int cold;             /* nonzero: start from phi = 0 on free nodes, not the last solution */
} fg_solve_config;

typedef struct fg_solve_report {
    int iterations;       /* V-cycles and CG iterations (each runs one cycle), or SOR sweeps */
    double residual;      /* final ||b - A phi|| / ||b|| over the free nodes */
    double initial_residual;
    int cg_iterations;    /* of iterations, those of conjugate gradient (0: the cycles
                             alone converged) */
} fg_solve_report;

/* Solves Laplace's equation for phi on the free nodes, starting from the
 * current phi unless config->cold. config may be NULL for the defaults; the
 * report may be NULL. The residual is relative to that of phi = 0 on the
 * free nodes, so warm and cold solves reach the same accuracy. [sim-thread]
 * Errors: FG_ERR_NULL field; FG_ERR_ARGUMENT no shapes set yet, an unknown
 * solver, a tolerance not in [0, 1), negative iterations, omega not in
 * [0, 2); FG_ERR_NOT_CONVERGED max_iterations ran out (phi holds the last
 * iterate, the report says how far it got). */
FG_API FG_NODISCARD fg_result fg_field_solve(fg_field *field, const fg_solve_config *config,
                                             fg_solve_report *report);

/* phi at n points (xyz triples, metres) by trilinear interpolation, into
 * out[0..n). Points outside the box take the value at the nearest point of
 * the box. [sim-thread]
 * Errors: FG_ERR_NULL field, points or out (n > 0); FG_ERR_NOT_FINITE a
 * coordinate (out is then unchanged). */
FG_API FG_NODISCARD fg_result fg_field_sample(const fg_field *field, const double *points_m,
                                              size_t n, double *out);

/* What occupies a point of space. */
typedef enum fg_region {
    FG_REGION_FREE = 0,
    FG_REGION_ORIGIN,
    FG_REGION_TARGET,
    FG_REGION_FIXED,
    FG_REGION_OUTSIDE    /* outside the grid's box, in no shape */
} fg_region;

/* The region at n points into out[0..n): the shapes tested geometrically
 * (later shapes win), also beyond the box (a target plane on the box's
 * face extends past it); else, inside the box, the label of the nearest
 * node (point shapes, spheres smaller than a cell); else OUTSIDE.
 * [sim-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE a coordinate (out unchanged). */
FG_API FG_NODISCARD fg_result fg_field_classify(const fg_field *field, const double *points_m,
                                                size_t n, uint8_t *out);

/* The free nodes next to the origin (face neighbours of an ORIGIN node),
 * where a leader may start: writes up to max positions (xyz triples; points
 * may be NULL) and returns how many there are in all. The list is cached
 * until the shapes change. [sim-thread]
 * Returns 0 when field is NULL or the cache cannot be allocated. */
FG_API size_t fg_field_origin_sites(fg_field *field, double *points_m, size_t max);

/* The number of nodes, n[0] * n[1] * n[2]: the length of the arrays below.
 * Node (i, j, k) is at index i + n[0] * (j + n[1] * k) and at position
 * min_m + (i, j, k) * cell. [sim-thread] */
FG_API size_t fg_field_node_count(const fg_field *field);

/* Copies every node's fg_region label into labels[0..node_count): FREE for
 * the unknowns, ORIGIN, TARGET or FIXED for Dirichlet nodes. This is the
 * boundary description another solver (gpu/) works from. [sim-thread]
 * Errors: FG_ERR_NULL field or labels. */
FG_API FG_NODISCARD fg_result fg_field_get_labels(const fg_field *field, uint8_t *labels);

/* Copies phi at every node into phi[0..node_count): Dirichlet nodes hold
 * their normalised values, free nodes the last solution. [sim-thread]
 * Errors: FG_ERR_NULL field or phi. */
FG_API FG_NODISCARD fg_result fg_field_get_potential(const fg_field *field, double *phi);

/* Sets phi on the free nodes from phi[0..node_count); Dirichlet nodes keep
 * their values. For a field solved elsewhere (gpu/), or a warm start from
 * one. [sim-thread]
 * Errors: FG_ERR_NULL field or phi; FG_ERR_NOT_FINITE a free node's value
 * (the field is then unchanged). */
FG_API FG_NODISCARD fg_result fg_field_set_potential(fg_field *field, const double *phi);

/* What a growth model reads: phi and regions at arbitrary points, and where
 * it may start. A CPU fg_field provides one (fg_field_source_init); a GPU
 * solver can provide the same. All calls come from the one sim thread. */
typedef struct fg_field_source {
    void *context;
    /* As fg_field_sample. */
    fg_result (*sample)(void *context, const double *points_m, size_t n, double *out);
    /* As fg_field_classify, fg_region values. */
    fg_result (*classify)(void *context, const double *points_m, size_t n, uint8_t *out);
    /* As fg_field_origin_sites. */
    size_t (*origin_sites)(void *context, double *points_m, size_t max);
    double cell_m;       /* the smallest node spacing, metres */
} fg_field_source;

/* Fills *out with a source reading field, valid while the field lives and
 * is not being solved or reshaped. [sim-thread] */
FG_API void fg_field_source_init(fg_field *field, fg_field_source *out);

#endif
