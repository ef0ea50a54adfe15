/* The drawables other than discharges: their checks, their poses, and the
 * instances a frame draws them from (eye-relative, in double until then, so
 * that a millimetre ball and a kilometre of ground keep float precision). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "picture_internal.h"
#include "fg_array.h"
#include "fg_vec3.h"

/* Linear albedos: a warm polished brass, a mid grey, a faint blue-white
 * glass tint. */
static const float default_colour[3][3] = {{0.80f, 0.62f, 0.32f},
                                           {0.35f, 0.35f, 0.35f},
                                           {0.90f, 0.95f, 1.00f}};
/* A flame's bounding box: half its base radius times this across. */
#define FLAME_BOUND 1.25
/* A plane is drawn as a box this thin, relative to its half size. */
#define PLANE_THICKNESS 0.002

/* Planck's law at three wavelengths (the sRGB primaries' dominant ones,
 * 610, 550 and 465 nm), normalised to a luminance of 1. */
static void blackbody_rgb(double temperature_k, float rgb[3])
{
    const double lambda_m[3] = {610e-9, 550e-9, 465e-9};
    const double c2 = 1.4388e-2; /* h c / k, m K */
    double v[3];
    for (int k = 0; k < 3; k++)
        v[k] = 1 / (pow(lambda_m[k], 5) * (exp(c2 / (lambda_m[k] * temperature_k)) - 1));
    double y = 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
    for (int k = 0; k < 3; k++)
        rgb[k] = (float)(v[k] / y);
}

void fgg_volume_colour(double temperature_k, float rgb[3])
{
    blackbody_rgb(temperature_k == 0 ? 1500 : temperature_k, rgb);
}

static fg_result finite_all(const double *v, int n, const char *who, const char *what)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(v[k]))
            return fgg_fail(FG_ERR_NOT_FINITE, "%s: %s is not finite", who, what);
    return FG_OK;
}

static fg_result positive(double v, const char *who, const char *what)
{
    if (!isfinite(v))
        return fgg_fail(FG_ERR_NOT_FINITE, "%s: %s is not finite", who, what);
    if (!(v > 0))
        return fgg_fail(FG_ERR_ARGUMENT, "%s: %s = %g must be > 0", who, what, v);
    return FG_OK;
}

static fg_result check_surface(const fgg_surface *s, const char *who)
{
    if (s->material != FGG_MATERIAL_METAL && s->material != FGG_MATERIAL_MATTE &&
        s->material != FGG_MATERIAL_GLASS)
        return fgg_fail(FG_ERR_ARGUMENT, "%s: unknown material %d", who, (int)s->material);
    for (int k = 0; k < 3; k++)
        if (!isfinite(s->colour[k]) || s->colour[k] < 0)
            return fgg_fail(isfinite(s->colour[k]) ? FG_ERR_ARGUMENT : FG_ERR_NOT_FINITE,
                            "%s: surface colour[%d] = %g is not a finite value >= 0", who, k,
                            (double)s->colour[k]);
    return FG_OK;
}

const fgg_ground *fgg_picture_ground(const fgg_picture *p)
{
    for (size_t i = 0; i < p->object_count; i++)
        if (p->objects[i].d.kind == FGG_DRAWABLE_GROUND)
            return &p->objects[i].d.ground;
    return NULL;
}

static fg_result check_ground(const fgg_picture *p, const fgg_ground *g, const char *who)
{
    const double v[] = {g->height_m, g->cloud_base_m, g->cloud_centre_m[0], g->cloud_centre_m[1],
                        g->cloud_radius_m, g->haze_per_m};
    fg_result r = finite_all(v, 6, who, "a ground value");
    if (r != FG_OK)
        return r;
    if (g->cloud_base_m != 0 && g->cloud_base_m <= g->height_m)
        return fgg_fail(FG_ERR_ARGUMENT, "%s: cloud_base_m %g is not above the ground (%g)", who,
                        g->cloud_base_m, g->height_m);
    if (g->cloud_radius_m < 0 || g->haze_per_m < 0)
        return fgg_fail(FG_ERR_ARGUMENT, "%s: cloud_radius_m %g and haze_per_m %g must be >= 0",
                        who, g->cloud_radius_m, g->haze_per_m);
    if (p && fgg_picture_ground(p))
        return fgg_fail(FG_ERR_ARGUMENT, "%s: the picture has a ground already", who);
    return FG_OK;
}

static fg_result check_volume(const fgg_volume *v, const char *who)
{
    fg_result r = finite_all(v->base_m, 3, who, "base_m");
    if (r == FG_OK)
        r = positive(v->radius_m, who, "radius_m");
    if (r == FG_OK)
        r = positive(v->height_m, who, "height_m");
    if (r != FG_OK)
        return r;
    if (!isfinite(v->temperature_k) || !isfinite(v->intensity))
        return fgg_fail(FG_ERR_NOT_FINITE, "%s: temperature_k or intensity is not finite", who);
    if (v->temperature_k != 0 && (v->temperature_k < 800 || v->temperature_k > 3000))
        return fgg_fail(FG_ERR_ARGUMENT, "%s: temperature_k %g is outside 800..3000", who,
                        v->temperature_k);
    if (v->intensity < 0)
        return fgg_fail(FG_ERR_ARGUMENT, "%s: intensity %g is negative", who, v->intensity);
    return FG_OK;
}

/* Checks d against its kind's rules; p NULL skips the one-ground rule. */
static fg_result check(const fgg_picture *p, const fgg_drawable *d, const char *who)
{
    fg_result r = FG_OK;
    switch (d->kind) {
    case FGG_DRAWABLE_SPHERE:
        r = finite_all(d->sphere.centre_m, 3, who, "centre_m");
        if (r == FG_OK)
            r = positive(d->sphere.radius_m, who, "radius_m");
        return r != FG_OK ? r : check_surface(&d->sphere.surface, who);
    case FGG_DRAWABLE_ROD:
        r = finite_all(d->rod.a_m, 3, who, "a_m");
        if (r == FG_OK)
            r = finite_all(d->rod.b_m, 3, who, "b_m");
        if (r == FG_OK)
            r = positive(d->rod.radius_m, who, "radius_m");
        return r != FG_OK ? r : check_surface(&d->rod.surface, who);
    case FGG_DRAWABLE_BOX:
        r = finite_all(d->box.min_m, 3, who, "min_m");
        if (r == FG_OK)
            r = finite_all(d->box.max_m, 3, who, "max_m");
        for (int k = 0; r == FG_OK && k < 3; k++)
            if (d->box.max_m[k] < d->box.min_m[k])
                return fgg_fail(FG_ERR_ARGUMENT, "%s: max_m[%d] %g is below min_m[%d] %g", who, k,
                                d->box.max_m[k], k, d->box.min_m[k]);
        return r != FG_OK ? r : check_surface(&d->box.surface, who);
    case FGG_DRAWABLE_PLANE:
        r = finite_all(d->plane.centre_m, 3, who, "centre_m");
        if (r == FG_OK)
            r = finite_all(d->plane.normal, 3, who, "normal");
        if (r == FG_OK && fg_v3_len(fg_v3_load(d->plane.normal)) == 0)
            return fgg_fail(FG_ERR_ARGUMENT, "%s: the plane's normal is zero", who);
        if (r == FG_OK)
            r = positive(d->plane.half_size_m, who, "half_size_m");
        return r != FG_OK ? r : check_surface(&d->plane.surface, who);
    case FGG_DRAWABLE_GROUND:
        return check_ground(p, &d->ground, who);
    case FGG_DRAWABLE_MARKER:
        r = finite_all(d->marker.position_m, 3, who, "position_m");
        if (r == FG_OK && !isfinite(d->marker.radius_px))
            r = fgg_fail(FG_ERR_NOT_FINITE, "%s: radius_px is not finite", who);
        if (r == FG_OK && (d->marker.sign < -1 || d->marker.sign > 1))
            r = fgg_fail(FG_ERR_ARGUMENT, "%s: sign %d is not -1, 0 or +1", who, d->marker.sign);
        if (r == FG_OK && (d->marker.radius_px < 0 || d->marker.radius_px > 256))
            r = fgg_fail(FG_ERR_ARGUMENT, "%s: radius_px %g is outside 0..256", who,
                         d->marker.radius_px);
        return r;
    case FGG_DRAWABLE_VOLUME:
        return check_volume(&d->volume, who);
    case FGG_DRAWABLE_DISCHARGE:
        break;
    }
    return fgg_fail(FG_ERR_ARGUMENT, "%s: unknown drawable kind %d", who, (int)d->kind);
}

fg_result fgg_picture_check_object(const fgg_picture *p, const fgg_drawable *d, const char *who)
{
    return check(p, d, who);
}

fg_result fgg_picture_add_object(fgg_picture *p, const fgg_drawable *d, uint32_t *id)
{
    if (p->object_count == FGG_PICTURE_MAX_OBJECTS)
        return fgg_fail(FG_ERR_CAPACITY, "fgg_picture_add_drawable: already %d drawables",
                        FGG_PICTURE_MAX_OBJECTS);
    fgg_object_rec *grown = fg_array_grow(p->objects, &p->object_capacity,
                                          p->object_count + 1, sizeof *grown, 16);
    float *floats = grown ? fg_array_grow(p->object_floats, &p->object_floats_capacity,
                                          FGG_OBJECT_FLOATS * (p->object_count + 1),
                                          sizeof *floats, 16 * FGG_OBJECT_FLOATS)
                          : NULL;
    if (grown)
        p->objects = grown;
    if (floats)
        p->object_floats = floats;
    if (!grown || !floats)
        return fgg_fail(FG_ERR_NO_MEMORY, "fgg_picture_add_drawable: no memory");
    fgg_object_rec *o = &p->objects[p->object_count++];
    *o = (fgg_object_rec){.id = fgg_picture_next_id(p), .d = *d};
    if (id)
        *id = o->id;
    return FG_OK;
}

size_t fgg_picture_remove_objects(fgg_picture *p, uint32_t id)
{
    size_t kept = 0;
    for (size_t i = 0; i < p->object_count; i++)
        if (id != 0 && p->objects[i].id != id)
            p->objects[kept++] = p->objects[i];
    size_t removed = p->object_count - kept;
    p->object_count = kept;
    return removed;
}

static fgg_object_rec *find_object(fgg_picture *p, uint32_t id)
{
    for (size_t i = 0; i < p->object_count; i++)
        if (p->objects[i].id == id && p->objects[i].d.kind != FGG_DRAWABLE_GROUND)
            return &p->objects[i];
    return NULL;
}

fg_result fgg_picture_update(fgg_picture *p, uint32_t id, const fgg_drawable *d)
{
    if (!p || !d)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_update: %s is NULL", !p ? "picture" : "drawable");
    fgg_object_rec *o = find_object(p, id);
    if (!o)
        return fgg_fail(FG_ERR_NOT_FOUND, "fgg_picture_update: no object has id %u (discharges "
                        "and the ground are removed and added again)", (unsigned)id);
    if (d->kind != o->d.kind)
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_update: object %u is of kind %d, not %d",
                        (unsigned)id, (int)o->d.kind, (int)d->kind);
    fg_result r = check(p, d, "fgg_picture_update");
    if (r == FG_OK)
        o->d = *d;
    return r;
}

fg_result fgg_picture_set_pose(fgg_picture *p, uint32_t id, const fgg_pose *pose)
{
    if (!p)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_set_pose: picture is NULL");
    fgg_object_rec *o = find_object(p, id);
    if (!o)
        return fgg_fail(FG_ERR_NOT_FOUND, "fgg_picture_set_pose: no object has id %u",
                        (unsigned)id);
    if (!pose) {
        o->pose = (fgg_pose){.position_m = {0}};
        return FG_OK;
    }
    fg_result r = finite_all(pose->position_m, 3, "fgg_picture_set_pose", "position_m");
    if (r == FG_OK)
        r = finite_all(pose->rotation, 9, "fgg_picture_set_pose", "rotation");
    if (r != FG_OK)
        return r;
    int zero = 1;
    for (int k = 0; k < 9; k++)
        zero &= pose->rotation[k] == 0;
    if (!zero) {
        const double *m = pose->rotation;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                double dot = m[a] * m[b] + m[3 + a] * m[3 + b] + m[6 + a] * m[6 + b];
                if (fabs(dot - (a == b)) > 1e-6)
                    return fgg_fail(FG_ERR_ARGUMENT,
                                    "fgg_picture_set_pose: the rotation is not orthonormal");
            }
        double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                     m[2] * (m[3] * m[7] - m[4] * m[6]);
        if (det < 0)
            return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_set_pose: the rotation is a reflection "
                            "(determinant -1)");
    }
    o->pose = *pose;
    return FG_OK;
}

static int posed(const fgg_pose *pose)
{
    for (int k = 0; k < 9; k++)
        if (pose->rotation[k] != 0)
            return 1;
    return 0;
}

/* A body direction into the world (rotation only). */
static void rotate(const fgg_object_rec *o, const double v[3], double out[3])
{
    if (!posed(&o->pose)) {
        memcpy(out, v, 3 * sizeof *out);
        return;
    }
    const double *m = o->pose.rotation;
    for (int r = 0; r < 3; r++)
        out[r] = m[3 * r] * v[0] + m[3 * r + 1] * v[1] + m[3 * r + 2] * v[2];
}

void fgg_object_to_world(const fgg_object_rec *o, const double body[3], double world[3])
{
    rotate(o, body, world);
    for (int k = 0; k < 3; k++)
        world[k] += o->pose.position_m[k];
}

/* An eye-relative point of the object into f[0..2]. */
static void put_point(const fgg_object_rec *o, const double body[3], const double eye[3],
                      float *f)
{
    double w[3];
    fgg_object_to_world(o, body, w);
    for (int k = 0; k < 3; k++)
        f[k] = (float)(w[k] - eye[k]);
}

static void put_colour(const fgg_surface *s, float *f)
{
    int given = s->colour[0] > 0 || s->colour[1] > 0 || s->colour[2] > 0;
    memcpy(f, given ? s->colour : default_colour[s->material], 3 * sizeof *f);
}

static void round_instance(const fgg_object_rec *o, const double eye[3], float *f)
{
    const fgg_drawable *d = &o->d;
    const double *a = d->kind == FGG_DRAWABLE_SPHERE ? d->sphere.centre_m : d->rod.a_m;
    const double *b = d->kind == FGG_DRAWABLE_SPHERE ? d->sphere.centre_m : d->rod.b_m;
    const fgg_surface *s = d->kind == FGG_DRAWABLE_SPHERE ? &d->sphere.surface : &d->rod.surface;
    put_point(o, a, eye, f);
    f[3] = (float)(d->kind == FGG_DRAWABLE_SPHERE ? d->sphere.radius_m : d->rod.radius_m);
    put_point(o, b, eye, f + 4);
    f[7] = (float)s->material;
    put_colour(s, f + 8);
}

/* A box given by its centre and three half-axes in the body frame. */
static void box_axes(const fgg_object_rec *o, const double centre[3], const double axes[3][3],
                     float material, const double eye[3], float *f)
{
    put_point(o, centre, eye, f);
    f[3] = material;
    for (int a = 0; a < 3; a++) {
        double w[3];
        rotate(o, axes[a], w);
        for (int k = 0; k < 3; k++)
            f[4 * (a + 1) + k] = (float)w[k];
    }
}

static void box_instance(const fgg_object_rec *o, const double eye[3], float *f)
{
    const fgg_drawable *d = &o->d;
    double c[3], ax[3][3] = {{0}};
    if (d->kind == FGG_DRAWABLE_BOX) {
        for (int k = 0; k < 3; k++) {
            c[k] = 0.5 * (d->box.min_m[k] + d->box.max_m[k]);
            ax[k][k] = 0.5 * (d->box.max_m[k] - d->box.min_m[k]);
        }
        box_axes(o, c, ax, (float)d->box.surface.material, eye, f);
        put_colour(&d->box.surface, f + 16);
        return;
    }
    /* a plane: two axes across the square, the third along its normal */
    fg_vec3 n = fg_v3_unit(fg_v3_load(d->plane.normal));
    fg_vec3 u = fg_v3_perp(n);
    fg_vec3 v = fg_v3_cross(n, u);
    double h = d->plane.half_size_m;
    fg_v3_store(fg_v3_scale(u, h), ax[0]);
    fg_v3_store(fg_v3_scale(v, h), ax[1]);
    fg_v3_store(fg_v3_scale(n, PLANE_THICKNESS * h), ax[2]);
    box_axes(o, d->plane.centre_m, ax, (float)d->plane.surface.material, eye, f);
    put_colour(&d->plane.surface, f + 16);
}

/* A flame in its bounding box: the box's third axis is the flame's up
 * and half its height; the fifth vec4 its colour and intensity; the
 * seed rides in the first vec4's w. */
static void volume_instance(const fgg_object_rec *o, const double eye[3], float *f)
{
    const fgg_volume *v = &o->d.volume;
    double c[3] = {v->base_m[0], v->base_m[1], v->base_m[2] + 0.5 * v->height_m};
    double r = FLAME_BOUND * v->radius_m;
    const double ax[3][3] = {{r, 0, 0}, {0, r, 0}, {0, 0, 0.5 * v->height_m}};
    box_axes(o, c, ax, 0, eye, f);
    f[3] = (float)(v->seed % 1024u);
    fgg_volume_colour(v->temperature_k, f + 16);
    f[19] = (float)v->intensity;
}

static void marker_instance(const fgg_object_rec *o, const double eye[3], float *f)
{
    put_point(o, o->d.marker.position_m, eye, f);
    f[3] = (float)(o->d.marker.radius_px == 0 ? 7 : o->d.marker.radius_px);
    f[4] = (float)o->d.marker.sign;
}

static int is_glass(const fgg_drawable *d)
{
    const fgg_surface *s = d->kind == FGG_DRAWABLE_SPHERE ? &d->sphere.surface
                           : d->kind == FGG_DRAWABLE_ROD  ? &d->rod.surface
                           : d->kind == FGG_DRAWABLE_BOX  ? &d->box.surface
                                                          : &d->plane.surface;
    return s->material == FGG_MATERIAL_GLASS;
}

/* The draw order's group of a drawable: 0..5, or -1 (the ground). */
static int group(const fgg_drawable *d)
{
    switch (d->kind) {
    case FGG_DRAWABLE_SPHERE:
    case FGG_DRAWABLE_ROD:
        return is_glass(d) ? 1 : 0;
    case FGG_DRAWABLE_BOX:
    case FGG_DRAWABLE_PLANE:
        return is_glass(d) ? 3 : 2;
    case FGG_DRAWABLE_VOLUME:
        return 4;
    case FGG_DRAWABLE_MARKER:
        return 5;
    default:
        return -1;
    }
}

fg_result fgg_picture_upload_objects(fgg_picture *p, const fgg_frame *frame,
                                     fgg_object_ranges *ranges)
{
    size_t count[6] = {0}, at[6];
    for (size_t i = 0; i < p->object_count; i++) {
        int g = group(&p->objects[i].d);
        if (g >= 0)
            count[g]++;
    }
    size_t total = 0;
    for (int g = 0; g < 6; g++) {
        at[g] = total;
        total += count[g];
    }
    *ranges = (fgg_object_ranges){.round_opaque = at[0], .round_glass = at[1],
                                  .box_opaque = at[2], .box_glass = at[3], .volume = at[4],
                                  .marker = at[5], .total = total};
    if (total == 0)
        return FG_OK;
    const double *eye = frame->camera->eye_m;
    for (size_t i = 0; i < p->object_count; i++) {
        const fgg_object_rec *o = &p->objects[i];
        int g = group(&o->d);
        if (g < 0)
            continue;
        float *f = p->object_floats + FGG_OBJECT_FLOATS * at[g]++;
        memset(f, 0, FGG_OBJECT_FLOATS * sizeof *f);
        if (g <= 1)
            round_instance(o, eye, f);
        else if (g <= 3)
            box_instance(o, eye, f);
        else if (g == 4)
            volume_instance(o, eye, f);
        else
            marker_instance(o, eye, f);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, p->object_buf);
    glBufferData(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)(total * FGG_OBJECT_FLOATS * sizeof(float)),
                 p->object_floats, GL_STREAM_DRAW);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return fgg_gl_check("fgg_picture_draw: uploading objects");
}
