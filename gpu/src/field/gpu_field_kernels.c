/* Launching the field's compute kernels. Uniform locations are fixed in
 * the shaders (layout(location = ...)); images go to fixed units. */
#include "gpu_field_internal.h"

#define LOCAL_X 8
#define LOCAL_Y 4
#define LOCAL_Z 4

static void bind(GLuint unit, GLuint texture, GLenum access, GLenum format)
{
    glBindImageTexture(unit, texture, 0, GL_TRUE, 0, access, format);
}

static void dispatch(int nx, int ny, int nz)
{
    glDispatchCompute((GLuint)((nx + LOCAL_X - 1) / LOCAL_X), (GLuint)((ny + LOCAL_Y - 1) / LOCAL_Y),
                      (GLuint)((nz + LOCAL_Z - 1) / LOCAL_Z));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

static void level_uniforms(const fgg_level *L)
{
    glUniform3i(0, L->n[0], L->n[1], L->n[2]);
    glUniform3f(1, L->c[0], L->c[1], L->c[2]);
}

void fgg_k_smooth(const fgg_field *f, const fgg_level *L, GLuint x, GLuint rhs, int color)
{
    glUseProgram(f->prog.smooth);
    level_uniforms(L);
    glUniform1i(2, color);
    glUniform1i(3, rhs != 0);
    bind(0, x, GL_READ_WRITE, GL_R32F);
    bind(1, rhs ? rhs : x, GL_READ_ONLY, GL_R32F); /* not read without rhs */
    bind(2, L->mask, GL_READ_ONLY, GL_R8UI);
    /* One invocation per node of the colour: half the nodes along x. */
    dispatch((L->n[0] + 1) / 2, L->n[1], L->n[2]);
}

void fgg_k_residual(const fgg_field *f, const fgg_level *L, GLuint x, GLuint rhs, GLuint out,
                    int zero_free)
{
    glUseProgram(f->prog.residual);
    level_uniforms(L);
    glUniform1i(2, zero_free);
    glUniform1i(3, rhs != 0);
    bind(0, x, GL_READ_ONLY, GL_R32F);
    bind(1, rhs ? rhs : x, GL_READ_ONLY, GL_R32F);
    bind(2, L->mask, GL_READ_ONLY, GL_R8UI);
    bind(3, out, GL_WRITE_ONLY, GL_R32F);
    dispatch(L->n[0], L->n[1], L->n[2]);
}

void fgg_k_restrict(const fgg_field *f, const fgg_level *F, const fgg_level *C)
{
    glUseProgram(f->prog.restrict_);
    glUniform3i(0, C->n[0], C->n[1], C->n[2]);
    glUniform3i(1, F->n[0], F->n[1], F->n[2]);
    bind(0, F->tmp, GL_READ_ONLY, GL_R32F);
    bind(2, C->mask, GL_READ_ONLY, GL_R8UI);
    bind(3, C->rhs, GL_WRITE_ONLY, GL_R32F);
    dispatch(C->n[0], C->n[1], C->n[2]);
}

void fgg_k_prolong(const fgg_field *f, const fgg_level *F, GLuint fine, const fgg_level *C)
{
    glUseProgram(f->prog.prolong);
    glUniform3i(0, F->n[0], F->n[1], F->n[2]);
    bind(0, fine, GL_READ_WRITE, GL_R32F);
    bind(1, C->e, GL_READ_ONLY, GL_R32F);
    bind(2, F->mask, GL_READ_ONLY, GL_R8UI);
    dispatch(F->n[0], F->n[1], F->n[2]);
}

void fgg_k_vector(const fgg_field *f, const fgg_level *L, int op, GLuint a, GLuint b, float alpha)
{
    glUseProgram(f->prog.vector);
    glUniform3i(0, L->n[0], L->n[1], L->n[2]);
    glUniform1i(2, op);
    glUniform1f(4, alpha);
    bind(0, a, GL_READ_WRITE, GL_R32F);
    bind(1, b ? b : a, GL_READ_ONLY, GL_R32F);
    bind(2, L->mask, GL_READ_ONLY, GL_R8UI);
    dispatch(L->n[0], L->n[1], L->n[2]);
}
