/* The flame front: B-spline lattice, marching cubes, flux quadrature. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bspline_internal.h"
#include "marching_cubes_internal.h"
#include "fulgur/fire.h"

struct fg_flame_front {
    fg_flame_front_config config;
    fg_mc_table table;
    fg_bspline_tap *taps[3];
    fg_bspline_volume volume;
    double *slice[2];
    double *tris;          /* the last good surface: 9 doubles per triangle */
    size_t tri_count, tris_cap;
    double *building;      /* the surface being built; swapped with tris on success */
    size_t building_cap;   /* triangles each can hold */
};

static int lattice_of(const fg_flame_front_config *c, int axis)
{
    return fg_bspline_lattice_nodes(c->grid.size[axis], c->subdivision);
}

static int subdivision_of(const fg_flame_front_config *c)
{
    return c->subdivision == 0 ? 1 : c->subdivision;
}

static int sizes_ok(const fg_flame_front_config *c)
{
    for (int a = 0; a < 3; a++)
        if (c->grid.size[a] < FG_FLAME_MIN_CELLS || c->grid.size[a] > FG_FLAME_MAX_CELLS)
            return 0;
    return c->subdivision >= 0 && c->subdivision <= FG_FLAME_MAX_SUBDIVISION;
}

size_t fg_flame_front_memory_bytes(const fg_flame_front_config *config)
{
    if (!config || !sizes_ok(config))
        return 0;
    fg_flame_front_config c = *config;
    c.subdivision = subdivision_of(config);
    size_t lx = (size_t)lattice_of(&c, 0), ly = (size_t)lattice_of(&c, 1),
           lz = (size_t)lattice_of(&c, 2);
    size_t ny = (size_t)c.grid.size[1], nz = (size_t)c.grid.size[2];
    size_t doubles = lx * ny * nz + lx * ly * nz + 2 * lx * ly;
    size_t taps = (lx + ly + lz) * sizeof(fg_bspline_tap);
    return sizeof(struct fg_flame_front) + doubles * sizeof(double) + taps;
}

fg_result fg_flame_front_create(const fg_flame_front_config *config, fg_flame_front **out)
{
    if (!config || !out)
        return FG_ERR_NULL;
    *out = NULL;
    const fg_flame_grid *g = &config->grid;
    for (int a = 0; a < 3; a++)
        if (!isfinite(g->origin_m[a]))
            return FG_ERR_NOT_FINITE;
    if (!isfinite(g->cell_m) || !isfinite(config->iso_level))
        return FG_ERR_NOT_FINITE;
    if (!sizes_ok(config) || !(g->cell_m > 0.0) || !(config->iso_level > 0.0) ||
        config->iso_level > FG_FLAME_MAX_BURN)
        return FG_ERR_ARGUMENT;
    size_t max_bytes = config->max_bytes ? config->max_bytes : FG_FLAME_DEFAULT_MAX_BYTES;
    if (fg_flame_front_memory_bytes(config) > max_bytes)
        return FG_ERR_CAPACITY;

    fg_flame_front *f = calloc(1, sizeof *f);
    if (!f)
        return FG_ERR_NO_MEMORY;
    f->config = *config;
    f->config.subdivision = subdivision_of(config);
    f->config.max_bytes = max_bytes;
    fg_mc_table_build(&f->table);
    fg_bspline_volume *v = &f->volume;
    for (int a = 0; a < 3; a++) {
        v->n[a] = g->size[a];
        v->lattice[a] = lattice_of(&f->config, a);
        f->taps[a] = malloc(sizeof(fg_bspline_tap) * (size_t)v->lattice[a]);
        if (f->taps[a])
            fg_bspline_taps(v->n[a], f->config.subdivision, f->taps[a]);
        v->taps[a] = f->taps[a];
    }
    size_t lx = (size_t)v->lattice[0], ly = (size_t)v->lattice[1];
    v->along_x = malloc(sizeof(double) * lx * (size_t)v->n[1] * (size_t)v->n[2]);
    v->along_xy = malloc(sizeof(double) * lx * ly * (size_t)v->n[2]);
    f->slice[0] = malloc(sizeof(double) * lx * ly);
    f->slice[1] = malloc(sizeof(double) * lx * ly);
    if (!f->taps[0] || !f->taps[1] || !f->taps[2] || !v->along_x || !v->along_xy ||
        !f->slice[0] || !f->slice[1]) {
        fg_flame_front_destroy(f);
        return FG_ERR_NO_MEMORY;
    }
    *out = f;
    return FG_OK;
}

void fg_flame_front_destroy(fg_flame_front *f)
{
    if (!f)
        return;
    for (int a = 0; a < 3; a++)
        free(f->taps[a]);
    free(f->volume.along_x);
    free(f->volume.along_xy);
    free(f->slice[0]);
    free(f->slice[1]);
    free(f->tris);
    free(f->building);
    free(f);
}

void fg_flame_front_get_config(const fg_flame_front *f, fg_flame_front_config *out)
{
    assert(f && out);
    *out = f->config;
}

/* One velocity component: its sample counts and where sample 0 sits, in
 * cells from the grid's corner. */
typedef struct component {
    const double *u;
    int n[3];
    double offset[3];
} component;

static double sample_component(const component *c, const double cell[3])
{
    int i0[3];
    double fr[3];
    for (int a = 0; a < 3; a++) {
        double u = cell[a] - c->offset[a];
        double fl = floor(u);
        int i = (int)fl;
        double t = u - fl;
        if (u < 0.0) {
            i = 0;
            t = 0.0;
        } else if (i >= c->n[a] - 1) {
            i = c->n[a] - 2;
            t = 1.0;
        }
        i0[a] = i;
        fr[a] = t;
    }
    size_t sx = 1, sy = (size_t)c->n[0], sz = (size_t)c->n[0] * (size_t)c->n[1];
    const double *p = c->u + (size_t)i0[0] + sy * (size_t)i0[1] + sz * (size_t)i0[2];
    double c00 = p[0] + fr[0] * (p[sx] - p[0]);
    double c10 = p[sy] + fr[0] * (p[sy + sx] - p[sy]);
    double c01 = p[sz] + fr[0] * (p[sz + sx] - p[sz]);
    double c11 = p[sz + sy] + fr[0] * (p[sz + sy + sx] - p[sz + sy]);
    double c0 = c00 + fr[1] * (c10 - c00), c1 = c01 + fr[1] * (c11 - c01);
    return c0 + fr[2] * (c1 - c0);
}

static int grow_building(fg_flame_front *f, size_t need)
{
    if (need <= f->building_cap)
        return 1;
    size_t cap = f->building_cap ? f->building_cap : 1024;
    while (cap < need)
        cap *= 2;
    double *b = realloc(f->building, sizeof(double) * 9 * cap);
    if (!b)
        return 0;
    f->building = b;
    f->building_cap = cap;
    return 1;
}

fg_result fg_flame_front_flux(fg_flame_front *f, const double *burn,
                              const fg_flame_velocity *velocity, fg_flame_flux *out)
{
    if (!f || !burn || !velocity || !out)
        return FG_ERR_NULL;
    for (int a = 0; a < 3; a++)
        if (!velocity->u_m_s[a])
            return FG_ERR_NULL;
    if (velocity->layout != FG_VELOCITY_MAC && velocity->layout != FG_VELOCITY_COLLOCATED)
        return FG_ERR_ARGUMENT;
    const fg_flame_grid *g = &f->config.grid;
    size_t cells = (size_t)g->size[0] * (size_t)g->size[1] * (size_t)g->size[2];
    for (size_t i = 0; i < cells; i++)
        if (!isfinite(burn[i]))
            return FG_ERR_NOT_FINITE;
    for (size_t i = 0; i < cells; i++)
        if (fabs(burn[i]) > FG_FLAME_MAX_BURN)
            return FG_ERR_ARGUMENT;

    component comp[3];
    for (int a = 0; a < 3; a++) {
        comp[a].u = velocity->u_m_s[a];
        for (int b = 0; b < 3; b++) {
            int staggered = velocity->layout == FG_VELOCITY_MAC && a == b;
            comp[a].n[b] = g->size[b] + staggered;
            comp[a].offset[b] = staggered ? 0.0 : 0.5;
        }
    }

    fg_bspline_volume *v = &f->volume;
    fg_bspline_prepare(v, burn);
    int lx = v->lattice[0], ly = v->lattice[1], lz = v->lattice[2], s = f->config.subdivision;
    double iso = f->config.iso_level, h = g->cell_m, step = 1.0 / (double)s;
    const fg_mc_table *t = &f->table;
    double flux = 0.0, area = 0.0;
    size_t count = 0;
    fg_bspline_slice(v, 0, f->slice[0]);
    for (int mz = 0; mz + 1 < lz; mz++) {
        const double *lo = f->slice[mz & 1];
        double *hi = f->slice[(mz + 1) & 1];
        fg_bspline_slice(v, mz + 1, hi);
        for (int my = 0; my + 1 < ly; my++)
            for (int mx = 0; mx + 1 < lx; mx++) {
                size_t at = (size_t)mx + (size_t)lx * (size_t)my;
                double val[8] = {lo[at],      lo[at + 1],      lo[at + lx],      lo[at + lx + 1],
                                 hi[at],      hi[at + 1],      hi[at + lx],      hi[at + lx + 1]};
                int mask = 0;
                for (int c = 0; c < 8; c++)
                    mask |= (val[c] > iso) << c;
                if (mask == 0 || mask == 255)
                    continue;
                /* the crossing on each edge, in cells from the grid's
                 * corner; computed from the edge's own two values in a
                 * fixed order, so a neighbouring cube gets the same bits */
                double vert[12][3];
                int base[3] = {mx, my, mz};
                for (int e = 0; e < 12; e++) {
                    int c0 = t->edge_corner[e][0], c1 = t->edge_corner[e][1];
                    if (((mask >> c0) & 1) == ((mask >> c1) & 1))
                        continue;
                    double frac = (iso - val[c0]) / (val[c1] - val[c0]);
                    for (int a = 0; a < 3; a++) {
                        double idx = (double)(base[a] + ((c0 >> a) & 1));
                        if (a == t->edge_axis[e])
                            idx += frac;
                        /* lattice u = -2 + idx / s from the centre of
                         * cell 0, i.e. idx / s - 1.5 cells from the corner */
                        vert[e][a] = idx * step - 1.5;
                    }
                }
                if (!grow_building(f, count + t->count[mask]))
                    return FG_ERR_NO_MEMORY;
                for (int k = 0; k < t->count[mask]; k++) {
                    const double *pa = vert[t->edges[mask][3 * k]];
                    const double *pb = vert[t->edges[mask][3 * k + 1]];
                    const double *pc = vert[t->edges[mask][3 * k + 2]];
                    double ab[3], ac[3], centroid[3], tri_area[3], u[3];
                    for (int a = 0; a < 3; a++) {
                        ab[a] = (pb[a] - pa[a]) * h;
                        ac[a] = (pc[a] - pa[a]) * h;
                        centroid[a] = (pa[a] + pb[a] + pc[a]) / 3.0;
                    }
                    tri_area[0] = 0.5 * (ab[1] * ac[2] - ab[2] * ac[1]);
                    tri_area[1] = 0.5 * (ab[2] * ac[0] - ab[0] * ac[2]);
                    tri_area[2] = 0.5 * (ab[0] * ac[1] - ab[1] * ac[0]);
                    for (int a = 0; a < 3; a++)
                        u[a] = sample_component(&comp[a], centroid);
                    double un = u[0] * tri_area[0] + u[1] * tri_area[1] + u[2] * tri_area[2];
                    if (!isfinite(un))
                        return FG_ERR_NOT_FINITE;
                    flux += un;
                    area += sqrt(tri_area[0] * tri_area[0] + tri_area[1] * tri_area[1] +
                                 tri_area[2] * tri_area[2]);
                    double *dst = f->building + 9 * count++;
                    for (int a = 0; a < 3; a++) {
                        dst[a] = g->origin_m[a] + pa[a] * h;
                        dst[3 + a] = g->origin_m[a] + pb[a] * h;
                        dst[6 + a] = g->origin_m[a] + pc[a] * h;
                    }
                }
            }
    }
    if (!isfinite(flux) || !isfinite(area))
        return FG_ERR_NOT_FINITE;
    /* success: the new surface replaces the last, whose storage is reused */
    double *old = f->tris;
    size_t old_cap = f->tris_cap;
    f->tris = f->building;
    f->tris_cap = f->building_cap;
    f->tri_count = count;
    f->building = old;
    f->building_cap = old_cap;
    *out = (fg_flame_flux){.flux_m3_s = flux, .area_m2 = area, .triangles = count};
    return FG_OK;
}

fg_result fg_flame_front_triangles(const fg_flame_front *f, const double **xyz_m, size_t *triangles)
{
    if (!f || !xyz_m || !triangles)
        return FG_ERR_NULL;
    *xyz_m = f->tris;
    *triangles = f->tri_count;
    return FG_OK;
}
