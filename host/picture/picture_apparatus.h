/* One discharge's apparatus as drawables (picture_apparatus.c). */
#ifndef HOST_PICTURE_PICTURE_APPARATUS_H
#define HOST_PICTURE_PICTURE_APPARATUS_H

#include "fulgur/gpu.h"
#include "scene/scene.h"

/* Adds a's drawables to pic. Returns 0, or -1 with gpu/'s message in err. */
int picture_apparatus_add(fgg_picture *pic, const scene_apparatus *a, char *err,
                          size_t err_size);

#endif
