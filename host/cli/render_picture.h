/* fulgur render --png: one picture of the scene's discharges through gpu/
 * (an EGL context, headless). Built only with FULGUR_GPU. */
#ifndef HOST_CLI_RENDER_PICTURE_H
#define HOST_CLI_RENDER_PICTURE_H

#include <stddef.h>

#include "scene/scene.h"

/* Draws the built scene at time_s (NAN: the first return stroke, the
 * earliest emit time) from the scene's camera and writes a PNG at path (no
 * file on error); name is the file's final name, for the line it prints.
 * Returns 0, or -1 with a message in err. */
int render_picture(const scene *s, const char *path, const char *name, double time_s, char *err,
                   size_t err_size);

#endif
