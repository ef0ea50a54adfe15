/* The GL half of the fulgur program, opened on demand.
 *
 * fulgur view, render --png and "solver": "gpu" draw or compute through
 * gpu/, which needs libepoxy, libpng, GLFW (and so X11), FreeType and
 * fontconfig, and at a context libEGL or OSMesa (and so libLLVM). Linked
 * into the program they were mapped, and their constructors run, in every
 * process: `fulgur --help` cost 17 ms of CPU and 55 MiB. They live in a
 * module instead, fulgur-gl.so, that the program opens with dlopen the
 * first time one of those is asked for; a WAV render, --help, --version
 * and analyze map none of them. The module takes the engine, scene and
 * common code from the program, which exports its symbols (one engine in
 * the process); it holds gpu/'s objects, picture/, view/ and the GPU field
 * grower.
 *
 * Where it is looked for: next to the program (the build tree), then at
 * the install path relative to the program (FULGUR_GL_MODULE_FROM_BIN,
 * CMake's libdir/fulgur/fulgur-gl.so). */
#ifndef HOST_CLI_GL_MODULE_H
#define HOST_CLI_GL_MODULE_H

#include <stddef.h>

#include "fulgur/fulgur.h"
#include "scene/scene.h"

/* What the module exports, as one table named GL_MODULE_SYMBOL. */
typedef struct gl_module {
    unsigned version; /* GL_MODULE_VERSION: a table of another layout is refused */
    int (*view_main)(int argc, char **argv);
    /* host/cli/render_picture.h */
    int (*render_picture)(const scene *s, const char *path, const char *name, double time_s,
                          int width, int height, char *err, size_t err_size);
    /* host/scene/generator_field_gpu.h */
    fg_result (*field_gpu_grow)(fg_field *description, const fg_growth_config *growth,
                                fg_tree *out, double *residual, char *msg, size_t msg_size);
} gl_module;

#define GL_MODULE_SYMBOL "fulgur_gl_module"
#define GL_MODULE_VERSION 1u

/* The module, opened on the first call (thread-safe; later calls return
 * the same table). NULL with a message in err naming the paths tried and
 * dlopen's reason. */
const gl_module *gl_module_get(char *err, size_t err_size);

/* fulgur view through the module: exit 1 with a message when it cannot be
 * opened. */
int gl_view_main(int argc, char **argv);

/* The grower the program installs for "solver": "gpu"
 * (gen_field_set_gpu_grower): the module's, FG_ERR_UNSUPPORTED with the
 * reason in msg when the module cannot be opened. */
fg_result gl_field_gpu_grow(fg_field *description, const fg_growth_config *growth, fg_tree *out,
                            double *residual, char *msg, size_t msg_size);

#endif
