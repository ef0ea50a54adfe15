/* The pressure solve: conjugate gradient preconditioned by one symmetric
 * V(2,2) cycle of a cell-centred multigrid.
 *
 * The operator is (A x)_c = sum over the cell's faces of c_f (x_c - x_nbr):
 * c_f = (fluid fraction of the face) * area / h, and beyond an open face of
 * the box a ghost cell with x = 0. A coarse cell is a 2x2(x2) block of fine
 * cells (the last one on an axis of odd size holds one); a coarse face's
 * conductance is half the sum of the fine faces it covers, which is the
 * operator rediscretised with averaged coefficients (for a uniform fine
 * grid, exactly the coarse Laplacian). Restriction sums the residuals of
 * the children, prolongation copies the parent's correction (its
 * transpose): against the Galerkin operator of that prolongation the
 * coarse matrix is half as stiff, so the coarse correction is doubled —
 * the over-correction that makes piecewise-constant cell-centred cycles
 * work. On a cylinder grid (320 x 192, random right-hand side) CG
 * converged 0.16 per iteration; bilinear prolongation with its transpose
 * as restriction gave 0.19, at twice the cost of the transfers.
 * Smoothing is red-black Gauss-Seidel, red first going down and
 * black first coming up, so the cycle is symmetric and CG may use it.
 *
 * Why not engine/src/multigrid.c: the field solver is vertex-centred (its
 * nodes are on the box faces, coarse levels take every second node, masks
 * are Dirichlet); the projection needs cell-centred unknowns with Neumann
 * walls and solids, variable face weights and a possibly singular matrix.
 * The ideas are the same — MGPCG with a symmetric V-cycle, warm starts,
 * denormals flushed — and so is the CG loop's shape (field_solve.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_state_internal.h"

#define COARSEST_SWEEPS 40
#define MIN_COARSE_AXIS 4

static size_t level_face_index(const fg_fluid_level *L, int a, int i, int j, int k)
{
    int m0 = L->n[0] + (a == 0), m1 = L->n[1] + (a == 1);
    return (size_t)i + (size_t)m0 * ((size_t)j + (size_t)m1 * (size_t)k);
}

static size_t level_faces(const fg_fluid_level *L, int a)
{
    return (size_t)(L->n[0] + (a == 0)) * (size_t)(L->n[1] + (a == 1)) *
           (size_t)(L->n[2] + (a == 2));
}

static fg_result level_alloc(fg_fluid_level *L, int dims, int own_x)
{
    L->count = (size_t)L->n[0] * (size_t)L->n[1] * (size_t)L->n[2];
    for (int a = 0; a < dims; a++)
        if (!(L->c[a] = calloc(level_faces(L, a), sizeof(double))))
            return FG_ERR_NO_MEMORY;
    L->diag = calloc(L->count, sizeof(double));
    L->inv_diag = calloc(L->count, sizeof(double));
    L->b = calloc(L->count, sizeof(double));
    L->r = calloc(L->count, sizeof(double));
    if (own_x)
        L->x = calloc(L->count, sizeof(double));
    return L->diag && L->inv_diag && L->b && L->r && L->x ? FG_OK : FG_ERR_NO_MEMORY;
}

fg_result fg_fluid_multigrid_init(fg_fluid *f)
{
    fg_fluid_level *L0 = &f->level[0];
    memcpy(L0->n, f->n, sizeof L0->n);
    L0->x = f->pcg_z;
    fg_result r = level_alloc(L0, f->dims, 0);
    f->levels = 1;
    while (r == FG_OK && f->levels < FG_FLUID_MAX_LEVELS) {
        const fg_fluid_level *F = &f->level[f->levels - 1];
        int ok = 1;
        for (int a = 0; a < f->dims; a++)
            ok &= (F->n[a] + 1) / 2 >= MIN_COARSE_AXIS;
        if (!ok)
            break;
        fg_fluid_level *C = &f->level[f->levels];
        for (int a = 0; a < 3; a++)
            C->n[a] = a < f->dims ? (F->n[a] + 1) / 2 : 1;
        f->levels++;
        r = level_alloc(C, f->dims, 1);
    }
    return r;
}

size_t fg_fluid_multigrid_bytes(int dims, const int n[3])
{
    fg_fluid_level L = {.n = {n[0], n[1], dims == 3 ? n[2] : 1}};
    size_t bytes = 0;
    for (int l = 0; l < FG_FLUID_MAX_LEVELS; l++) {
        L.count = (size_t)L.n[0] * (size_t)L.n[1] * (size_t)L.n[2];
        for (int a = 0; a < dims; a++)
            bytes += level_faces(&L, a) * sizeof(double);
        /* diag, inv_diag, b, r, and x on the coarse levels */
        bytes += (l > 0 ? 5u : 4u) * L.count * sizeof(double);
        int ok = 1;
        for (int a = 0; a < dims; a++)
            ok &= (L.n[a] + 1) / 2 >= MIN_COARSE_AXIS;
        if (!ok)
            break;
        for (int a = 0; a < dims; a++)
            L.n[a] = (L.n[a] + 1) / 2;
    }
    return bytes;
}

void fg_fluid_multigrid_deinit(fg_fluid *f)
{
    for (int l = 0; l < FG_FLUID_MAX_LEVELS; l++) {
        fg_fluid_level *L = &f->level[l];
        for (int a = 0; a < 3; a++)
            free(L->c[a]);
        free(L->diag);
        free(L->inv_diag);
        free(L->b);
        free(L->r);
        if (l > 0)
            free(L->x);
    }
    f->levels = 0;
}

static void level_diagonal(fg_fluid_level *L, int dims)
{
    for (int k = 0; k < L->n[2]; k++)
        for (int j = 0; j < L->n[1]; j++)
            for (int i = 0; i < L->n[0]; i++) {
                int ijk[3] = {i, j, k};
                double d = 0.0;
                for (int a = 0; a < dims; a++) {
                    int hi[3] = {i, j, k};
                    hi[a]++;
                    d += L->c[a][level_face_index(L, a, ijk[0], ijk[1], ijk[2])] +
                         L->c[a][level_face_index(L, a, hi[0], hi[1], hi[2])];
                }
                size_t id = (size_t)i + (size_t)L->n[0] * ((size_t)j + (size_t)L->n[1] * k);
                L->diag[id] = d;
                L->inv_diag[id] = d > 0.0 ? 1.0 / d : 0.0;
            }
}

static void coarsen(const fg_fluid_level *F, fg_fluid_level *C, int dims)
{
    for (int a = 0; a < dims; a++) {
        int m[3] = {C->n[0] + (a == 0), C->n[1] + (a == 1), C->n[2] + (a == 2)};
        for (int K = 0; K < m[2]; K++)
            for (int J = 0; J < m[1]; J++)
                for (int I = 0; I < m[0]; I++) {
                    int IJK[3] = {I, J, K}, lo[3], hi[3];
                    for (int b = 0; b < 3; b++) {
                        if (b == a) {
                            lo[b] = hi[b] = 2 * IJK[b] < F->n[b] ? 2 * IJK[b] : F->n[b];
                        } else if (b < dims) {
                            lo[b] = 2 * IJK[b];
                            hi[b] = 2 * IJK[b] + 1 < F->n[b] ? 2 * IJK[b] + 1 : F->n[b] - 1;
                        } else {
                            lo[b] = hi[b] = 0;
                        }
                    }
                    double s = 0.0;
                    for (int k = lo[2]; k <= hi[2]; k++)
                        for (int j = lo[1]; j <= hi[1]; j++)
                            for (int i = lo[0]; i <= hi[0]; i++)
                                s += F->c[a][level_face_index(F, a, i, j, k)];
                    C->c[a][level_face_index(C, a, I, J, K)] = 0.5 * s;
                }
    }
    level_diagonal(C, dims);
}

void fg_fluid_multigrid_build(fg_fluid *f)
{
    fg_fluid_level *L0 = &f->level[0];
    double scale = f->dims == 2 ? 1.0 : f->h; /* area / h */
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        size_t id = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, id++) {
                    int ijk[3] = {i, j, k};
                    double c = f->face_fraction[a][id] * scale;
                    if (ijk[a] == 0 && f->config.boundary[a][0] != FG_FLUID_OPEN)
                        c = 0.0;
                    if (ijk[a] == m[a] - 1 && f->config.boundary[a][1] != FG_FLUID_OPEN)
                        c = 0.0;
                    L0->c[a][id] = c;
                }
    }
    level_diagonal(L0, f->dims);
    for (int l = 1; l < f->levels; l++)
        coarsen(&f->level[l - 1], &f->level[l], f->dims);
}

/* Row bases of a cell row (j, k) in the cell and face arrays. */
typedef struct row_index {
    size_t cell, fx, fy;
} row_index;

static inline row_index row_at(const fg_fluid_level *L, int j, int k)
{
    size_t n0 = (size_t)L->n[0], n1 = (size_t)L->n[1];
    return (row_index){.cell = n0 * ((size_t)j + n1 * (size_t)k),
                       .fx = (n0 + 1) * ((size_t)j + n1 * (size_t)k),
                       .fy = n0 * ((size_t)j + (n1 + 1) * (size_t)k)};
}

/* sum over the faces of cell i of row r of c_f x_nbr, for any cell. */
static inline double neighbours_edge(const fg_fluid_level *L, int dims, const double *x,
                                     row_index r, int i, int j, int k)
{
    size_t sy = (size_t)L->n[0], sz = sy * (size_t)L->n[1], id = r.cell + (size_t)i;
    size_t fx = r.fx + (size_t)i, fy = r.fy + (size_t)i;
    double s = 0.0;
    if (i > 0)
        s += L->c[0][fx] * x[id - 1];
    if (i < L->n[0] - 1)
        s += L->c[0][fx + 1] * x[id + 1];
    if (j > 0)
        s += L->c[1][fy] * x[id - sy];
    if (j < L->n[1] - 1)
        s += L->c[1][fy + sy] * x[id + sy];
    if (dims == 3) {
        if (k > 0)
            s += L->c[2][id] * x[id - sz];
        if (k < L->n[2] - 1)
            s += L->c[2][id + sz] * x[id + sz];
    }
    return s;
}

/* The same for a cell with neighbours on every side; d is a constant. */
FG_FLUID_HOT double neighbours_inner(const fg_fluid_level *L, const double *x, size_t id,
                                     size_t fx, size_t fy, size_t sy, size_t sz, int d)
{
    double s = L->c[0][fx] * x[id - 1] + L->c[0][fx + 1] * x[id + 1] + L->c[1][fy] * x[id - sy] +
               L->c[1][fy + sy] * x[id + sy];
    if (d == 3)
        s += L->c[2][id] * x[id - sz] + L->c[2][id + sz] * x[id + sz];
    return s;
}

static inline int edge_row(const fg_fluid_level *L, int dims, int j, int k)
{
    return j == 0 || j == L->n[1] - 1 || (dims == 3 && (k == 0 || k == L->n[2] - 1));
}

FG_FLUID_HOT void apply_rows(const fg_fluid_level *L, const double *x, double *out, int d)
{
    size_t sy = (size_t)L->n[0], sz = sy * (size_t)L->n[1];
    for (int k = 0; k < L->n[2]; k++)
        for (int j = 0; j < L->n[1]; j++) {
            row_index r = row_at(L, j, k);
            int edge = edge_row(L, d, j, k);
            for (int i = 0; i < L->n[0]; i++) {
                size_t id = r.cell + (size_t)i;
                double s = edge || i == 0 || i == L->n[0] - 1
                               ? neighbours_edge(L, d, x, r, i, j, k)
                               : neighbours_inner(L, x, id, r.fx + (size_t)i, r.fy + (size_t)i,
                                                  sy, sz, d);
                out[id] = L->diag[id] * x[id] - s;
            }
        }
}

void fg_fluid_level_apply(const fg_fluid_level *L, int dims, const double *x, double *out)
{
    if (dims == 2)
        apply_rows(L, x, out, 2);
    else
        apply_rows(L, x, out, 3);
}

/* Red-black Gauss-Seidel half-sweep on the cells of one colour. */
FG_FLUID_HOT void sweep_rows(const fg_fluid_level *L, int color, int d)
{
    size_t sy = (size_t)L->n[0], sz = sy * (size_t)L->n[1];
    double *x = L->x;
    for (int k = 0; k < L->n[2]; k++)
        for (int j = 0; j < L->n[1]; j++) {
            row_index r = row_at(L, j, k);
            int i0 = (color + j + k) & 1, last = L->n[0] - 1;
            if (edge_row(L, d, j, k)) {
                for (int i = i0; i <= last; i += 2) {
                    size_t id = r.cell + (size_t)i;
                    x[id] = (L->b[id] + neighbours_edge(L, d, x, r, i, j, k)) * L->inv_diag[id];
                }
                continue;
            }
            if (i0 == 0)
                x[r.cell] = (L->b[r.cell] + neighbours_edge(L, d, x, r, 0, j, k)) *
                            L->inv_diag[r.cell];
            for (int i = i0 == 0 ? 2 : 1; i < last; i += 2) {
                size_t id = r.cell + (size_t)i;
                x[id] = (L->b[id] + neighbours_inner(L, x, id, r.fx + (size_t)i,
                                                     r.fy + (size_t)i, sy, sz, d)) *
                        L->inv_diag[id];
            }
            if (((last + j + k) & 1) == color) {
                size_t id = r.cell + (size_t)last;
                x[id] = (L->b[id] + neighbours_edge(L, d, x, r, last, j, k)) * L->inv_diag[id];
            }
        }
}

static void sweep(const fg_fluid_level *L, int dims, int color)
{
    if (dims == 2)
        sweep_rows(L, color, 2);
    else
        sweep_rows(L, color, 3);
}

static void smooth(const fg_fluid_level *L, int dims, int first, int times)
{
    for (int t = 0; t < times; t++) {
        sweep(L, dims, first);
        sweep(L, dims, 1 - first);
    }
}

static void restrict_residual(const fg_fluid_level *F, fg_fluid_level *C)
{
    memset(C->b, 0, C->count * sizeof(double));
    size_t id = 0;
    for (int k = 0; k < F->n[2]; k++)
        for (int j = 0; j < F->n[1]; j++)
            for (int i = 0; i < F->n[0]; i++, id++) {
                size_t p = (size_t)(i / 2) +
                           (size_t)C->n[0] * ((size_t)(j / 2) + (size_t)C->n[1] * (size_t)(k / 2));
                C->b[p] += F->r[id];
            }
}

static void prolong_add(fg_fluid_level *F, const fg_fluid_level *C)
{
    size_t id = 0;
    for (int k = 0; k < F->n[2]; k++)
        for (int j = 0; j < F->n[1]; j++)
            for (int i = 0; i < F->n[0]; i++, id++) {
                if (F->diag[id] == 0.0)
                    continue;
                size_t p = (size_t)(i / 2) +
                           (size_t)C->n[0] * ((size_t)(j / 2) + (size_t)C->n[1] * (size_t)(k / 2));
                F->x[id] += C->x[p];
            }
}

static void vcycle(fg_fluid *f, int l)
{
    fg_fluid_level *L = &f->level[l];
    memset(L->x, 0, L->count * sizeof(double));
    if (l == f->levels - 1) {
        smooth(L, f->dims, 0, COARSEST_SWEEPS);
        smooth(L, f->dims, 1, COARSEST_SWEEPS);
        return;
    }
    fg_fluid_level *C = &f->level[l + 1];
    smooth(L, f->dims, 0, 2);
    fg_fluid_level_apply(L, f->dims, L->x, L->r);
    for (size_t i = 0; i < L->count; i++)
        L->r[i] = L->b[i] - L->r[i];
    restrict_residual(L, C);
    vcycle(f, l + 1);
    prolong_add(L, C);
    smooth(L, f->dims, 1, 2);
}

static double dot(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; i++)
        s += a[i] * b[i];
    return s;
}

/* The mean over solved cells is removed when the matrix is singular. */
static void remove_mean(const fg_fluid *f, double *v)
{
    const fg_fluid_level *L = &f->level[0];
    double s = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < L->count; i++)
        if (L->diag[i] != 0.0) {
            s += v[i];
            n++;
        }
    if (n == 0)
        return;
    s /= (double)n;
    for (size_t i = 0; i < L->count; i++)
        v[i] = L->diag[i] != 0.0 ? v[i] - s : 0.0;
}

/* z = M r: the V-cycle on level 0 with b = r. */
static void precondition(fg_fluid *f)
{
    vcycle(f, 0);
    if (f->singular)
        remove_mean(f, f->level[0].x);
}

fg_result fg_fluid_multigrid_solve(fg_fluid *f)
{
    fg_fluid_level *L0 = &f->level[0];
    size_t n = L0->count;
    double *x = f->q, *r = L0->b, *z = L0->x, *p = f->pcg_p, *ap = f->pcg_ap;
    fg_fluid_report *rep = &f->report;
    if (f->singular)
        remove_mean(f, f->div_rhs);
    /* The residual is measured against the right-hand side, but never
     * against less than a thousandth of the fluxes it is made of: when the
     * flow is already nearly divergence-free (a steady state), a tolerance
     * relative to the tiny rhs would ask for less than round-off. */
    double bn = sqrt(dot(f->div_rhs, f->div_rhs, n));
    rep->iterations = 0;
    rep->initial_residual = rep->residual = 0.0;
    if (bn > 0.0 && bn < 1e-3 * f->flux_norm)
        bn = 1e-3 * f->flux_norm;
    if (!(bn > 0.0)) {
        memset(x, 0, n * sizeof(double));
        return FG_OK;
    }
    for (size_t i = 0; i < n; i++)
        if (L0->diag[i] == 0.0)
            x[i] = 0.0;
    fg_fluid_level_apply(L0, f->dims, x, ap);
    for (size_t i = 0; i < n; i++)
        r[i] = f->div_rhs[i] - ap[i];
    double res = sqrt(dot(r, r, n)) / bn;
    rep->initial_residual = rep->residual = res;
    double tol = f->config.tolerance;
    if (res <= tol)
        return FG_OK;
    precondition(f);
    memcpy(p, z, n * sizeof(double));
    double rz = dot(r, z, n);
    for (int it = 1; it <= f->config.max_iterations; it++) {
        fg_fluid_level_apply(L0, f->dims, p, ap);
        double pap = dot(p, ap, n);
        if (!(pap > 0.0))
            break;
        double alpha = rz / pap, rr = 0.0;
        for (size_t i = 0; i < n; i++) {
            x[i] += alpha * p[i];
            r[i] -= alpha * ap[i];
            rr += r[i] * r[i];
        }
        rep->iterations = it;
        rep->residual = sqrt(rr) / bn;
        if (rep->residual <= tol)
            return FG_OK;
        precondition(f);
        double rz_new = dot(r, z, n);
        double beta = rz_new / rz;
        rz = rz_new;
        for (size_t i = 0; i < n; i++)
            p[i] = z[i] + beta * p[i];
    }
    return rep->residual <= tol ? FG_OK : FG_ERR_NOT_CONVERGED;
}
