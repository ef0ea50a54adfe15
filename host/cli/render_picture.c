/* fulgur render --png: the scene's discharges as gpu/ draws them, each a
 * flash at its emit time with the stroke times the engine will use. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fulgur/gpu.h"
#include "render_picture.h"

#define PICTURE_WIDTH 1280
#define PICTURE_HEIGHT 720
/* How long a leader is shown growing before its return stroke. */
#define LEADER_S 0.03

static int add_flashes(fgg_picture *pic, const scene *s, char *err, size_t err_size)
{
    for (size_t i = 0; i < s->discharge_count; i++) {
        const scene_discharge *d = &s->discharges[i];
        double strokes[FG_MAX_STROKES];
        uint32_t n = fg_discharge_stroke_offsets(&d->post, strokes, FG_MAX_STROKES);
        fgg_flash f = {.nodes = d->post.nodes, .node_count = d->post.node_count,
                       .start_s = d->post.emit_time_s,
                       .leader_s = d->post.continuous ? 0 : LEADER_S,
                       .stroke_offsets_s = n ? strokes : NULL,
                       .stroke_count = n > FG_MAX_STROKES ? FG_MAX_STROKES : n,
                       .continuous = d->post.continuous, .duration_s = d->post.duration_s};
        if (fgg_picture_add(pic, &f, NULL) != FG_OK) {
            snprintf(err, err_size, "discharges[%zu]: the picture refused it: %s", i,
                     fgg_error_message());
            return -1;
        }
    }
    return 0;
}

int render_picture(const scene *s, const char *path, const char *name, double time_s, char *err,
                   size_t err_size)
{
    double t = time_s;
    if (isnan(t)) {
        t = s->discharges[0].post.emit_time_s;
        for (size_t i = 1; i < s->discharge_count; i++)
            if (s->discharges[i].post.emit_time_s < t)
                t = s->discharges[i].post.emit_time_s;
    }
    scene_camera sc;
    scene_camera_framing(s, &sc);
    fgg_camera cam;
    memcpy(cam.eye_m, sc.eye_m, sizeof cam.eye_m);
    memcpy(cam.target_m, sc.target_m, sizeof cam.target_m);
    memcpy(cam.up, sc.up, sizeof cam.up);
    cam.fov_y_deg = sc.fov_y_deg;

    fgg_context *ctx = NULL;
    fgg_picture *pic = NULL;
    fgg_context_config cc = {.backend = FGG_BACKEND_EGL};
    fgg_picture_config pc = {.width = PICTURE_WIDTH, .height = PICTURE_HEIGHT};
    int rc = -1;
    if (fgg_context_create(&cc, &ctx) != FG_OK)
        snprintf(err, err_size, "--png: no GL context: %s", fgg_error_message());
    else if (fgg_picture_create(ctx, &pc, &pic) != FG_OK)
        snprintf(err, err_size, "--png: %s", fgg_error_message());
    else if (add_flashes(pic, s, err, err_size) != 0)
        ;
    else if (fgg_picture_draw(pic, &cam, t) != FG_OK || fgg_picture_write_png(pic, path) != FG_OK)
        snprintf(err, err_size, "--png: %s", fgg_error_message());
    else
        rc = 0;
    if (rc == 0)
        printf("%s: the picture at %.6f s (%d x %d)\n", name, t, PICTURE_WIDTH, PICTURE_HEIGHT);
    fgg_picture_destroy(pic);
    fgg_context_destroy(ctx);
    return rc;
}
