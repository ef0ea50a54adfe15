/* Level 0 in single precision, for a correction (0 on Dirichlet nodes):
 * red-black Gauss-Seidel and the residual, in the mirror form of
 * fg_level_row (laplace.c has the operator), on split rows (fg_split).
 *
 * On split rows the nodes of one colour in a row are one contiguous half,
 * their x-neighbours the other half, their y- and z-neighbours the same
 * half of the next rows: a half-sweep reads and writes four nodes at a
 * time with no gather and no blend. L->inv_diag is 1 / dg on free nodes
 * and 0 on Dirichlet ones, so the update leaves those at 0. */
#include "field_internal.h"
#include "field_simd.h"

/* A row: the level's constants and where its neighbours are. */
typedef struct fine_row {
    float cx, cy, cz, dg;
    int n, ne;                 /* nodes, and of those even */
    size_t at;                 /* index of the row's first node */
    ptrdiff_t south, north, down, up;
    float scale;               /* fg_row's */
    float unscale;             /* 1 / scale, a power of two: multiplying by it
                                  is dividing by scale exactly */
} fine_row;

static inline fine_row row_of(const fg_level *L, int j, int k)
{
    fg_row r = fg_level_row(L, j, k);
    fine_row f;
    f.cx = (float)L->c[0];
    f.cy = (float)L->c[1];
    f.cz = (float)L->c[2];
    f.dg = 2.0f * (f.cx + f.cy + f.cz);
    f.n = L->n[0];
    f.ne = (L->n[0] + 1) / 2;
    f.at = r.at;
    f.south = r.south;
    f.north = r.north;
    f.down = r.down;
    f.up = r.up;
    f.scale = (float)r.scale;
    f.unscale = 1.0f / f.scale;
    return f;
}

/* Node q of a row of x (split), q mirrored into the row. */
static inline float node(const fine_row *f, const float *x, int q)
{
    q = q < 0 ? -q : (q >= f->n ? 2 * (f->n - 1) - q : q);
    return x[f->at + fg_split(f->n, q)];
}

/* The mirror-form neighbour sum sum_j c_ij x_j at node i, and the scale of
 * its finite-volume row. */
static inline float neighbours(const fine_row *f, const float *x, int i)
{
    const float *s = x + f->at + fg_split(f->n, i);
    return f->cx * (node(f, x, i - 1) + node(f, x, i + 1)) +
           f->cy * (s[f->south] + s[f->north]) + f->cz * (s[f->down] + s[f->up]);
}

static inline float scale_at(const fine_row *f, int i)
{
    return i == 0 || i == f->n - 1 ? 0.5f * f->scale : f->scale;
}

/* The run of a half (h = 0 even, 1 odd) where both x-neighbours are in the
 * other half at t + west and t + west + 1: [lo, hi). */
typedef struct half {
    int first, count;          /* the half's offset in the row, and its length */
    int other, west;           /* the other half's offset; its index of the west neighbour */
    int lo, hi;
} half;

static inline half half_of(const fine_row *f, int h)
{
    int no = f->n / 2;
    half s;
    if (h == 0) {
        s = (half){0, f->ne, f->ne, -1, 1, f->ne < no ? f->ne : no};
    } else {
        int top = f->ne - 1;
        s = (half){f->ne, no, 0, 0, 0, no < top ? no : top};
    }
    return s;
}

/* 1 / scale_at, exactly. */
static inline float unscale_at(const fine_row *f, int i)
{
    return i == 0 || i == f->n - 1 ? 2.0f * f->unscale : f->unscale;
}

/* inv (rhs / scale + neighbours) at node i, one node. */
static inline float relaxed(const fg_level *L, const fine_row *f, const float *x,
                            const float *rhs, int i)
{
    size_t id = f->at + fg_split(f->n, i);
    float b = rhs[id] * unscale_at(f, i);
    return L->inv_diag[id] * (b + neighbours(f, x, i));
}

/* The blocks of lanes over [lo, hi) that the vector loops take: from lo
 * a block at a time, and where a part of a block is left, one more moved
 * back to end at hi, so that it overlaps the one before. A half-sweep may
 * do that, since it reads only the other colour, and so may the residual,
 * which writes elsewhere. Whether that last block is due once the whole
 * ones end at t: */
static inline int part_left(const half *s, int t)
{
    return t < s->hi && s->hi - s->lo >= FG_VF_LANES;
}

/* Where the scalar nodes after the blocks start: hi, or lo when [lo, hi)
 * is shorter than a block (no block then). */
static inline int after_blocks(const half *s)
{
    return s->hi - s->lo >= FG_VF_LANES ? s->hi : s->lo;
}

/* One half-row of a half-sweep: its nodes, the other half's (at the west
 * neighbour of its first node), the rows around, rhs and inv_diag. */
typedef struct sweep_run {
    float *x;
    const float *o, *s, *n, *d, *u, *b, *inv;
    fg_vf cx, cy, cz, up;
} sweep_run;

static inline void sweep_block(const sweep_run *r, int t)
{
    fg_vf v = r->cx * (fg_vf_load(r->o + t) + fg_vf_load(r->o + t + 1)) +
              r->cy * (fg_vf_load(r->s + t) + fg_vf_load(r->n + t)) +
              r->cz * (fg_vf_load(r->d + t) + fg_vf_load(r->u + t));
    v += fg_vf_load(r->b + t) * r->up;
    fg_vf_store(r->x + t, fg_vf_load(r->inv + t) * v);
}

/* Plane k of a Gauss-Seidel half-sweep over the nodes of one colour. */
static void sweep_plane(const fg_level *L, float *e, const float *rhs, int color, int k)
{
    for (int j = 0; j < L->n[1]; j++) {
        const fine_row f = row_of(L, j, k);
        const int h = (color + j + k) & 1;
        const half s = half_of(&f, h);
        float *x = e + f.at + s.first;
        const sweep_run r = {x,
                             e + f.at + s.other + s.west,
                             x + f.south,
                             x + f.north,
                             x + f.down,
                             x + f.up,
                             rhs + f.at + s.first,
                             L->inv_diag + f.at + s.first,
                             fg_vf_set(f.cx),
                             fg_vf_set(f.cy),
                             fg_vf_set(f.cz),
                             fg_vf_set(f.unscale)};
        int t = s.lo;
        for (; t + FG_VF_LANES <= s.hi; t += FG_VF_LANES)
            sweep_block(&r, t);
        if (part_left(&s, t))
            sweep_block(&r, s.hi - FG_VF_LANES);
        for (int u = 0; u < s.lo; u++)
            x[u] = relaxed(L, &f, e, rhs, 2 * u + h);
        for (int u = after_blocks(&s); u < s.count; u++)
            x[u] = relaxed(L, &f, e, rhs, 2 * u + h);
    }
}

/* Plane k of the first red half-sweep from e = 0 (black nodes 0). */
static void sweep_plane_from_zero(const fg_level *L, float *e, const float *rhs, int k)
{
    for (int j = 0; j < L->n[1]; j++) {
        const fine_row f = row_of(L, j, k);
        const half s = half_of(&f, (j + k) & 1), other = half_of(&f, (j + k + 1) & 1);
        float *x = e + f.at + s.first;
        const float *b = rhs + f.at + s.first, *inv = L->inv_diag + f.at + s.first;
        const fg_vf up = fg_vf_set(f.unscale);
        int t = 0;
        for (; t + FG_VF_LANES <= s.count; t += FG_VF_LANES)
            fg_vf_store(x + t, fg_vf_load(inv + t) * (fg_vf_load(b + t) * up));
        for (; t < s.count; t++)
            x[t] = inv[t] * (b[t] * f.unscale);
        /* A row's end nodes have their right-hand side doubled again. */
        int ends[2] = {0, f.n - 1};
        for (int a = 0; a < 2; a++)
            if ((ends[a] & 1) == ((j + k) & 1))
                x[ends[a] / 2] = inv[ends[a] / 2] * (b[ends[a] / 2] * unscale_at(&f, ends[a]));
        memset(e + f.at + other.first, 0, (size_t)other.count * sizeof *e);
    }
}

/* Half-sweep t works on plane k - t while half-sweep t - 1 is on the plane
 * above: the planes it reads are then done by the one before and not yet
 * by the ones after, as in count sweeps one after another, and e, rhs
 * and inv_diag pass through the cache once for all of them. */
void fg_fine_smooth(const fg_level *L, float *e, const float *rhs, int color, int count,
                    int from_zero)
{
    for (int step = 0; step < L->n[2] + count - 1; step++)
        for (int t = 0; t < count; t++) {
            int k = step - t;
            if (k < 0 || k >= L->n[2])
                continue;
            if (t == 0 && from_zero)
                sweep_plane_from_zero(L, e, rhs, k);
            else
                sweep_plane(L, e, rhs, (color + t) & 1, k);
        }
}

/* One node of fg_fine_residual: node u of the half at first, h's parity. */
static inline float residual_at(const fine_row *f, const float *x, const float *rhs, int first,
                                const float *inv, int u, int h)
{
    int i = 2 * u + h;
    size_t id = f->at + (size_t)first + (size_t)u;
    float v = (neighbours(f, x, i) - f->dg * x[id]) * scale_at(f, i);
    if (rhs)
        v += rhs[id];
    return inv[u] != 0.0f ? v : 0.0f;
}

/* One half-row of fg_fine_residual, as sweep_run; b may be NULL. */
typedef struct residual_run {
    float *res;
    const float *x, *o, *s, *n, *d, *u, *b, *inv;
    fg_vf cx, cy, cz, dg, scale;
} residual_run;

static inline void residual_block(const residual_run *r, int t)
{
    const fg_vf zero = fg_vf_set(0.0f);
    fg_vf v = r->cx * (fg_vf_load(r->o + t) + fg_vf_load(r->o + t + 1)) +
              r->cy * (fg_vf_load(r->s + t) + fg_vf_load(r->n + t)) +
              r->cz * (fg_vf_load(r->d + t) + fg_vf_load(r->u + t));
    v = (v - r->dg * fg_vf_load(r->x + t)) * r->scale;
    if (r->b)
        v += fg_vf_load(r->b + t);
    fg_vf_store(r->res + t, fg_vf_select(fg_vf_load(r->inv + t) != zero, v, zero));
}

void fg_fine_residual(const fg_level *L, const float *x, const float *rhs, float *out)
{
    for (int k = 0; k < L->n[2]; k++)
        for (int j = 0; j < L->n[1]; j++) {
            const fine_row f = row_of(L, j, k);
            for (int h = 0; h < 2; h++) {
                const half s = half_of(&f, h);
                const float *xr = x + f.at + s.first;
                const float *inv = L->inv_diag + f.at + s.first;
                float *res = out + f.at + s.first;
                const residual_run r = {res,
                                        xr,
                                        x + f.at + s.other + s.west,
                                        xr + f.south,
                                        xr + f.north,
                                        xr + f.down,
                                        xr + f.up,
                                        rhs ? rhs + f.at + s.first : NULL,
                                        inv,
                                        fg_vf_set(f.cx),
                                        fg_vf_set(f.cy),
                                        fg_vf_set(f.cz),
                                        fg_vf_set(f.dg),
                                        fg_vf_set(f.scale)};
                int t = s.lo;
                for (; t + FG_VF_LANES <= s.hi; t += FG_VF_LANES)
                    residual_block(&r, t);
                if (part_left(&s, t))
                    residual_block(&r, s.hi - FG_VF_LANES);
                for (int u = 0; u < s.lo; u++)
                    res[u] = residual_at(&f, x, rhs, s.first, inv, u, h);
                for (int u = after_blocks(&s); u < s.count; u++)
                    res[u] = residual_at(&f, x, rhs, s.first, inv, u, h);
            }
        }
}
