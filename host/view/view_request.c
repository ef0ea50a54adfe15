/* The frame thread's side of the requests to the sim thread: the rings
 * they travel through, and a request for a discharge. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fg_math.h"
#include "view.h"

bool view_ring_push(fg_ring *r, void *item)
{
    return fg_ring_push(r, &item);
}

void *view_ring_pop(fg_ring *r)
{
    void *item;
    return fg_ring_pop(r, &item) ? item : NULL;
}

void view_request_discharge(view *v, view_request_kind kind, size_t index, double emit_s)
{
    view_request *q = calloc(1, sizeof *q);
    if (!q)
        return;
    q->kind = kind;
    q->emit_s = emit_s;
    q->scene_index = index;
    q->seed = scene_discharge_seed(v->s->seed, (size_t)v->seed_counter++);
    q->charge_count = v->charge_count;
    memcpy(q->charges, v->charges, v->charge_count * sizeof *q->charges);
    /* the leader's step: a fiftieth of the view's height at the target */
    q->step_m = 2 * v->cam.distance_m * tan(v->cam.fov_y_deg * FG_PI / 360.0) / 50;
    if (view_ring_push(&v->to_sim, q))
        v->requests++;
    else
        free(q);
}
