/* Building GL programs, with the driver's log in the error message. */
#include <stdio.h>

#include "gpu_internal.h"

static fg_result compile(const char *label, GLenum stage, const char *source, GLuint *out)
{
    GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &source, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        glDeleteShader(s);
        return fgg_fail(FG_ERR_GPU, "shader %s did not compile: %s", label, log);
    }
    *out = s;
    return FG_OK;
}

static fg_result link(const char *label, const GLuint *shaders, int count, GLuint *out)
{
    GLuint p = glCreateProgram();
    for (int i = 0; i < count; i++)
        glAttachShader(p, shaders[i]);
    glLinkProgram(p);
    for (int i = 0; i < count; i++)
        glDeleteShader(shaders[i]);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[1024] = "";
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        glDeleteProgram(p);
        return fgg_fail(FG_ERR_GPU, "program %s did not link: %s", label, log);
    }
    *out = p;
    return FG_OK;
}

fg_result fgg_program_compute(const char *label, const char *source, GLuint *out)
{
    GLuint s;
    fg_result r = compile(label, GL_COMPUTE_SHADER, source, &s);
    return r != FG_OK ? r : link(label, &s, 1, out);
}

fg_result fgg_program_graphics(const char *label, const char *vertex, const char *fragment,
                               GLuint *out)
{
    GLuint s[2];
    fg_result r = compile(label, GL_VERTEX_SHADER, vertex, &s[0]);
    if (r != FG_OK)
        return r;
    r = compile(label, GL_FRAGMENT_SHADER, fragment, &s[1]);
    if (r != FG_OK) {
        glDeleteShader(s[0]);
        return r;
    }
    return link(label, s, 2, out);
}

fg_result fgg_gl_check(const char *what)
{
    GLenum e = glGetError();
    if (e == GL_NO_ERROR)
        return FG_OK;
    while (glGetError() != GL_NO_ERROR)
        ;
    return fgg_fail(FG_ERR_GPU, "%s: GL error 0x%x", what, (unsigned)e);
}
