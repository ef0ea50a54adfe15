/* fulgur render --png: one picture of the scene through gpu/ (an EGL
 * context, headless) and host/picture. Built only with FULGUR_GPU. */
#ifndef HOST_CLI_RENDER_PICTURE_H
#define HOST_CLI_RENDER_PICTURE_H

#include <stddef.h>

#include "scene/scene.h"

/* Draws the built scene at time_s (NAN: the first return stroke, the
 * earliest emit time), width x height pixels, from the scene's camera or
 * framing the discharge the time belongs to (the latest whose leader has
 * started by then, else the first), and writes a PNG at path (no file on
 * error); name is the file's final name, for the line it prints. Warns on
 * stderr when no discharge is lit at time_s. Returns 0, or -1 with a
 * message in err. */
int render_picture(const scene *s, const char *path, const char *name, double time_s, int width,
                   int height, char *err, size_t err_size);

#endif
