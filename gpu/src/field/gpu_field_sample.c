/* The gather: phi at a growth model's candidate points, the only values
 * that come back from the GPU per step. Each point's cell and fractions are
 * computed here exactly as fg_field_sample computes them (GLSL's double
 * division need not be correctly rounded); the kernel interpolates. */
#include <math.h>
#include <stdlib.h>

#include "gpu_field_internal.h"

static fg_result reserve(fgg_field *f, size_t n)
{
    if (n <= f->gather_capacity)
        return FG_OK;
    size_t cap = f->gather_capacity ? f->gather_capacity : 64;
    while (cap < n)
        cap *= 2;
    GLuint b[3] = {f->gather_cells, f->gather_fracs, f->gather_out};
    size_t bytes[3] = {cap * 3 * sizeof(GLint), cap * 3 * sizeof(double), cap * sizeof(double)};
    for (int i = 0; i < 3; i++) {
        if (!b[i])
            glGenBuffers(1, &b[i]);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, b[i]);
        glBufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)bytes[i], NULL, GL_DYNAMIC_DRAW);
    }
    f->gather_cells = b[0], f->gather_fracs = b[1], f->gather_out = b[2];
    fg_result r = fgg_gl_check("allocating the gather buffers");
    if (r == FG_OK)
        f->gather_capacity = cap;
    return r;
}

fg_result fgg_field_sample(fgg_field *f, const double *pts, size_t n, double *out)
{
    if (!f || (n > 0 && (!pts || !out)))
        return fgg_fail(FG_ERR_NULL, "fgg_field_sample: NULL %s",
                        !f ? "field" : (!pts ? "points" : "out"));
    for (size_t i = 0; i < 3 * n; i++)
        if (!isfinite(pts[i]))
            return fgg_fail(FG_ERR_NOT_FINITE, "fgg_field_sample: point %zu is not finite", i / 3);
    if (n == 0)
        return FG_OK;
    if (n > (size_t)INT32_MAX / 3)
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_field_sample: %zu points are too many", n);
    fg_result r = reserve(f, n);
    if (r != FG_OK)
        return r;
    GLint *cells = malloc(n * 3 * sizeof *cells);
    double *fracs = malloc(n * 3 * sizeof *fracs);
    if (!cells || !fracs) {
        free(cells), free(fracs);
        return FG_ERR_NO_MEMORY;
    }
    const int *size = f->level[0].n;
    for (size_t p = 0; p < n; p++)
        for (int a = 0; a < 3; a++) {
            double u = (pts[3 * p + a] - f->config.min_m[a]) / f->h[a];
            double top = size[a] - 1;
            u = u < 0.0 ? 0.0 : (u > top ? top : u);
            int c = (int)u;
            if (c > size[a] - 2)
                c = size[a] - 2;
            cells[3 * p + a] = c;
            fracs[3 * p + a] = u - c;
        }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, f->gather_cells);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)(n * 3 * sizeof *cells), cells);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, f->gather_fracs);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)(n * 3 * sizeof *fracs), fracs);
    free(cells), free(fracs);
    glUseProgram(f->prog.gather);
    glUniform1i(0, (GLint)n);
    glBindImageTexture(0, f->phi, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, f->gather_cells);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, f->gather_fracs);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, f->gather_out);
    glDispatchCompute((GLuint)((n + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, f->gather_out);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)(n * sizeof *out), out);
    return fgg_gl_check("gathering samples");
}
