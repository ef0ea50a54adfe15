/* The fluid grid: creation with validated configuration, its storage,
 * views and diagnostics. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_state_internal.h"

#define MAX_CELLS (1u << 28)
#define DEFAULT_TOLERANCE 1e-6
#define DEFAULT_ITERATIONS 200

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static fg_result check_config(const fg_fluid_config *c)
{
    if (c->dims != 2 && c->dims != 3)
        return FG_ERR_ARGUMENT;
    double total = 1.0;
    for (int a = 0; a < c->dims; a++) {
        if (c->cells[a] < 4)
            return FG_ERR_ARGUMENT;
        total *= c->cells[a];
    }
    if (total > MAX_CELLS)
        return FG_ERR_ARGUMENT;
    if (!isfinite(c->cell_m) || !finite3(c->origin_m) || !finite3(c->inflow_m_s) ||
        !isfinite(c->viscosity_m2_s) || !isfinite(c->density_kg_m3) || !isfinite(c->tolerance))
        return FG_ERR_NOT_FINITE;
    if (!(c->cell_m > 0.0) || c->density_kg_m3 < 0.0)
        return FG_ERR_ARGUMENT;
    for (int a = 0; a < 3; a++)
        for (int s = 0; s < 2; s++)
            if ((unsigned)c->boundary[a][s] > FG_FLUID_OPEN)
                return FG_ERR_ARGUMENT;
    if (c->scalars < 0 || c->scalars > FG_FLUID_MAX_SCALARS)
        return FG_ERR_ARGUMENT;
    for (int k = 0; k < c->scalars; k++)
        if (!isfinite(c->inflow_scalar[k]))
            return FG_ERR_NOT_FINITE;
    if (c->tolerance < 0.0 || c->tolerance >= 1.0 || c->max_iterations < 0)
        return FG_ERR_ARGUMENT;
    return FG_OK;
}

static fg_result allocate(fg_fluid *f)
{
    size_t cells = f->cells;
    for (int a = 0; a < f->dims; a++) {
        size_t m = f->faces[a];
        f->u[a] = calloc(m, sizeof(double));
        f->u_prev[a] = calloc(m, sizeof(double));
        f->u_old[a] = calloc(m, sizeof(double));
        f->u_carry[a] = calloc(m, sizeof(double));
        f->u_src[a] = calloc(m, sizeof(double));
        f->u_fwd[a] = calloc(m, sizeof(double));
        f->lo[a] = calloc(m, sizeof(double));
        f->hi[a] = calloc(m, sizeof(double));
        f->face_fraction[a] = calloc(m, sizeof(double));
        f->face_sdf[a] = calloc(m, sizeof(double));
        f->visc_kind[a] = calloc(m, 1);
        if (!f->visc_kind[a] || !f->u[a] || !f->u_prev[a] || !f->u_old[a] || !f->u_carry[a] || !f->u_src[a] || !f->u_fwd[a] || !f->lo[a] || !f->hi[a] ||
            !f->face_fraction[a] || !f->face_sdf[a])
            return FG_ERR_NO_MEMORY;
    }
    for (int k = 0; k < f->config.scalars; k++)
        if (!(f->s[k] = calloc(cells, sizeof(double))))
            return FG_ERR_NO_MEMORY;
    if (f->config.scalars > 0) {
        for (int k = 0; k < 3; k++)
            if (!(f->s_scratch[k] = calloc(cells, sizeof(double))))
                return FG_ERR_NO_MEMORY;
        f->s_lo = f->s_scratch[1];
        f->s_hi = f->s_scratch[2];
    }
    size_t most = cells;
    for (int a = 0; a < f->dims; a++)
        most = f->faces[a] > most ? f->faces[a] : most;
    if (!(f->disp = malloc(most * (size_t)f->dims * sizeof(double))))
        return FG_ERR_NO_MEMORY;
    double **cell_arrays[] = {&f->q, &f->pressure, &f->div_rhs, &f->phi, &f->pcg_z,
                              &f->pcg_p, &f->pcg_ap, &f->cell_fraction};
    for (size_t i = 0; i < sizeof cell_arrays / sizeof cell_arrays[0]; i++)
        if (!(*cell_arrays[i] = calloc(cells, sizeof(double))))
            return FG_ERR_NO_MEMORY;
    return fg_fluid_multigrid_init(f);
}

size_t fg_fluid_memory_bytes(const fg_fluid_config *c)
{
    if (!c || check_config(c) != FG_OK)
        return 0;
    int n[3] = {c->cells[0], c->cells[1], c->dims == 3 ? c->cells[2] : 1};
    size_t cells = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    size_t bytes = sizeof(fg_fluid), most = cells;
    for (int a = 0; a < c->dims; a++) {
        size_t faces = 1, inner = 1;
        for (int b = 0; b < 3; b++) {
            int m = n[b] + (a == b);
            faces *= (size_t)m;
            inner *= b < c->dims && m > 2 ? (size_t)(m - 2) : (size_t)(b < c->dims ? 0 : m);
        }
        most = faces > most ? faces : most;
        /* u, u_prev, u_old, u_carry, u_src, u_fwd, lo, hi, face_fraction,
         * face_sdf; visc_kind; the viscous nodes on the box's faces */
        bytes += faces * (10 * sizeof(double) + 1) + (faces - inner) * sizeof(fg_fluid_visc_node);
    }
    size_t scalar_arrays = (size_t)c->scalars + (c->scalars > 0 ? 3 : 0);
    bytes += (scalar_arrays + 8) * cells * sizeof(double);
    bytes += most * (size_t)c->dims * sizeof(double);
    return bytes + fg_fluid_multigrid_bytes(c->dims, n);
}

fg_result fg_fluid_create(const fg_fluid_config *c, fg_fluid **out)
{
    if (!c || !out)
        return FG_ERR_NULL;
    fg_result r = check_config(c);
    if (r != FG_OK)
        return r;
    fg_fluid *f = calloc(1, sizeof *f);
    if (!f)
        return FG_ERR_NO_MEMORY;
    f->config = *c;
    f->dims = c->dims;
    f->h = c->cell_m;
    if (f->config.viscosity_m2_s == 0.0)
        f->config.viscosity_m2_s = FG_AIR_KINEMATIC_VISCOSITY;
    if (f->config.density_kg_m3 == 0.0)
        f->config.density_kg_m3 = FG_AIR_DENSITY;
    if (f->config.tolerance == 0.0)
        f->config.tolerance = DEFAULT_TOLERANCE;
    if (f->config.max_iterations == 0)
        f->config.max_iterations = DEFAULT_ITERATIONS;
    f->nu = f->config.viscosity_m2_s > 0.0 ? f->config.viscosity_m2_s : 0.0;
    f->rho = f->config.density_kg_m3;
    if (f->dims == 2) {
        f->config.cells[2] = 1;
        f->config.origin_m[2] = 0.0;
        f->config.inflow_m_s[2] = 0.0;
        f->config.boundary[2][0] = f->config.boundary[2][1] = FG_FLUID_SLIP;
    }
    for (int a = 0; a < 3; a++)
        f->n[a] = f->config.cells[a];
    f->cells = (size_t)f->n[0] * (size_t)f->n[1] * (size_t)f->n[2];
    for (int a = 0; a < f->dims; a++) {
        for (int b = 0; b < 3; b++)
            f->fsize[a][b] = f->n[b] + (a == b);
        f->faces[a] = (size_t)f->fsize[a][0] * (size_t)f->fsize[a][1] * (size_t)f->fsize[a][2];
    }
    f->singular = 1;
    for (int a = 0; a < f->dims; a++)
        for (int s = 0; s < 2; s++)
            if (f->config.boundary[a][s] == FG_FLUID_OPEN)
                f->singular = 0;
    r = allocate(f);
    if (r != FG_OK) {
        fg_fluid_destroy(f);
        return r;
    }
    r = fg_fluid_clear_solid(f);
    if (r != FG_OK) {
        fg_fluid_destroy(f);
        return r;
    }
    fg_fluid_impose_box(f);
    *out = f;
    return FG_OK;
}

void fg_fluid_destroy(fg_fluid *f)
{
    if (!f)
        return;
    for (int a = 0; a < 3; a++) {
        free(f->u[a]);
        free(f->u_prev[a]);
        free(f->u_old[a]);
        free(f->u_carry[a]);
        free(f->u_src[a]);
        free(f->u_fwd[a]);
        free(f->lo[a]);
        free(f->hi[a]);
        free(f->face_fraction[a]);
        free(f->face_sdf[a]);
        free(f->visc_kind[a]);
        free(f->s_scratch[a]);
    }
    for (int k = 0; k < FG_FLUID_MAX_SCALARS; k++)
        free(f->s[k]);
    free(f->disp);
    free(f->q);
    free(f->pressure);
    free(f->div_rhs);
    free(f->phi);
    free(f->pcg_z);
    free(f->pcg_p);
    free(f->pcg_ap);
    free(f->cell_fraction);
    free(f->links);
    free(f->link_force);
    free(f->link_wall);
    free(f->visc_nodes);
    free(f->cut);
    free(f->cut_force);
    fg_fluid_multigrid_deinit(f);
    free(f);
}

const fg_fluid_config *fg_fluid_get_config(const fg_fluid *f)
{
    return &f->config;
}

static fg_fluid_array view(const fg_fluid *f, double *data, const int size[3], int a)
{
    fg_fluid_array v = {.data = data, .cell_m = f->h};
    for (int b = 0; b < 3; b++) {
        v.size[b] = size[b];
        v.origin_m[b] = f->config.origin_m[b] + f->h * (b == a ? 0.0 : 0.5);
    }
    if (f->dims == 2)
        v.origin_m[2] = 0.0;
    v.stride[0] = 1;
    v.stride[1] = (size_t)size[0];
    v.stride[2] = (size_t)size[0] * (size_t)size[1];
    return v;
}

fg_fluid_array fg_fluid_velocity(fg_fluid *f, int axis)
{
    return view(f, f->u[axis], f->fsize[axis], axis);
}

fg_fluid_array fg_fluid_scalar(fg_fluid *f, int k)
{
    return view(f, f->s[k], f->n, -1);
}

fg_fluid_array fg_fluid_pressure(fg_fluid *f)
{
    return view(f, f->pressure, f->n, -1);
}

const fg_fluid_report *fg_fluid_last_report(const fg_fluid *f)
{
    return &f->report;
}

double fg_fluid_time_s(const fg_fluid *f)
{
    return f->time;
}

double fg_fluid_max_speed(const fg_fluid *f)
{
    double m = 0.0;
    for (int a = 0; a < f->dims; a++)
        for (size_t i = 0; i < f->faces[a]; i++)
            m = fmax(m, fabs(f->u[a][i]));
    return m;
}

double fg_fluid_divergence_error(const fg_fluid *f, const double *phi)
{
    double worst = 0.0, area = f->dims == 2 ? f->h : f->h * f->h;
    for (int k = 0; k < f->n[2]; k++)
        for (int j = 0; j < f->n[1]; j++)
            for (int i = 0; i < f->n[0]; i++) {
                size_t c = fg_fluid_cell_index(f, i, j, k);
                if (f->level[0].diag[c] == 0.0)
                    continue;
                int ijk[3] = {i, j, k};
                double flux = 0.0;
                for (int a = 0; a < f->dims; a++) {
                    for (int side = 0; side < 2; side++) {
                        int fi[3] = {ijk[0], ijk[1], ijk[2]};
                        fi[a] += side;
                        size_t id = fg_fluid_face_index(f, a, fi[0], fi[1], fi[2]);
                        double w = f->face_fraction[a][id], us[3], x[3];
                        fg_fluid_face_position(f, a, fi[0], fi[1], fi[2], x);
                        fg_fluid_solid_velocity(f, x, us);
                        double un = w * f->u[a][id] + (1.0 - w) * us[a];
                        flux += (side ? un : -un) * area;
                    }
                }
                double volume = f->cell_fraction[c] * area * f->h;
                double e = (flux - (phi ? phi[c] * volume : 0.0)) / area;
                worst = fmax(worst, fabs(e));
            }
    return worst;
}

double fg_fluid_kinetic_energy(const fg_fluid *f)
{
    double e = 0.0, volume = f->dims == 2 ? f->h * f->h : f->h * f->h * f->h;
    for (int a = 0; a < f->dims; a++)
        for (size_t i = 0; i < f->faces[a]; i++)
            e += f->face_fraction[a][i] * f->u[a][i] * f->u[a][i];
    return 0.5 * f->rho * e * volume;
}
