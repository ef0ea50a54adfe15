/* The scene's "camera" (what `fulgur render --png` and the viewer look
 * through), and the default framing of a discharge when a scene gives
 * none. */
#include <math.h>
#include <string.h>

#include "scene_internal.h"
#include "fg_vec3.h"

static const char *const camera_keys[] = {"eye", "target", "up", "fov", NULL};

#define DEFAULT_FOV_DEG 45.0
/* The default framings (scene_camera_framing): a lab apparatus seen from
 * a little above; lightning seen from the ground, the horizon and the
 * channel's top at these heights of the frame (-1 bottom, +1 top); a
 * margin around what is framed. */
#define LAB_ELEVATION_DEG 12.0
#define HORIZON_NDC (-0.7)
#define TOP_NDC 0.85
#define FRAME_MARGIN 1.15

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

/* The bounds of a discharge's tree and apparatus. */
static void bounds(const scene *s, size_t index, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    const scene_discharge *d = &s->discharges[index];
    for (size_t n = 0; n < d->post.node_count; n++) {
        const double p[3] = {d->post.nodes[n].x, d->post.nodes[n].y, d->post.nodes[n].z};
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], p[k]), hi[k] = fmax(hi[k], p[k]);
    }
    scene_apparatus a;
    char err[256];
    if (scene_discharge_apparatus(s, index, &a, err, sizeof err) != 0)
        return; /* the tree alone: the generator's errors were reported when it was built */
    for (size_t i = 0; i < a.shape_count; i++) {
        const fg_shape *sh = &a.shapes[i];
        double r = sh->kind == FG_SHAPE_SPHERE ? sh->radius_m : 0;
        if (sh->kind == FG_SHAPE_PLANE)
            continue; /* unbounded */
        for (int k = 0; k < 3; k++) {
            double a0 = sh->kind == FG_SHAPE_BOX ? sh->box_min_m[k] : sh->centre_m[k] - r;
            double a1 = sh->kind == FG_SHAPE_BOX ? sh->box_max_m[k] : sh->centre_m[k] + r;
            lo[k] = fmin(lo[k], a0), hi[k] = fmax(hi[k], a1);
        }
    }
}

/* The bounds of a scene without discharges: its fires' points, padded,
 * and the reach of its aero objects about where each starts. */
static void source_bounds(const scene *s, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (size_t i = 0; i < s->fire_count; i++)
        for (size_t n = 0; n < s->fires[i].path_count; n++)
            for (int k = 0; k < 3; k++) {
                double p = s->fires[i].path[n].position_m[k];
                lo[k] = fmin(lo[k], p - SCENE_FRAME_FIRE_M), hi[k] = fmax(hi[k], p + SCENE_FRAME_FIRE_M);
            }
    for (size_t i = 0; i < s->aero_count; i++) {
        const scene_aero *a = &s->aeros[i];
        double reach = fmax(fabs(a->post.start_m), fabs(a->post.end_m));
        for (int k = 0; k < 3; k++) {
            double p = a->motion.position_m[k];
            lo[k] = fmin(lo[k], p - reach), hi[k] = fmax(hi[k], p + reach);
        }
    }
}

/* The horizontal direction from the centre towards the listener (behind
 * the listener's forward when the listener is straight above or below). */
static fg_vec3 listener_side(const scene *s, const double centre[3], double radius)
{
    const scene_pose *ear = &s->poses[0];
    fg_vec3 side = fg_v3(ear->position_m[0] - centre[0], ear->position_m[1] - centre[1], 0);
    if (fg_v3_len(side) < 1e-6 * radius)
        side = fg_v3(-ear->forward[0], -ear->forward[1], 0);
    if (fg_v3_len(side) == 0)
        side = fg_v3(0, -1, 0);
    return fg_v3_unit(side);
}

/* Lab framing: the pose looks at the centre from side, raised by
 * LAB_ELEVATION_DEG, far enough that the box (half sizes h) fits. */
static void frame_lab(const double centre[3], const double h[3], fg_vec3 side, double aspect,
                      scene_camera *out)
{
    double e = LAB_ELEVATION_DEG * FG_PI / 180, t = tan(DEFAULT_FOV_DEG * FG_PI / 360);
    fg_vec3 back = fg_v3_add(fg_v3_scale(side, cos(e)), fg_v3(0, 0, sin(e))); /* to the eye */
    fg_vec3 right = fg_v3_unit(fg_v3_cross(fg_v3_scale(back, -1), fg_v3(0, 0, 1)));
    fg_vec3 up = fg_v3_cross(right, fg_v3_scale(back, -1));
    double hw = fabs(right.x) * h[0] + fabs(right.y) * h[1] + fabs(right.z) * h[2];
    double hh = fabs(up.x) * h[0] + fabs(up.y) * h[1] + fabs(up.z) * h[2];
    double hd = fabs(back.x) * h[0] + fabs(back.y) * h[1] + fabs(back.z) * h[2];
    double dist = hd + FRAME_MARGIN * fmax(hh / t, hw / (aspect * t));
    for (int k = 0; k < 3; k++)
        out->target_m[k] = centre[k];
    fg_v3_store(fg_v3_add(fg_v3_load(centre), fg_v3_scale(back, dist)), out->eye_m);
}

/* Lightning framing: from the ground at the listener's height, pitched so
 * that the horizon sits at HORIZON_NDC and the channel's top at TOP_NDC of
 * the frame's height, or farther when the channel is too wide. */
static void frame_sky(const scene *s, const double lo[3], const double hi[3], fg_vec3 side,
                      double aspect, scene_camera *out)
{
    double t = tan(DEFAULT_FOV_DEG * FG_PI / 360);
    double pitch = atan(-HORIZON_NDC * t), top = pitch + atan(TOP_NDC * t);
    double eye_z = fmax(s->poses[0].position_m[2], 1.7);
    double centre[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0};
    fg_vec3 across = fg_v3_cross(side, fg_v3(0, 0, 1));
    double hw = 0.5 * (fabs(across.x) * (hi[0] - lo[0]) + fabs(across.y) * (hi[1] - lo[1]));
    double hd = 0.5 * (fabs(side.x) * (hi[0] - lo[0]) + fabs(side.y) * (hi[1] - lo[1]));
    double dist = fmax((hi[2] - eye_z) / tan(top), FRAME_MARGIN * hw / (aspect * t));
    dist = fmax(dist, 1e-3);
    fg_vec3 eye = fg_v3_add(fg_v3_load(centre), fg_v3_scale(side, dist + hd));
    eye.z = eye_z;
    fg_vec3 look = fg_v3_add(fg_v3_scale(side, -cos(pitch)), fg_v3(0, 0, sin(pitch)));
    fg_v3_store(eye, out->eye_m);
    fg_v3_store(fg_v3_add(eye, fg_v3_scale(look, dist)), out->target_m);
}

void scene_camera_framing(const scene *s, size_t index, double aspect, scene_camera *out)
{
    if (s->camera.given) {
        *out = s->camera;
        return;
    }
    double lo[3], hi[3], centre[3], half[3];
    if (s->discharge_count)
        bounds(s, index, lo, hi);
    else
        source_bounds(s, lo, hi);
    for (int k = 0; k < 3; k++) {
        centre[k] = isfinite(lo[k]) ? 0.5 * (lo[k] + hi[k]) : 0;
        half[k] = isfinite(lo[k]) ? fmax(0.5 * (hi[k] - lo[k]), 1e-3) : 0.5;
    }
    memset(out, 0, sizeof *out);
    out->up[2] = 1;
    out->fov_y_deg = DEFAULT_FOV_DEG;
    fg_vec3 side = listener_side(s, centre, fg_v3_len(fg_v3_load(half)));
    fg_preset preset = s->discharge_count ? s->discharges[index].preset : FG_PRESET_COUNT;
    int sky = preset == FG_PRESET_LIGHTNING || preset == FG_PRESET_LIGHTNING_TABLE1;
    if (sky && isfinite(lo[0]))
        frame_sky(s, lo, hi, side, aspect, out);
    else
        frame_lab(centre, half, side, aspect, out);
}
