/* The pressure projection on the cut-cell grid.
 *
 * With q = dt p / rho on the cells, the projected velocity on every face
 * with fluid is u = u* - dq/dx (across the face; beyond an open face of the
 * box q = 0), and the discrete divergence of a cell counts each face's
 * flux as w u + (1 - w) u_solid, w the face's fluid fraction. Asking that
 * divergence to equal phi times the cell's fluid volume gives A q = phi V -
 * div u*, A the weighted Laplacian of fluid_multigrid.c: the
 * energy-minimising projection of Batty, Bertails & Bridson (2007), whose
 * pressure converges at second order next to curved walls (Ng, Min & Gibou
 * 2009) where a staircase would give first order. */
#include <math.h>
#include <string.h>

#include "fluid_state_internal.h"

/* The flux every face carries, into flux[a] (face layout): its fluid part
 * moves with u, its solid part with the solid. */
static void face_fluxes(fg_fluid *f, double *const flux[3])
{
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        const double *w = f->face_fraction[a], *u = f->u[a];
        size_t id = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, id++) {
                    double v = w[id] * u[id];
                    if (w[id] < 1.0) {
                        double x[3], us[3];
                        fg_fluid_face_position(f, a, i, j, k, x);
                        fg_fluid_solid_velocity(f, x, us);
                        v += (1.0 - w[id]) * us[a];
                    }
                    flux[a][id] = v;
                }
    }
}

static void right_hand_side(fg_fluid *f, const double *phi)
{
    double area = f->dims == 2 ? f->h : f->h * f->h, volume = area * f->h;
    const fg_fluid_level *L0 = &f->level[0];
    /* the MacCormack scratch is free once the velocity has been advected */
    double *const *flux = f->u_fwd;
    face_fluxes(f, flux);
    size_t n0 = (size_t)f->n[0], n1 = (size_t)f->n[1];
    size_t step[3] = {1, n0, n0 * n1};
    double gross = 0.0;
    size_t c = 0;
    for (int k = 0; k < f->n[2]; k++)
        for (int j = 0; j < f->n[1]; j++)
            for (int i = 0; i < f->n[0]; i++, c++) {
                if (L0->diag[c] == 0.0) {
                    f->div_rhs[c] = 0.0;
                    continue;
                }
                /* the low face of cell (i, j, k) on axis a has the index
                 * c + (row offset of the longer axis) */
                size_t low[3] = {c + (size_t)j + (size_t)k * n1, c + (size_t)k * n0, c};
                double div = 0.0, through = 0.0;
                for (int a = 0; a < f->dims; a++) {
                    double in = flux[a][low[a]], out = flux[a][low[a] + step[a]];
                    div += out - in;
                    through += fabs(out) + fabs(in);
                }
                double target = phi ? phi[c] * f->cell_fraction[c] * volume : 0.0;
                f->div_rhs[c] = target - div * area;
                gross += through * through * area * area;
            }
    f->flux_norm = sqrt(gross);
}

void fg_fluid_pressure_gradient(fg_fluid *f, double *const u[3], const double *field,
                                double scale)
{
    double inv_h = scale / f->h;
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        size_t id = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, id++) {
                    if (f->face_fraction[a][id] == 0.0)
                        continue;
                    int ijk[3] = {i, j, k};
                    int low = ijk[a] == 0, high = ijk[a] == m[a] - 1;
                    if ((low && f->config.boundary[a][0] != FG_FLUID_OPEN) ||
                        (high && f->config.boundary[a][1] != FG_FLUID_OPEN))
                        continue;
                    /* cells on either side: ijk[a] - 1 and ijk[a] */
                    int cell[3] = {i, j, k};
                    double qh = 0.0, ql = 0.0;
                    if (!high)
                        qh = field[fg_fluid_cell_index(f, cell[0], cell[1], cell[2])];
                    if (!low) {
                        cell[a]--;
                        ql = field[fg_fluid_cell_index(f, cell[0], cell[1], cell[2])];
                    }
                    u[a][id] -= (qh - ql) * inv_h;
                }
    }
}

fg_result fg_fluid_solve_pressure(fg_fluid *f, double dt, const double *phi, double share)
{
    const fg_fluid_level *L0 = &f->level[0];
    double to_q = share * dt / f->rho;
    right_hand_side(f, phi);
    for (size_t c = 0; c < f->cells; c++)
        f->q[c] = f->pressure[c] * to_q; /* warm start: the last pressure */
    fg_result r = fg_fluid_multigrid_solve(f);
    fg_fluid_pressure_gradient(f, f->u, f->q, 1.0);
    for (size_t c = 0; c < f->cells; c++)
        f->pressure[c] = L0->diag[c] != 0.0 ? f->q[c] / to_q : 0.0;
    fg_fluid_pressure_force(f);
    return r;
}

fg_result fg_fluid_project(fg_fluid *f, double dt, const double *phi)
{
    return fg_fluid_solve_pressure(f, dt, phi, 1.0);
}
