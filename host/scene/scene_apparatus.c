/* What a discharge happens among: the conductors of its field generator,
 * or for an explicit tree of a lab preset that preset's electrodes fitted
 * to the tree, in the scene's frame. */
#include <math.h>
#include <string.h>

#include "generator.h"
#include "scene_internal.h"
#include "fg_vec3.h"

/* The plasma ball preset: an electrode of 3 cm in a globe of 20 cm. */
#define PLASMA_ELECTRODE_RATIO 0.15

static void offset_shape(fg_shape *sh, const double off[3], const double box_min[3],
                         const double box_max[3])
{
    if (sh->kind == FG_SHAPE_GROUND) { /* z <= 0 of the generator's frame */
        sh->kind = FG_SHAPE_PLANE;
        sh->centre_m[0] = 0.5 * (box_min[0] + box_max[0]);
        sh->centre_m[1] = 0.5 * (box_min[1] + box_max[1]);
        sh->centre_m[2] = 0;
        sh->normal[0] = sh->normal[1] = 0;
        sh->normal[2] = 1;
    }
    for (int k = 0; k < 3; k++) {
        sh->centre_m[k] += off[k];
        sh->box_min_m[k] += off[k];
        sh->box_max_m[k] += off[k];
    }
}

static void set_sphere(fg_shape *sh, fg_vec3 centre, double radius, fg_shape_role role,
                       int outside)
{
    *sh = (fg_shape){.kind = FG_SHAPE_SPHERE, .role = role, .radius_m = radius,
                     .outside = outside};
    fg_v3_store(centre, sh->centre_m);
}

/* The end of the main channel: the node flagged main farthest from the
 * root, or the farthest node when none is flagged (the engine's rule). */
static size_t main_end(const fg_node *n, size_t count)
{
    int flagged = 0;
    for (size_t i = 1; i < count; i++)
        flagged |= (n[i].flags & FG_NODE_MAIN) != 0;
    size_t far = 0;
    double best = -1;
    for (size_t i = 1; i < count; i++) {
        if (flagged && !(n[i].flags & FG_NODE_MAIN))
            continue;
        double d = hypot(hypot(n[i].x - n[0].x, n[i].y - n[0].y), n[i].z - n[0].z);
        if (d > best)
            best = d, far = i;
    }
    return far;
}

/* The box around the fitted spheres. */
static void spheres_box(scene_apparatus *a)
{
    for (int k = 0; k < 3; k++) {
        a->box_min_m[k] = INFINITY;
        a->box_max_m[k] = -INFINITY;
    }
    for (size_t i = 0; i < a->shape_count; i++)
        for (int k = 0; k < 3; k++) {
            const fg_shape *sh = &a->shapes[i];
            a->box_min_m[k] = fmin(a->box_min_m[k], sh->centre_m[k] - sh->radius_m);
            a->box_max_m[k] = fmax(a->box_max_m[k], sh->centre_m[k] + sh->radius_m);
        }
}

static void fit(const scene_discharge *d, scene_apparatus *a)
{
    const fg_node *n = d->post.nodes;
    size_t count = d->post.node_count;
    if (!n || count < 2)
        return;
    fg_vec3 root = fg_v3(n[0].x, n[0].y, n[0].z);
    if (d->preset == FG_PRESET_SPARK_BALLS) {
        size_t e = main_end(n, count);
        fg_vec3 gap = fg_v3_sub(fg_v3(n[e].x, n[e].y, n[e].z), root);
        double len = fg_v3_len(gap);
        if (!(len > 0))
            return;
        fg_vec3 u = fg_v3_div(gap, len);
        double r = 0.5 * len;
        a->kind = SCENE_APPARATUS_SPARK_GAP;
        set_sphere(&a->shapes[0], fg_v3_sub(root, fg_v3_scale(u, r)), r, FG_ROLE_ORIGIN, 0);
        set_sphere(&a->shapes[1], fg_v3_add(root, fg_v3_scale(u, len + r)), r, FG_ROLE_TARGET, 0);
        a->shape_count = 2;
    } else if (d->preset == FG_PRESET_PLASMA_BALL) {
        double r = 0;
        for (size_t i = 1; i < count; i++)
            r = fmax(r, fg_v3_len(fg_v3_sub(fg_v3(n[i].x, n[i].y, n[i].z), root)));
        if (!(r > 0))
            return;
        a->kind = SCENE_APPARATUS_PLASMA_BALL;
        set_sphere(&a->shapes[0], root, PLASMA_ELECTRODE_RATIO * r, FG_ROLE_ORIGIN, 0);
        set_sphere(&a->shapes[1], root, r, FG_ROLE_TARGET, 1);
        a->shape_count = 2;
    }
    if (a->shape_count)
        spheres_box(a);
}

int scene_discharge_apparatus(const scene *s, size_t index, scene_apparatus *out, char *err,
                              size_t err_size)
{
    const scene_discharge *d = &s->discharges[index];
    memset(out, 0, sizeof *out);
    if (!d->generator) {
        fit(d, out);
        return 0;
    }
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(d->generator, "type");
    const gen_entry *g = gen_find(type->valuestring);
    if (!g->shapes)
        return 0;
    char path[JSON_PATH_MAX], at[JSON_PATH_MAX];
    json_path_index(at, sizeof at, "discharges", index);
    json_path_key(path, sizeof path, at, "generator");
    scene_apparatus a = {0};
    if (g->shapes(d->generator, path, a.shapes, &a.shape_count, a.box_min_m, a.box_max_m, err,
                  err_size) != 0)
        return -1;
    a.kind = g->apparatus;
    for (size_t i = 0; i < a.shape_count; i++)
        offset_shape(&a.shapes[i], d->offset_m, a.box_min_m, a.box_max_m);
    for (int k = 0; k < 3; k++) {
        a.box_min_m[k] += d->offset_m[k];
        a.box_max_m[k] += d->offset_m[k];
    }
    *out = a;
    return 0;
}
