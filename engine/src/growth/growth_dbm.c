/* The dielectric breakdown model on the field's lattice (growth.h). */
#include <math.h>
#include <stdlib.h>

#include "fg_array.h"
#include "field/field_internal.h"
#include "growth_internal.h"

/* Global cycles are this many CG iterations, warm. */
#define GLOBAL_ITERATIONS 2
#define LOCAL_SWEEPS 2

typedef struct lattice_node {
    size_t id;      /* grid index */
    int ijk[3];
    int32_t parent; /* index in the channel, -1 for the root */
    int children;
} lattice_node;

typedef struct dbm {
    fg_field *f;
    fg_growth_config c;
    fg_rng rng;
    lattice_node *chan;
    size_t count, cap;
    size_t *perim;          /* grid indices of free nodes touching the channel (some stale) */
    size_t perim_count, perim_cap;
    uint8_t *in_perim;      /* per grid node */
    double *w;              /* weights, parallel to perim */
    int hit[3];             /* the target node touched, when connected */
    int connected;
} dbm;

static void ijk_of(const fg_level *L, size_t id, int ijk[3])
{
    ijk[0] = (int)(id % (size_t)L->n[0]);
    ijk[1] = (int)((id / (size_t)L->n[0]) % (size_t)L->n[1]);
    ijk[2] = (int)(id / ((size_t)L->n[0] * (size_t)L->n[1]));
}

/* Room for one more channel node. */
static fg_result reserve_channel(dbm *d)
{
    lattice_node *chan = fg_array_grow(d->chan, &d->cap, d->count + 1, sizeof *chan, 256);
    if (!chan)
        return FG_ERR_NO_MEMORY;
    d->chan = chan;
    return FG_OK;
}

/* Adds grid node id to the channel (held at phi = 0) and its free
 * neighbours to the perimeter; notes a target neighbour. */
static fg_result add_node(dbm *d, size_t id, int32_t parent)
{
    fg_field *f = d->f;
    const fg_level *L = &f->level[0];
    fg_result r = reserve_channel(d);
    if (r != FG_OK)
        return r;
    lattice_node *nd = &d->chan[d->count++];
    *nd = (lattice_node){.id = id, .parent = parent};
    ijk_of(L, id, nd->ijk);
    if (parent >= 0)
        d->chan[parent].children++;
    f->label[id] = FG_REGION_ORIGIN;
    f->phi[id] = 0.0;
    double best = INFINITY;
    for (int dk = -1; dk <= 1; dk++)
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++) {
                int q[3] = {nd->ijk[0] + di, nd->ijk[1] + dj, nd->ijk[2] + dk};
                if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= L->n[0] || q[1] >= L->n[1] ||
                    q[2] >= L->n[2])
                    continue;
                size_t qid = fg_level_index(L, q[0], q[1], q[2]);
                double dist = di * di + dj * dj + dk * dk;
                if (f->label[qid] == FG_REGION_TARGET && dist < best) {
                    best = dist;
                    for (int a = 0; a < 3; a++)
                        d->hit[a] = q[a];
                    d->connected = 1;
                }
                if (f->label[qid] != FG_REGION_FREE || d->in_perim[qid])
                    continue;
                size_t *perim = fg_array_grow(d->perim, &d->perim_cap, d->perim_count + 1,
                                              sizeof *perim, 256);
                if (!perim)
                    return FG_ERR_NO_MEMORY;
                d->perim = perim;
                d->perim[d->perim_count++] = qid;
                d->in_perim[qid] = 1;
            }
    return FG_OK;
}

/* The channel node nearest to grid node id among its 26 neighbours (the
 * earliest on a tie). */
static int32_t parent_of(const dbm *d, size_t id)
{
    int ijk[3];
    ijk_of(&d->f->level[0], id, ijk);
    int32_t best = -1;
    int best_dist = 4;
    for (size_t i = 0; i < d->count; i++) {
        int dist = 0, far = 0;
        for (int a = 0; a < 3; a++) {
            int s = d->chan[i].ijk[a] - ijk[a];
            far |= s < -1 || s > 1;
            dist += s * s;
        }
        if (!far && dist < best_dist) {
            best_dist = dist;
            best = (int32_t)i;
        }
    }
    return best;
}

/* Drops stale perimeter entries and returns the pick, or SIZE_MAX. */
static size_t choose(dbm *d)
{
    size_t live = 0;
    for (size_t i = 0; i < d->perim_count; i++) {
        size_t id = d->perim[i];
        if (d->f->label[id] == FG_REGION_FREE)
            d->perim[live++] = id;
        else
            d->in_perim[id] = 0;
    }
    d->perim_count = live;
    if (live == 0)
        return SIZE_MAX;
    double u = fg_rng_uniform(&d->rng), sum = 0.0;
    for (size_t i = 0; i < live; i++) {
        d->w[i] = fg_eq2_weight(d->f->phi[d->perim[i]], d->c.eta);
        sum += d->w[i];
    }
    if (!(sum > 0.0))
        for (size_t i = 0; i < live; i++)
            d->w[i] = 1.0;
    int k = fg_pick(d->w, (int)live, u);
    return d->perim[k];
}

static fg_result update_field(dbm *d, int step, double *last_residual, fg_growth_report *rep)
{
    const lattice_node *nd = &d->chan[d->count - 1];
    fg_field_labels_changed(d->f);
    fg_lap_relax_box(&d->f->level[0], d->f->phi, nd->ijk[0], nd->ijk[1], nd->ijk[2],
                     d->c.dbm_relax_radius, LOCAL_SWEEPS);
    if (step % d->c.dbm_global_every != 0)
        return FG_OK;
    fg_solve_config sc = {.max_iterations = GLOBAL_ITERATIONS};
    fg_solve_report sr;
    fg_result r = fg_field_solve(d->f, &sc, &sr);
    rep->solves++;
    rep->solver_iterations += sr.iterations;
    /* The cheap cycles are falling behind the growing channel: catch up. */
    int grew = r == FG_ERR_NOT_CONVERGED && sr.residual > *last_residual;
    *last_residual = sr.residual;
    if (grew) {
        fg_solve_config full = {0};
        r = fg_field_solve(d->f, &full, &sr);
        rep->solves++;
        rep->solver_iterations += sr.iterations;
    }
    return r == FG_ERR_NOT_CONVERGED ? FG_OK : r;
}

/* Keeps the root, branch points, leaves, the connecting node, and a node
 * wherever the path from the last kept one reaches step_m. */
static fg_result resample(const dbm *d, size_t hit_node, fg_nodebuf *out, size_t *hit_out)
{
    const fg_field *f = d->f;
    int32_t *kept_as = malloc(d->count * sizeof *kept_as);
    int32_t *anchor = malloc(d->count * sizeof *anchor);
    double *run = malloc(d->count * sizeof *run);
    fg_result r = FG_ERR_NO_MEMORY;
    if (!kept_as || !anchor || !run)
        goto done;
    r = FG_OK;
    for (size_t i = 0; i < d->count && r == FG_OK; i++) {
        const lattice_node *nd = &d->chan[i];
        double x[3];
        for (int a = 0; a < 3; a++)
            x[a] = f->config.min_m[a] + nd->ijk[a] * f->h[a];
        int32_t p = nd->parent;
        kept_as[i] = -1;
        if (p < 0) {
            run[i] = 0.0;
            anchor[i] = -1;
        } else {
            double s = 0.0;
            for (int a = 0; a < 3; a++) {
                double dx = (nd->ijk[a] - d->chan[p].ijk[a]) * f->h[a];
                s += dx * dx;
            }
            int32_t up = kept_as[p] >= 0 ? p : anchor[p];
            run[i] = (kept_as[p] >= 0 ? 0.0 : run[p]) + sqrt(s);
            anchor[i] = up;
        }
        if (p >= 0 && nd->children == 1 && i != hit_node && run[i] < d->c.step_m)
            continue;
        size_t id;
        r = fg_nodebuf_push(out, x, p < 0 ? -1 : kept_as[anchor[i]], &id);
        kept_as[i] = (int32_t)id;
        if (i == hit_node)
            *hit_out = id;
    }
done:
    free(kept_as);
    free(anchor);
    free(run);
    return r;
}

static fg_result grow(dbm *d, fg_growth_report *rep)
{
    fg_field_source src;
    fg_field_source_init(d->f, &src);
    double root[3], dir[3];
    int ijk[3];
    fg_result r = fg_growth_root(&src, d->c.eta, &d->rng, root, dir);
    if (r != FG_OK)
        return r;
    fg_field_nearest(d->f, root, ijk);
    if ((r = add_node(d, fg_level_index(&d->f->level[0], ijk[0], ijk[1], ijk[2]), -1)) != FG_OK)
        return r;
    double last_residual = INFINITY;
    for (int step = 1; !d->connected; step++) {
        if (step > d->c.max_steps)
            return FG_ERR_UNREACHABLE;
        size_t id = choose(d);
        if (id == SIZE_MAX)
            return FG_ERR_UNREACHABLE;
        if ((r = add_node(d, id, parent_of(d, id))) != FG_OK ||
            (r = update_field(d, step, &last_residual, rep)) != FG_OK)
            return r;
        rep->steps = step;
    }
    return FG_OK;
}

fg_result fg_grow_dbm(fg_field *f, const fg_growth_config *config, fg_tree *out,
                      fg_growth_report *report)
{
    if (!f || !config || !out)
        return FG_ERR_NULL;
    dbm d = {.f = f};
    fg_result r = fg_growth_config_resolve(config, &d.c);
    if (r != FG_OK)
        return r;
    if (f->shape_count == 0)
        return FG_ERR_ARGUMENT;
    fg_rng_seed(&d.rng, d.c.seed);
    fg_growth_report rep = {0};
    size_t count = f->level[0].count;
    d.in_perim = calloc(count, 1);
    d.w = malloc(count * sizeof *d.w);
    fg_nodebuf nodes = {0};
    if (!d.in_perim || !d.w)
        r = FG_ERR_NO_MEMORY;
    else
        r = grow(&d, &rep);
    size_t hit = 0;
    if (r == FG_OK) {
        /* The connection: the touched target node, child of the last one. */
        r = reserve_channel(&d);
        if (r == FG_OK) {
            lattice_node *last = &d.chan[d.count - 1];
            last->children++;
            d.chan[d.count] = (lattice_node){
                .id = fg_level_index(&f->level[0], d.hit[0], d.hit[1], d.hit[2]),
                .ijk = {d.hit[0], d.hit[1], d.hit[2]},
                .parent = (int32_t)(d.count - 1)};
            d.count++;
            r = resample(&d, d.count - 1, &nodes, &hit);
        }
    }
    /* The channel's nodes were free before: give them back (not the target node). */
    for (size_t i = 0; i < d.count; i++)
        if (f->label[d.chan[i].id] == FG_REGION_ORIGIN)
            f->label[d.chan[i].id] = FG_REGION_FREE;
    fg_field_labels_changed(f);
    if (r == FG_OK) {
        rep.main_nodes = fg_nodes_mark_main(nodes.v, hit);
        rep.nodes = nodes.count;
        r = fg_nodebuf_emit(&nodes, out);
        if (r == FG_OK && report)
            *report = rep;
    }
    fg_nodebuf_free(&nodes);
    free(d.chan);
    free(d.perim);
    free(d.in_perim);
    free(d.w);
    return r;
}
