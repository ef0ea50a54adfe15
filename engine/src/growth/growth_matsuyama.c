/* Matsuyama's leader (eq. 2) with the branching rule of growth.h. */
#include <math.h>
#include <stdlib.h>

#include "fg_math.h"
#include "growth_internal.h"

#define BLOCKED_LIMIT 5
#define SURFACE_BISECTIONS 8

typedef struct tip {
    size_t node;
    double dir[3];
    double grown_m;
    int leader;
    int blocked;
} tip;

fg_result fg_matsuyama_weigh(const fg_field_source *src, const double tip_m[3],
                             const double *dirs, int n, double step_m, double gamma, double *w,
                             int *hit)
{
    /* points 0..n-1 are the candidates, n..2n-1 their midpoints */
    double pts[2 * 3 * FG_GROWTH_MAX_CANDIDATES], phi[FG_GROWTH_MAX_CANDIDATES];
    uint8_t region[2 * FG_GROWTH_MAX_CANDIDATES];
    for (int i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) {
            pts[3 * i + a] = tip_m[a] + step_m * dirs[3 * i + a];
            pts[3 * (n + i) + a] = tip_m[a] + 0.5 * step_m * dirs[3 * i + a];
        }
    fg_result r = src->classify(src->context, pts, (size_t)(2 * n), region);
    if (r == FG_OK)
        r = src->sample(src->context, pts, (size_t)n, phi);
    if (r != FG_OK)
        return r;
    *hit = -1;
    for (int i = 0; i < n; i++) {
        int end = region[i], mid = region[n + i];
        if (*hit < 0 && (end == FG_REGION_TARGET || mid == FG_REGION_TARGET))
            *hit = i;
        w[i] = end == FG_REGION_FREE && mid == FG_REGION_FREE ? fg_eq2_weight(phi[i], gamma) : 0.0;
    }
    return FG_OK;
}

/* The point where the segment tip -> tip + step * dir first enters the
 * target, to within step / 2^SURFACE_BISECTIONS (on the target side). */
static fg_result surface(const fg_field_source *src, const double tip_m[3], const double dir[3],
                         double step_m, double out[3])
{
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < SURFACE_BISECTIONS; it++) {
        double t = 0.5 * (lo + hi), x[3];
        uint8_t region;
        for (int a = 0; a < 3; a++)
            x[a] = tip_m[a] + t * step_m * dir[a];
        fg_result r = src->classify(src->context, x, 1, &region);
        if (r != FG_OK)
            return r;
        if (region == FG_REGION_TARGET)
            hi = t;
        else
            lo = t;
    }
    for (int a = 0; a < 3; a++)
        out[a] = tip_m[a] + hi * step_m * dir[a];
    return FG_OK;
}

typedef struct grower {
    const fg_field_source *src;
    fg_growth_config c;
    fg_rng rng;
    fg_nodebuf nodes;
    tip *tips;
    int ntips;
    size_t first_hit;
    int connected;
} grower;

static void node_pos(const grower *g, size_t i, double x[3])
{
    x[0] = g->nodes.v[i].x;
    x[1] = g->nodes.v[i].y;
    x[2] = g->nodes.v[i].z;
}

/* Removes tip t; if it led, the oldest branch (the next in order) leads. */
static void remove_tip(grower *g, int t)
{
    int leader = g->tips[t].leader;
    for (int i = t; i + 1 < g->ntips; i++)
        g->tips[i] = g->tips[i + 1];
    g->ntips--;
    if (leader && g->ntips > 0)
        g->tips[t < g->ntips ? t : 0].leader = 1;
}

/* Steps tip t once; *advance says whether t still names the same tip. */
static fg_result step_tip(grower *g, int t, int *advance)
{
    tip *tp = &g->tips[t];
    double x[3], dirs[3 * FG_GROWTH_MAX_CANDIDATES], w[FG_GROWTH_MAX_CANDIDATES], at[3];
    int hit, n = g->c.candidates;
    node_pos(g, tp->node, x);
    /* The cone's axis: halfway between the tip's direction and the field's. */
    double axis[3] = {tp->dir[0], tp->dir[1], tp->dir[2]};
    fg_result r = fg_field_direction(g->src, x, axis);
    if (r != FG_OK)
        return r;
    double len = 0.0;
    for (int a = 0; a < 3; a++) {
        axis[a] += tp->dir[a];
        len += axis[a] * axis[a];
    }
    len = sqrt(len);
    for (int a = 0; a < 3; a++)
        axis[a] = len > 0.0 ? axis[a] / len : tp->dir[a];
    double half = 0.5 * g->c.cone_rad * (1 + tp->blocked);
    fg_cone_directions(&g->rng, axis, half < FG_PI ? half : FG_PI, n, dirs);
    r = fg_matsuyama_weigh(g->src, x, dirs, n, g->c.step_m, g->c.gamma, w, &hit);
    if (r != FG_OK)
        return r;
    *advance = 0;
    if (hit >= 0) {
        size_t id;
        if ((r = surface(g->src, x, &dirs[3 * hit], g->c.step_m, at)) != FG_OK ||
            (r = fg_nodebuf_push(&g->nodes, at, (int32_t)tp->node, &id)) != FG_OK)
            return r;
        if (!g->connected)
            g->first_hit = id;
        g->connected = 1;
        remove_tip(g, t);
        return FG_OK;
    }
    int c = fg_pick(w, n, fg_rng_uniform(&g->rng));
    if (c < 0) {
        if (++tp->blocked >= BLOCKED_LIMIT)
            remove_tip(g, t);
        else
            *advance = 1;
        return FG_OK;
    }
    size_t parent = tp->node, id;
    for (int a = 0; a < 3; a++)
        at[a] = x[a] + g->c.step_m * dirs[3 * c + a];
    if ((r = fg_nodebuf_push(&g->nodes, at, (int32_t)parent, &id)) != FG_OK)
        return r;
    tp->node = id;
    tp->blocked = 0;
    tp->grown_m += g->c.step_m;
    for (int a = 0; a < 3; a++)
        tp->dir[a] = dirs[3 * c + a];

    if (g->ntips < g->c.max_tips && fg_rng_uniform(&g->rng) < g->c.branch_probability) {
        w[c] = 0.0;
        int b = fg_pick(w, n, fg_rng_uniform(&g->rng));
        if (b >= 0) {
            for (int a = 0; a < 3; a++)
                at[a] = x[a] + g->c.step_m * dirs[3 * b + a];
            if ((r = fg_nodebuf_push(&g->nodes, at, (int32_t)parent, &id)) != FG_OK)
                return r;
            tip *nt = &g->tips[g->ntips++];
            *nt = (tip){.node = id, .grown_m = g->c.step_m};
            for (int a = 0; a < 3; a++)
                nt->dir[a] = dirs[3 * b + a];
        }
    }
    if (!tp->leader && tp->grown_m >= g->c.branch_length_m)
        remove_tip(g, t);
    else
        *advance = 1;
    return FG_OK;
}

static fg_result grow(grower *g, int *steps)
{
    double root[3], dir[3];
    fg_result r = fg_growth_root(g->src, g->c.gamma, &g->rng, root, dir);
    if (r != FG_OK || (r = fg_nodebuf_push(&g->nodes, root, -1, NULL)) != FG_OK)
        return r;
    g->tips[0] = (tip){.node = 0, .dir = {dir[0], dir[1], dir[2]}, .leader = 1};
    g->ntips = 1;
    *steps = 0;
    while (g->ntips > 0) {
        for (int t = 0; t < g->ntips;) {
            if (*steps >= g->c.max_steps)
                return FG_ERR_UNREACHABLE;
            ++*steps;
            int advance;
            if ((r = step_tip(g, t, &advance)) != FG_OK)
                return r;
            if (g->connected && !g->c.all_tips_connect)
                return FG_OK;
            t += advance;
        }
    }
    return g->connected ? FG_OK : FG_ERR_UNREACHABLE;
}

fg_result fg_grow_matsuyama(const fg_field_source *src, const fg_growth_config *config,
                            fg_tree *out, fg_growth_report *report)
{
    if (!src || !src->sample || !src->classify || !src->origin_sites || !config || !out)
        return FG_ERR_NULL;
    grower g = {.src = src};
    fg_result r = fg_growth_config_resolve(config, &g.c);
    if (r != FG_OK)
        return r;
    fg_rng_seed(&g.rng, g.c.seed);
    g.tips = malloc((size_t)g.c.max_tips * sizeof *g.tips);
    if (!g.tips)
        return FG_ERR_NO_MEMORY;
    int steps = 0;
    r = grow(&g, &steps);
    if (r == FG_OK) {
        size_t main_nodes = fg_nodes_mark_main(g.nodes.v, g.first_hit);
        r = fg_nodebuf_emit(&g.nodes, out);
        if (r == FG_OK && report)
            *report = (fg_growth_report){.nodes = g.nodes.count, .main_nodes = main_nodes,
                                         .steps = steps};
    }
    free(g.tips);
    fg_nodebuf_free(&g.nodes);
    return r;
}
