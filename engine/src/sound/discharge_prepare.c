/* Turning a posted discharge into a voice: segments, main channel, return
 * stroke timing, T0 fluctuation, geometry at the current pose, the arrival
 * sort and the strokes. Sim thread; uses only the discharge kind's
 * preallocated storage. */
#include <math.h>
#include <string.h>

#include "air/ground_internal.h"
#include "air/turbulence_internal.h"
#include "discharge_internal.h"
#include "strokes_internal.h"

static double distance(const fg_node *a, const fg_node *b)
{
    double dx = a->x - b->x, dy = a->y - b->y, dz = a->z - b->z;
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The main channel is the path from the root to the strike node: the
 * deepest node flagged FG_NODE_MAIN, or else the node farthest from the
 * root. Fills main[] and junction[]; returns the strike node. */
static size_t mark_main_channel(const fg_node *nodes, size_t n, fg_prep_scratch *s)
{
    size_t strike = 0;
    bool flagged = false;
    double best = -1;
    for (size_t i = 1; i < n; i++) {
        bool f = nodes[i].flags & FG_NODE_MAIN;
        double key = f ? s->path_m[i] : distance(&nodes[i], &nodes[0]);
        if ((f && !flagged) || (f == flagged && key > best)) {
            flagged = flagged || f;
            best = key;
            strike = i;
        }
    }
    memset(s->main, 0, n);
    for (size_t i = strike;; i = (size_t)nodes[i].parent) {
        s->main[i] = 1;
        if (i == 0)
            break;
    }
    for (size_t i = 0; i < n; i++)
        s->junction[i] = s->main[i] ? (uint32_t)i : s->junction[nodes[i].parent];
    return strike;
}

/* Puts events in arrival order: a radix sort of the keys, then the
 * permutation applied in place, cycle by cycle. */
static void sort_by_start(fg_event *events, uint32_t n, fg_prep_scratch *s)
{
    for (uint32_t i = 0; i < n; i++)
        s->order[i] = (fg_sort_pair){fg_sort_key(events[i].start_s), i};
    fg_sort_pairs(s->order, s->order_tmp, n);
    for (uint32_t i = 0; i < n; i++) {
        if (s->order[i].index == i)
            continue;
        fg_event held = events[i];
        uint32_t j = i;
        for (;;) {
            uint32_t k = s->order[j].index;
            s->order[j].index = j;
            if (k == i) {
                events[j] = held;
                break;
            }
            events[j] = events[k];
            j = k;
        }
    }
}

/* Fills ev from segment i (node i and its parent). */
static void segment_event(const fg_discharge *d, const fg_prep_scratch *s, size_t strike,
                          size_t i, fg_rng *rng, fg_event *ev)
{
    const fg_node *nodes = d->nodes;
    const fg_sound_config *p = &d->sound;
    const fg_node *a = &nodes[i], *b = &nodes[nodes[i].parent];
    double len = distance(a, b);
    ev->mid[0] = 0.5 * (a->x + b->x);
    ev->mid[1] = 0.5 * (a->y + b->y);
    ev->mid[2] = 0.5 * (a->z + b->z);
    ev->dir[0] = (a->x - b->x) / len;
    ev->dir[1] = (a->y - b->y) / len;
    ev->dir[2] = (a->z - b->z) / len;
    ev->half_len_m = 0.5 * len;
    ev->t0_s = p->t0_s * (1.0 + p->t0_jitter * (2.0 * fg_rng_uniform(rng) - 1.0));
    /* the return stroke climbs from the strike node and runs out along the
     * branches: its path to node k is strike -> junction -> k */
    double to_strike[2];
    for (int j = 0; j < 2; j++) {
        size_t k = j == 0 ? i : (size_t)nodes[i].parent;
        to_strike[j] = s->path_m[strike] + s->path_m[k] - 2.0 * s->path_m[s->junction[k]];
    }
    ev->emit_s = 0.5 * (to_strike[0] + to_strike[1]) / p->return_stroke_speed_m_s;
    ev->main = s->main[i];
    ev->image = false;
}

/* The same segment seen in the ground: mirrored in z = 0, weaker by the
 * reflection coefficient (path_to, discharge_event.c), emitting at the
 * same moment. */
static void image_event(const fg_event *src, fg_event *ev)
{
    *ev = *src;
    fg_ground_mirror(src->mid, ev->mid);
    fg_ground_mirror(src->dir, ev->dir);
    ev->image = true;
}

fg_result fg_discharge_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                               const fg_post_context *post)
{
    const fg_discharge *d = desc;
    fg_discharge_voice *v = voice;
    fg_discharge_store *store = post->storage;
    const fg_discharge_model *model = ops->model;
    size_t extent;
    if (!fg_arena_alloc(&store->arena, fg_discharge_events(d, model), &extent))
        return FG_ERR_POOL_FULL;
    if (d->propagation.absorption == FG_ABSORPTION_ISO9613)
        fg_bus_set_design_bands(post->buses);
    v->model = model;
    v->extent = extent;
    v->events = &store->events[extent];
    v->main_index = &store->main_index[extent];

    const fg_node *nodes = d->nodes;
    size_t n = d->node_count;
    fg_prep_scratch *s = &store->scratch;
    fg_rng rng;
    fg_rng_seed(&rng, d->seed);

    s->path_m[0] = 0;
    for (size_t i = 1; i < n; i++)
        s->path_m[i] = s->path_m[nodes[i].parent] + distance(&nodes[i], &nodes[nodes[i].parent]);
    size_t strike = mark_main_channel(nodes, n, s);

    const fg_engine_config *cfg = post->cfg;
    fg_head head;
    fg_head_of_pose(post->pose, &head);
    fg_ears ears;
    fg_head_ears(&head, fg_layout_ears(cfg), cfg->ear_spacing_m, &ears);
    memcpy(v->post_position, post->pose->position, sizeof v->post_position);
    v->sound = d->sound;
    fg_result checked = fg_propagation_config_resolve(&d->propagation, &v->propagation);
    (void)checked; /* fg_engine_post checked it */

    const fg_propagation_config *pr = &v->propagation;
    fg_turbulence turbulence = {
        .seed = fg_rng_next(&rng),
        .amplitude_s = pr->turbulence_s,
        .correlation_m = pr->turbulence_length_m,
    };
    /* one source point per stride segments */
    size_t stride = model->stride(n - 1);
    uint32_t m = 0;
    for (size_t i = 1; i < n; i += stride) {
        fg_event *ev = &v->events[m++];
        segment_event(d, s, strike, i, &rng, ev);
        if (pr->turbulence_s > 0)
            ev->emit_s += fg_turbulence_offset_s(&turbulence, ev->mid);
        if (pr->ground_reflection > 0)
            image_event(ev, &v->events[m++]);
    }
    v->event_count = m;
    const double c = cfg->speed_of_sound_m_s;
    for (uint32_t k = 0; k < m; k++) {
        fg_event *ev = &v->events[k];
        ev->serial = post->pose_serial;
        ev->start_s = INFINITY;
        bool finite = isfinite(ev->emit_s);
        for (unsigned j = 0; j < ears.count; j++) {
            fg_event_geometry(v, ev, &ears, (int)j, c, post->buses);
            ev->start_s = fmin(ev->start_s, model->start_s(ev, &ev->ear[j], c));
            finite = finite && model->finite(ev, &ev->ear[j], cfg->sample_rate_hz, c);
        }
        if (!finite || !isfinite(ev->start_s)) {
            fg_arena_free(&store->arena, extent, fg_discharge_events(d, model));
            return FG_ERR_NOT_FINITE;
        }
    }
    sort_by_start(v->events, v->event_count, s);
    v->main_count = 0;
    for (uint32_t k = 0; k < v->event_count; k++)
        if (v->events[k].main)
            v->main_index[v->main_count++] = k;

    v->continuous = d->continuous != 0;
    v->strokes = fg_discharge_stroke_offsets(d, v->stroke_offset_s, FG_MAX_STROKES);
    fg_discharge_repeat_range(d, &v->repeat_min_s, &v->repeat_max_s);
    v->duration_s = d->duration_s;
    fg_rng_seed(&v->rng, fg_rng_next(&rng));
    v->emit_time_s = d->emit_time_s;
    return FG_OK;
}
