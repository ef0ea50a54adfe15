/* The finite-volume 7-point Laplacian and its Gauss-Seidel relaxation.
 *
 * (A x)_i = sum_j c_ij (x_i - x_j) over the face neighbours j inside the box.
 * An edge lying on a box face has half the dual-face area of an interior one
 * (a quarter on an edge of the box): that is what makes the box faces
 * Neumann and keeps A symmetric. Masked (Dirichlet) neighbours contribute
 * their value in x: phi for the potential, 0 for a correction. */
#include <stddef.h>

#include "field_internal.h"

static inline double face(int i, int n)
{
    return (i == 0 || i == n - 1) ? 0.5 : 1.0;
}

/* diag = sum_j c_ij, off = sum_j c_ij x_j, for a node anywhere in the box. */
static void node_sums(const fg_level *L, const double *x, int i, int j, int k, double *diag,
                      double *off)
{
    const int *n = L->n;
    size_t id = fg_level_index(L, i, j, k);
    size_t sy = (size_t)n[0], sz = (size_t)n[0] * (size_t)n[1];
    double fx = face(i, n[0]), fy = face(j, n[1]), fz = face(k, n[2]);
    double cx = L->c[0] * fy * fz, cy = L->c[1] * fx * fz, cz = L->c[2] * fx * fy;
    double d = 0.0, o = 0.0;
    if (i > 0) { d += cx; o += cx * x[id - 1]; }
    if (i < n[0] - 1) { d += cx; o += cx * x[id + 1]; }
    if (j > 0) { d += cy; o += cy * x[id - sy]; }
    if (j < n[1] - 1) { d += cy; o += cy * x[id + sy]; }
    if (k > 0) { d += cz; o += cz * x[id - sz]; }
    if (k < n[2] - 1) { d += cz; o += cz * x[id + sz]; }
    *diag = d;
    *off = o;
}

static inline int boundary_row(const fg_level *L, int j, int k)
{
    return j == 0 || k == 0 || j == L->n[1] - 1 || k == L->n[2] - 1;
}

static inline void residual_at(const fg_level *L, const double *x, const double *rhs,
                               double *out, int i, int j, int k)
{
    size_t id = fg_level_index(L, i, j, k);
    double d, o;
    node_sums(L, x, i, j, k, &d, &o);
    out[id] = L->mask[id] ? 0.0 : (rhs ? rhs[id] : 0.0) - (d * x[id] - o);
}

void fg_lap_residual(const fg_level *L, const double *x, const double *rhs, double *out)
{
    const int *n = L->n;
    /* signed strides: xr[i - sy] steps back from a row, never round the
     * address space */
    ptrdiff_t sy = n[0], sz = (ptrdiff_t)n[0] * n[1];
    double cx = L->c[0], cy = L->c[1], cz = L->c[2], dg = 2.0 * (cx + cy + cz);
    for (int k = 0; k < n[2]; k++)
        for (int j = 0; j < n[1]; j++) {
            if (boundary_row(L, j, k)) {
                for (int i = 0; i < n[0]; i++)
                    residual_at(L, x, rhs, out, i, j, k);
                continue;
            }
            residual_at(L, x, rhs, out, 0, j, k);
            residual_at(L, x, rhs, out, n[0] - 1, j, k);
            size_t row = fg_level_index(L, 0, j, k);
            const double *xr = x + row;
            const uint8_t *m = L->mask + row;
            double *o = out + row;
            /* Two copies of the loop so that neither tests rhs per node. */
            if (rhs) {
                const double *b = rhs + row;
                for (int i = 1; i < n[0] - 1; i++) {
                    double v = b[i] - (dg * xr[i] - cx * (xr[i - 1] + xr[i + 1]) -
                                       cy * (xr[i - sy] + xr[i + sy]) -
                                       cz * (xr[i - sz] + xr[i + sz]));
                    o[i] = m[i] ? 0.0 : v;
                }
            } else {
                for (int i = 1; i < n[0] - 1; i++) {
                    double v = -(dg * xr[i] - cx * (xr[i - 1] + xr[i + 1]) -
                                 cy * (xr[i - sy] + xr[i + sy]) -
                                 cz * (xr[i - sz] + xr[i + sz]));
                    o[i] = m[i] ? 0.0 : v;
                }
            }
        }
}

static inline void relax(const fg_level *L, double *x, const double *rhs, int i, int j, int k,
                         double omega)
{
    size_t id = fg_level_index(L, i, j, k);
    if (L->mask[id])
        return;
    double d, o;
    node_sums(L, x, i, j, k, &d, &o);
    x[id] += omega * (((rhs ? rhs[id] : 0.0) + o) / d - x[id]);
}

void fg_lap_sweep(const fg_level *L, double *x, const double *rhs, int color, double omega)
{
    const int *n = L->n;
    ptrdiff_t sy = n[0], sz = (ptrdiff_t)n[0] * n[1]; /* signed, as in the residual */
    double cx = L->c[0], cy = L->c[1], cz = L->c[2];
    double inv = omega / (2.0 * (cx + cy + cz));
    for (int k = 0; k < n[2]; k++)
        for (int j = 0; j < n[1]; j++) {
            int i0 = (color + j + k) & 1;
            if (boundary_row(L, j, k)) {
                for (int i = i0; i < n[0]; i += 2)
                    relax(L, x, rhs, i, j, k, omega);
                continue;
            }
            if (i0 == 0)
                relax(L, x, rhs, 0, j, k, omega);
            size_t row = fg_level_index(L, 0, j, k);
            int last = n[0] - 1;
            double *xr = x + row;
            const uint8_t *m = L->mask + row;
            /* Two copies of the loop so that neither tests rhs per node. */
            if (rhs) {
                const double *b = rhs + row;
                for (int i = i0 == 0 ? 2 : 1; i < last; i += 2)
                    if (!m[i])
                        xr[i] += inv * (b[i] + cx * (xr[i - 1] + xr[i + 1]) +
                                        cy * (xr[i - sy] + xr[i + sy]) +
                                        cz * (xr[i - sz] + xr[i + sz])) -
                                 omega * xr[i];
            } else {
                for (int i = i0 == 0 ? 2 : 1; i < last; i += 2)
                    if (!m[i])
                        xr[i] += inv * (cx * (xr[i - 1] + xr[i + 1]) +
                                        cy * (xr[i - sy] + xr[i + sy]) +
                                        cz * (xr[i - sz] + xr[i + sz])) -
                                 omega * xr[i];
            }
            if (((last + j + k) & 1) == color)
                relax(L, x, rhs, last, j, k, omega);
        }
}

static inline int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

void fg_lap_relax_box(const fg_level *L, double *x, int ci, int cj, int ck, int radius,
                      int sweeps)
{
    int lo[3] = {ci - radius, cj - radius, ck - radius};
    int hi[3] = {ci + radius, cj + radius, ck + radius};
    for (int a = 0; a < 3; a++) {
        lo[a] = clampi(lo[a], 0, L->n[a] - 1);
        hi[a] = clampi(hi[a], 0, L->n[a] - 1);
    }
    for (int s = 0; s < sweeps; s++)
        for (int color = 0; color < 2; color++)
            for (int k = lo[2]; k <= hi[2]; k++)
                for (int j = lo[1]; j <= hi[1]; j++)
                    for (int i = lo[0] + ((lo[0] + j + k + color) & 1); i <= hi[0]; i += 2)
                        relax(L, x, NULL, i, j, k, 1.0);
}

double fg_dot(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; i++)
        s += a[i] * b[i];
    return s;
}
