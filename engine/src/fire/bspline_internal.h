/* The burn field's reconstruction (eqs. 7-8): B~(x) = sum_ijk
 * phi(u - i) phi(v - j) phi(w - k) B_ijk, with (u, v, w) the position in
 * units of cells from the centre of cell 0 and phi the cubic B-spline.
 * The samples are used as the spline's coefficients, as the paper does.
 *
 * B~ is evaluated on a lattice `subdivision` times finer than the grid,
 * reaching 2 cells past the outermost centres on every side (where B~ is
 * exactly 0, B being 0 outside the grid): lattice node m on an axis of n
 * cells is at u = -2 + m / subdivision, m = 0 .. (n + 3) subdivision. The
 * sum is separable: one pass along x into a (lattice x) * ny * nz array,
 * one along y into (lattice x) * (lattice y) * nz, then each lattice
 * z-slice on demand. [sim-thread]; never allocates (the caller gives the
 * storage). */
#ifndef FULGUR_FIRE_BSPLINE_INTERNAL_H
#define FULGUR_FIRE_BSPLINE_INTERNAL_H

#include <stddef.h>

/* eq. 8: phi(t) = (1/6)(-3 tau^3 + 3 tau^2 + 3 tau + 1) for |t| <= 1,
 * (1/6)(1 + tau)^3 for 1 <= |t| <= 2, 0 beyond; tau = 1 - |t|. */
double fg_bspline_phi(double t);

/* The 4 weights of one lattice node on one axis. */
typedef struct fg_bspline_tap {
    int first;      /* index of the first of 4 consecutive cells (clamped) */
    double w[4];    /* weights; 0 for cells outside the grid */
} fg_bspline_tap;

/* Lattice nodes on an axis of n cells. */
static inline int fg_bspline_lattice_nodes(int n, int subdivision)
{
    return (n + 3) * subdivision + 1;
}

/* taps[0 .. lattice nodes) for an axis of n cells. */
void fg_bspline_taps(int n, int subdivision, fg_bspline_tap *taps);

typedef struct fg_bspline_volume {
    int n[3];                /* cells */
    int lattice[3];          /* lattice nodes per axis */
    const fg_bspline_tap *taps[3];
    double *along_x;         /* lattice[0] * n[1] * n[2] */
    double *along_xy;        /* lattice[0] * lattice[1] * n[2] */
} fg_bspline_volume;

/* The x and y passes over B (n[0] * n[1] * n[2], x fastest). */
void fg_bspline_prepare(fg_bspline_volume *v, const double *burn);

/* slice[0 .. lattice[0] * lattice[1]) = B~ on lattice z-slice mz. */
void fg_bspline_slice(const fg_bspline_volume *v, int mz, double *slice);

#endif
