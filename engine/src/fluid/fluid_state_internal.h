/* The fluid's storage and the kernels its files share.
 *
 * Cell (i, j, k): index i + n0 * (j + n1 * k), centre at origin + h (i+½,
 * j+½, k+½). Face array of axis a: size n + e_a, index i + m0 * (j + m1 * k)
 * with m = n + e_a; face (i, j, k) of axis a lies between cells i-1 and i
 * along a, at origin + h ((i, j+½, k+½) with the ½ dropped on axis a). In
 * 2-D n2 = 1 and the axis-2 arrays are absent. */
#ifndef FULGUR_FLUID_STATE_INTERNAL_H
#define FULGUR_FLUID_STATE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "fluid_internal.h"

#define FG_FLUID_MAX_LEVELS 12
/* The part of a step's pressure gradient taken at the departure point of
 * the trajectory (fluid_step.c); the arrival point takes the rest. */
#define FG_FLUID_DEPARTURE_SHARE 0.45

/* A velocity node next to the solid: along axis dir_axis, on side dir_side
 * (0: -, 1: +), the wall is theta * h away. */
typedef struct fg_fluid_wall_link {
    size_t face;          /* index in the component's face array */
    uint8_t component;    /* velocity component */
    uint8_t dir_axis;
    uint8_t dir_side;
    float theta;
} fg_fluid_wall_link;

/* A cell cut by the solid: where its surface is and its vector area. */
typedef struct fg_fluid_cut_cell {
    size_t cell;
    double area_normal[3]; /* sum of the fluid face areas times outward normals = the
                              solid surface's area times its outward normal, m^2 (m in 2-D) */
} fg_fluid_cut_cell;

/* A velocity node next to a wall or the box: the weights of its sides in
 * the viscous operator, side (axis b, s) at index 2b + s. */
typedef struct fg_fluid_visc_node {
    size_t id;
    float weight[6];  /* 2 h^2 / ((dl + dr) d_side); 0: no term (zero gradient) */
    int32_t link[6];  /* the side's wall link, or -1 */
    uint8_t box[6];   /* 1: the side's value is the box face's (0, or the inflow) */
    uint8_t component;
} fg_fluid_visc_node;

enum { FG_VISC_REGULAR = 0, FG_VISC_SPECIAL = 1, FG_VISC_FIXED = 2 };

/* One level of the pressure multigrid. Level 0 is the grid. */
typedef struct fg_fluid_level {
    int n[3];
    size_t count;
    double *c[3];  /* conductance of each face (face layout of the level) */
    double *diag;  /* sum of the cell's conductances; 0: the cell is not solved for */
    double *inv_diag; /* 1 / diag, 0 where diag is 0 */
    double *x, *b, *r;
} fg_fluid_level;

struct fg_fluid {
    fg_fluid_config config;
    int dims;
    int n[3];
    double h;
    double nu, rho;
    size_t cells;
    int fsize[3][3];       /* face array sizes per component */
    size_t faces[3];
    double *u[3];          /* velocity */
    double *u_prev[3];     /* u at the start of the step */
    double *u_old[3];      /* u at the start of the last step */
    double *u_carry[3];    /* advection's carrier: u extrapolated to the middle of the step */
    double *u_src[3];      /* what advection moves: u_prev less its share of grad p */
    double dt_prev;        /* the last step's dt; 0 before the first */
    double *u_fwd[3];      /* MacCormack scratch */
    double *lo[3], *hi[3]; /* the MacCormack clamp bounds */
    double *disp;          /* back-trace displacements, dims per node of the largest array */
    double *s[FG_FLUID_MAX_SCALARS];
    double *s_scratch[3];  /* forward, back, clamp scratch for scalars (cell layout) */
    double *s_lo, *s_hi;
    double *q;             /* dt p / rho, the projection's unknown (warm start) */
    double *pressure;      /* Pa */
    double *div_rhs;       /* the projection's right-hand side */
    double *phi;           /* the divergence target the hooks fill */
    double flux_norm;      /* ||sum of |flux| through each cell||: the scale of the rhs */
    double *pcg_z, *pcg_p, *pcg_ap;
    /* solid */
    int has_solid;
    double *face_fraction[3]; /* fluid part of each face, 0..1 */
    double *face_sdf[3];      /* signed distance at each velocity node */
    double *cell_fraction;    /* fluid part of each cell (from its faces) */
    fg_fluid_wall_link *links;
    size_t link_count;
    fg_fluid_cut_cell *cut;
    size_t cut_count;
    double solid_v[3], solid_omega[3], solid_centre[3];
    /* forces of the last step, per cut cell and per wall link */
    double *cut_force;        /* 3 per cut cell */
    double *link_force;       /* 1 per link, along its component */
    double *link_wall;        /* the solid's velocity at each link's wall point */
    uint8_t *visc_kind[3];    /* FG_VISC_* per velocity node */
    fg_fluid_visc_node *visc_nodes;
    size_t visc_count;
    fg_fluid_level level[FG_FLUID_MAX_LEVELS];
    int levels;
    int singular;             /* no open face: pressure fixed up to a constant */
    fg_fluid_report report;
    double time;
};

static inline size_t fg_fluid_cell_index(const fg_fluid *f, int i, int j, int k)
{
    return (size_t)i + (size_t)f->n[0] * ((size_t)j + (size_t)f->n[1] * (size_t)k);
}

static inline size_t fg_fluid_face_index(const fg_fluid *f, int a, int i, int j, int k)
{
    const int *m = f->fsize[a];
    return (size_t)i + (size_t)m[0] * ((size_t)j + (size_t)m[1] * (size_t)k);
}

/* The position of face (i, j, k) of component a. */
static inline void fg_fluid_face_position(const fg_fluid *f, int a, int i, int j, int k,
                                          double x[3])
{
    int ijk[3] = {i, j, k};
    for (int b = 0; b < 3; b++)
        x[b] = f->config.origin_m[b] + f->h * (ijk[b] + (b == a ? 0.0 : 0.5));
    if (f->dims == 2)
        x[2] = 0.0;
}

/* fluid_solid.c */
void fg_fluid_solid_velocity(const fg_fluid *f, const double x[3], double out[3]);
/* Velocity nodes inside the solid (node sdf < 0) get the solid's velocity. */
void fg_fluid_impose_solid(fg_fluid *f);
/* Sets every face and cell fully fluid (no solid). Errors: NO_MEMORY. */
fg_result fg_fluid_clear_solid(fg_fluid *f);

/* fluid_viscosity.c — classifies the velocity nodes after a solid change;
 * the viscous step and the wall shear on the solid. */
fg_result fg_fluid_viscosity_build(fg_fluid *f);
void fg_fluid_apply_viscosity(fg_fluid *f, double dt);

/* fluid_boundary.c — the domain box. */
/* Normal velocity on the WALL, SLIP and INFLOW faces of the box. */
void fg_fluid_impose_box(fg_fluid *f);

/* Interpolation in one array (a component's faces, or the cells) at grid
 * coordinates g = (x - origin) / h, clamped into the array; beyond an
 * INFLOW face of the box it returns the inflow value. */
typedef struct fg_fluid_sampler {
    const double *arr;
    int dims;
    int top[3];        /* last index per axis */
    size_t sy, sz;
    double off[3];     /* 0 along the component's axis, 1/2 across */
    double box[3];     /* cells per axis */
    int inflow_lo[3], inflow_hi[3];
    int any_inflow;
    double inflow_value;
} fg_fluid_sampler;

/* a: component, or -1 for a cell array. */
fg_fluid_sampler fg_fluid_make_sampler(const fg_fluid *f, const double *arr, int a,
                                       double inflow_value);

/* Inlined: it is the inner loop of advection, and GCC's heuristics keep it
 * out of line otherwise (a third of the step's time in calls). */
#if defined(__GNUC__)
#define FG_FLUID_HOT static inline __attribute__((always_inline))
#else
#define FG_FLUID_HOT static inline
#endif

/* dims is passed as a constant so that each caller gets its own unrolled copy. */
FG_FLUID_HOT double fg_fluid_sample(const fg_fluid_sampler *s, int dims, const double g[3],
                                     double *lo, double *hi)
{
    if (s->any_inflow)
        for (int b = 0; b < dims; b++)
            if ((g[b] < 0.0 && s->inflow_lo[b]) || (g[b] > s->box[b] && s->inflow_hi[b])) {
                if (lo)
                    *lo = *hi = s->inflow_value;
                return s->inflow_value;
            }
    int i[3] = {0, 0, 0};
    double t[3] = {0, 0, 0};
    for (int b = 0; b < dims; b++) {
        double x = g[b] - s->off[b];
        x = x < 0.0 ? 0.0 : (x > s->top[b] ? s->top[b] : x);
        int k = (int)x;
        k = k < s->top[b] ? k : s->top[b] - 1;
        i[b] = k;
        t[b] = x - k;
    }
    const double *p = s->arr + (size_t)i[0] + (size_t)i[1] * s->sy + (size_t)i[2] * s->sz;
    double v00 = p[0], v01 = p[1], v10 = p[s->sy], v11 = p[s->sy + 1];
    double r0 = v00 + t[0] * (v01 - v00), r1 = v10 + t[0] * (v11 - v10);
    double v = r0 + t[1] * (r1 - r0);
    if (lo) {
        double mn = v00 < v01 ? v00 : v01, mx = v00 > v01 ? v00 : v01;
        mn = v10 < mn ? v10 : mn;
        mx = v10 > mx ? v10 : mx;
        mn = v11 < mn ? v11 : mn;
        mx = v11 > mx ? v11 : mx;
        *lo = mn;
        *hi = mx;
    }
    if (dims == 3) {
        const double *q = p + s->sz;
        double w00 = q[0], w01 = q[1], w10 = q[s->sy], w11 = q[s->sy + 1];
        double s0 = w00 + t[0] * (w01 - w00), s1 = w10 + t[0] * (w11 - w10);
        double w = s0 + t[1] * (s1 - s0);
        v += t[2] * (w - v);
        if (lo) {
            double vals[4] = {w00, w01, w10, w11};
            for (int c = 0; c < 4; c++) {
                *lo = vals[c] < *lo ? vals[c] : *lo;
                *hi = vals[c] > *hi ? vals[c] : *hi;
            }
        }
    }
    return v;
}

/* The same at a point in metres, for callers outside the hot loops. */
double fg_fluid_interpolate(const fg_fluid *f, const double *arr, int a, const double x[3],
                            double inflow_value);

/* fluid_advect.c — scalars and velocity, carried by u at mid-step. */
void fg_fluid_advect(fg_fluid *f, double dt);
void fg_fluid_velocity_at(const fg_fluid *f, double *const u[3], const double x[3],
                          double out[3]);

/* fluid_multigrid.c */
fg_result fg_fluid_multigrid_init(fg_fluid *f);
void fg_fluid_multigrid_deinit(fg_fluid *f);
/* What fg_fluid_multigrid_init allocates for a grid of n cells. */
size_t fg_fluid_multigrid_bytes(int dims, const int n[3]);
/* Rebuilds level 0's conductances from the face fractions and the coarse
 * levels from level 0. */
void fg_fluid_multigrid_build(fg_fluid *f);
/* Solves level 0's A x = b (x = f->q, b = f->div_rhs) by MGPCG. */
fg_result fg_fluid_multigrid_solve(fg_fluid *f);
/* out = A x on a level. */
void fg_fluid_level_apply(const fg_fluid_level *L, int dims, const double *x, double *out);

/* fluid_project.c — u -= scale * grad(field) on the faces the projection
 * moves (field on cells; 0 beyond an open face). */
void fg_fluid_pressure_gradient(fg_fluid *f, double *const u[3], const double *field,
                                double scale);
/* The projection, as the share of dt grad p / rho it applies (the rest was
 * applied at the departure points): the pressure it stores is q / share. */
fg_result fg_fluid_solve_pressure(fg_fluid *f, double dt, const double *phi, double share);

/* fluid_force.c — the pressure part from the last projection. */
void fg_fluid_pressure_force(fg_fluid *f);

#endif
