/* The flame front (Chadwick & James eqs. 2-9): the B-spline iso-surface
 * by marching cubes is watertight and outward-wound on random fields full
 * of ambiguous faces; a closed front in a uniform flow has I = 0 (to
 * 1e-10 of |u| times its area), also where it touches the grid's edge;
 * u = a x through a sphere of radius R gives 4 pi a R^3 with the error
 * falling to <= 0.3x when the cell halves (both velocity layouts, two
 * subdivisions); a non-uniform flow gives the divergence theorem's
 * volume integral; bad input changes nothing. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fg_math.h"
#include "fulgur/fire.h"
#include "fg_rng.h"


typedef double (*field_fn)(const double x[3], const void *ctx);

typedef struct grid_fields {
    int n;
    double h;
    double *burn;
    double *u[3];
    fg_velocity_layout layout;
} grid_fields;

/* The burn field at cell centres and the velocity in a layout, on an
 * n^3 grid over the unit cube. */
static grid_fields make_fields(int n, fg_velocity_layout layout, field_fn burn, field_fn u[3],
                               const void *ctx)
{
    grid_fields g = {.n = n, .h = 1.0 / n, .layout = layout};
    g.burn = malloc(sizeof(double) * (size_t)n * n * n);
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                double x[3] = {(i + 0.5) * g.h, (j + 0.5) * g.h, (k + 0.5) * g.h};
                g.burn[i + n * (j + n * k)] = burn(x, ctx);
            }
    for (int a = 0; a < 3; a++) {
        int m[3] = {n, n, n};
        if (layout == FG_VELOCITY_MAC)
            m[a]++;
        g.u[a] = malloc(sizeof(double) * (size_t)m[0] * m[1] * m[2]);
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++) {
                    int idx[3] = {i, j, k};
                    double x[3];
                    for (int b = 0; b < 3; b++)
                        x[b] = (idx[b] + (layout == FG_VELOCITY_MAC && b == a ? 0.0 : 0.5)) * g.h;
                    g.u[a][i + m[0] * (j + m[1] * k)] = u[a](x, ctx);
                }
    }
    return g;
}

static void free_fields(grid_fields *g)
{
    free(g->burn);
    for (int a = 0; a < 3; a++)
        free(g->u[a]);
}

static fg_flame_front *front_for(int n, int subdivision, double iso)
{
    fg_flame_front_config c = {.grid = {{n, n, n}, {0, 0, 0}, 1.0 / n}, .iso_level = iso,
                               .subdivision = subdivision};
    fg_flame_front *f;
    assert_int_equal(fg_flame_front_create(&c, &f), FG_OK);
    return f;
}

static fg_flame_flux flux_of(fg_flame_front *f, const grid_fields *g)
{
    fg_flame_velocity v = {g->layout, {g->u[0], g->u[1], g->u[2]}};
    fg_flame_flux out;
    assert_int_equal(fg_flame_front_flux(f, g->burn, &v, &out), FG_OK);
    return out;
}

/* ---- the sphere ---- */

typedef struct sphere {
    double c[3], r, a;
} sphere;

static double sphere_burn(const double x[3], const void *ctx)
{
    const sphere *s = ctx;
    double d2 = 0.0;
    for (int b = 0; b < 3; b++)
        d2 += (x[b] - s->c[b]) * (x[b] - s->c[b]);
    return 1.0 + s->r - sqrt(d2); /* iso 1 at radius r, below 1 outside */
}
static double ux(const double x[3], const void *ctx)
{
    const sphere *s = ctx;
    return s->a * (x[0] - s->c[0]);
}
static double uy(const double x[3], const void *ctx)
{
    const sphere *s = ctx;
    return s->a * (x[1] - s->c[1]);
}
static double uz(const double x[3], const void *ctx)
{
    const sphere *s = ctx;
    return s->a * (x[2] - s->c[2]);
}

static double sphere_error(int n, int subdivision, fg_velocity_layout layout, double *area_error)
{
    sphere s = {{0.513, 0.479, 0.507}, 0.3, 0.7};
    field_fn u[3] = {ux, uy, uz};
    grid_fields g = make_fields(n, layout, sphere_burn, u, &s);
    fg_flame_front *f = front_for(n, subdivision, 1.0);
    fg_flame_flux fl = flux_of(f, &g);
    double exact = 4.0 * FG_PI * s.a * s.r * s.r * s.r;
    *area_error = fl.area_m2 / (4.0 * FG_PI * s.r * s.r) - 1.0;
    fg_flame_front_destroy(f);
    free_fields(&g);
    return fl.flux_m3_s / exact - 1.0;
}

static void test_sphere_convergence(void **state)
{
    (void)state;
    for (int sub = 1; sub <= 2; sub++)
        for (int mac = 0; mac < 2; mac++) {
            fg_velocity_layout layout = mac ? FG_VELOCITY_MAC : FG_VELOCITY_COLLOCATED;
            double a16, a32, a64;
            double e16 = sphere_error(16, sub, layout, &a16), e32 = sphere_error(32, sub, layout, &a32);
            double e64 = sphere_error(64, sub, layout, &a64);
            print_message("sub %d %s: I error %.2e %.2e %.2e (ratios %.3f %.3f); area %.2e\n",
                          sub, mac ? "MAC" : "collocated", e16, e32, e64, e32 / e16, e64 / e32,
                          a64);
            assert_true(fabs(e32) <= 0.3 * fabs(e16));
            assert_true(fabs(e64) <= 0.3 * fabs(e32));
            assert_true(fabs(e64) < 5e-3);
            assert_true(fabs(a64) < 5e-3);
        }
}

/* u = (x^2, y, 0) - centre terms: div u = 2 (x - cx) + 1; over the ball
 * the first term integrates to 0, so I = (4/3) pi R^3. */
static double quad_x(const double x[3], const void *ctx)
{
    const sphere *s = ctx;
    return (x[0] - s->c[0]) * (x[0] - s->c[0]);
}
static double lin_y(const double x[3], const void *ctx)
{
    const sphere *s = ctx;
    return x[1] - s->c[1];
}
static double zero(const double x[3], const void *ctx)
{
    (void)x;
    (void)ctx;
    return 0.0;
}

static void test_divergence_theorem(void **state)
{
    (void)state;
    sphere s = {{0.49, 0.52, 0.5}, 0.28, 1.0};
    field_fn u[3] = {quad_x, lin_y, zero};
    grid_fields g = make_fields(48, FG_VELOCITY_MAC, sphere_burn, u, &s);
    fg_flame_front *f = front_for(48, 2, 1.0);
    fg_flame_flux fl = flux_of(f, &g);
    double want = 4.0 / 3.0 * FG_PI * s.r * s.r * s.r, err = fl.flux_m3_s / want - 1.0;
    /* the spline smooths: B~ = B + (h^2/6) lap B + ..., which moves the
     * front of B = 1 + R - r inward by h^2 / 3R, the volume by (h / R)^2 */
    double bias = (1.0 / 48.0 / s.r) * (1.0 / 48.0 / s.r);
    print_message("div u = 2x + 1 over a ball: I / volume integral - 1 = %.2e ((h/R)^2 = %.2e)\n",
                  err, bias);
    assert_true(err < 0.0 && fabs(err) < 1.5 * bias);
    fg_flame_front_destroy(f);
    free_fields(&g);
}

/* ---- closed fronts: uniform flow, watertightness ---- */

typedef struct blobs {
    double c[6][3], r[6];
    double noise[4096];
    int n;
} blobs;

/* Six overlapping bumps, one against the grid's edge, plus cell noise:
 * many components, holes and ambiguous faces. */
static double blobs_burn(const double x[3], const void *ctx)
{
    const blobs *b = ctx;
    double v = 0.0;
    for (int i = 0; i < 6; i++) {
        double d2 = 0.0;
        for (int a = 0; a < 3; a++)
            d2 += (x[a] - b->c[i][a]) * (x[a] - b->c[i][a]);
        v += exp(-d2 / (b->r[i] * b->r[i]));
    }
    int cell = ((int)(x[0] * b->n) * 31 + (int)(x[1] * b->n) * 17 + (int)(x[2] * b->n) * 7) % 4096;
    return v + b->noise[cell];
}
static double u0(const double x[3], const void *c)
{
    (void)x;
    (void)c;
    return 1.3;
}
static double u1(const double x[3], const void *c)
{
    (void)x;
    (void)c;
    return -0.7;
}
static double u2(const double x[3], const void *c)
{
    (void)x;
    (void)c;
    return 2.1;
}

static blobs make_blobs(int n, double noise, uint64_t seed)
{
    blobs b = {.n = n};
    fg_rng rng;
    fg_rng_seed(&rng, seed);
    for (int i = 0; i < 6; i++) {
        for (int a = 0; a < 3; a++)
            b.c[i][a] = fg_rng_range(&rng, 0.2, 0.8);
        b.r[i] = fg_rng_range(&rng, 0.08, 0.2);
    }
    b.c[5][0] = 0.02; /* against the x = 0 face */
    for (int i = 0; i < 4096; i++)
        b.noise[i] = noise * fg_rng_range(&rng, -1.0, 1.0);
    return b;
}

typedef struct edge {
    double a[3], b[3];
} edge;

static int cmp_point(const double *p, const double *q)
{
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k])
            return p[k] < q[k] ? -1 : 1;
    return 0;
}

static int cmp_edge(const void *x, const void *y)
{
    const edge *e = x, *f = y;
    int c = cmp_point(e->a, f->a);
    return c ? c : cmp_point(e->b, f->b);
}

/* Every directed edge (a, b) of the mesh has exactly one (b, a). */
static void assert_watertight(const double *xyz, size_t tris)
{
    size_t n = 3 * tris;
    edge *fwd = malloc(sizeof(edge) * n), *rev = malloc(sizeof(edge) * n);
    for (size_t t = 0; t < tris; t++)
        for (int k = 0; k < 3; k++) {
            const double *a = xyz + 9 * t + 3 * k, *b = xyz + 9 * t + 3 * ((k + 1) % 3);
            memcpy(fwd[3 * t + k].a, a, sizeof(double) * 3);
            memcpy(fwd[3 * t + k].b, b, sizeof(double) * 3);
            memcpy(rev[3 * t + k].a, b, sizeof(double) * 3);
            memcpy(rev[3 * t + k].b, a, sizeof(double) * 3);
        }
    qsort(fwd, n, sizeof(edge), cmp_edge);
    qsort(rev, n, sizeof(edge), cmp_edge);
    size_t degenerate = 0;
    for (size_t i = 0; i < n; i++) {
        if (cmp_point(fwd[i].a, fwd[i].b) == 0) {
            degenerate++;
            continue;
        }
        assert_int_equal(cmp_edge(&fwd[i], &rev[i]), 0);
    }
    assert_true(degenerate < n / 100 + 1);
    free(fwd);
    free(rev);
}

static void test_closed_front_uniform_flow(void **state)
{
    (void)state;
    field_fn u[3] = {u0, u1, u2};
    double speed = sqrt(1.3 * 1.3 + 0.7 * 0.7 + 2.1 * 2.1);
    for (int trial = 0; trial < 4; trial++) {
        int n = 20 + 6 * trial, sub = 1 + trial % 3;
        blobs b = make_blobs(n, trial % 2 ? 0.25 : 0.05, (uint64_t)trial + 1);
        fg_velocity_layout layout = trial % 2 ? FG_VELOCITY_MAC : FG_VELOCITY_COLLOCATED;
        grid_fields g = make_fields(n, layout, blobs_burn, u, &b);
        fg_flame_front *f = front_for(n, sub, 0.5);
        fg_flame_flux fl = flux_of(f, &g);
        double rel = fabs(fl.flux_m3_s) / (speed * fl.area_m2);
        print_message("n %d sub %d: %zu triangles, area %.4f m^2, |I| / (|u| A) = %.1e\n", n, sub,
                      fl.triangles, fl.area_m2, rel);
        assert_true(fl.triangles > 1000);
        assert_true(rel <= 1e-10);
        const double *xyz;
        size_t tris;
        assert_int_equal(fg_flame_front_triangles(f, &xyz, &tris), FG_OK);
        assert_int_equal(tris, fl.triangles);
        assert_watertight(xyz, tris);
        fg_flame_front_destroy(f);
        free_fields(&g);
    }
}

/* Coin-flip fields: every pattern of the 256, ambiguous faces everywhere. */
static double coin_burn(const double x[3], const void *ctx)
{
    const blobs *b = ctx;
    int cell = ((int)(x[0] * b->n) * 131 + (int)(x[1] * b->n) * 37 + (int)(x[2] * b->n) * 11) % 4096;
    return b->noise[cell] > 0.0 ? 1.0 : 0.0;
}

static void test_random_patterns(void **state)
{
    (void)state;
    field_fn u[3] = {u0, u1, u2};
    blobs b = make_blobs(12, 1.0, 77);
    grid_fields g = make_fields(12, FG_VELOCITY_MAC, coin_burn, u, &b);
    fg_flame_front *f = front_for(12, 1, 0.5);
    fg_flame_flux fl = flux_of(f, &g);
    assert_true(fabs(fl.flux_m3_s) <= 1e-10 * 2.6 * fl.area_m2);
    const double *xyz;
    size_t tris;
    assert_int_equal(fg_flame_front_triangles(f, &xyz, &tris), FG_OK);
    assert_watertight(xyz, tris);
    /* outward winding: the vector area weighted by position gives the
     * enclosed volume (div x = 3), which must be positive */
    double volume = 0.0;
    for (size_t t = 0; t < tris; t++) {
        const double *p = xyz + 9 * t;
        double e1[3], e2[3], c[3], n[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = p[3 + k] - p[k];
            e2[k] = p[6 + k] - p[k];
            c[k] = (p[k] + p[3 + k] + p[6 + k]) / 3.0;
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        volume += (c[0] * n[0] + c[1] * n[1] + c[2] * n[2]) / 6.0;
    }
    assert_true(volume > 0.0);
    fg_flame_front_destroy(f);
    free_fields(&g);
}

/* ---- bad input ---- */

static void test_errors(void **state)
{
    (void)state;
    fg_flame_front *f = (fg_flame_front *)state;
    fg_flame_front_config good = {.grid = {{8, 8, 8}, {0, 0, 0}, 0.125}, .iso_level = 1.0};
    struct {
        fg_flame_front_config c;
        fg_result want;
    } bad[] = {
        {{.grid = {{1, 8, 8}, {0, 0, 0}, 0.125}, .iso_level = 1.0}, FG_ERR_ARGUMENT},
        {{.grid = {{8, 8, 513}, {0, 0, 0}, 0.125}, .iso_level = 1.0}, FG_ERR_ARGUMENT},
        {{.grid = {{8, 8, 8}, {0, 0, 0}, 0.0}, .iso_level = 1.0}, FG_ERR_ARGUMENT},
        {{.grid = {{8, 8, 8}, {0, 0, 0}, 0.125}, .iso_level = 0.0}, FG_ERR_ARGUMENT},
        {{.grid = {{8, 8, 8}, {0, 0, 0}, 0.125}, .iso_level = -1.0}, FG_ERR_ARGUMENT},
        {{.grid = {{8, 8, 8}, {0, 0, 0}, 0.125}, .iso_level = 1e301}, FG_ERR_ARGUMENT},
        {{.grid = {{8, 8, 8}, {0, 0, 0}, 0.125}, .iso_level = 1.0, .subdivision = 5},
         FG_ERR_ARGUMENT},
        {{.grid = {{8, 8, 8}, {0, NAN, 0}, 0.125}, .iso_level = 1.0}, FG_ERR_NOT_FINITE},
        {{.grid = {{8, 8, 8}, {0, 0, 0}, INFINITY}, .iso_level = 1.0}, FG_ERR_NOT_FINITE},
        {{.grid = {{512, 512, 512}, {0, 0, 0}, 0.01}, .iso_level = 1.0}, FG_ERR_CAPACITY},
        {{.grid = {{64, 64, 64}, {0, 0, 0}, 0.01}, .iso_level = 1.0, .max_bytes = 100000},
         FG_ERR_CAPACITY},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        f = (fg_flame_front *)state;
        assert_int_equal(fg_flame_front_create(&bad[i].c, &f), bad[i].want);
        assert_null(f);
    }
    assert_int_equal(fg_flame_front_create(NULL, &f), FG_ERR_NULL);
    assert_int_equal(fg_flame_front_create(&good, NULL), FG_ERR_NULL);
    assert_int_equal(fg_flame_front_memory_bytes(&bad[0].c), 0);
    assert_true(fg_flame_front_memory_bytes(&good) > 8 * 8 * 8 * sizeof(double));

    /* a good surface, then bad steps: the surface and *out stay */
    sphere s = {{0.5, 0.5, 0.5}, 0.3, 0.7};
    field_fn u[3] = {ux, uy, uz};
    grid_fields g = make_fields(8, FG_VELOCITY_MAC, sphere_burn, u, &s);
    fg_flame_front_config cfg;
    assert_int_equal(fg_flame_front_create(&good, &f), FG_OK);
    fg_flame_front_get_config(f, &cfg);
    assert_int_equal(cfg.subdivision, 1);
    assert_true(cfg.max_bytes == FG_FLAME_DEFAULT_MAX_BYTES);
    fg_flame_flux first = flux_of(f, &g), out = {.flux_m3_s = 42.0};
    const double *xyz;
    size_t tris;
    assert_int_equal(fg_flame_front_triangles(f, &xyz, &tris), FG_OK);
    double *keep = malloc(sizeof(double) * 9 * tris);
    memcpy(keep, xyz, sizeof(double) * 9 * tris);
    size_t keep_tris = tris;
    fg_flame_velocity v = {FG_VELOCITY_MAC, {g.u[0], g.u[1], g.u[2]}};
    g.burn[100] = NAN;
    assert_int_equal(fg_flame_front_flux(f, g.burn, &v, &out), FG_ERR_NOT_FINITE);
    g.burn[100] = sphere_burn((double[]){(100 % 8 + 0.5) / 8, (100 / 8 % 8 + 0.5) / 8,
                                         (100 / 64 + 0.5) / 8}, &s);
    /* a NaN in the velocity next to the front (cell 4,4,6 sits on it) */
    g.u[2][4 + 8 * (4 + 8 * 6)] = NAN;
    assert_int_equal(fg_flame_front_flux(f, g.burn, &v, &out), FG_ERR_NOT_FINITE);
    assert_true(out.flux_m3_s == 42.0);
    assert_int_equal(fg_flame_front_triangles(f, &xyz, &tris), FG_OK);
    assert_int_equal(tris, keep_tris);
    assert_memory_equal(xyz, keep, sizeof(double) * 9 * tris);
    /* a NaN where no triangle samples (a corner of the grid) is never read */
    g.u[2][4 + 8 * (4 + 8 * 6)] = 0.0;
    g.u[2][4 + 8 * (4 + 8 * 6)] = uz((double[]){4.5 / 8, 4.5 / 8, 6.0 / 8}, &s);
    g.u[0][0] = NAN;
    fg_flame_flux again = flux_of(f, &g);
    assert_true(again.flux_m3_s == first.flux_m3_s);
    /* beyond the burn limit, and a velocity whose flux overflows */
    double save = g.burn[7];
    g.burn[7] = 2e300;
    assert_int_equal(fg_flame_front_flux(f, g.burn, &v, &out), FG_ERR_ARGUMENT);
    g.burn[7] = save;
    /* finite layers whose difference overflows in the interpolation */
    double *uz_copy = malloc(sizeof(double) * 8 * 8 * 9);
    memcpy(uz_copy, g.u[2], sizeof(double) * 8 * 8 * 9);
    for (int i = 0; i < 64; i++) {
        g.u[2][i + 64 * 5] = -1.7e308;
        g.u[2][i + 64 * 6] = 1.7e308;
    }
    assert_int_equal(fg_flame_front_flux(f, g.burn, &v, &out), FG_ERR_NOT_FINITE);
    memcpy(g.u[2], uz_copy, sizeof(double) * 8 * 8 * 9);
    free(uz_copy);
    assert_true(out.flux_m3_s == 42.0);
    v.layout = (fg_velocity_layout)7;
    assert_int_equal(fg_flame_front_flux(f, g.burn, &v, &out), FG_ERR_ARGUMENT);
    v.layout = FG_VELOCITY_MAC;
    v.u_m_s[1] = NULL;
    assert_int_equal(fg_flame_front_flux(f, g.burn, &v, &out), FG_ERR_NULL);
    assert_int_equal(fg_flame_front_flux(f, NULL, &v, &out), FG_ERR_NULL);
    assert_int_equal(fg_flame_front_triangles(f, NULL, &tris), FG_ERR_NULL);

    /* no flame: no triangles, no flux */
    for (int i = 0; i < 512; i++)
        g.burn[i] = 0.5;
    v.u_m_s[1] = g.u[1];
    g.u[0][0] = 0.0;
    assert_int_equal(fg_flame_front_flux(f, g.burn, &v, &out), FG_OK);
    assert_int_equal(out.triangles, 0);
    assert_true(out.flux_m3_s == 0.0 && out.area_m2 == 0.0);
    free(keep);
    fg_flame_front_destroy(f);
    fg_flame_front_destroy(NULL);
    free_fields(&g);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_convergence),
        cmocka_unit_test(test_divergence_theorem),
        cmocka_unit_test(test_closed_front_uniform_flow),
        cmocka_unit_test(test_random_patterns),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
