/* The parts of a growth step both models share: the configuration, the
 * candidate cone, eq. 2's weighted choice, and the root. */
#include <math.h>
#include <stdlib.h>

#include "fg_math.h"
#include "fg_rules.h"
#include "growth_internal.h"

#define DEFAULT_GAMMA 2.5
#define DEFAULT_CANDIDATES 8
#define DEFAULT_CONE_RAD (FG_PI / 2.0)
#define DEFAULT_BRANCH_PROBABILITY 0.1
#define DEFAULT_MAX_TIPS 16
#define DEFAULT_BRANCH_STEPS 6
#define DEFAULT_MAX_STEPS 4096
#define DEFAULT_ETA 2.0
#define DEFAULT_GLOBAL_EVERY 8
#define DEFAULT_RELAX_RADIUS 3

fg_result fg_growth_config_resolve(const fg_growth_config *in, fg_growth_config *out)
{
    if (!in || !out)
        return FG_ERR_NULL;
    fg_growth_config c = *in;
    if (!isfinite(c.step_m) || !isfinite(c.gamma) || !isfinite(c.cone_rad) ||
        !isfinite(c.branch_probability) || !isfinite(c.branch_length_m) || !isfinite(c.eta))
        return FG_ERR_NOT_FINITE;
    if (!(c.step_m > 0.0) || c.gamma < 0.0 || c.candidates < 0 ||
        c.candidates > FG_GROWTH_MAX_CANDIDATES || c.cone_rad < 0.0 || c.cone_rad > FG_PI ||
        c.branch_probability < 0.0 || c.branch_probability > 1.0 || c.max_tips < 0 ||
        c.branch_length_m < 0.0 || c.max_steps < 0 || c.eta < 0.0 || c.dbm_global_every < 0 ||
        c.dbm_relax_radius < 0)
        return FG_ERR_ARGUMENT;
    c.gamma = FG_DEF(c.gamma, DEFAULT_GAMMA);
    c.candidates = FG_DEF(c.candidates, DEFAULT_CANDIDATES);
    c.cone_rad = FG_DEF(c.cone_rad, DEFAULT_CONE_RAD);
    c.branch_probability = FG_DEF(c.branch_probability, DEFAULT_BRANCH_PROBABILITY);
    c.max_tips = FG_DEF(c.max_tips, DEFAULT_MAX_TIPS);
    c.branch_length_m = FG_DEF(c.branch_length_m, DEFAULT_BRANCH_STEPS * c.step_m);
    c.max_steps = FG_DEF(c.max_steps, DEFAULT_MAX_STEPS);
    c.eta = FG_DEF(c.eta, DEFAULT_ETA);
    c.dbm_global_every = FG_DEF(c.dbm_global_every, DEFAULT_GLOBAL_EVERY);
    c.dbm_relax_radius = FG_DEF(c.dbm_relax_radius, DEFAULT_RELAX_RADIUS);
    *out = c;
    return FG_OK;
}

void fg_cone_directions(fg_rng *rng, const double a[3], double half_rad, int n, double *dirs)
{
    /* An orthonormal basis (u, v, a). */
    double t[3] = {0.0, 0.0, 0.0};
    t[fabs(a[0]) < 0.6 ? 0 : (fabs(a[1]) < 0.6 ? 1 : 2)] = 1.0;
    double u[3] = {a[1] * t[2] - a[2] * t[1], a[2] * t[0] - a[0] * t[2], a[0] * t[1] - a[1] * t[0]};
    double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; i++)
        u[i] /= un;
    double v[3] = {a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2], a[0] * u[1] - a[1] * u[0]};
    double c0 = cos(half_rad);
    for (int k = 0; k < n; k++) {
        /* Uniform on the cap: cos(theta) uniform in [cos(half), 1]. */
        double ct = 1.0 - fg_rng_uniform(rng) * (1.0 - c0);
        double st = sqrt(fmax(0.0, 1.0 - ct * ct));
        double ph = 2.0 * FG_PI * fg_rng_uniform(rng);
        double cu = st * cos(ph), cv = st * sin(ph);
        for (int i = 0; i < 3; i++)
            dirs[3 * k + i] = ct * a[i] + cu * u[i] + cv * v[i];
    }
}

double fg_eq2_weight(double phi, double exponent)
{
    return phi > 0.0 ? pow(phi, exponent) : 0.0;
}

fg_result fg_field_direction(const fg_field_source *src, const double x[3], double dir[3])
{
    double h = src->cell_m, probe[18], v[6];
    for (int a = 0; a < 3; a++)
        for (int s = 0; s < 2; s++)
            for (int b = 0; b < 3; b++)
                probe[3 * (2 * a + s) + b] = x[b] + (b == a ? (s ? h : -h) : 0.0);
    fg_result r = src->sample(src->context, probe, 6, v);
    if (r != FG_OK)
        return r;
    double g[3] = {v[1] - v[0], v[3] - v[2], v[5] - v[4]};
    double gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (gn > 0.0)
        for (int a = 0; a < 3; a++)
            dir[a] = g[a] / gn;
    return FG_OK;
}

fg_result fg_growth_root(const fg_field_source *src, double exponent, fg_rng *rng,
                         double root[3], double dir[3])
{
    size_t n = src->origin_sites(src->context, NULL, 0);
    if (n == 0)
        return FG_ERR_ARGUMENT;
    double *pts = malloc(n * 3 * sizeof(double));
    double *w = malloc(n * sizeof(double));
    fg_result r = FG_ERR_NO_MEMORY;
    if (!pts || !w)
        goto done;
    src->origin_sites(src->context, pts, n);
    if ((r = src->sample(src->context, pts, n, w)) != FG_OK)
        goto done;
    for (size_t i = 0; i < n; i++)
        w[i] = fg_eq2_weight(w[i], exponent);
    double u = fg_rng_uniform(rng);
    int pick = fg_pick(w, (int)n, u);
    if (pick < 0) { /* phi is 0 all round the origin: any site */
        for (size_t i = 0; i < n; i++)
            w[i] = 1.0;
        pick = fg_pick(w, (int)n, u);
    }
    for (int a = 0; a < 3; a++) {
        root[a] = pts[3 * pick + a];
        dir[a] = a == 2 ? 1.0 : 0.0;
    }
    r = fg_field_direction(src, root, dir);
done:
    free(pts);
    free(w);
    return r;
}
