/* The field generators' GPU path: "solver": "gpu" grows through the grower
 * a program installs. The grower itself (generator_field_gpu.c) needs
 * gpu/ and its GL libraries, so it is not in the scene library: the fulgur
 * program installs one that opens its GL module on first use
 * (host/cli/gl_module.h), and without one (libfulgur-scene, the tests)
 * "gpu" is refused at parse time as not built in. */
#ifndef HOST_SCENE_GENERATOR_FIELD_GPU_H
#define HOST_SCENE_GENERATOR_FIELD_GPU_H

#include <stddef.h>

#include "fulgur/fulgur.h"

/* Solves description's field on the GPU in an EGL context made on the
 * calling thread for this call, and grows a Matsuyama tree from it into
 * out. On failure msg holds what went wrong (the GL message where there is
 * one); *residual is the solve's final relative residual. */
typedef fg_result (*gen_field_gpu_grower)(fg_field *description, const fg_growth_config *growth,
                                          fg_tree *out, double *residual, char *msg,
                                          size_t msg_size);

/* Installs grow (NULL: none) for every later parse and build. Called once,
 * before any scene is parsed and before threads start. */
void gen_field_set_gpu_grower(gen_field_gpu_grower grow);

/* The grower over gpu/ (generator_field_gpu.c, built where gpu/ is). */
fg_result gen_field_gpu_grow(fg_field *description, const fg_growth_config *growth, fg_tree *out,
                             double *residual, char *msg, size_t msg_size);

#endif
