/* Dot products by reduction on the GPU: workgroups write partial sums in
 * double, one workgroup adds them, and 8 bytes come back. */
#include "gpu_field_internal.h"

#define DOT_GROUP 256
#define DOT_ITEMS 16

double fgg_dot(fgg_field *f, GLuint a, GLuint b)
{
    const fgg_level *L = &f->level[0];
    GLuint groups = (GLuint)((L->count + DOT_GROUP * DOT_ITEMS - 1) / (DOT_GROUP * DOT_ITEMS));
    glUseProgram(f->prog.dot);
    glUniform3i(0, L->n[0], L->n[1], L->n[2]);
    glBindImageTexture(0, a, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(1, b, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, f->partials);
    glDispatchCompute(groups, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(f->prog.sum);
    glUniform1i(0, (GLint)groups);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, f->result);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    double s = 0.0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, f->result);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof s, &s);
    return s;
}

size_t fgg_dot_partials(size_t count)
{
    return (count + DOT_GROUP * DOT_ITEMS - 1) / (DOT_GROUP * DOT_ITEMS);
}
