/* Leader growth in the field of point charges (Sosorbaram; Abe §4.1). */
#include <stdlib.h>
#include <string.h>

#include "fg_rules.h"
#include "charges_internal.h"
#include "pick_internal.h"
#include "tree_internal.h"
#include "fulgur/sound.h"

#define DEFAULT_CANDIDATES 8
#define DEFAULT_CHOSEN 2
#define DEFAULT_EXCLUSION_STEPS 0.75
#define DEFAULT_MAX_TIPS 4
#define DEFAULT_MAX_NODES 200000
#define MAX_CANDIDATES 4096
#define MAX_TIPS 4096
/* In a uniform field each random candidate goes backward with probability
 * 1/2, so all M = 8 of them do once in 256 draws: a tip draws again (up to
 * this many times) before it is given up. */
#define REDRAWS 16
/* Distance from a charge below which the potential is taken as at 1 nm. */
#define MIN_DISTANCE_M 1e-9

static fg_vec3 v3_of(const double p[3])
{
    return fg_v3(p[0], p[1], p[2]);
}

static double potential(const fg_point_charge *q, size_t count, fg_vec3 p)
{
    double sum = 0;
    for (size_t i = 0; i < count; i++) {
        double r = fg_v3_len(fg_v3_sub(p, v3_of(q[i].position_m)));
        sum += q[i].charge_c / (r > MIN_DISTANCE_M ? r : MIN_DISTANCE_M);
    }
    return sum / (4.0 * FG_PI * FG_EPSILON0);
}

double fg_charges_potential(const fg_point_charge *charges, size_t count, const double p[3])
{
    return potential(charges, count, v3_of(p));
}

static int finite3(const double p[3])
{
    return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]);
}

fg_result fg_charges_config_resolve(const fg_charges_config *in, fg_charges_config *out)
{
    if (!in || !out)
        return FG_ERR_NULL;
    fg_charges_config p = *in;
    if (p.charge_count == 0)
        return FG_ERR_ARGUMENT;
    if (!p.charges)
        return FG_ERR_NULL;
    for (size_t i = 0; i < p.charge_count; i++)
        if (!finite3(p.charges[i].position_m) || !isfinite(p.charges[i].charge_c))
            return FG_ERR_NOT_FINITE;
    if (!finite3(p.start_m) || !finite3(p.target_m) || !isfinite(p.step_m) ||
        !isfinite(p.exclusion_m) || !isfinite(p.target_radius_m))
        return FG_ERR_NOT_FINITE;
    if (p.step_m < 0 || p.exclusion_m < 0 || p.target_radius_m < 0)
        return FG_ERR_ARGUMENT;
    fg_preset_scale scale;
    if (fg_preset_get_scale(FG_PRESET_LIGHTNING, &scale) != FG_OK)
        return FG_ERR_ARGUMENT;
    p.step_m = FG_DEF(p.step_m, 2 * scale.half_step_m); /* a segment is 2 l long */
    p.candidates = FG_DEF(p.candidates, DEFAULT_CANDIDATES);
    p.chosen = FG_DEF(p.chosen, DEFAULT_CHOSEN);
    p.exclusion_m = FG_DEF(p.exclusion_m, DEFAULT_EXCLUSION_STEPS * p.step_m);
    p.max_tips = FG_DEF(p.max_tips, DEFAULT_MAX_TIPS);
    p.max_nodes = FG_DEF(p.max_nodes, DEFAULT_MAX_NODES);
    if (p.candidates > MAX_CANDIDATES || p.max_tips > MAX_TIPS || p.chosen > p.candidates ||
        p.exclusion_m >= 2 * p.step_m)
        return FG_ERR_ARGUMENT;
    if (p.target_radius_m == 0 ? p.start_m[2] <= 0
                               : fg_v3_len(fg_v3_sub(v3_of(p.start_m), v3_of(p.target_m))) <=
                                     p.target_radius_m)
        return FG_ERR_ARGUMENT;
    *out = p;
    return FG_OK;
}

void fg_charges_field(const fg_point_charge *charges, size_t count, double phi_tip, double sign,
                      const fg_vec3 *cand, size_t m, double d, double *e)
{
    for (size_t k = 0; k < m; k++) {
        double dphi = potential(charges, count, cand[k]) - phi_tip;
        e[k] = sign * dphi > 0 ? fabs(dphi) / d : 0.0;
    }
}

size_t fg_charges_choose(fg_rng *rng, const fg_vec3 *cand, double *e, size_t m, size_t n,
                         double r, size_t *chosen)
{
    size_t got = 0;
    while (got < n) {
        int drawn = fg_pick(e, (int)m, fg_rng_uniform(rng));
        if (drawn < 0)
            break;
        size_t pick = (size_t)drawn;
        chosen[got++] = pick;
        e[pick] = 0;
        for (size_t k = 0; k < m; k++)
            if (e[k] > 0 && fg_v3_len(fg_v3_sub(cand[k], cand[pick])) < r)
                e[k] = 0;
    }
    return got;
}

typedef struct tip {
    size_t node;
    double e;  /* the field strength of the step that made it */
} tip;

/* Strongest first; ties by node index so that the order is reproducible. */
static int tip_cmp(const void *a, const void *b)
{
    const tip *x = a, *y = b;
    if (x->e != y->e)
        return x->e < y->e ? 1 : -1;
    return x->node < y->node ? -1 : x->node > y->node;
}

typedef struct grower {
    const fg_charges_config *p;
    fg_tree *tree;
    fg_rng rng;
    double sign;
    fg_vec3 *cand;
    double *e, *e_saved;
    size_t *chosen;
    tip *tips, *next;
    size_t ntips, nnext;
} grower;

/* Where the step from a to candidate c ends: on the target if it gets
 * there (*reached set), else at c. */
static fg_vec3 step_end(const fg_charges_config *p, fg_vec3 a, fg_vec3 c, int *reached)
{
    if (p->target_radius_m == 0) {
        *reached = c.z <= 0;
        if (*reached) /* stop on the ground, where the step crosses z = 0 */
            return fg_v3_add(a, fg_v3_scale(fg_v3_sub(c, a), a.z / (a.z - c.z)));
        return c;
    }
    *reached = fg_v3_len(fg_v3_sub(c, v3_of(p->target_m))) <= p->target_radius_m;
    return c;
}

/* Advances one tip: its chosen candidates become nodes and next tips; sets
 * *done when one of them reaches the target. */
static fg_result advance(grower *g, const tip *t, int *done)
{
    const fg_charges_config *p = g->p;
    const fg_node *n = &fg_tree_nodes(g->tree)[t->node];
    fg_vec3 a = fg_v3(n->x, n->y, n->z);
    double phi = potential(p->charges, p->charge_count, a);
    int any = 0;
    for (int draw = 0; draw < REDRAWS && !any; draw++) {
        for (uint32_t k = 0; k < p->candidates; k++)
            g->cand[k] = fg_v3_add(a, fg_v3_scale(fg_v3_random_unit(&g->rng), p->step_m));
        fg_charges_field(p->charges, p->charge_count, phi, g->sign, g->cand, p->candidates,
                         p->step_m, g->e);
        for (uint32_t k = 0; k < p->candidates; k++) {
            if (p->target_radius_m > 0 && g->cand[k].z <= 0)
                g->e[k] = 0; /* the ground bounds the air even when it is not the target */
            any |= g->e[k] > 0;
        }
    }
    memcpy(g->e_saved, g->e, p->candidates * sizeof *g->e);
    size_t got = fg_charges_choose(&g->rng, g->cand, g->e, p->candidates, p->chosen,
                                   p->exclusion_m, g->chosen);
    for (size_t i = 0; i < got; i++) {
        int reached;
        fg_vec3 c = step_end(p, a, g->cand[g->chosen[i]], &reached);
        size_t idx;
        fg_result r = fg_tree_add(g->tree, c.x, c.y, c.z, (int32_t)t->node, 0, &idx);
        if (r != FG_OK)
            return r;
        if (reached) {
            fg_nodes_mark_main(fg_tree_nodes(g->tree), idx);
            *done = 1;
            return FG_OK;
        }
        g->next[g->nnext++] = (tip){idx, g->e_saved[g->chosen[i]]};
    }
    return FG_OK;
}

static fg_result grow(grower *g)
{
    const fg_charges_config *p = g->p;
    fg_vec3 root = v3_of(p->start_m);
    fg_vec3 goal = p->target_radius_m > 0 ? v3_of(p->target_m) : fg_v3(root.x, root.y, 0);
    g->sign = potential(p->charges, p->charge_count, goal) >=
                      potential(p->charges, p->charge_count, root)
                  ? 1.0
                  : -1.0;
    fg_result r = fg_tree_add(g->tree, root.x, root.y, root.z, -1, 0, NULL);
    if (r != FG_OK)
        return r;
    g->tips[0] = (tip){0, 0};
    g->ntips = 1;
    int done = 0;
    while (!done) {
        g->nnext = 0;
        for (size_t i = 0; i < g->ntips && !done; i++)
            if ((r = advance(g, &g->tips[i], &done)) != FG_OK)
                return r;
        if (done)
            break;
        if (g->nnext == 0 || fg_tree_count(g->tree) >= p->max_nodes)
            return FG_ERR_UNREACHABLE;
        qsort(g->next, g->nnext, sizeof *g->next, tip_cmp);
        g->ntips = g->nnext < p->max_tips ? g->nnext : p->max_tips;
        memcpy(g->tips, g->next, g->ntips * sizeof *g->tips);
    }
    return FG_OK;
}

fg_result fg_charges_grow(const fg_charges_config *config, fg_tree *out)
{
    fg_charges_config p;
    fg_result r = fg_charges_config_resolve(config, &p);
    if (r != FG_OK)
        return r;
    if (!out)
        return FG_ERR_NULL;
    if (fg_tree_count(out) != 0)
        return FG_ERR_ARGUMENT;
    grower g = {.p = &p, .tree = out};
    fg_rng_seed(&g.rng, p.seed);
    g.cand = malloc(p.candidates * sizeof *g.cand);
    g.e = malloc(p.candidates * sizeof *g.e);
    g.e_saved = malloc(p.candidates * sizeof *g.e_saved);
    g.chosen = malloc(p.chosen * sizeof *g.chosen);
    g.tips = malloc(p.max_tips * sizeof *g.tips);
    g.next = malloc((size_t)p.max_tips * p.chosen * sizeof *g.next);
    r = g.cand && g.e && g.e_saved && g.chosen && g.tips && g.next ? grow(&g) : FG_ERR_NO_MEMORY;
    free(g.cand);
    free(g.e);
    free(g.e_saved);
    free(g.chosen);
    free(g.tips);
    free(g.next);
    if (r != FG_OK)
        fg_tree_clear(out);
    return r;
}
