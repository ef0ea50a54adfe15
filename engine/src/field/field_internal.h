/* The field's storage and the solver kernels shared by its files.
 *
 * Index of node (i, j, k) on a level: i + n[0] * (j + n[1] * k). Level 0 is
 * the grid itself; level l + 1 takes every second node of level l.
 *
 * Precision: phi is double, and so is the residual b - A phi that decides
 * convergence (laplace.c). The multigrid cycle and the conjugate-gradient
 * fallback work on corrections in single precision (fine_kernels.c,
 * coarse_kernels.c, transfer.c): each outer step adds a float correction
 * to the double phi and recomputes the double residual, so the solve
 * reaches double accuracy while the heavy sweeps move half the bytes. */
#ifndef FULGUR_FIELD_INTERNAL_H
#define FULGUR_FIELD_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/field.h"

#define FG_FIELD_MAX_LEVELS 8

typedef struct fg_level {
    int n[3];
    size_t count;
    int split;        /* the float vectors are in split rows (level 0) */
    double c[3];      /* edge weight along each axis in the interior: area / length */
    uint8_t *mask;    /* nonzero: Dirichlet (level 0: the field's labels) */
    float *e;         /* correction (level 0: split rows; levels >= 1: padded by a
                         plane each side) */
    float *rhs;       /* right-hand side */
    float *tmp;       /* residual, restricted to the next level */
    /* Level 0: inv_diag (split rows) is 1 / diag on free nodes, 0 on
     * Dirichlet ones. Levels >= 1: the assembled operator (coarse_operator.c). w[a][i] is the
     * weight of the edge from node i to its +a neighbour, 0 where there is
     * none (box face, Dirichlet end, or a Dirichlet node between); diag is
     * the row sum with cut edges counted as c / theta (Shortley-Weller),
     * 0 on Dirichlet nodes, and inv_diag its inverse (0 there too). The
     * w arrays are padded like e, so that a kernel reads i - 1, i - n[0]
     * and i - n[0] n[1] anywhere on the level. */
    float *w[3];
    float *diag;
    float *inv_diag;
    float *block;     /* levels >= 1: the one allocation behind the arrays */
} fg_level;

struct fg_field {
    fg_grid_config config;
    const struct fg_field_kernels *kernels; /* fg_field_kernels_pick's */
    double h[3];
    double *phi;
    uint8_t *label;    /* fg_region per node; FREE means unknown */
    /* Level-0 float vectors (split rows): the fallback CG's correction x,
     * its residual r (the cycle's right-hand side), z = M r, the direction
     * p and q = -A p (also the cycle's residual scratch). */
    float *x, *r, *z, *p, *q;
    fg_level level[FG_FIELD_MAX_LEVELS];
    int levels;
    int operators_dirty; /* coarse masks and operators must be rebuilt from the labels */
    double b_norm;     /* ||residual|| with phi = 0 on free nodes; < 0 when stale */
    fg_shape shapes[FG_FIELD_MAX_SHAPES];
    size_t shape_count;
    double *sites;     /* origin sites (xyz), valid while sites_valid */
    size_t site_count;
    int sites_valid;
};

static inline size_t fg_level_index(const fg_level *L, int i, int j, int k)
{
    return (size_t)i + (size_t)L->n[0] * ((size_t)j + (size_t)L->n[1] * (size_t)k);
}

/* Level 0's float vectors keep each row as its even nodes, then its odd
 * ones (split rows): one colour of a row is then one contiguous run, and so
 * are its x-neighbours. Node i of a row of n is at fg_split(n, i) in it. */
static inline size_t fg_split(int n, int i)
{
    return (size_t)(i & 1 ? (n + 1) / 2 + i / 2 : i / 2);
}

/* Nodes before (and after) a padded array's first (last) node. */
static inline size_t fg_level_pad(const fg_level *L)
{
    return (size_t)L->n[0] * (size_t)L->n[1] + 1;
}

/* The rows next to row (j, k) of a level. A node on a box face, its
 * finite-volume row multiplied by 2 per face it lies on, has the interior
 * stencil with the missing neighbour replaced by its mirror image (the
 * Neumann face as a ghost node). So the level-0 kernels run the interior
 * stencil everywhere, reading mirrored rows on the faces, and multiply by
 * scale (and 1/2 more at i = 0 or n[0] - 1) where the finite-volume row is
 * meant. */
typedef struct fg_row {
    size_t at;                        /* index of node (0, j, k) */
    ptrdiff_t south, north, down, up; /* offsets to rows j - 1, j + 1, k - 1, k + 1 */
    double scale;                     /* 1/2 per face the row lies on */
} fg_row;

static inline fg_row fg_level_row(const fg_level *L, int j, int k)
{
    ptrdiff_t sy = L->n[0], sz = sy * L->n[1];
    int jf = j == 0 || j == L->n[1] - 1, kf = k == 0 || k == L->n[2] - 1;
    fg_row r = {fg_level_index(L, 0, j, k), j > 0 ? -sy : sy, j < L->n[1] - 1 ? sy : -sy,
                k > 0 ? -sz : sz, k < L->n[2] - 1 ? sz : -sz, (jf ? 0.5 : 1.0) * (kf ? 0.5 : 1.0)};
    return r;
}

/* laplace.c — level 0 in double, on phi, Dirichlet nodes holding their
 * values. Writes the residual -A phi of the free nodes (0 on Dirichlet
 * nodes) into out as floats (split rows) when out is not NULL, and returns
 * its squared norm. zero_free: read phi as 0 on free nodes (the residual is
 * then b). */
double fg_lap_residual(const fg_level *L, const double *phi, int zero_free, float *out);
/* phi += e (a correction in split rows, 0 on Dirichlet nodes), then
 * fg_lap_residual(L, phi, 0, out), in one pass over phi. */
double fg_lap_correct_residual(const fg_level *L, double *phi, const float *e, float *out);
/* One over-relaxed Gauss-Seidel half-sweep over the nodes of one colour
 * ((i + j + k) % 2 == color) for A phi = 0. omega = 1 is plain
 * Gauss-Seidel. */
void fg_lap_sweep(const fg_level *L, double *phi, int color, double omega);
/* Gauss-Seidel sweeps restricted to the box of nodes within radius of
 * (i, j, k) on level 0 (DBM's local relaxation). */
void fg_lap_relax_box(const fg_level *L, double *phi, int i, int j, int k, int radius,
                      int sweeps);

/* fine_kernels.c — level 0 in float, for a correction (0 on Dirichlet
 * nodes). */
/* count Gauss-Seidel half-sweeps over the nodes of one colour, color
 * first and then alternating (rhs not NULL), in one pass over the planes.
 * from_zero (with color 0): the first starts from e = 0 (black nodes 0). */
void fg_fine_smooth(const fg_level *L, float *e, const float *rhs, int color, int count,
                    int from_zero);
/* out = rhs - A x on free nodes (rhs NULL: zero), 0 on Dirichlet nodes. */
void fg_fine_residual(const fg_level *L, const float *x, const float *rhs, float *out);

/* coarse_operator.c — level 0's inv_diag, and every level's mask
 * (injection) and operator below, from the labels. */
void fg_multigrid_assemble(fg_field *f);

/* coarse_kernels.c — a level >= 1, its e for its rhs. */
void fg_coarse_sweep_from_zero(const fg_level *L);
void fg_coarse_sweep(const fg_level *L, int color);
/* L->tmp = L->rhs - A L->e. */
void fg_coarse_residual(const fg_level *L);

/* transfer.c — between level F and the next coarser level C. */
/* C->rhs = P^T r (full weighting), 0 on C's Dirichlet nodes. */
void fg_restrict(const fg_level *F, const float *r, fg_level *C);
/* e += P C->e (trilinear) on F's free nodes. */
void fg_prolong_add(const fg_level *C, const fg_level *F, float *e);

/* The vector kernels above (laplace.c's residuals, fine_kernels.c,
 * coarse_kernels.c, transfer.c) as the solver calls them: the portable
 * build's, or where the CPU has AVX2 the same files built again for it,
 * eight floats at a time (kernels_avx2.h). Both give the same floats:
 * the arithmetic is lane by lane in the same order, with no FMA. */
typedef struct fg_field_kernels {
    double (*lap_residual)(const fg_level *L, const double *phi, int zero_free, float *out);
    double (*lap_correct_residual)(const fg_level *L, double *phi, const float *e, float *out);
    void (*fine_smooth)(const fg_level *L, float *e, const float *rhs, int color, int count,
                        int from_zero);
    void (*fine_residual)(const fg_level *L, const float *x, const float *rhs, float *out);
    void (*coarse_sweep_from_zero)(const fg_level *L);
    void (*coarse_sweep)(const fg_level *L, int color);
    void (*coarse_residual)(const fg_level *L);
    void (*restrict_down)(const fg_level *F, const float *r, fg_level *C);
    void (*prolong_add)(const fg_level *C, const fg_level *F, float *e);
} fg_field_kernels;

extern const fg_field_kernels fg_field_kernels_portable;
#ifdef FG_FIELD_AVX2
extern const fg_field_kernels fg_field_kernels_avx2;
#endif

/* multigrid.c — the kernels for the CPU this runs on. */
const fg_field_kernels *fg_field_kernels_pick(void);

/* multigrid.c — the levels below level 0 (sizes, weights, storage), and the
 * cycle. */
fg_result fg_multigrid_init(fg_field *f);
void fg_multigrid_deinit(fg_field *f);
size_t fg_multigrid_bytes(const int n[3]);
/* e = M rhs on level 0: one symmetric V(2,2) cycle for A e = rhs from
 * e = 0. Uses q as scratch; rhs and e are not q. */
void fg_multigrid_cycle(fg_field *f, float *rhs, float *e);

/* boundary.c — the region a shape or the labels give a point. */
int fg_shape_contains(const fg_shape *s, const double x[3]);

/* field_solve.c — ||b|| for the relative residual, recomputed when stale. */
double fg_field_b_norm(fg_field *f);
/* ||b - A phi|| / ||b||, leaving the residual in f->r. */
double fg_field_residual(fg_field *f);
/* One step of the stationary iteration from the residual in f->r:
 * phi += M r, and the new residual (returned as fg_field_residual). */
double fg_field_vcycle(fg_field *f);

/* Marks the field's Dirichlet set changed (DBM adds and removes nodes). */
void fg_field_labels_changed(fg_field *f);

/* The nearest node to a point (clamped into the grid). */
void fg_field_nearest(const fg_field *f, const double x[3], int ijk[3]);

#endif
