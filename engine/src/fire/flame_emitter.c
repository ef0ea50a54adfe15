/* The flame simulation's emitters: which cells a source, jet or burning
 * object feeds, and the release of one step's fuel into them. */
#include <math.h>
#include <string.h>

#include "flame_sim_internal.h"

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* Distance from x to the shape's surface, negative inside. */
static double shape_distance(const fg_flame_emitter *e, const double x[3])
{
    if (e->shape == FG_FLAME_SPHERE) {
        double d[3] = {x[0] - e->centre_m[0], x[1] - e->centre_m[1], x[2] - e->centre_m[2]};
        return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - e->radius_m;
    }
    double outside = 0.0, inside = -INFINITY;
    for (int a = 0; a < 3; a++) {
        double q = fabs(x[a] - e->centre_m[a]) - e->half_size_m[a];
        outside += q > 0.0 ? q * q : 0.0;
        inside = q > inside ? q : inside;
    }
    return outside > 0.0 ? sqrt(outside) : inside;
}

/* How far the emitter's cells reach from its centre along each axis. */
static void reach(const fg_flame_emitter *e, double cell_m, double out[3])
{
    double shell = e->kind == FG_FLAME_EMITTER_OBJECT ? cell_m : 0.0;
    for (int a = 0; a < 3; a++)
        out[a] = (e->shape == FG_FLAME_SPHERE ? e->radius_m : e->half_size_m[a]) + shell;
}

fg_result fg_flame_emitter_prepare(const fg_flame_emitter *e, const double lo[3],
                                   const double hi[3], double cell_m, fg_flame_emitter *out)
{
    if (!e)
        return FG_ERR_NULL;
    if (!finite3(e->centre_m) || !isfinite(e->radius_m) || !finite3(e->half_size_m) ||
        !isfinite(e->fuel_m3_s) || !isfinite(e->temperature_k) ||
        !finite3(e->jet_velocity_m_s))
        return FG_ERR_NOT_FINITE;
    if ((unsigned)e->kind > FG_FLAME_EMITTER_OBJECT || (unsigned)e->shape > FG_FLAME_BOX)
        return FG_ERR_ARGUMENT;
    if (e->radius_m < 0.0 || e->half_size_m[0] < 0.0 || e->half_size_m[1] < 0.0 ||
        e->half_size_m[2] < 0.0 || e->fuel_m3_s < 0.0 || e->temperature_k < 0.0)
        return FG_ERR_ARGUMENT;
    if (e->kind == FG_FLAME_EMITTER_JET && e->jet_velocity_m_s[0] == 0.0 &&
        e->jet_velocity_m_s[1] == 0.0 && e->jet_velocity_m_s[2] == 0.0)
        return FG_ERR_ARGUMENT;
    double r[3];
    reach(e, cell_m, r);
    for (int a = 0; a < 3; a++)
        if (e->centre_m[a] - r[a] < lo[a] || e->centre_m[a] + r[a] > hi[a])
            return FG_ERR_ARGUMENT;
    *out = *e;
    if (out->temperature_k == 0.0)
        out->temperature_k = FG_FLAME_EMITTER_DEFAULT_K;
    return FG_OK;
}

/* The index range [first, last] of an array's elements within [c - r, c + r]
 * on one axis; empty when first > last. */
static void index_range(const fg_fluid_array *v, int a, double c, double r, int *first, int *last)
{
    double lo = (c - r - v->origin_m[a]) / v->cell_m, hi = (c + r - v->origin_m[a]) / v->cell_m;
    int i0 = (int)ceil(lo), i1 = (int)floor(hi);
    *first = i0 < 0 ? 0 : i0;
    *last = i1 > v->size[a] - 1 ? v->size[a] - 1 : i1;
}

/* How much of the element at x the emitter covers, 0 .. 1: the share of
 * the cell-wide interval [d - h/2, d + h/2] of signed distances (d the
 * element's) that lies inside the shape (sources, jets) or within one cell
 * outside its surface (objects). It changes smoothly as the emitter moves,
 * so a carried torch releases its fuel without steps at cell crossings. */
static double coverage(const fg_flame_emitter *e, const double x[3], double cell_m)
{
    double d = shape_distance(e, x) / cell_m;
    double lo = d - 0.5, hi = d + 0.5;
    double from = e->kind == FG_FLAME_EMITTER_OBJECT ? 0.0 : -INFINITY;
    double to = e->kind == FG_FLAME_EMITTER_OBJECT ? 1.0 : 0.0;
    lo = lo > from ? lo : from;
    hi = hi < to ? hi : to;
    return hi > lo ? hi - lo : 0.0;
}

/* What the release does to one element: `share` of the emitter's amount
 * goes to it (the shares sum to 1), and it is `cover`ed by the emitter
 * (0 .. 1). */
typedef struct release_op {
    void (*apply)(double *value, double share, double cover, const struct release_op *op);
    double amount; /* fuel added (F units summed over the shares) */
    double target; /* the temperature or the velocity component to reach */
} release_op;

/* The sum of the coverages of v's elements; with op, applies it to each
 * covered element with share coverage / total. */
static double walk_region(const fg_flame_emitter *e, const fg_fluid_array *v, double cell_m,
                          const release_op *op, double total)
{
    double r[3];
    reach(e, cell_m, r);
    int first[3], last[3];
    for (int a = 0; a < 3; a++)
        index_range(v, a, e->centre_m[a], r[a] + 0.5 * cell_m, &first[a], &last[a]);
    double sum = 0.0;
    for (int k = first[2]; k <= last[2]; k++)
        for (int j = first[1]; j <= last[1]; j++)
            for (int i = first[0]; i <= last[0]; i++) {
                double x[3] = {v->origin_m[0] + i * v->cell_m, v->origin_m[1] + j * v->cell_m,
                               v->origin_m[2] + k * v->cell_m};
                double w = coverage(e, x, cell_m);
                if (w <= 0.0)
                    continue;
                sum += w;
                if (op)
                    op->apply(&v->data[i * v->stride[0] + j * v->stride[1] + k * v->stride[2]],
                              w / total, w, op);
            }
    return sum;
}

/* Applies op to every element of v the emitter covers; the shares are the
 * coverages over their sum. Where the shape covers less than one element
 * in all, the trilinear weights of its centre on the 8 elements around it
 * are the shares instead, and each is fully covered. */
static void for_emitter(const fg_flame_emitter *e, const fg_fluid_array *v, double cell_m,
                        const release_op *op)
{
    double total = walk_region(e, v, cell_m, NULL, 0.0);
    if (total >= 1.0) {
        walk_region(e, v, cell_m, op, total);
        return;
    }
    int base[3];
    double frac[3];
    for (int a = 0; a < 3; a++) {
        double u = (e->centre_m[a] - v->origin_m[a]) / v->cell_m, fl = floor(u);
        base[a] = (int)fl;
        frac[a] = u - fl;
    }
    for (int corner = 0; corner < 8; corner++) {
        double w = 1.0;
        size_t at = 0;
        for (int a = 0; a < 3; a++) {
            int up = (corner >> a) & 1, i = base[a] + up;
            w *= up ? frac[a] : 1.0 - frac[a];
            i = i < 0 ? 0 : i > v->size[a] - 1 ? v->size[a] - 1 : i;
            at += (size_t)i * v->stride[a];
        }
        if (w > 0.0)
            op->apply(&v->data[at], w, 1.0, op);
    }
}

static void add_fuel(double *value, double share, double cover, const release_op *op)
{
    (void)cover;
    *value += share * op->amount;
}

/* every covered cell is heated to the emitter's temperature, so that all
 * the fuel it receives is lit (heating in proportion to the coverage left
 * the fringe's fuel unlit, to drift off unburnt) */
static void heat(double *value, double share, double cover, const release_op *op)
{
    (void)share;
    (void)cover;
    *value = *value < op->target ? op->target : *value;
}

/* the jet's velocity blended in as far as the face is covered */
static void blow(double *value, double share, double cover, const release_op *op)
{
    (void)share;
    *value += cover * (op->target - *value);
}

double fg_flame_emitter_release(const fg_flame_emitter *e, fg_fluid *f, double dt)
{
    if (e->kind == FG_FLAME_EMITTER_OFF)
        return 0.0;
    fg_fluid_array fuel = fg_fluid_scalar(f, FG_FLAME_FUEL);
    fg_fluid_array temp = fg_fluid_scalar(f, FG_FLAME_TEMPERATURE);
    double h = fuel.cell_m, volume = e->fuel_m3_s * dt;
    release_op op = {.apply = add_fuel, .amount = volume / (h * h * h)};
    for_emitter(e, &fuel, h, &op);
    op = (release_op){.apply = heat, .target = e->temperature_k};
    for_emitter(e, &temp, h, &op);
    if (e->kind == FG_FLAME_EMITTER_JET) {
        const fg_fluid_config *c = fg_fluid_get_config(f);
        for (int a = 0; a < c->dims; a++) {
            fg_fluid_array u = fg_fluid_velocity(f, a);
            op = (release_op){.apply = blow, .target = e->jet_velocity_m_s[a]};
            for_emitter(e, &u, h, &op);
        }
    }
    return volume;
}
