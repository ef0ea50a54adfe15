/* The scene's "camera" (what `fulgur render --png` and the viewer look
 * through), and the default framing when a scene gives none. */
#include <math.h>
#include <string.h>

#include "scene_internal.h"
#include "fg_vec3.h"

static const char *const camera_keys[] = {"eye", "target", "up", "fov", NULL};

#define DEFAULT_FOV_DEG 45.0

int scene_parse_camera(const cJSON *item, scene *s, char *err, size_t err_size)
{
    scene_camera *c = &s->camera;
    memset(c, 0, sizeof *c);
    c->up[2] = 1;
    c->fov_y_deg = DEFAULT_FOV_DEG;
    if (!item)
        return 0;
    if (json_check_keys(item, "camera", camera_keys, err, err_size))
        return -1;
    if (!cJSON_GetObjectItemCaseSensitive(item, "eye"))
        return json_fail(err, err_size, "camera.eye", "required (where the camera is, [x, y, z])");
    if (!cJSON_GetObjectItemCaseSensitive(item, "target"))
        return json_fail(err, err_size, "camera.target", "required (where it looks, [x, y, z])");
    if (json_vec3(item, "camera", "eye", c->eye_m, err, err_size) ||
        json_vec3(item, "camera", "target", c->target_m, err, err_size) ||
        json_vec3(item, "camera", "up", c->up, err, err_size) ||
        json_number(item, "camera", "fov", (number_range){0, 179, .lo_open = true, .hi_open = true},
                    &c->fov_y_deg, err, err_size))
        return -1;
    fg_vec3 view = fg_v3_sub(fg_v3_load(c->target_m), fg_v3_load(c->eye_m)), up = fg_v3_load(c->up);
    double vl = fg_v3_len(view), ul = fg_v3_len(up);
    if (!(vl > 0) || !isfinite(vl))
        return json_fail(err, err_size, "camera.target", "must differ from camera.eye");
    if (!(ul > 0) || !isfinite(ul))
        return json_fail(err, err_size, "camera.up", "must have a finite, non-zero length");
    if (fabs(fg_v3_dot(view, up)) > (1 - 1e-9) * vl * ul)
        return json_fail(err, err_size, "camera.up", "is parallel to the view (eye to target)");
    c->given = true;
    return 0;
}

void scene_camera_framing(const scene *s, scene_camera *out)
{
    if (s->camera.given) {
        *out = s->camera;
        return;
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < s->discharge_count; i++) {
        const scene_discharge *d = &s->discharges[i];
        for (size_t n = 0; n < d->post.node_count; n++) {
            const double p[3] = {d->post.nodes[n].x, d->post.nodes[n].y, d->post.nodes[n].z};
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], p[k]);
                hi[k] = fmax(hi[k], p[k]);
            }
        }
    }
    double centre[3], half[3];
    for (int k = 0; k < 3; k++) {
        centre[k] = isfinite(lo[k]) ? 0.5 * (lo[k] + hi[k]) : 0;
        half[k] = isfinite(lo[k]) ? 0.5 * (hi[k] - lo[k]) : 0.5;
    }
    double radius = fmax(fg_v3_len(fg_v3_load(half)), 1e-3);
    /* From the trees towards the listener, level: the listener's side. */
    const scene_pose *ear = &s->poses[0];
    double side[3] = {ear->position_m[0] - centre[0], ear->position_m[1] - centre[1], 0};
    if (fg_v3_len(fg_v3_load(side)) < 1e-6 * radius) {
        side[0] = -ear->forward[0];
        side[1] = -ear->forward[1];
    }
    if (fg_v3_len(fg_v3_load(side)) == 0)
        side[1] = -1;
    double sl = fg_v3_len(fg_v3_load(side));
    /* Far enough that the bounding sphere fits the vertical field of view. */
    double dist = 1.1 * radius / sin(DEFAULT_FOV_DEG * FG_PI / 360);
    memset(out, 0, sizeof *out);
    for (int k = 0; k < 3; k++) {
        out->target_m[k] = centre[k];
        out->eye_m[k] = centre[k] + dist * side[k] / sl;
    }
    out->up[2] = 1;
    out->fov_y_deg = DEFAULT_FOV_DEG;
}
