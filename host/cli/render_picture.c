/* fulgur render --png: the scene as host/picture shows it, from the
 * scene's camera or framing the discharge of the picture's time, into a
 * PNG; a warning when nothing is lit then. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fulgur/gpu.h"
#include "picture/picture.h"
#include "render_picture.h"

/* Says why a picture at t shows no flash. */
static void warn_unlit(const scene *s, double t)
{
    if (s->discharge_count == 0) {
        fprintf(stderr, "fulgur render: warning: the scene has no discharge and no fire: nothing "
                        "in the picture glows (its objects show in the dim room light)\n");
        return;
    }
    double first = INFINITY, emit = INFINITY;
    for (size_t i = 0; i < s->discharge_count; i++)
        if (picture_leader_start_s(&s->discharges[i]) < first) {
            first = picture_leader_start_s(&s->discharges[i]);
            emit = s->discharges[i].post.emit_time_s;
        }
    if (t < first)
        fprintf(stderr,
                "fulgur render: warning: --png-time %g s is before anything is lit: the first "
                "leader starts at %g s, its return stroke at %g s; the picture shows no "
                "discharge\n",
                t, first, emit);
    else
        fprintf(stderr,
                "fulgur render: warning: at --png-time %g s no discharge is lit (each has faded, "
                "or has not begun); the picture shows no discharge\n",
                t);
}

int render_picture(const scene *s, const char *path, const char *name, double time_s, int width,
                   int height, char *err, size_t err_size)
{
    double t = isnan(time_s) ? picture_first_stroke_s(s) : time_s;
    scene_camera sc;
    scene_camera_framing(s, picture_framed_discharge(s, t), (double)width / height, &sc);
    fgg_camera cam;
    picture_camera(&sc, &cam);

    fgg_context *ctx = NULL;
    fgg_picture *pic = NULL;
    fgg_context_config cc = {.backend = FGG_BACKEND_EGL};
    fgg_picture_config pc;
    picture_config(s, width, height, &pc);
    int rc = -1;
    if (fgg_context_create(&cc, &ctx) != FG_OK)
        snprintf(err, err_size, "--png: no GL context: %s", fgg_error_message());
    else if (fgg_picture_create(ctx, &pc, &pic) != FG_OK)
        snprintf(err, err_size, "--png: %s", fgg_error_message());
    else if (picture_add_scene(pic, s, t, err, err_size) != 0)
        ;
    else if (fgg_picture_draw(pic, &cam, t) != FG_OK || fgg_picture_write_png(pic, path) != FG_OK)
        snprintf(err, err_size, "--png: %s", fgg_error_message());
    else
        rc = 0;
    if (rc == 0 && fgg_picture_lit_count(pic, t) == 0)
        warn_unlit(s, t);
    if (rc == 0)
        printf("%s: the picture at %.6f s (%d x %d)\n", name, t, width, height);
    fgg_picture_destroy(pic);
    fgg_context_destroy(ctx);
    return rc;
}
