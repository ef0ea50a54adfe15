/* The field generators' GPU path (built when gpu/ is: FULGUR_HOST_GPU). */
#ifndef HOST_SCENE_GENERATOR_FIELD_GPU_H
#define HOST_SCENE_GENERATOR_FIELD_GPU_H

#include <stddef.h>

#include "fulgur/fulgur.h"

/* Solves description's field on the GPU in an EGL context made on the
 * calling thread for this call, and grows a Matsuyama tree from it into
 * out. On failure msg holds what went wrong (the GL message where there is
 * one); *residual is the solve's final relative residual. */
fg_result gen_field_gpu_grow(fg_field *description, const fg_growth_config *growth, fg_tree *out,
                             double *residual, char *msg, size_t msg_size);

#endif
