/* Solids as an immersed boundary, from a signed distance function.
 *
 * From the distance at the cell corners come the fluid fractions of the
 * faces (linear along an edge in 2-D, the marching-squares polygon on a
 * face in 3-D) that weight the projection; from the distance at the
 * velocity nodes come the wall links: for a fluid node whose neighbour
 * along an axis is inside, the wall lies theta * h away, theta from the
 * linear zero crossing of the distance. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fg_array.h"
#include "fluid_state_internal.h"

/* Faces with less fluid than this are closed: a sliver would couple two
 * cells through a vanishing conductance and slow the solver for nothing. */
#define MIN_FACE_FRACTION 1e-3
/* A wall closer than this to a velocity node is taken at this distance. */
#define MIN_THETA 0.02

void fg_fluid_solid_velocity(const fg_fluid *f, const double x[3], double out[3])
{
    const double *v = f->solid_v, *w = f->solid_omega, *c = f->solid_centre;
    double r[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    out[0] = v[0] + w[1] * r[2] - w[2] * r[1];
    out[1] = v[1] + w[2] * r[0] - w[0] * r[2];
    out[2] = f->dims == 2 ? 0.0 : v[2] + w[0] * r[1] - w[1] * r[0];
}

static double segment_fraction(double a, double b)
{
    if (a > 0.0 && b > 0.0)
        return 1.0;
    if (a <= 0.0 && b <= 0.0)
        return 0.0;
    return a > 0.0 ? a / (a - b) : b / (b - a);
}

/* The part of a unit square where the distance, linear along each edge, is
 * positive: the polygon of its positive corners and edge crossings. */
static double square_fraction(const double phi[4])
{
    static const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double px[8], py[8];
    int n = 0;
    for (int i = 0; i < 4; i++) {
        int j = (i + 1) & 3;
        if (phi[i] > 0.0) {
            px[n] = corner[i][0];
            py[n++] = corner[i][1];
        }
        if ((phi[i] > 0.0) != (phi[j] > 0.0)) {
            double t = phi[i] / (phi[i] - phi[j]);
            px[n] = corner[i][0] + t * (corner[j][0] - corner[i][0]);
            py[n++] = corner[i][1] + t * (corner[j][1] - corner[i][1]);
        }
    }
    double area = 0.0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        area += px[i] * py[j] - px[j] * py[i];
    }
    return fabs(0.5 * area);
}

fg_result fg_fluid_clear_solid(fg_fluid *f)
{
    for (int a = 0; a < f->dims; a++)
        for (size_t i = 0; i < f->faces[a]; i++) {
            f->face_fraction[a][i] = 1.0;
            f->face_sdf[a][i] = HUGE_VAL;
        }
    for (size_t c = 0; c < f->cells; c++)
        f->cell_fraction[c] = 1.0;
    f->link_count = 0;
    f->cut_count = 0;
    f->has_solid = 0;
    fg_fluid_multigrid_build(f);
    return fg_fluid_viscosity_build(f);
}

void fg_fluid_impose_solid(fg_fluid *f)
{
    if (!f->has_solid)
        return;
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        size_t id = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, id++) {
                    if (f->face_sdf[a][id] > 0.0 && f->face_fraction[a][id] > 0.0)
                        continue;
                    double x[3], us[3];
                    fg_fluid_face_position(f, a, i, j, k, x);
                    fg_fluid_solid_velocity(f, x, us);
                    f->u[a][id] = us[a];
                }
    }
}

/* The distance at every cell corner, into corner[] ((n+1) per axis, one
 * layer in 2-D). Returns 0, or -1 when a value is not finite. */
static int sample_corners(const fg_fluid *f, fg_fluid_sdf_fn sdf, void *user, double *corner)
{
    int m[3] = {f->n[0] + 1, f->n[1] + 1, f->dims == 3 ? f->n[2] + 1 : 1};
    size_t id = 0;
    for (int k = 0; k < m[2]; k++)
        for (int j = 0; j < m[1]; j++)
            for (int i = 0; i < m[0]; i++, id++) {
                double x[3] = {f->config.origin_m[0] + f->h * i,
                               f->config.origin_m[1] + f->h * j,
                               f->dims == 3 ? f->config.origin_m[2] + f->h * k : 0.0};
                corner[id] = sdf(x, user);
                if (!isfinite(corner[id]))
                    return -1;
            }
    return 0;
}

static int sample_nodes(const fg_fluid *f, fg_fluid_sdf_fn sdf, void *user, double *node[3])
{
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        size_t id = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, id++) {
                    double x[3];
                    fg_fluid_face_position(f, a, i, j, k, x);
                    node[a][id] = sdf(x, user);
                    if (!isfinite(node[a][id]))
                        return -1;
                }
    }
    return 0;
}

static void face_fractions(fg_fluid *f, const double *corner)
{
    size_t cx = 1, cy = (size_t)f->n[0] + 1, cz = cy * ((size_t)f->n[1] + 1);
    size_t step[3] = {cx, cy, cz};
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        int p = (a + 1) % 3, q = (a + 2) % 3;
        size_t id = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, id++) {
                    size_t c0 = (size_t)i * cx + (size_t)j * cy +
                                (f->dims == 3 ? (size_t)k * cz : 0);
                    double w;
                    if (f->dims == 2) {
                        /* the face of axis a spans the other in-plane axis */
                        size_t s = step[a == 0 ? 1 : 0];
                        w = segment_fraction(corner[c0], corner[c0 + s]);
                    } else {
                        double phi[4] = {corner[c0], corner[c0 + step[p]],
                                         corner[c0 + step[p] + step[q]], corner[c0 + step[q]]};
                        w = square_fraction(phi);
                    }
                    f->face_fraction[a][id] = w < MIN_FACE_FRACTION ? 0.0 : w;
                }
    }
}

/* Cell fractions, and the cut cells with their solid surface's vector area. */
static fg_result cut_cells(fg_fluid *f)
{
    double area = f->dims == 2 ? f->h : f->h * f->h;
    size_t count = 0, cap = 0;
    fg_fluid_cut_cell *cut = NULL;
    for (int k = 0; k < f->n[2]; k++)
        for (int j = 0; j < f->n[1]; j++)
            for (int i = 0; i < f->n[0]; i++) {
                size_t c = fg_fluid_cell_index(f, i, j, k);
                double sum = 0.0, an[3] = {0, 0, 0};
                int ijk[3] = {i, j, k}, partial = 0;
                for (int a = 0; a < f->dims; a++) {
                    int lo[3] = {ijk[0], ijk[1], ijk[2]}, hi[3] = {ijk[0], ijk[1], ijk[2]};
                    hi[a]++;
                    double wl = f->face_fraction[a][fg_fluid_face_index(f, a, lo[0], lo[1], lo[2])];
                    double wh = f->face_fraction[a][fg_fluid_face_index(f, a, hi[0], hi[1], hi[2])];
                    sum += wl + wh;
                    an[a] = (wh - wl) * area;
                    partial |= wl < 1.0 || wh < 1.0;
                }
                f->cell_fraction[c] = sum / (2.0 * f->dims);
                if (!partial || sum == 0.0)
                    continue;
                if (fabs(an[0]) + fabs(an[1]) + fabs(an[2]) < 1e-9 * area)
                    continue;
                fg_fluid_cut_cell *grown = fg_array_grow(cut, &cap, count + 1, sizeof *cut, 256);
                if (!grown) {
                    free(cut);
                    return FG_ERR_NO_MEMORY;
                }
                cut = grown;
                cut[count].cell = c;
                memcpy(cut[count].area_normal, an, sizeof an);
                count++;
            }
    free(f->cut);
    free(f->cut_force);
    f->cut = cut;
    f->cut_count = count;
    f->cut_force = calloc(count ? 3 * count : 1, sizeof(double));
    return f->cut_force ? FG_OK : FG_ERR_NO_MEMORY;
}

static fg_result wall_links(fg_fluid *f)
{
    size_t count = 0, cap = 0;
    fg_fluid_wall_link *links = NULL;
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        const double *sdf = f->face_sdf[a];
        size_t id = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, id++) {
                    if (!(sdf[id] > 0.0))
                        continue;
                    int ijk[3] = {i, j, k};
                    for (int b = 0; b < f->dims; b++)
                        for (int side = 0; side < 2; side++) {
                            int nb = ijk[b] + (side ? 1 : -1);
                            if (nb < 0 || nb >= m[b])
                                continue;
                            int p[3] = {ijk[0], ijk[1], ijk[2]};
                            p[b] = nb;
                            double other = sdf[fg_fluid_face_index(f, a, p[0], p[1], p[2])];
                            if (other > 0.0)
                                continue;
                            double theta = sdf[id] / (sdf[id] - other);
                            fg_fluid_wall_link *grown =
                                fg_array_grow(links, &cap, count + 1, sizeof *links, 256);
                            if (!grown) {
                                free(links);
                                return FG_ERR_NO_MEMORY;
                            }
                            links = grown;
                            links[count++] = (fg_fluid_wall_link){
                                .face = id, .component = (uint8_t)a, .dir_axis = (uint8_t)b,
                                .dir_side = (uint8_t)side,
                                .theta = (float)(theta < MIN_THETA ? MIN_THETA : theta)};
                        }
                }
    }
    free(f->links);
    free(f->link_force);
    free(f->link_wall);
    f->links = links;
    f->link_count = count;
    f->link_force = calloc(count ? count : 1, sizeof(double));
    f->link_wall = calloc(count ? count : 1, sizeof(double));
    return f->link_force && f->link_wall ? FG_OK : FG_ERR_NO_MEMORY;
}

fg_result fg_fluid_set_solid(fg_fluid *f, fg_fluid_sdf_fn sdf, void *user)
{
    if (!f)
        return FG_ERR_NULL;
    if (!sdf)
        return fg_fluid_clear_solid(f);
    size_t corners = ((size_t)f->n[0] + 1) * ((size_t)f->n[1] + 1) *
                     (f->dims == 3 ? (size_t)f->n[2] + 1 : 1);
    double *corner = malloc(corners * sizeof(double));
    double *node[3] = {NULL, NULL, NULL};
    fg_result r = corner ? FG_OK : FG_ERR_NO_MEMORY;
    for (int a = 0; a < f->dims && r == FG_OK; a++)
        if (!(node[a] = malloc(f->faces[a] * sizeof(double))))
            r = FG_ERR_NO_MEMORY;
    if (r == FG_OK && (sample_corners(f, sdf, user, corner) != 0 ||
                       sample_nodes(f, sdf, user, node) != 0))
        r = FG_ERR_NOT_FINITE;
    if (r == FG_OK) {
        for (int a = 0; a < f->dims; a++) {
            double *old = f->face_sdf[a];
            f->face_sdf[a] = node[a];
            node[a] = old;
        }
        face_fractions(f, corner);
        r = cut_cells(f);
        if (r == FG_OK)
            r = wall_links(f);
        f->has_solid = 1;
        fg_fluid_multigrid_build(f);
        if (r == FG_OK)
            r = fg_fluid_viscosity_build(f);
        fg_fluid_impose_solid(f);
    }
    free(corner);
    for (int a = 0; a < 3; a++)
        free(node[a]);
    return r;
}

fg_result fg_fluid_set_solid_motion(fg_fluid *f, const double v[3], const double omega[3],
                                    const double centre[3])
{
    if (!f)
        return FG_ERR_NULL;
    const double zero[3] = {0, 0, 0};
    v = v ? v : zero;
    omega = omega ? omega : zero;
    centre = centre ? centre : zero;
    for (int a = 0; a < 3; a++)
        if (!isfinite(v[a]) || !isfinite(omega[a]) || !isfinite(centre[a]))
            return FG_ERR_NOT_FINITE;
    memcpy(f->solid_v, v, sizeof f->solid_v);
    memcpy(f->solid_omega, omega, sizeof f->solid_omega);
    memcpy(f->solid_centre, centre, sizeof f->solid_centre);
    return FG_OK;
}
