/* An apparatus into drawables: the conductors as the field knows them,
 * and what a viewer expects around them. A spark gap's brass balls sit on
 * stems along the gap's axis; a plasma ball's globe is glass, its
 * electrode a small steel ball on a stem, and it stands in a black base on
 * a table; a field generator's conductors are drawn as they are, in metal,
 * glass where they enclose the rest (an "outside" shape). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "picture_apparatus.h"
#include "fg_vec3.h"

/* Proportions, of a ball's radius (spark gap) or the globe's (plasma ball). */
#define STEM_LENGTH 2.5
#define STEM_RADIUS 0.28
#define BASE_HALF_WIDTH 0.42
#define BASE_HEIGHT 0.45
#define BASE_SINK 0.88      /* the base's top, below the globe's centre */
#define TABLE_HALF_SIZE 2.5
#define ELECTRODE_STEM_RADIUS 0.04
/* A field's point conductor, and its planes, of the grid box's diagonal. */
#define POINT_RADIUS 0.01
#define PLANE_HALF_SIZE 0.5

static const float STEEL[3] = {0.55f, 0.56f, 0.58f};
static const float BLACK[3] = {0.025f, 0.025f, 0.028f};
static const float WOOD[3] = {0.20f, 0.12f, 0.07f};

typedef struct adder {
    fgg_picture *pic;
    char *err;
    size_t err_size;
    int failed;
} adder;

static void add(adder *a, const fgg_drawable *d)
{
    if (a->failed || fgg_picture_add_drawable(a->pic, d, NULL) == FG_OK)
        return;
    snprintf(a->err, a->err_size, "the picture refused the apparatus: %s", fgg_error_message());
    a->failed = 1;
}

static fgg_surface surface(fgg_material m, const float *colour)
{
    fgg_surface s = {.material = m};
    if (colour)
        memcpy(s.colour, colour, sizeof s.colour);
    return s;
}

static void sphere(adder *a, const double c[3], double r, fgg_surface s)
{
    fgg_drawable d = {.kind = FGG_DRAWABLE_SPHERE, .sphere = {.radius_m = r, .surface = s}};
    memcpy(d.sphere.centre_m, c, sizeof d.sphere.centre_m);
    add(a, &d);
}

static void rod(adder *a, fg_vec3 from, fg_vec3 to, double r, fgg_surface s)
{
    fgg_drawable d = {.kind = FGG_DRAWABLE_ROD, .rod = {.radius_m = r, .surface = s}};
    fg_v3_store(from, d.rod.a_m);
    fg_v3_store(to, d.rod.b_m);
    add(a, &d);
}

static void box(adder *a, const double lo[3], const double hi[3], fgg_surface s)
{
    fgg_drawable d = {.kind = FGG_DRAWABLE_BOX, .box = {.surface = s}};
    memcpy(d.box.min_m, lo, sizeof d.box.min_m);
    memcpy(d.box.max_m, hi, sizeof d.box.max_m);
    add(a, &d);
}

static void spark_gap(adder *a, const scene_apparatus *ap)
{
    const fg_shape *b0 = &ap->shapes[0], *b1 = &ap->shapes[1];
    fg_vec3 c0 = fg_v3_load(b0->centre_m), c1 = fg_v3_load(b1->centre_m);
    fg_vec3 axis = fg_v3_sub(c1, c0);
    double len = fg_v3_len(axis);
    axis = len > 0 ? fg_v3_div(axis, len) : fg_v3(1, 0, 0);
    for (int i = 0; i < 2; i++) {
        const fg_shape *b = i ? b1 : b0;
        fg_vec3 c = fg_v3_load(b->centre_m), out = fg_v3_scale(axis, i ? 1 : -1);
        sphere(a, b->centre_m, b->radius_m, surface(FGG_MATERIAL_METAL, NULL));
        rod(a, c, fg_v3_add(c, fg_v3_scale(out, (1 + STEM_LENGTH) * b->radius_m)),
            STEM_RADIUS * b->radius_m, surface(FGG_MATERIAL_METAL, STEEL));
    }
}

static void plasma_ball(adder *a, const scene_apparatus *ap)
{
    const fg_shape *electrode = &ap->shapes[0], *globe = &ap->shapes[1];
    if (globe->outside == 0) { /* whichever is the glass */
        const fg_shape *t = electrode;
        electrode = globe, globe = t;
    }
    double R = globe->radius_m;
    fg_vec3 c = fg_v3_load(globe->centre_m);
    sphere(a, globe->centre_m, R, surface(FGG_MATERIAL_GLASS, NULL));
    sphere(a, electrode->centre_m, electrode->radius_m, surface(FGG_MATERIAL_METAL, STEEL));
    fg_vec3 e = fg_v3_load(electrode->centre_m);
    rod(a, e, fg_v3_add(c, fg_v3(0, 0, -BASE_SINK * R)), ELECTRODE_STEM_RADIUS * R,
        surface(FGG_MATERIAL_GLASS, NULL));
    double top = c.z - BASE_SINK * R, w = BASE_HALF_WIDTH * R;
    const double lo[3] = {c.x - w, c.y - w, top - BASE_HEIGHT * R};
    const double hi[3] = {c.x + w, c.y + w, top};
    box(a, lo, hi, surface(FGG_MATERIAL_MATTE, BLACK));
    fgg_drawable table = {.kind = FGG_DRAWABLE_PLANE,
                          .plane = {.centre_m = {c.x, c.y, lo[2]}, .normal = {0, 0, 1},
                                    .half_size_m = TABLE_HALF_SIZE * R,
                                    .surface = surface(FGG_MATERIAL_MATTE, WOOD)}};
    add(a, &table);
}

static void field(adder *a, const scene_apparatus *ap)
{
    double diag = fg_v3_len(fg_v3_sub(fg_v3_load(ap->box_max_m), fg_v3_load(ap->box_min_m)));
    for (size_t i = 0; i < ap->shape_count; i++) {
        const fg_shape *sh = &ap->shapes[i];
        fgg_surface s = surface(sh->outside ? FGG_MATERIAL_GLASS : FGG_MATERIAL_METAL, NULL);
        switch (sh->kind) {
        case FG_SHAPE_SPHERE:
            sphere(a, sh->centre_m, sh->radius_m, s);
            break;
        case FG_SHAPE_BOX:
            box(a, sh->box_min_m, sh->box_max_m, s);
            break;
        case FG_SHAPE_POINT:
            sphere(a, sh->centre_m, POINT_RADIUS * diag, s);
            break;
        case FG_SHAPE_PLANE:
        case FG_SHAPE_GROUND: { /* ground: made a plane by scene_discharge_apparatus */
            /* the square of the plane nearest the grid's centre */
            fg_vec3 n = fg_v3_unit(fg_v3_load(sh->normal));
            fg_vec3 mid = fg_v3_scale(fg_v3_add(fg_v3_load(ap->box_min_m),
                                                fg_v3_load(ap->box_max_m)), 0.5);
            double off = fg_v3_dot(fg_v3_sub(mid, fg_v3_load(sh->centre_m)), n);
            fgg_drawable d = {.kind = FGG_DRAWABLE_PLANE,
                              .plane = {.half_size_m = PLANE_HALF_SIZE * diag, .surface = s}};
            fg_v3_store(fg_v3_sub(mid, fg_v3_scale(n, off)), d.plane.centre_m);
            fg_v3_store(n, d.plane.normal);
            add(a, &d);
            break;
        }
        }
    }
}

int picture_apparatus_add(fgg_picture *pic, const scene_apparatus *ap, char *err,
                          size_t err_size)
{
    adder a = {pic, err, err_size, 0};
    switch (ap->kind) {
    case SCENE_APPARATUS_SPARK_GAP:
        if (ap->shape_count == 2)
            spark_gap(&a, ap);
        break;
    case SCENE_APPARATUS_PLASMA_BALL:
        if (ap->shape_count == 2)
            plasma_ball(&a, ap);
        break;
    case SCENE_APPARATUS_FIELD:
        field(&a, ap);
        break;
    case SCENE_APPARATUS_NONE:
        break;
    }
    return a.failed ? -1 : 0;
}
