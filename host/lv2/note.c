/* From a note to a posted discharge, on the worker: the note map, the
 * preset's tree, where it is heard and how loud. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "plugin.h"
#include "fg_math.h"
#include "fg_array.h"

#define NEAREST_M 0.05
#define FARTHEST_M 20000.0

double note_distance_m(double distance_m, uint8_t note)
{
    double d = distance_m * exp2((60.0 - note) / 12.0);
    return d < NEAREST_M ? NEAREST_M : d > FARTHEST_M ? FARTHEST_M : d;
}

/* The preset's field, solved on first use and kept: later notes grow in it
 * in about a millisecond. */
static fg_result field_ready(preset_field *pf, fg_preset preset, fg_field **out)
{
    if (!pf->field) {
        fg_field *field;
        fg_result r = fg_field_scene_preset(preset, 0, &pf->setup);
        if (r == FG_OK)
            r = fg_field_create(&pf->setup.grid, &field);
        if (r != FG_OK)
            return r;
        r = fg_field_set_shapes(field, pf->setup.shapes, pf->setup.shape_count, NULL);
        if (r == FG_OK)
            r = fg_field_solve(field, &(fg_solve_config){.tolerance = FG_GROWTH_FIELD_TOLERANCE},
                               NULL);
        if (r != FG_OK) {
            fg_field_destroy(field);
            return r;
        }
        pf->field = field;
    }
    *out = pf->field;
    return FG_OK;
}

/* Copies the tree to p->placed, moved by offset_m. */
static fg_result place(plugin *p, const double offset_m[3])
{
    size_t n = fg_tree_count(p->tree);
    fg_node *grown = fg_array_grow(p->placed, &p->placed_capacity, n, sizeof *grown, n);
    if (!grown)
        return FG_ERR_NO_MEMORY;
    p->placed = grown;
    memcpy(p->placed, fg_tree_nodes(p->tree), n * sizeof *p->placed);
    fg_tree_translate(p->placed, n, offset_m);
    return FG_OK;
}

/* Grows the preset's tree with its centre (lightning: its strike point) at
 * the note's distance and direction from the listener; *nodes is valid until
 * the next call. */
static fg_result grow(plugin *p, const work_request *rq, const fg_node **nodes)
{
    const note_controls *c = &rq->controls;
    fg_listener head;
    fg_engine_get_listener(p->slots[p->posting].engine, &head);
    double d = note_distance_m(c->distance_m, rq->note);
    double az = c->azimuth_deg * FG_PI / 180, el = c->elevation_deg * FG_PI / 180;
    /* the listener faces +y with +x on the right and +z up (instantiate) */
    double at[3] = {head.position[0] + d * sin(az) * cos(el),
                    head.position[1] + d * cos(az) * cos(el), head.position[2] + d * sin(el)};
    fg_tree_clear(p->tree);
    if (c->preset == FG_PRESET_LIGHTNING || c->preset == FG_PRESET_LIGHTNING_TABLE1) {
        /* a cloud-to-ground bolt strikes the ground: elevation does not apply */
        fg_lightning_config lp = {.strike_m = {head.position[0] + d * sin(az),
                                               head.position[1] + d * cos(az)},
                                  .seed = rq->seed};
        fg_result r = fg_lightning_generate(&lp, p->tree, NULL);
        *nodes = fg_tree_nodes(p->tree);
        return r;
    }
    preset_field *pf = &p->fields[c->preset == FG_PRESET_PLASMA_BALL];
    fg_field *field;
    fg_result r = field_ready(pf, c->preset, &field);
    if (r != FG_OK)
        return r;
    fg_field_source src;
    fg_field_source_init(field, &src);
    fg_growth_config growth = pf->setup.growth;
    growth.seed = rq->seed;
    r = fg_grow_matsuyama(&src, &growth, p->tree, NULL);
    if (r == FG_OK)
        r = place(p, at);
    *nodes = p->placed;
    return r;
}

fg_result note_post(plugin *p, const work_request *rq, fg_voice_id *id)
{
    const note_controls *c = &rq->controls;
    fg_discharge d = {.emit_time_s = FG_EMIT_NOW, .seed = rq->seed};
    fg_result r = fg_preset_sound(c->preset, &d.sound);
    if (r != FG_OK)
        return r;
    d.sound.t0_s *= c->t0_scale;
    d.sound.ps0_pa *= rq->velocity / 127.0;
    if (c->preset == FG_PRESET_PLASMA_BALL)
        d.continuous = 1;   /* until note-off */
    else
        d.strokes = c->strokes;
    if (c->refraction)
        d.propagation.refraction_radius_m = FG_REFRACTION_STORM_M;
    if (c->absorption)
        d.propagation.absorption = FG_ABSORPTION_ISO9613;
    r = grow(p, rq, &d.nodes);
    if (r != FG_OK)
        return r;
    d.node_count = fg_tree_count(p->tree);
    return fg_engine_post(p->slots[p->posting].engine, &d, id);
}
