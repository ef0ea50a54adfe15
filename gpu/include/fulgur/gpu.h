/* fulgur gpu/ — everything: a context, the field solver, the picture. */
#ifndef FULGUR_GPU_H
#define FULGUR_GPU_H

#include "fulgur/gpu_context.h"
#include "fulgur/gpu_field.h"
#include "fulgur/gpu_picture.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifdef __cplusplus
}
#endif

#endif
