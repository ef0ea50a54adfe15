/* The finite-volume 7-point Laplacian on level 0, in double, for phi: the
 * residual that decides convergence, red-black SOR (the oracle) and DBM's
 * local relaxation.
 *
 * (A x)_i = sum_j c_ij (x_i - x_j) over the face neighbours j inside the box.
 * An edge lying on a box face has half the dual-face area of an interior one
 * (a quarter on an edge of the box): that is what makes the box faces
 * Neumann and keeps A symmetric. The kernels run it in the mirror form of
 * fg_level_row. Masked (Dirichlet) nodes hold their value in phi. */
#include "field_internal.h"
#include "field_simd.h"

/* x at the two x-neighbours of node i of a row, mirrored at the ends. */
static inline double west(const double *x, int i)
{
    return i > 0 ? x[i - 1] : x[1];
}

static inline double east(const double *x, int i, int n)
{
    return i < n - 1 ? x[i + 1] : x[n - 2];
}

/* The mirror-form sum of the neighbours, sum_j c_ij x_j, at node i of row r. */
static inline double neighbours(const fg_level *L, const double *xr, const fg_row *r, int i)
{
    return L->c[0] * (west(xr, i) + east(xr, i, L->n[0])) +
           L->c[1] * (xr[r->south + i] + xr[r->north + i]) +
           L->c[2] * (xr[r->down + i] + xr[r->up + i]);
}

static inline double end_scale(const fg_level *L, int i)
{
    return i == 0 || i == L->n[0] - 1 ? 0.5 : 1.0;
}

/* The finite-volume residual -A x at node i of row r (free or not). */
static inline double residual_at(const fg_level *L, const double *xr, const fg_row *r, int i,
                                 double dg)
{
    return (neighbours(L, xr, r, i) - dg * xr[i]) * (r->scale * end_scale(L, i));
}

/* Nodes [i0, i1) of a row of fg_lap_residual, one at a time. */
static double scalar_residuals(const fg_level *L, const double *xr, const fg_row *r, int i0,
                               int i1, double dg, float *out)
{
    double sum = 0.0;
    for (int i = i0; i < i1; i++) {
        double v = L->mask[r->at + (size_t)i] ? 0.0 : residual_at(L, xr, r, i, dg);
        sum += v * v;
        if (out)
            out[r->at + fg_split(L->n[0], i)] = (float)v;
    }
    return sum;
}

/* A row of phi and its neighbour rows, for residual_row's blocks. */
typedef struct row_view {
    const double *x, *s, *n, *d, *u;
    const uint8_t *m;
    fg_vd cx, cy, cz, dg, scale;
    float *out;       /* the row's residual (split), or NULL */
    int size;
} row_view;

/* The residual at the block of lanes from node i (0 on Dirichlet nodes). */
static inline fg_vd residual_block(const row_view *w, int i)
{
    fg_vd v = w->cx * (fg_vd_load(w->x + i - 1) + fg_vd_load(w->x + i + 1)) +
              w->cy * (fg_vd_load(w->s + i) + fg_vd_load(w->n + i)) +
              w->cz * (fg_vd_load(w->d + i) + fg_vd_load(w->u + i)) - w->dg * fg_vd_load(w->x + i);
    return fg_vd_select(fg_vl_zero_bytes(w->m + i), v * w->scale, fg_vd_set(0.0));
}

/* The residual v of the block from node i into the row's out (split), if
 * it has one. */
static inline void store_block(const row_view *w, int i, fg_vd v)
{
    if (w->out)
        for (int l = 0; l < FG_VD_LANES; l++)
            w->out[fg_split(w->size, i + l)] = (float)fg_vd_lane(v, l);
}

/* The same for v0 from node i and v1 of the next block. */
static inline void store_blocks(const row_view *w, int i, fg_vd v0, fg_vd v1)
{
#ifdef FG_FIELD_SPLIT_VECTORS
    if (w->out)
        fg_vd_store_split(w->out + fg_split(w->size, i), w->out + fg_split(w->size, i + 1), v0,
                          v1);
#else
    store_block(w, i, v0);
    store_block(w, i + FG_VD_LANES, v1);
#endif
}

/* One row of fg_lap_residual with phi as it is; returns the squared norm.
 * Two blocks a step, summed apart, so that the additions do not wait on
 * each other. */
static double residual_row(const fg_level *L, const double *x, const fg_row *r, float *out)
{
    const int n = L->n[0];
    const double *xr = x + r->at;
    const double dg = 2.0 * (L->c[0] + L->c[1] + L->c[2]);
    const row_view w = {xr,
                        xr + r->south,
                        xr + r->north,
                        xr + r->down,
                        xr + r->up,
                        L->mask + r->at,
                        fg_vd_set(L->c[0]),
                        fg_vd_set(L->c[1]),
                        fg_vd_set(L->c[2]),
                        fg_vd_set(dg),
                        fg_vd_set(r->scale),
                        out ? out + r->at : NULL,
                        n};
    fg_vd acc0 = fg_vd_set(0.0), acc1 = acc0;
    int i = 1;
    for (; i + 2 * FG_VD_LANES <= n - 1; i += 2 * FG_VD_LANES) {
        fg_vd v0 = residual_block(&w, i), v1 = residual_block(&w, i + FG_VD_LANES);
        store_blocks(&w, i, v0, v1);
        acc0 += v0 * v0;
        acc1 += v1 * v1;
    }
    for (; i + FG_VD_LANES <= n - 1; i += FG_VD_LANES) {
        fg_vd v = residual_block(&w, i);
        store_block(&w, i, v);
        acc0 += v * v;
    }
    acc0 += acc1;
    double sum = 0.0;
    for (int l = 0; l < FG_VD_LANES; l++)
        sum += fg_vd_lane(acc0, l);
    sum += scalar_residuals(L, xr, r, 0, 1, dg, out);
    sum += scalar_residuals(L, xr, r, i, n - 1, dg, out);
    sum += scalar_residuals(L, xr, r, n - 1, n, dg, out);
    return sum;
}

/* One row with phi read as 0 on free nodes: the residual is b. */
static double b_row(const fg_level *L, const double *x, const fg_row *r)
{
    const int n = L->n[0];
    const uint8_t *m = L->mask + r->at;
    const ptrdiff_t off[4] = {r->south, r->north, r->down, r->up};
    double sum = 0.0;
    for (int i = 0; i < n; i++) {
        if (m[i])
            continue;
        int w = i > 0 ? i - 1 : 1, e = i < n - 1 ? i + 1 : n - 2;
        double v = L->c[0] * ((m[w] ? x[r->at + (size_t)w] : 0.0) +
                              (m[e] ? x[r->at + (size_t)e] : 0.0));
        for (int a = 0; a < 4; a++) {
            size_t q = (size_t)((ptrdiff_t)(r->at + (size_t)i) + off[a]);
            v += L->c[1 + a / 2] * (L->mask[q] ? x[q] : 0.0);
        }
        v *= r->scale * end_scale(L, i);
        sum += v * v;
    }
    return sum;
}

/* The residual rows of plane k; returns their squared norm. */
static double residual_plane(const fg_level *L, const double *phi, int zero_free, int k,
                             float *out)
{
    double sum = 0.0;
    for (int j = 0; j < L->n[1]; j++) {
        fg_row r = fg_level_row(L, j, k);
        sum += zero_free ? b_row(L, phi, &r) : residual_row(L, phi, &r, out);
    }
    return sum;
}

double fg_lap_residual(const fg_level *L, const double *phi, int zero_free, float *out)
{
    double sum = 0.0;
    for (int k = 0; k < L->n[2]; k++)
        sum += residual_plane(L, phi, zero_free, k, out);
    fg_simd_leave();
    return sum;
}

/* phi += e (split rows) on plane k, a row's even nodes and then its odd
 * ones. e is 0 on the Dirichlet nodes (every kernel leaves it so), so
 * adding it everywhere keeps their values. */
static void correct_plane(const fg_level *L, double *phi, const float *e, int k)
{
    const size_t n = (size_t)L->n[0], ne = (n + 1) / 2;
    for (int j = 0; j < L->n[1]; j++) {
        size_t row = fg_level_index(L, 0, j, k);
        double *x = phi + row;
        const float *even = e + row, *odd = e + row + ne;
        size_t u = 0;
#ifdef FG_FIELD_SPLIT_VECTORS
        for (; 2 * u + 2 * FG_VF_LANES <= n; u += FG_VF_LANES)
            fg_vd_add_interleaved(x + 2 * u, even + u, odd + u);
#endif
        for (size_t v = u; v < ne; v++)
            x[2 * v] += even[v];
        for (size_t v = u; v < n / 2; v++)
            x[2 * v + 1] += odd[v];
    }
}

/* A plane's residual reads the planes either side: the one above is
 * corrected just before, so that phi is read once while in cache. */
double fg_lap_correct_residual(const fg_level *L, double *phi, const float *e, float *out)
{
    double sum = 0.0;
    correct_plane(L, phi, e, 0);
    for (int k = 0; k < L->n[2]; k++) {
        if (k + 1 < L->n[2])
            correct_plane(L, phi, e, k + 1);
        sum += residual_plane(L, phi, 0, k, out);
    }
    fg_simd_leave();
    return sum;
}

/* The relaxations in double are not vector kernels: the AVX2 build
 * (kernels_avx2.h) leaves them out. */
#ifndef FG_SIMD_WIDE

/* Over-relaxed Gauss-Seidel at free node i of row r. */
static inline void relax_at(const fg_level *L, double *xr, const fg_row *r, int i, double omega,
                            double dg)
{
    if (!L->mask[r->at + (size_t)i])
        xr[i] += omega * (neighbours(L, xr, r, i) / dg - xr[i]);
}

void fg_lap_sweep(const fg_level *L, double *x, int color, double omega)
{
    const int n = L->n[0];
    const double cx = L->c[0], cy = L->c[1], cz = L->c[2], dg = 2.0 * (cx + cy + cz);
    const double inv = omega / dg;
    for (int k = 0; k < L->n[2]; k++)
        for (int j = 0; j < L->n[1]; j++) {
            fg_row r = fg_level_row(L, j, k);
            double *xr = x + r.at;
            const double *xs = xr + r.south, *xn = xr + r.north, *xd = xr + r.down,
                         *xu = xr + r.up;
            const uint8_t *m = L->mask + r.at;
            int i0 = (color + j + k) & 1;
            if (i0 == 0)
                relax_at(L, xr, &r, 0, omega, dg);
            for (int i = i0 == 0 ? 2 : 1; i < n - 1; i += 2)
                if (!m[i])
                    xr[i] += inv * (cx * (xr[i - 1] + xr[i + 1]) + cy * (xs[i] + xn[i]) +
                                    cz * (xd[i] + xu[i])) -
                             omega * xr[i];
            if (((n - 1 + j + k) & 1) == color)
                relax_at(L, xr, &r, n - 1, omega, dg);
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
    const double dg = 2.0 * (L->c[0] + L->c[1] + L->c[2]);
    for (int s = 0; s < sweeps; s++)
        for (int color = 0; color < 2; color++)
            for (int k = lo[2]; k <= hi[2]; k++)
                for (int j = lo[1]; j <= hi[1]; j++) {
                    fg_row r = fg_level_row(L, j, k);
                    for (int i = lo[0] + ((lo[0] + j + k + color) & 1); i <= hi[0]; i += 2)
                        relax_at(L, x + r.at, &r, i, 1.0, dg);
                }
}

#endif
