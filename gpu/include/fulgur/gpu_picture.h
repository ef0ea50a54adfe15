/* fulgur gpu/ — the picture of a discharge: glowing channels over time.
 *
 * Each segment is an additive camera-facing quad drawn into a float target.
 * Width and brightness follow the channel level: the main channel (root to
 * the strike) is widest and brightest, branches fade with their depth (how
 * many branchings separate them from the main channel). Over time a
 * discharge shows its leader growing dim from the root, then the return
 * stroke lighting the whole tree bright, then a decay; later strokes
 * re-flash the main channel (the strokes come from
 * fg_discharge_stroke_offsets, so the picture flashes with the sound).
 * A bloom (bright pass, a chain of downsampled blurs, added back) and a
 * tonemap give the glow; frames can be read back or written as PNG. */
#ifndef FULGUR_GPU_PICTURE_H
#define FULGUR_GPU_PICTURE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/engine.h"
#include "fulgur/gpu_context.h"
#include "fulgur/tree.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fgg_picture fgg_picture;

typedef struct fgg_picture_config {
    int width, height;      /* pixels; 0 means 1280 x 720 */
    double exposure;        /* tonemap exposure; 0 means 1 */
    double bloom;           /* bloom strength; 0 means 0.6, negative means none */
    float background[3];    /* linear RGB of the sky behind; zero is black */
} fgg_picture_config;

typedef struct fgg_camera {
    double eye_m[3];
    double target_m[3];
    double up[3];           /* need not be unit length; zero means +z */
    double fov_y_deg;       /* vertical field of view; 0 means 45 */
} fgg_camera;

/* One discharge shown on the picture's timeline. */
typedef struct fgg_flash {
    const fg_node *nodes;   /* borrowed for the duration of fgg_picture_add */
    size_t node_count;
    double start_s;         /* picture clock time of the first return stroke */
    double leader_s;        /* how long the leader grows before it; 0: none shown */
    double radius_m;        /* main channel half-width; 0 means 1 % of the tree's extent */
    const double *stroke_offsets_s; /* strokes after start_s (first 0); NULL: one */
    size_t stroke_count;
    int continuous;         /* nonzero: glows steadily (plasma ball), flickering */
    double duration_s;      /* continuous: how long; 0: until removed */
} fgg_flash;

/* Creates a picture with its render targets. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_ARGUMENT a size outside 16..8192 or a
 * non-finite exposure; FG_ERR_GPU; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fgg_picture_create(fgg_context *context,
                                                 const fgg_picture_config *config,
                                                 fgg_picture **out);

/* NULL is a no-op. [gpu-thread] */
FG_API void fgg_picture_destroy(fgg_picture *picture);

/* Adds a discharge; its tree is checked (fg_tree_check) and copied to the
 * GPU. Returns its id in *id (may be NULL). [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_TREE; FG_ERR_NOT_FINITE a time;
 * FG_ERR_ARGUMENT negative times or counts; FG_ERR_CAPACITY too many
 * flashes; FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_add(fgg_picture *picture, const fgg_flash *flash,
                                              uint32_t *id);

/* Removes one flash, or all when id is 0. [gpu-thread] */
FG_API void fgg_picture_remove(fgg_picture *picture, uint32_t id);

/* Draws the picture as it looks at time_s from the camera, into the
 * picture's target. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT a degenerate
 * camera (eye at target, up along the view); FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_draw(fgg_picture *picture, const fgg_camera *camera,
                                               double time_s);

/* Copies the last drawn frame to the current default framebuffer (the
 * window), scaled to width x height. [gpu-thread] */
FG_API void fgg_picture_blit(fgg_picture *picture, int width, int height);

/* The last drawn frame as 8-bit sRGB RGBA, rows top first, into
 * rgba[0 .. 4 * width * height). [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_read_rgba8(fgg_picture *picture, uint8_t *rgba);

/* Writes the last drawn frame as a PNG (libpng), through a temporary file
 * renamed into place, so a failure leaves no partial file. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_ARGUMENT the file cannot be written (the
 * message names it and why); FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_write_png(fgg_picture *picture, const char *path);

/* The picture's size in pixels. [gpu-thread] */
FG_API void fgg_picture_size(const fgg_picture *picture, int *width, int *height);

#ifdef __cplusplus
}
#endif

#endif
