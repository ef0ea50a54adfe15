/* Viscosity: Crank-Nicolson, (1 - dt nu L / 2) u = (1 + dt nu L / 2) u*,
 * by Gauss-Seidel.
 *
 * L is the standard 5/7-point Laplacian per velocity component. Along an
 * axis where a node has a wall at distance d != h (the solid, theta * h; a
 * no-slip face of the box, h / 2) the second difference is the non-uniform
 * one, 2 / (dl + dr) * ((ul - u0) / dl + (ur - u0) / dr) (Shortley-Weller):
 * the no-slip condition holds at the true wall, to second order. Implicit,
 * because a wall at theta * h makes the explicit limit theta times smaller.
 * The matrix is diagonally dominant with ratio 2 dims lambda / (1 + 2 dims
 * lambda), lambda = nu dt / 2h^2, so a few sweeps converge. Interior nodes
 * are swept red-black (no chain of dependent updates along a row); the
 * nodes next to a wall or the box have their weights precomputed when the
 * solid is set.
 *
 * The wall shear the step applies, rho nu (u0 - u_wall) / (theta h) per
 * link times the node's transverse area (averaged over the step's two
 * halves), is the viscous force on the
 * solid: summed over the links of all axes it approximates the integral of
 * mu du/dn over the surface, which at a rigid no-slip wall is the viscous
 * traction (the normal viscous stress vanishes there by continuity). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_state_internal.h"

#define MAX_SWEEPS 60
#define SWEEP_TOLERANCE 1e-7 /* of the largest speed */

/* Is node (ijk) of component a held fixed (box normal face, or solid)? */
static int fixed_node(const fg_fluid *f, int a, const int ijk[3], size_t id)
{
    if (ijk[a] == 0 && f->config.boundary[a][0] != FG_FLUID_OPEN)
        return 1;
    if (ijk[a] == f->fsize[a][a] - 1 && f->config.boundary[a][1] != FG_FLUID_OPEN)
        return 1;
    return !(f->face_sdf[a][id] > 0.0 && f->face_fraction[a][id] > 0.0);
}

/* The wall link of a node's side, or -1; links are ordered by component,
 * then node, and the cursor only moves forward. */
static int32_t find_link(const fg_fluid *f, size_t *cursor, int a, size_t id, int b, int side)
{
    while (*cursor < f->link_count &&
           (f->links[*cursor].component < a ||
            (f->links[*cursor].component == a && f->links[*cursor].face < id)))
        (*cursor)++;
    for (size_t l = *cursor; l < f->link_count && f->links[l].component == a &&
                             f->links[l].face == id;
         l++)
        if (f->links[l].dir_axis == b && f->links[l].dir_side == side)
            return (int32_t)l;
    return -1;
}

/* The weights of a node with a wall or a box face on some side. */
static void special_node(const fg_fluid *f, int a, const int ijk[3], size_t id, size_t *cursor,
                         fg_fluid_visc_node *v)
{
    v->id = id;
    v->component = (uint8_t)a;
    for (int b = 0; b < f->dims; b++) {
        double d[2];
        int has[2];
        for (int side = 0; side < 2; side++) {
            int s = 2 * b + side;
            v->link[s] = find_link(f, cursor, a, id, b, side);
            v->box[s] = 0;
            d[side] = 1.0;
            has[side] = 1;
            if (v->link[s] >= 0) {
                d[side] = f->links[v->link[s]].theta;
                continue;
            }
            int nb = ijk[b] + (side ? 1 : -1);
            if (nb >= 0 && nb < f->fsize[a][b])
                continue;
            /* beyond the box: a no-slip or inflow face is a wall h/2 away
             * for a tangential component; anything else is zero-gradient */
            fg_fluid_boundary t = f->config.boundary[b][side];
            if (b != a && (t == FG_FLUID_WALL || t == FG_FLUID_INFLOW)) {
                d[side] = 0.5;
                v->box[s] = 1;
            } else {
                has[side] = 0;
            }
        }
        for (int side = 0; side < 2; side++)
            v->weight[2 * b + side] = has[side] ? (float)(2.0 / ((d[0] + d[1]) * d[side])) : 0.0f;
    }
}

fg_result fg_fluid_viscosity_build(fg_fluid *f)
{
    size_t count = 0;
    for (int pass = 0; pass < 2; pass++) {
        size_t n = 0;
        for (int a = 0; a < f->dims; a++) {
            const int *m = f->fsize[a];
            size_t cursor = 0, id = 0;
            for (int k = 0; k < m[2]; k++)
                for (int j = 0; j < m[1]; j++)
                    for (int i = 0; i < m[0]; i++, id++) {
                        int ijk[3] = {i, j, k};
                        uint8_t kind = FG_VISC_REGULAR;
                        if (fixed_node(f, a, ijk, id)) {
                            kind = FG_VISC_FIXED;
                        } else {
                            for (int b = 0; b < f->dims && kind == FG_VISC_REGULAR; b++) {
                                if (ijk[b] == 0 || ijk[b] == m[b] - 1)
                                    kind = FG_VISC_SPECIAL;
                                for (int side = 0; side < 2; side++)
                                    if (find_link(f, &cursor, a, id, b, side) >= 0)
                                        kind = FG_VISC_SPECIAL;
                            }
                        }
                        if (pass == 1) {
                            f->visc_kind[a][id] = kind;
                            if (kind == FG_VISC_SPECIAL)
                                special_node(f, a, ijk, id, &cursor, &f->visc_nodes[n]);
                        }
                        n += kind == FG_VISC_SPECIAL;
                    }
        }
        if (pass == 0) {
            count = n;
            free(f->visc_nodes);
            f->visc_nodes = malloc((count ? count : 1) * sizeof *f->visc_nodes);
            if (!f->visc_nodes)
                return FG_ERR_NO_MEMORY;
        }
    }
    f->visc_count = count;
    return FG_OK;
}

/* The solid's velocity at each link's wall point, along the link's component. */
static void wall_velocities(fg_fluid *f)
{
    for (size_t l = 0; l < f->link_count; l++) {
        const fg_fluid_wall_link *k = &f->links[l];
        const int *m = f->fsize[k->component];
        int ijk[3] = {(int)(k->face % (size_t)m[0]), (int)(k->face / (size_t)m[0] % (size_t)m[1]),
                      (int)(k->face / ((size_t)m[0] * (size_t)m[1]))};
        double x[3], us[3];
        fg_fluid_face_position(f, k->component, ijk[0], ijk[1], ijk[2], x);
        x[k->dir_axis] += (k->dir_side ? 1.0 : -1.0) * k->theta * f->h;
        fg_fluid_solid_velocity(f, x, us);
        f->link_wall[l] = us[k->component];
    }
}

/* For a node next to a wall or the box: the sum of its side weights
 * times lambda, and of the weighted side values. */
static void special_sums(const fg_fluid *f, const fg_fluid_visc_node *v, double lambda,
                         double *weights, double *values)
{
    int a = v->component;
    const double *u = f->u[a];
    size_t stride[3] = {1, (size_t)f->fsize[a][0], (size_t)f->fsize[a][0] * f->fsize[a][1]};
    double w = 0.0, sum = 0.0;
    for (int s = 0; s < 2 * f->dims; s++) {
        if (v->weight[s] == 0.0f)
            continue;
        double value;
        if (v->link[s] >= 0)
            value = f->link_wall[v->link[s]];
        else if (v->box[s])
            value = f->config.boundary[s / 2][s & 1] == FG_FLUID_INFLOW ? f->config.inflow_m_s[a]
                                                                          : 0.0;
        else
            value = u[(s & 1) ? v->id + stride[s / 2] : v->id - stride[s / 2]];
        double c = lambda * v->weight[s];
        w += c;
        sum += c * value;
    }
    *weights = w;
    *values = sum;
}

static double relax_special(fg_fluid *f, const fg_fluid_visc_node *v, const double *rhs,
                            double lambda)
{
    double w, sum;
    special_sums(f, v, lambda, &w, &sum);
    double *u = f->u[v->component];
    double next = (rhs[v->id] + sum) / (1.0 + w), change = fabs(next - u[v->id]);
    u[v->id] = next;
    return change;
}

/* rhs = u + lambda L u (the explicit half of Crank-Nicolson). */
static void explicit_half(fg_fluid *f, int a, double *rhs, double lambda)
{
    const int *m = f->fsize[a];
    size_t sy = (size_t)m[0], sz = sy * (size_t)m[1];
    const double *u = f->u[a];
    const uint8_t *kind = f->visc_kind[a];
    memcpy(rhs, u, f->faces[a] * sizeof(double));
    int k0 = f->dims == 3 ? 1 : 0, k1 = f->dims == 3 ? m[2] - 1 : 1;
    for (int k = k0; k < k1; k++)
        for (int j = 1; j < m[1] - 1; j++) {
            size_t row = sy * (size_t)j + sz * (size_t)k;
            for (int i = 1; i < m[0] - 1; i++) {
                size_t id = row + (size_t)i;
                if (kind[id] != FG_VISC_REGULAR)
                    continue;
                double s = u[id - 1] + u[id + 1] + u[id - sy] + u[id + sy] - 4.0 * u[id];
                if (f->dims == 3)
                    s += u[id - sz] + u[id + sz] - 2.0 * u[id];
                rhs[id] += lambda * s;
            }
        }
    for (size_t n = 0; n < f->visc_count; n++) {
        const fg_fluid_visc_node *v = &f->visc_nodes[n];
        if (v->component != a)
            continue;
        double w, sum;
        special_sums(f, v, lambda, &w, &sum);
        rhs[v->id] += sum - w * u[v->id];
    }
}

/* One red-black half-sweep over the interior nodes of a component. */
static double sweep_regular(fg_fluid *f, int a, int color, const double *rhs, double lambda)
{
    const int *m = f->fsize[a];
    size_t sy = (size_t)m[0], sz = sy * (size_t)m[1];
    double *u = f->u[a], inv = 1.0 / (1.0 + 2.0 * f->dims * lambda), change = 0.0;
    const uint8_t *kind = f->visc_kind[a];
    int k0 = f->dims == 3 ? 1 : 0, k1 = f->dims == 3 ? m[2] - 1 : 1;
    for (int k = k0; k < k1; k++)
        for (int j = 1; j < m[1] - 1; j++) {
            size_t row = sy * (size_t)j + sz * (size_t)k;
            for (int i = 1 + ((1 + j + k + color) & 1); i < m[0] - 1; i += 2) {
                size_t id = row + (size_t)i;
                if (kind[id] != FG_VISC_REGULAR)
                    continue;
                double s = u[id - 1] + u[id + 1] + u[id - sy] + u[id + sy];
                if (f->dims == 3)
                    s += u[id - sz] + u[id + sz];
                double next = (rhs[id] + lambda * s) * inv;
                double d = fabs(next - u[id]);
                change = d > change ? d : change;
                u[id] = next;
            }
        }
    return change;
}

/* Adds weight times the wall shear of the current velocity to the links'
 * forces. */
static void wall_forces(fg_fluid *f, double weight)
{
    double area = f->dims == 2 ? f->h : f->h * f->h;
    for (size_t l = 0; l < f->link_count; l++) {
        const fg_fluid_wall_link *k = &f->links[l];
        double du = f->u[k->component][k->face] - f->link_wall[l];
        f->link_force[l] += weight * f->rho * f->nu * du / (k->theta * f->h) * area;
    }
}

void fg_fluid_apply_viscosity(fg_fluid *f, double dt)
{
    if (f->link_count)
        memset(f->link_force, 0, f->link_count * sizeof(double));
    if (!(f->nu > 0.0))
        return;
    /* Crank-Nicolson: (1 - lambda/2 L) u = (1 + lambda/2 L) u* */
    double lambda = 0.5 * f->nu * dt / (f->h * f->h), scale = fg_fluid_max_speed(f);
    wall_velocities(f);
    wall_forces(f, 0.5); /* the explicit half's wall shear */
    for (int a = 0; a < f->dims; a++)
        explicit_half(f, a, f->u_fwd[a], lambda);
    for (int sweep = 0; sweep < MAX_SWEEPS; sweep++) {
        double change = 0.0;
        for (int a = 0; a < f->dims; a++)
            for (int color = 0; color < 2; color++) {
                double d = sweep_regular(f, a, color, f->u_fwd[a], lambda);
                change = d > change ? d : change;
            }
        for (size_t n = 0; n < f->visc_count; n++) {
            const fg_fluid_visc_node *v = &f->visc_nodes[n];
            double d = relax_special(f, v, f->u_fwd[v->component], lambda);
            change = d > change ? d : change;
        }
        if (change <= SWEEP_TOLERANCE * scale)
            break;
    }
    wall_forces(f, 0.5); /* and the implicit half's */
}
