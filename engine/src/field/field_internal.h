/* The field's storage and the solver kernels shared by its files.
 *
 * Index of node (i, j, k) on a level: i + n[0] * (j + n[1] * k). Level 0 is
 * the grid itself; level l + 1 takes every second node of level l. */
#ifndef FULGUR_FIELD_INTERNAL_H
#define FULGUR_FIELD_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/field.h"

#define FG_FIELD_MAX_LEVELS 8

typedef struct fg_level {
    int n[3];
    size_t count;
    double c[3];       /* edge weight along each axis in the interior: area / length */
    uint8_t *mask;     /* nonzero: Dirichlet (on level 0, the field's labels) */
    double *e;         /* correction (level 0: the CG vector z) */
    double *rhs;       /* right-hand side (level 0: the CG residual r) */
    double *tmp;       /* residual scratch (level 0: the CG vector q) */
} fg_level;

struct fg_field {
    fg_grid_config config;
    double h[3];
    double *phi;
    uint8_t *label;    /* fg_region per node; FREE means unknown */
    double *r, *z, *p, *q;
    fg_level level[FG_FIELD_MAX_LEVELS];
    int levels;
    int masks_dirty;   /* coarse masks must be rebuilt from the labels */
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

/* laplace.c — out = rhs - A x on free nodes (rhs NULL: zero), 0 on masked. */
void fg_lap_residual(const fg_level *L, const double *x, const double *rhs, double *out);
/* One over-relaxed Gauss-Seidel half-sweep over the nodes of one colour
 * ((i + j + k) % 2 == color) for A x = rhs (rhs NULL: zero). omega = 1 is
 * plain Gauss-Seidel. */
void fg_lap_sweep(const fg_level *L, double *x, const double *rhs, int color, double omega);
/* Gauss-Seidel sweeps restricted to the box of nodes within radius of
 * (i, j, k) on level 0 (DBM's local relaxation). */
void fg_lap_relax_box(const fg_level *L, double *x, int i, int j, int k, int radius, int sweeps);
double fg_dot(const double *a, const double *b, size_t n);

/* multigrid.c — the levels below level 0 (sizes, weights, storage). */
fg_result fg_multigrid_init(fg_field *f);
void fg_multigrid_deinit(fg_field *f);
size_t fg_multigrid_bytes(const int n[3]);
void fg_multigrid_update_masks(fg_field *f);
/* z = M r: one symmetric V(2,2) cycle for A z = r from z = 0. */
void fg_multigrid_precondition(fg_field *f);

/* boundary.c — the region a shape or the labels give a point. */
int fg_shape_contains(const fg_shape *s, const double x[3]);

/* field_solve: ||b|| for the relative residual, recomputed when stale. */
double fg_field_b_norm(fg_field *f);

/* Marks the field's Dirichlet set changed (DBM adds and removes nodes). */
void fg_field_labels_changed(fg_field *f);

/* The nearest node to a point (clamped into the grid). */
void fg_field_nearest(const fg_field *f, const double x[3], int ijk[3]);

#endif
