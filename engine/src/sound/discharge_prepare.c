/* Turning a posted discharge into a voice: segments, main channel, return
 * stroke timing, T0 fluctuation, geometry at the current pose, the arrival
 * sort and the strokes. Sim thread; uses only preallocated storage. */
#include <math.h>
#include <string.h>

#include "core/engine_internal.h"
#include "sound/strokes_internal.h"
#include "air/turbulence_internal.h"

#define REPEAT_MIN_DEFAULT_S 0.010
#define REPEAT_MAX_DEFAULT_S 0.050
#define REPEAT_LIMIT_S 10.0

fg_result fg_discharge_check(const fg_discharge *d)
{
    fg_result r = fg_sound_params_check(&d->sound);
    if (r == FG_OK)
        r = fg_propagation_check(&d->propagation);
    if (r != FG_OK)
        return r;
    if ((unsigned)d->model > FG_MODEL_ABE)
        return FG_ERR_ARGUMENT;
    if (!isfinite(d->emit_time_s) || !isfinite(d->repeat_min_s) || !isfinite(d->repeat_max_s) ||
        !isfinite(d->duration_s))
        return FG_ERR_NOT_FINITE;
    if (d->emit_time_s < 0 && d->emit_time_s != FG_EMIT_NOW)
        return FG_ERR_ARGUMENT;
    if (d->strokes > FG_MAX_STROKES)
        return FG_ERR_ARGUMENT;
    if (!d->continuous)
        return FG_OK;
    double lo = d->repeat_min_s > 0 ? d->repeat_min_s : REPEAT_MIN_DEFAULT_S;
    double hi = d->repeat_max_s > 0 ? d->repeat_max_s : REPEAT_MAX_DEFAULT_S;
    if (d->strokes > 1 || d->repeat_min_s < 0 || d->repeat_max_s < 0 || lo > hi ||
        hi > REPEAT_LIMIT_S || d->duration_s < 0)
        return FG_ERR_ARGUMENT;
    return FG_OK;
}

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

size_t fg_discharge_events(const fg_discharge *d)
{
    size_t segments = d->node_count - 1;
    size_t stride = (segments + FG_ABE_MAX_SOURCES - 1) / FG_ABE_MAX_SOURCES;
    size_t events = d->model == FG_MODEL_ABE ? (segments + stride - 1) / stride : segments;
    return d->propagation.ground_reflection > 0 ? 2 * events : events;
}

/* Fills ev from segment i (node i and its parent). */
static void segment_event(const fg_discharge *d, const fg_prep_scratch *s, size_t strike,
                          size_t i, fg_rng *rng, fg_event *ev)
{
    const fg_node *nodes = d->nodes;
    const fg_sound_params *p = &d->sound;
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
    ev->gain = 1.0;
    ev->segment = (uint32_t)i;
    ev->main = s->main[i];
}

/* The same segment seen in the ground: mirrored in z = 0, weaker by the
 * reflection coefficient, emitting at the same moment. */
static void image_event(const fg_event *src, double reflection, fg_event *ev)
{
    *ev = *src;
    ev->mid[2] = -src->mid[2];
    ev->dir[2] = -src->dir[2];
    ev->gain = reflection;
}

void fg_prepare_voice(fg_engine *e, fg_voice *v, const fg_discharge *d)
{
    const fg_node *nodes = d->nodes;
    size_t n = d->node_count;
    fg_prep_scratch *s = &e->scratch;
    fg_rng rng;
    fg_rng_seed(&rng, d->seed);

    s->path_m[0] = 0;
    for (size_t i = 1; i < n; i++)
        s->path_m[i] = s->path_m[nodes[i].parent] + distance(&nodes[i], &nodes[nodes[i].parent]);
    size_t strike = mark_main_channel(nodes, n, s);

    fg_listener pose;
    unsigned serial;
    fg_listener_cell_read(&e->listener, &pose, &serial);
    fg_ears ears;
    fg_listener_ears(&pose, e->cfg.channels, e->cfg.ear_spacing_m, &ears);
    memcpy(v->post_position, pose.position, sizeof v->post_position);
    v->sound = d->sound;
    v->propagation = d->propagation;
    v->model = d->model;

    const fg_propagation *pr = &d->propagation;
    fg_turbulence turbulence = {
        .seed = fg_rng_next(&rng),
        .amplitude_s = pr->turbulence_s,
        .correlation_m = pr->turbulence_length_m > 0 ? pr->turbulence_length_m
                                                     : FG_TURBULENCE_DEFAULT_LENGTH_M,
    };
    /* Abe's model places one source per stride segments */
    size_t stride = d->model == FG_MODEL_ABE ? (n - 1 + FG_ABE_MAX_SOURCES - 1) / FG_ABE_MAX_SOURCES
                                             : 1;
    uint32_t m = 0;
    for (size_t i = 1; i < n; i += stride) {
        fg_event *ev = &v->events[m++];
        segment_event(d, s, strike, i, &rng, ev);
        if (pr->turbulence_s > 0)
            ev->emit_s += fg_turbulence_offset_s(&turbulence, ev->mid);
        if (pr->ground_reflection > 0)
            image_event(ev, pr->ground_reflection, &v->events[m++]);
    }
    v->event_count = m;
    for (uint32_t k = 0; k < m; k++) {
        fg_event *ev = &v->events[k];
        ev->serial = serial;
        ev->start_s = INFINITY;
        for (unsigned j = 0; j < ears.count; j++) {
            fg_event_geometry(e, v, ev, &ears, (int)j);
            ev->start_s = fmin(ev->start_s, fg_event_start_s(e, v, ev, (int)j));
        }
    }
    sort_by_start(v->events, v->event_count, s);
    v->main_count = 0;
    for (uint32_t k = 0; k < v->event_count; k++)
        if (v->events[k].main)
            v->main_index[v->main_count++] = k;

    v->continuous = d->continuous != 0;
    v->strokes = fg_discharge_stroke_offsets(d, v->stroke_offset_s, FG_MAX_STROKES);
    v->repeat_min_s = d->repeat_min_s > 0 ? d->repeat_min_s : REPEAT_MIN_DEFAULT_S;
    v->repeat_max_s = d->repeat_max_s > 0 ? d->repeat_max_s : REPEAT_MAX_DEFAULT_S;
    v->duration_s = d->duration_s;
    fg_rng_seed(&v->rng, fg_rng_next(&rng));
    v->emit_time_s = d->emit_time_s;
    atomic_store_explicit(&v->stop, false, memory_order_relaxed);
}
