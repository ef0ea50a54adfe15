/* A scene's surroundings and flashes for gpu/'s picture. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "picture.h"
#include "picture_apparatus.h"
#include "fg_array.h"

/* A dim room's radiance (warm), so that an apparatus shows before it
 * sparks; the cloud deck's base just under the lowest lightning root, of
 * the root's height; the storm cell at least this wide. */
static const float ROOM_AMBIENT[3] = {0.030f, 0.028f, 0.025f};
#define CLOUD_BASE_RATIO 0.94
#define MIN_CELL_M 12000.0
/* A plasma ball's filaments: the pink-violet of its neon and xenon. */
static const float NOBLE_GAS[3] = {0.85f, 0.30f, 1.00f};

bool picture_outdoors(const scene *s)
{
    for (size_t i = 0; i < s->discharge_count; i++)
        if (s->discharges[i].preset == FG_PRESET_LIGHTNING)
            return true;
    return false;
}

void picture_config(const scene *s, int width, int height, fgg_picture_config *out)
{
    *out = (fgg_picture_config){.width = width, .height = height};
    if (!picture_outdoors(s))
        memcpy(out->ambient, ROOM_AMBIENT, sizeof out->ambient);
}

/* The ground and, over the lightning channels' roots, a cloud deck. */
static int add_ground(fgg_picture *pic, const scene *s, char *err, size_t err_size)
{
    double low = INFINITY, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < s->discharge_count; i++) {
        const scene_discharge *d = &s->discharges[i];
        if (d->preset != FG_PRESET_LIGHTNING || d->post.node_count == 0)
            continue;
        const fg_node *root = &d->post.nodes[0];
        low = fmin(low, root->z);
        lo[0] = fmin(lo[0], root->x), hi[0] = fmax(hi[0], root->x);
        lo[1] = fmin(lo[1], root->y), hi[1] = fmax(hi[1], root->y);
    }
    fgg_drawable g = {.kind = FGG_DRAWABLE_GROUND};
    if (isfinite(low) && low > 0) {
        g.ground.cloud_base_m = CLOUD_BASE_RATIO * low;
        g.ground.cloud_centre_m[0] = 0.5 * (lo[0] + hi[0]);
        g.ground.cloud_centre_m[1] = 0.5 * (lo[1] + hi[1]);
        g.ground.cloud_radius_m = fmax(MIN_CELL_M, hypot(hi[0] - lo[0], hi[1] - lo[1]));
    }
    if (fgg_picture_add_drawable(pic, &g, NULL) != FG_OK) {
        snprintf(err, err_size, "the picture refused the ground: %s", fgg_error_message());
        return -1;
    }
    return 0;
}

static bool same_shape(const fg_shape *a, const fg_shape *b)
{
    if (a->kind != b->kind || a->role != b->role || a->outside != b->outside ||
        a->radius_m != b->radius_m)
        return false;
    for (int k = 0; k < 3; k++)
        if (a->centre_m[k] != b->centre_m[k] || a->box_min_m[k] != b->box_min_m[k] ||
            a->box_max_m[k] != b->box_max_m[k] || a->normal[k] != b->normal[k])
            return false;
    return true;
}

static bool same_apparatus(const scene_apparatus *a, const scene_apparatus *b)
{
    if (a->kind != b->kind || a->shape_count != b->shape_count)
        return false;
    for (size_t i = 0; i < a->shape_count; i++)
        if (!same_shape(&a->shapes[i], &b->shapes[i]))
            return false;
    return true;
}

int picture_add_surroundings(fgg_picture *pic, const scene *s, char *err, size_t err_size)
{
    if (picture_outdoors(s) && add_ground(pic, s, err, err_size) != 0)
        return -1;
    scene_apparatus *drawn = NULL, a; /* the different ones so far */
    size_t count = 0, capacity = 0;
    int rc = 0;
    for (size_t i = 0; i < s->discharge_count && rc == 0; i++) {
        if ((rc = scene_discharge_apparatus(s, i, &a, err, err_size)) != 0 ||
            a.kind == SCENE_APPARATUS_NONE)
            continue;
        bool repeat = false;
        for (size_t k = 0; k < count && !repeat; k++)
            repeat = same_apparatus(&a, &drawn[k]);
        if (repeat)
            continue;
        scene_apparatus *grown = fg_array_grow(drawn, &capacity, count + 1, sizeof *grown, 4);
        if (!grown) {
            snprintf(err, err_size, "out of memory");
            rc = -1;
            break;
        }
        drawn = grown;
        drawn[count++] = a;
        rc = picture_apparatus_add(pic, &a, err, err_size);
    }
    free(drawn);
    return rc;
}

void picture_flash(const fg_discharge *post, fg_preset preset, double start_s,
                   const double *strokes_s, uint32_t stroke_count, fgg_flash *out)
{
    *out = (fgg_flash){.nodes = post->nodes, .node_count = post->node_count,
                       .start_s = start_s, .leader_s = post->continuous ? 0 : PICTURE_LEADER_S,
                       .stroke_offsets_s = stroke_count ? strokes_s : NULL,
                       .stroke_count = stroke_count > FG_MAX_STROKES ? FG_MAX_STROKES
                                                                     : stroke_count,
                       .continuous = post->continuous, .duration_s = post->duration_s};
    if (preset == FG_PRESET_PLASMA_BALL)
        memcpy(out->colour, NOBLE_GAS, sizeof out->colour);
}

void picture_camera(const scene_camera *sc, fgg_camera *out)
{
    memcpy(out->eye_m, sc->eye_m, sizeof out->eye_m);
    memcpy(out->target_m, sc->target_m, sizeof out->target_m);
    memcpy(out->up, sc->up, sizeof out->up);
    out->fov_y_deg = sc->fov_y_deg;
}

int picture_add_scene(fgg_picture *pic, const scene *s, double t_s, char *err, size_t err_size)
{
    if (picture_add_surroundings(pic, s, err, err_size) != 0)
        return -1;
    for (size_t i = 0; i < s->discharge_count; i++) {
        const scene_discharge *d = &s->discharges[i];
        double strokes[FG_MAX_STROKES];
        uint32_t n = fg_discharge_stroke_offsets(&d->post, strokes, FG_MAX_STROKES);
        fgg_flash f;
        picture_flash(&d->post, d->preset, d->post.emit_time_s, strokes, n, &f);
        if (fgg_picture_add(pic, &f, NULL) != FG_OK) {
            snprintf(err, err_size, "discharges[%zu]: the picture refused it: %s", i,
                     fgg_error_message());
            return -1;
        }
    }
    uint32_t *ids = malloc((s->fire_count + s->aero_count + 1) * sizeof *ids);
    if (!ids) {
        snprintf(err, err_size, "the picture's fires and aero objects: out of memory");
        return -1;
    }
    int rc = picture_sources_add(pic, s, t_s, ids, err, err_size);
    free(ids);
    return rc;
}

double picture_first_stroke_s(const scene *s)
{
    double t = s->discharge_count ? INFINITY : 0.0;
    for (size_t i = 0; i < s->discharge_count; i++)
        t = fmin(t, s->discharges[i].post.emit_time_s);
    return t;
}

double picture_leader_start_s(const scene_discharge *d)
{
    return d->post.emit_time_s - (d->post.continuous ? 0 : PICTURE_LEADER_S);
}

size_t picture_framed_discharge(const scene *s, double t_s)
{
    size_t best = 0;
    for (size_t i = 1; i < s->discharge_count; i++) {
        double a = picture_leader_start_s(&s->discharges[i]);
        double b = picture_leader_start_s(&s->discharges[best]);
        bool started = a <= t_s, best_started = b <= t_s;
        if (started ? !best_started || a > b : !best_started && a < b)
            best = i;
    }
    return best;
}
