/* What the GPU field's files share: its storage on the GPU and the kernel
 * launches. Level 0 is the grid itself, level l + 1 takes every second node
 * of level l, as in the engine's multigrid.c. */
#ifndef FULGUR_GPU_FIELD_INTERNAL_H
#define FULGUR_GPU_FIELD_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "context/gpu_internal.h"

#define FGG_MAX_LEVELS 8

typedef struct fgg_level {
    int n[3];
    size_t count;
    float c[3];     /* edge weight along each axis in the interior: area / length */
    GLuint mask;    /* R8UI: nonzero is Dirichlet (level 0: the description's labels) */
    GLuint e;       /* R32F correction (level 0: the CG vector z) */
    GLuint rhs;     /* R32F right-hand side (level 0: the CG residual r) */
    GLuint tmp;     /* R32F residual scratch (level 0: the CG vector q) */
} fgg_level;

typedef struct fgg_programs {
    GLuint smooth, residual, restrict_, prolong, vector, dot, sum, gather;
} fgg_programs;

struct fgg_field {
    fgg_context *context;
    fg_grid_config config;
    double h[3];
    GLuint phi;     /* R32F: the potential, Dirichlet values on masked nodes */
    GLuint p;       /* R32F: the CG search direction */
    fgg_level level[FGG_MAX_LEVELS];
    int levels;
    fgg_programs prog;
    GLuint partials, result;  /* reduction buffers (doubles) */
    size_t partial_count;
    GLuint gather_cells, gather_fracs, gather_out;
    size_t gather_capacity;   /* points the gather buffers hold */
    double b_norm;            /* ||b||; < 0 when the Dirichlet set changed */
    fg_field *description;    /* the field source's regions and sites */
};

/* Node-wise operations of field_vector.glsl. */
enum { FGG_VEC_ZERO = 0, FGG_VEC_AXPY = 1, FGG_VEC_XPAY = 2, FGG_VEC_ZERO_FREE = 3,
       FGG_VEC_SET_MASKED = 4 };

/* gpu_field_kernels.c — one dispatch each, followed by a memory barrier. */
void fgg_k_smooth(const fgg_field *f, const fgg_level *L, GLuint x, GLuint rhs, int color);
void fgg_k_residual(const fgg_field *f, const fgg_level *L, GLuint x, GLuint rhs, GLuint out,
                    int zero_free);
void fgg_k_restrict(const fgg_field *f, const fgg_level *F, const fgg_level *C);
void fgg_k_prolong(const fgg_field *f, const fgg_level *F, GLuint fine, const fgg_level *C);
void fgg_k_vector(const fgg_field *f, const fgg_level *L, int op, GLuint a, GLuint b, float alpha);

/* gpu_multigrid.c — one V(2,2) cycle: for the correction scheme on level
 * 0 (x = phi, no right-hand side) or as CG's preconditioner (x = z from 0,
 * rhs = r). */
void fgg_vcycle(fgg_field *f, GLuint x, GLuint rhs);

/* gpu_reduce.c — sum over level 0 of a * b, in double on the GPU; only the
 * sum is read back. */
double fgg_dot(fgg_field *f, GLuint a, GLuint b);
/* How many partial sums a dot product over count nodes writes. */
size_t fgg_dot_partials(size_t count);

/* gpu_field_solve.c — ||b|| for the relative residual, recomputed when stale. */
double fgg_field_b_norm(fgg_field *f);

#endif
