/* The scene's fires and aero objects in the picture: see picture.h. */
#include <stdio.h>
#include <stdlib.h>

#include "picture.h"

static const float STEEL[3] = {0.55f, 0.56f, 0.58f};

/* Fire i at t_s: a flame standing on the fire's point, lowered by a
 * fifth of its height (the point is where the sound comes from, in the
 * flame's lower part). */
static fgg_drawable fire_at(const scene *s, size_t i, double t_s)
{
    fg_fire_pose pose;
    scene_fire_pose_at(&s->fires[i], t_s, &pose);
    fgg_drawable d = {.kind = FGG_DRAWABLE_VOLUME,
                      .volume = {.radius_m = PICTURE_FLAME_RADIUS_M,
                                 .height_m = PICTURE_FLAME_HEIGHT_M, .intensity = 1.0,
                                 .seed = (uint32_t)i + 1}};
    for (int k = 0; k < 3; k++)
        d.volume.base_m[k] = pose.position[k];
    d.volume.base_m[2] -= 0.2 * PICTURE_FLAME_HEIGHT_M;
    return d;
}

/* Aero object i at t_s: a stick a rod along its span, D across; a compact
 * body a ball of D. */
static fgg_drawable aero_at(const scene *s, size_t i, double t_s)
{
    const scene_aero *a = &s->aeros[i];
    fg_aero_pose pose;
    scene_aero_pose_at(a, t_s, &pose);
    double radius = 0.5 * fg_aero_texture_get(a->texture)->reference_m;
    fgg_surface metal = {.material = FGG_MATERIAL_METAL,
                         .colour = {STEEL[0], STEEL[1], STEEL[2]}};
    if (a->post.body == FG_AERO_COMPACT) {
        fgg_drawable d = {.kind = FGG_DRAWABLE_SPHERE,
                          .sphere = {.radius_m = radius, .surface = metal}};
        for (int k = 0; k < 3; k++)
            d.sphere.centre_m[k] = pose.position[k];
        return d;
    }
    fgg_drawable d = {.kind = FGG_DRAWABLE_ROD, .rod = {.radius_m = radius, .surface = metal}};
    for (int k = 0; k < 3; k++) {
        d.rod.a_m[k] = pose.position[k] + a->post.start_m * pose.axis[k];
        d.rod.b_m[k] = pose.position[k] + a->post.end_m * pose.axis[k];
    }
    return d;
}

int picture_sources_add(fgg_picture *pic, const scene *s, double t_s, uint32_t *ids, char *err,
                        size_t err_size)
{
    for (size_t i = 0; i < s->fire_count + s->aero_count; i++) {
        bool fire = i < s->fire_count;
        fgg_drawable d = fire ? fire_at(s, i, t_s) : aero_at(s, i - s->fire_count, t_s);
        if (fgg_picture_add_drawable(pic, &d, &ids[i]) != FG_OK) {
            snprintf(err, err_size, "%s[%zu]: the picture refused it: %s",
                     fire ? "fires" : "aero_objects", fire ? i : i - s->fire_count,
                     fgg_error_message());
            return -1;
        }
    }
    return 0;
}

int picture_sources_move(fgg_picture *pic, const scene *s, double t_s, const uint32_t *ids,
                         char *err, size_t err_size)
{
    for (size_t i = 0; i < s->fire_count + s->aero_count; i++) {
        bool fire = i < s->fire_count;
        if (fire && s->fires[i].path_count < 2)
            continue; /* it does not move */
        fgg_drawable d = fire ? fire_at(s, i, t_s) : aero_at(s, i - s->fire_count, t_s);
        if (fgg_picture_update(pic, ids[i], &d) != FG_OK) {
            snprintf(err, err_size, "%s[%zu]: the picture refused its pose at %.3f s: %s",
                     fire ? "fires" : "aero_objects", fire ? i : i - s->fire_count, t_s,
                     fgg_error_message());
            return -1;
        }
    }
    return 0;
}
