/* Statistical lightning: the tortuous walk along a skeleton, its branches,
 * and the designer features' effect on the walk (rules in fulgur/lightning.h). */
#include <math.h>
#include <stdlib.h>

#include "designer_internal.h"
#include "fg_array.h"
#include "fulgur/sound.h"

#define BRANCH_ANGLE_MIN_DEG 20.0
#define BRANCH_ANGLE_MAX_DEG 50.0
/* A clap stretch closes on its radius by at most this many steps' worth. */
#define CLAP_CLOSING 0.7
#define ROAR_GAIN 3.0
/* Within this many steps of the skeleton's end the walk goes straight in:
 * a walk turning 16 degrees a step can circle a point ~11 m away forever. */
#define FINAL_STEPS 4.0
#define WALK_LIMIT 50.0

static const double deg = FG_PI / 180.0;

typedef struct spawn {
    size_t node;
    fg_vec3 dir;
    uint32_t depth;
} spawn;

typedef struct walker {
    const fg_lightning_config *p;
    const fg_skeleton *skel;
    const fg_stretch *stretches;
    fg_tree *tree;
    fg_rng rng;
    spawn *spawns;
    size_t nspawn, spawn_cap;
    /* the turn law and the branching at segment_m (per_step) */
    double turn_rad, branch_p;
    /* the in-cloud channel: nodes in_cloud_first .. in_cloud_end - 1 */
    size_t in_cloud_first, in_cloud_end;
} walker;

/* The direction after one step of the turn law (see fulgur/lightning.h). */
static fg_vec3 turn(walker *w, fg_vec3 d, fg_vec3 heading, double mean_rad)
{
    double gauss = fg_rng_gaussian(&w->rng);
    double theta = fabs(gauss) * mean_rad * sqrt(FG_PI / 2.0); /* half-normal of mean mean_rad */
    double dev = fg_v3_angle(d, heading) / (w->p->max_deviation_deg * deg);
    double k = dev < 1 ? dev : 1;
    fg_vec3 u = fg_v3_perp(d), v = fg_v3_cross(d, u);
    double phi = atan2(fg_v3_dot(heading, v), fg_v3_dot(heading, u)) +
                 FG_PI * (1 - k) * fg_rng_range(&w->rng, -1, 1);
    return fg_v3_unit(fg_v3_turn(d, theta, phi));
}

static fg_result add(walker *w, fg_vec3 q, size_t parent, uint32_t flags, uint32_t depth,
                     fg_vec3 dir, size_t *index)
{
    if (fg_tree_count(w->tree) >= w->p->max_nodes)
        return FG_ERR_CAPACITY;
    fg_result r = fg_tree_add(w->tree, q.x, q.y, q.z, (int32_t)parent, flags, index);
    if (r != FG_OK || depth >= w->p->branch_depth || w->p->branch_probability < 0 ||
        fg_rng_uniform(&w->rng) >= w->branch_p)
        return r;
    spawn *s = fg_array_grow(w->spawns, &w->spawn_cap, w->nspawn + 1, sizeof *s, 256);
    if (!s)
        return FG_ERR_NO_MEMORY;
    w->spawns = s;
    w->spawns[w->nspawn++] = (spawn){*index, dir, depth + 1};
    return FG_OK;
}

/* The designer feature whose stretch holds arclength s, or -1. */
static int feature_at(const walker *w, double s)
{
    for (size_t i = 0; i < w->p->feature_count; i++)
        if (s >= w->stretches[i].s0 && s < w->stretches[i].s1)
            return (int)i;
    return -1;
}

/* One step on the sphere of a clap stretch: the tangential part of dir, and
 * a radial part closing on the radius. */
static fg_vec3 clap_step(fg_vec3 pos, fg_vec3 dir, fg_vec3 centre, double radius, double step)
{
    fg_vec3 rv = fg_v3_sub(pos, centre);
    double r = fg_v3_len(rv);
    fg_vec3 n = fg_v3_scale(rv, 1 / r);
    fg_vec3 t = fg_v3_sub(dir, fg_v3_scale(n, fg_v3_dot(dir, n)));
    t = fg_v3_len(t) > 1e-9 ? fg_v3_unit(t) : fg_v3_perp(n);
    double dr = radius - r, lim = CLAP_CLOSING * step;
    dr = dr > lim ? lim : dr < -lim ? -lim : dr;
    fg_vec3 q = fg_v3_add(pos, fg_v3_add(fg_v3_scale(t, sqrt(step * step - dr * dr)),
                                         fg_v3_scale(n, dr)));
    return fg_v3_add(centre, fg_v3_scale(fg_v3_unit(fg_v3_sub(q, centre)), r + dr));
}

/* Where the step a -> b crosses the ground. */
static fg_vec3 ground_hit(fg_vec3 a, fg_vec3 b)
{
    return fg_v3_add(a, fg_v3_scale(fg_v3_sub(b, a), a.z / (a.z - b.z)));
}

/* Walks skeleton k from node (already in the tree, at k's first point) to
 * k's end or the ground, flagging its nodes with flags; designed: the
 * designer features' stretches (of w->skel) apply. */
static fg_result walk(walker *w, const fg_skeleton *k, size_t node, uint32_t flags, int designed)
{
    const fg_lightning_config *p = w->p;
    double step = p->segment_m, total = fg_skeleton_length(k);
    fg_vec3 listener = fg_v3(p->listener_m[0], p->listener_m[1], p->listener_m[2]);
    fg_vec3 end = k->p[k->n - 1], pos = k->p[0];
    fg_vec3 dir = fg_v3_unit(fg_v3_sub(fg_skeleton_at(k, p->lookahead_m), pos));
    size_t hint = 0;
    fg_result r = FG_OK;
    for (size_t steps = 0; r == FG_OK; steps++) {
        if ((double)steps * step > WALK_LIMIT * total)
            return FG_ERR_UNREACHABLE;
        double left = fg_v3_len(fg_v3_sub(end, pos));
        if (left <= FINAL_STEPS * step) {
            size_t pieces = (size_t)ceil(left / step);
            fg_vec3 from = pos;
            for (size_t i = 1; i <= pieces && r == FG_OK; i++) {
                pos = fg_v3_add(from, fg_v3_scale(fg_v3_sub(end, from), (double)i / pieces));
                r = add(w, pos, node, flags, 0, dir, &node);
            }
            return r;
        }
        double s = fg_skeleton_project(k, pos, &hint);
        int b = designed ? feature_at(w, s) : -1;
        fg_thunder_kind f = b >= 0 ? p->features[b].kind : 0;
        double a = b >= 0 ? fg_thunder_amplitude(&p->features[b]) : 1;
        double mean = w->turn_rad * (f == FG_THUNDER_ROAR ? 1 + ROAR_GAIN * a : 1);
        fg_vec3 heading = fg_v3_unit(fg_v3_sub(fg_skeleton_at(k, s + p->lookahead_m), pos));
        dir = turn(w, dir, heading, mean);
        fg_vec3 next = fg_v3_add(pos, fg_v3_scale(dir, step));
        if (f == FG_THUNDER_CLAP) {
            next = clap_step(pos, dir, listener, w->stretches[b].radius_m, step);
            dir = fg_v3_unit(fg_v3_sub(next, pos));
        }
        if (next.z <= 0)
            return add(w, ground_hit(pos, next), node, flags, 0, dir, &node);
        r = add(w, next, node, flags, 0, dir, &node);
        pos = next;
    }
    return r;
}

static fg_result walk_main(walker *w)
{
    fg_vec3 root = w->skel->p[0];
    size_t node;
    fg_result r = fg_tree_add(w->tree, root.x, root.y, root.z, -1, FG_NODE_MAIN, &node);
    return r == FG_OK ? walk(w, w->skel, node, FG_NODE_MAIN, 1) : r;
}

/* The in-cloud channel: from the root along a jittered horizontal course
 * (see fulgur/lightning.h). */
static fg_result walk_in_cloud(walker *w)
{
    const fg_lightning_config *p = w->p;
    fg_vec3 root = w->skel->p[0];
    double az = p->in_cloud_azimuth_deg * deg;
    fg_vec3 far = fg_v3_add(root, fg_v3(p->in_cloud_m * cos(az), p->in_cloud_m * sin(az), 0));
    fg_skeleton course = {0};
    fg_result r = fg_skeleton_course(&course, &w->rng, root, far);
    if (r == FG_OK)
        r = walk(w, &course, 0, 0, 0);
    fg_skeleton_free(&course);
    return r;
}

static fg_result grow_branch(walker *w, spawn sp)
{
    const fg_lightning_config *p = w->p;
    const fg_node *n = &fg_tree_nodes(w->tree)[sp.node];
    fg_vec3 pos = fg_v3(n->x, n->y, n->z);
    double angle = fg_rng_range(&w->rng, BRANCH_ANGLE_MIN_DEG, BRANCH_ANGLE_MAX_DEG) * deg;
    fg_vec3 heading = fg_v3_unit(fg_v3_turn(sp.dir, angle, fg_rng_range(&w->rng, 0, 2 * FG_PI)));
    double mean_len = p->branch_length_m / (double)(1u << (sp.depth - 1));
    double length = -log(1.0 - fg_rng_uniform(&w->rng)) * mean_len;
    size_t steps = (size_t)ceil(length / p->segment_m), node = sp.node;
    fg_vec3 dir = heading;
    for (size_t i = 0; i < steps; i++) {
        dir = turn(w, dir, heading, w->turn_rad);
        fg_vec3 next = fg_v3_add(pos, fg_v3_scale(dir, p->segment_m));
        if (next.z <= 0)
            break;
        fg_result r = add(w, next, node, 0, sp.depth, dir, &node);
        if (r != FG_OK)
            return r;
        pos = next;
    }
    return FG_OK;
}

static void fill_report(const walker *w, size_t main_nodes, fg_lightning_report *report)
{
    const fg_node *nodes = fg_tree_nodes(w->tree);
    *report = (fg_lightning_report){.main_nodes = main_nodes,
                                    .segments = fg_tree_count(w->tree) - 1,
                                    .skeleton_length_m = fg_skeleton_length(w->skel),
                                    .in_cloud_first = w->in_cloud_first,
                                    .in_cloud_nodes = w->in_cloud_end - w->in_cloud_first};
    for (size_t i = w->in_cloud_first; i < w->in_cloud_end; i++) {
        const fg_node *a = &nodes[i], *b = &nodes[a->parent];
        report->in_cloud_length_m += fg_v3_len(fg_v3_sub(fg_v3(a->x, a->y, a->z),
                                                         fg_v3(b->x, b->y, b->z)));
    }
    for (size_t i = 0; i < w->p->feature_count; i++) {
        report->features[i].distance_m = w->stretches[i].radius_m;
        report->features[i].first_node = main_nodes; /* none yet */
    }
    size_t hint = 0;
    for (size_t i = 0; i < main_nodes; i++) {
        fg_vec3 q = fg_v3(nodes[i].x, nodes[i].y, nodes[i].z);
        if (i > 0) {
            const fg_node *a = &nodes[i - 1];
            report->main_length_m += fg_v3_len(fg_v3_sub(q, fg_v3(a->x, a->y, a->z)));
        }
        int b = feature_at(w, fg_skeleton_project(w->skel, q, &hint));
        if (b < 0)
            continue;
        if (report->features[b].first_node == main_nodes)
            report->features[b].first_node = i;
        report->features[b].last_node = i;
    }
}

static fg_result build(walker *w, fg_skeleton *base, fg_skeleton *shaped, fg_stretch *stretches)
{
    const fg_lightning_config *p = w->p;
    fg_result r = FG_OK;
    if (p->skeleton_m)
        for (size_t i = 0; i < p->skeleton_points && r == FG_OK; i++)
            r = fg_skeleton_push(base, fg_v3(p->skeleton_m[3 * i], p->skeleton_m[3 * i + 1],
                                             p->skeleton_m[3 * i + 2]));
    else
        r = fg_skeleton_random(base, &w->rng, p->strike_m[0], p->strike_m[1], p->height_m);
    if (r != FG_OK)
        return r;
    fg_vec3 listener = fg_v3(p->listener_m[0], p->listener_m[1], p->listener_m[2]);
    if ((r = fg_designer_shape(base, p->features, p->feature_count, listener, shaped, stretches)) !=
        FG_OK)
        return r;
    w->skel = shaped;
    w->stretches = stretches;
    if ((r = walk_main(w)) != FG_OK)
        return r;
    size_t i = 0;
    for (; i < w->nspawn && r == FG_OK; i++)
        r = grow_branch(w, w->spawns[i]);
    w->in_cloud_first = w->in_cloud_end = fg_tree_count(w->tree);
    if (r != FG_OK || p->in_cloud_m < p->segment_m) /* shorter than a step: none */
        return r;
    if ((r = walk_in_cloud(w)) != FG_OK)
        return r;
    w->in_cloud_end = fg_tree_count(w->tree);
    for (; i < w->nspawn && r == FG_OK; i++)
        r = grow_branch(w, w->spawns[i]);
    return r;
}

fg_result fg_lightning_generate(const fg_lightning_config *config, fg_tree *out,
                                fg_lightning_report *report)
{
    fg_lightning_config p;
    fg_result r = fg_lightning_config_resolve(config, &p);
    if (r != FG_OK)
        return r;
    if (!out)
        return FG_ERR_NULL;
    if (fg_tree_count(out) != 0)
        return FG_ERR_ARGUMENT;
    /* turn_mean_deg and branch_probability hold for the reference step
     * (2 l of the lightning preset): a finer or coarser walk turns and
     * branches as much per metre of channel, so its shape and length, and
     * so its sound (the line integral), do not depend on segment_m */
    fg_preset_scale scale;
    if (fg_preset_get_scale(FG_PRESET_LIGHTNING, &scale) != FG_OK)
        return FG_ERR_ARGUMENT;
    double per_step = p.segment_m / (2.0 * scale.half_step_m);
    walker w = {.p = &p, .tree = out, .turn_rad = p.turn_mean_deg * deg * sqrt(per_step),
                .branch_p = fmin(1.0, p.branch_probability * per_step)};
    fg_rng_seed(&w.rng, p.seed);
    fg_skeleton base = {0}, shaped = {0};
    fg_stretch stretches[FG_THUNDER_MAX_FEATURES] = {{0}};
    r = build(&w, &base, &shaped, stretches);
    if (r == FG_OK && report) {
        size_t main_nodes = 0;
        while (main_nodes < fg_tree_count(out) &&
               (fg_tree_nodes(out)[main_nodes].flags & FG_NODE_MAIN))
            main_nodes++;
        fill_report(&w, main_nodes, report);
    }
    free(w.spawns);
    fg_skeleton_free(&base);
    fg_skeleton_free(&shaped);
    if (r != FG_OK)
        fg_tree_clear(out);
    return r;
}
