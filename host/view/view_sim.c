/* The viewer's sim thread: every request from the frame thread becomes a
 * tree (grown here, never on the frame or audio thread), a post, and a
 * reply carrying the tree and the stroke offsets the engine will use.
 *
 * A timed discharge of the scene is posted as the scene gives it (its tree
 * was built before the threads started). For space, with no charges
 * placed, the scene's first discharge, rebuilt with the request's seed
 * when it has a generator. With charges, the
 * "charges" growth (fulgur/charges.h, Sosorbaram / Abe): the field of the
 * placed point charges steers the leader, which is what placing charges
 * means physically. The leader starts one step from the first charge
 * placed and grows toward the nearest charge of the other sign (a sphere
 * of two steps around it); with none, toward the ground, as a cloud
 * charge's stepped leader does. Either way the sound is the scene's first
 * discharge's (preset and overrides). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/clock.h"
#include "view.h"

static int grow_charges(const view_request *q, fg_tree *tree, char *err, size_t err_size)
{
    const fg_point_charge *first = &q->charges[0];
    const fg_point_charge *target = NULL;
    double best = INFINITY;
    for (size_t i = 1; i < q->charge_count; i++) {
        const fg_point_charge *c = &q->charges[i];
        double d = hypot(hypot(c->position_m[0] - first->position_m[0],
                               c->position_m[1] - first->position_m[1]),
                         c->position_m[2] - first->position_m[2]);
        if (c->charge_c * first->charge_c < 0 && d < best && d > 0)
            best = d, target = c;
    }
    fg_charges_config p = {.charges = q->charges, .charge_count = q->charge_count,
                           .step_m = q->step_m, .seed = q->seed, .max_nodes = 20000};
    double dir[3] = {0, 0, -1};
    if (target) {
        for (int k = 0; k < 3; k++)
            dir[k] = (target->position_m[k] - first->position_m[k]) / best;
        memcpy(p.target_m, target->position_m, sizeof p.target_m);
        p.target_radius_m = 2 * q->step_m;
    }
    for (int k = 0; k < 3; k++)
        p.start_m[k] = first->position_m[k] + q->step_m * dir[k];
    if (!target && p.start_m[2] <= 0) {
        snprintf(err, err_size, "the charge is on or below the ground and has no partner of the "
                                "other sign: place it higher, or add one");
        return -1;
    }
    if (target && best <= 3 * q->step_m) {
        snprintf(err, err_size, "the charges are too close together for a leader (zoom in)");
        return -1;
    }
    fg_result r = fg_charges_grow(&p, tree);
    if (r != FG_OK)
        snprintf(err, err_size, "the leader did not grow: %s", fg_result_str(r));
    return r == FG_OK ? 0 : -1;
}

/* The tree for q into q->nodes (malloc'd). */
static int grow(view *v, view_request *q)
{
    if (q->kind == VIEW_REQ_SCENE || q->charge_count == 0) {
        scene_discharge *d = &v->s->discharges[q->kind == VIEW_REQ_SCENE ? q->scene_index : 0];
        if (d->generator && q->kind != VIEW_REQ_SCENE) { /* a new tree for each press */
            scene_discharge_unbuild(d);
            d->post.seed = q->seed;
            if (scene_build_discharge(v->s, 0, q->error, sizeof q->error) != 0)
                return -1;
        }
        q->nodes = malloc(d->post.node_count * sizeof *q->nodes);
        if (!q->nodes) {
            snprintf(q->error, sizeof q->error, "out of memory");
            return -1;
        }
        memcpy(q->nodes, d->post.nodes, d->post.node_count * sizeof *q->nodes);
        q->node_count = d->post.node_count;
        return 0;
    }
    fg_tree *tree;
    if (fg_tree_create(0, &tree) != FG_OK) {
        snprintf(q->error, sizeof q->error, "out of memory");
        return -1;
    }
    int rc = grow_charges(q, tree, q->error, sizeof q->error);
    if (rc == 0) {
        q->node_count = fg_tree_count(tree);
        q->nodes = malloc(q->node_count * sizeof *q->nodes);
        if (q->nodes)
            memcpy(q->nodes, fg_tree_nodes(tree), q->node_count * sizeof *q->nodes);
        else
            rc = -1, snprintf(q->error, sizeof q->error, "out of memory");
    }
    fg_tree_destroy(tree);
    return rc;
}

static void answer(view *v, view_request *q, fg_voice_id *held)
{
    if (q->kind == VIEW_REQ_STOP) {
        if (*held && fg_engine_stop(v->engine, *held) != FG_OK)
            snprintf(q->error, sizeof q->error, "the held discharge had already ended");
        *held = 0;
        return;
    }
    if (grow(v, q) != 0)
        return;
    const scene_discharge *d = &v->s->discharges[q->kind == VIEW_REQ_SCENE ? q->scene_index : 0];
    fg_discharge post = d->post;
    q->preset = d->preset;
    post.nodes = q->nodes;
    post.node_count = q->node_count;
    if (q->kind != VIEW_REQ_SCENE)
        post.seed = q->seed;
    post.emit_time_s = fmax(q->emit_s, fg_engine_time_s(v->engine));
    q->emit_s = post.emit_time_s;
    if (q->kind == VIEW_REQ_HOLD) {
        post.continuous = 1;
        post.strokes = 1;
        post.duration_s = 0; /* until H again; the scene's repeat, else the engine's */
    }
    q->post = post;
    q->stroke_count = fg_discharge_stroke_offsets(&post, q->strokes_s, FG_MAX_STROKES);
    if (q->stroke_count > FG_MAX_STROKES)
        q->stroke_count = FG_MAX_STROKES;
    fg_voice_id id = 0;
    fg_result r = fg_engine_post(v->engine, &post, &id);
    if (r != FG_OK) {
        snprintf(q->error, sizeof q->error, "the engine refused the discharge: %s",
                 fg_result_str(r));
        return;
    }
    if (q->kind == VIEW_REQ_HOLD) {
        /* holds alternate with stops, so none is held here; were one, it
         * would end by itself only at the run's end */
        *held = id;
    }
}

void *view_sim_thread(void *arg)
{
    view *v = arg;
    fg_voice_id held = 0;
    while (!atomic_load(&v->stop)) {
        fg_engine_collect(v->engine);
        /* the fires' poses at the frame ticks up to a lead past the engine
         * clock (headless: past the frame thread's target), their sound */
        uint64_t target = atomic_load(&v->fire_target);
        double until = fmax(fg_engine_time_s(v->engine), (double)target / v->rate_hz);
        if (scene_fire_job_follow(&v->fires, v->engine, until + VIEW_LEAD_S, 1.0 / v->opt.fps,
                                  &v->fire_pose_tick, v->sim_error,
                                  sizeof v->sim_error) != FG_OK) {
            view_stop(v);
            break;
        }
        atomic_store(&v->fire_done, target);
        view_request *q = view_ring_pop(&v->to_sim);
        if (!q) {
            monotonic_sleep_until_ns(monotonic_now_ns() + 500000);
            continue;
        }
        answer(v, q, &held);
        /* the frame thread drains the replies every frame */
        while (!view_ring_push(&v->from_sim, q) && !atomic_load(&v->stop))
            monotonic_sleep_until_ns(monotonic_now_ns() + 500000);
    }
    fg_engine_collect(v->engine);
    return NULL;
}
