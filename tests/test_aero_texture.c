/* Sound textures without the CFD: validation of a texture and of a
 * configuration, the symmetry's map of flow angles, the level law, the
 * shapes (their symmetry, their checks), and the loop: the period found
 * in a signal, whole periods, the seam. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "aero/aero_internal.h"
#include "fulgur/aero.h"
#include "fg_math.h"

#define DEG (FG_PI / 180.0)

static float zeros[4 * 64 * 3];

/* A 2-D texture of the given symmetry with directions every step_deg over
 * its range; samples all zero. */
static fg_aero_texture_desc desc2d(uint32_t order, uint32_t mirror, double beta, double step_deg,
                                   fg_aero_direction *dir, uint32_t *count)
{
    double lo, span;
    fg_aero_symmetry_range(order, mirror, beta, &lo, &span);
    uint32_t n = order == 0 ? 1 : (uint32_t)lround(span / (step_deg * DEG)) + (mirror ? 1 : 0);
    for (uint32_t i = 0; i < n; i++)
        dir[i] = (fg_aero_direction){.angle_rad = lo + i * step_deg * DEG, .frontal_m = 0.01,
                                     .frequency_hz = 200, .strouhal = 0.2, .periods = 2,
                                     .frames = 64, .samples = zeros};
    *count = n;
    static const fg_aero_source one = {0.0, 1.0};
    fg_aero_texture_desc d = {.shape = FG_AERO_RECTANGLE, .dims = 2, .components = 2,
                              .length_m = 0.01, .height_m = 0.01, .reference_m = 0.01,
                              .speed_m_s = 10, .viscosity_m2_s = 1.5e-5, .density_kg_m3 = 1.2,
                              .sample_rate_hz = 16000, .cells_per_length = 32,
                              .rotation_order = order, .mirror = mirror, .mirror_angle_rad = beta,
                              .sources = 1, .source = &one, .directions = n, .direction = dir};
    d.reynolds = d.reference_m * d.speed_m_s / d.viscosity_m2_s;
    return d;
}

static void check_lookup(const fg_aero_texture *t, double angle_deg, double at_deg, float sign)
{
    fg_aero_lookup l;
    fg_aero_texture_lookup(t, angle_deg * DEG, &l);
    const fg_aero_texture_desc *d = fg_aero_texture_get(t);
    double a = l.weight[0] * d->direction[l.index[0]].angle_rad +
               l.weight[1] * d->direction[l.index[1]].angle_rad;
    if (l.index[1] < l.index[0]) /* across the wrap of a periodic range */
        a += l.weight[1] * 2.0 * FG_PI / d->rotation_order;
    if (fabs(a / DEG - at_deg) > 1e-6 || l.lift_sign != sign ||
        fabs(l.weight[0] + l.weight[1] - 1.0f) > 1e-6f)
        fail_msg("%g deg: read at %g deg (sign %g), expected %g deg (sign %g)", angle_deg,
                 a / DEG, l.lift_sign, at_deg, sign);
}

/* A square prism (4-fold, mirrored: 0..45 deg), a shape with a mirror only
 * at 90 deg (90..270), one without symmetry (0..360, periodic), a circle. */
static void lookup(void **state)
{
    (void)state;
    fg_aero_direction dir[80];
    uint32_t n;
    fg_aero_texture *t;
    fg_aero_texture_desc d = desc2d(4, 1, 0.0, 5.0, dir, &n);
    assert_int_equal(n, 10);
    assert_int_equal(fg_aero_texture_create(&d, &t), FG_OK);
    check_lookup(t, 10, 10, 1);
    check_lookup(t, 100, 10, 1);    /* a quarter turn on */
    check_lookup(t, 80, 10, -1);    /* the mirror image of 10 */
    check_lookup(t, -10, 10, -1);
    check_lookup(t, 47.5, 42.5, -1);
    check_lookup(t, 42.5, 42.5, 1); /* half way between 40 and 45 */
    check_lookup(t, 45, 45, 1);
    check_lookup(t, 721, 1, 1);
    fg_aero_texture_destroy(t);
    d = desc2d(1, 1, 90 * DEG, 5.0, dir, &n);
    assert_int_equal(n, 37);
    assert_int_equal(fg_aero_texture_create(&d, &t), FG_OK);
    check_lookup(t, 60, 120, -1);   /* mirrored across 90 */
    check_lookup(t, 300, 240, -1);
    check_lookup(t, 200, 200, 1);
    fg_aero_texture_destroy(t);
    d = desc2d(1, 0, 0.0, 5.0, dir, &n);
    assert_int_equal(n, 72);
    assert_int_equal(fg_aero_texture_create(&d, &t), FG_OK);
    check_lookup(t, 357.5, 357.5, 1); /* between 355 and 0 + 360 */
    check_lookup(t, -2.5, 357.5, 1);
    check_lookup(t, 12.5, 12.5, 1);
    fg_aero_lookup l;
    fg_aero_texture_lookup(t, 357.5 * DEG, &l);
    assert_int_equal(l.index[0], 71);
    assert_int_equal(l.index[1], 0);
    assert_float_equal(l.weight[1], 0.5, 1e-6);
    fg_aero_texture_lookup(t, NAN, &l); /* never an index out of range */
    assert_true(l.index[0] < n && l.index[1] < n);
    fg_aero_texture_destroy(t);
    d = desc2d(0, 1, 0.0, 5.0, dir, &n);
    d.shape = FG_AERO_CIRCLE;
    assert_int_equal(fg_aero_texture_create(&d, &t), FG_OK);
    fg_aero_texture_lookup(t, 123 * DEG, &l);
    assert_int_equal(l.index[0], 0);
    assert_float_equal(l.weight[0], 1.0, 0);
    fg_aero_texture_destroy(t);
}

/* The level law: pressure (v/v0)^3 (aeolian), (v/v0)^2 (cavity): +18.06
 * and +12.04 dB a doubling (the paper's v^6 would give +36.1 dB). */
static void level_law(void **state)
{
    (void)state;
    fg_aero_direction dir[80];
    uint32_t n;
    fg_aero_texture *t;
    fg_aero_texture_desc d = desc2d(4, 1, 0.0, 5.0, dir, &n);
    for (int tone = 0; tone < 2; tone++) {
        d.tone = (fg_aero_tone)tone;
        assert_int_equal(fg_aero_texture_create(&d, &t), FG_OK);
        assert_float_equal(fg_aero_pressure_scale(t, 10.0), 1.0, 1e-12);
        double db = 20.0 * log10(fg_aero_pressure_scale(t, 20.0));
        assert_float_equal(db, tone ? 12.0412 : 18.0618, 1e-3);
        assert_float_equal(fg_aero_pressure_scale(t, 5.0), tone ? 0.25 : 0.125, 1e-12);
        assert_true(fg_aero_pressure_scale(t, 0.0) == 0.0);
        assert_true(fg_aero_pressure_scale(t, -3.0) == 0.0);
        assert_true(fg_aero_pressure_scale(t, NAN) == 0.0);
        assert_true(fg_aero_pressure_scale(t, INFINITY) == 0.0);
        fg_aero_texture_destroy(t);
    }
}

/* Every field of a texture that can be wrong: the code, and nothing made. */
static void texture_checks(void **state)
{
    (void)state;
    static float bad_sample[64 * 2];
    bad_sample[77] = NAN;
    for (int k = 0; k < 19; k++) {
        fg_aero_direction dir[80];
        uint32_t n;
        fg_aero_texture_desc d = desc2d(4, 1, 0.0, 5.0, dir, &n);
        fg_result want = FG_ERR_ARGUMENT;
        switch (k) {
        case 0: d.shape = (fg_aero_shape)9; break;
        case 1: d.tone = (fg_aero_tone)2; break;
        case 2: d.dims = 3; break;
        case 3: d.components = 3; break;
        case 4: d.speed_m_s = 0; break;
        case 5: d.speed_m_s = NAN; want = FG_ERR_NOT_FINITE; break;
        case 6: d.reynolds *= 1.01; break;
        case 7: d.sources = 2; break;
        case 8: d.directions = 0; break;
        case 9: dir[3].angle_rad = dir[2].angle_rad; break;          /* not increasing */
        case 10: dir[9].angle_rad = 50 * DEG; break;                  /* outside 0..45 */
        case 11: dir[0].frames = 0; break;
        case 12: dir[0].frames = FG_AERO_MAX_FRAMES + 1; break;
        case 13: dir[4].samples = bad_sample; want = FG_ERR_NOT_FINITE; break;
        case 14: dir[4].samples = NULL; want = FG_ERR_NULL; break;
        case 15: d.rotation_order = 13; break;
        case 16: d.mirror_angle_rad = FG_PI; break;                      /* beyond pi / 4 */
        case 17: d.height_m = 0; break;
        case 18: dir[2].periods = 0; break;
        }
        fg_aero_texture *t = (fg_aero_texture *)&d;
        fg_result r = fg_aero_texture_create(&d, &t);
        if (r != want)
            fail_msg("case %d: got %d, expected %d", k, r, want);
        assert_ptr_equal(t, (fg_aero_texture *)&d);
    }
    assert_int_equal(fg_aero_texture_create(NULL, NULL), FG_ERR_NULL);
    fg_aero_texture_destroy(NULL);
}

/* --- shapes ------------------------------------------------------------- */

static fg_result body_of(const double *xy, uint32_t n, fg_aero_body *b)
{
    fg_aero_config c = {.shape = FG_AERO_POLYGON, .polygon_xy = xy, .polygon_vertices = n,
                        .speed_m_s = 10};
    fg_aero_check why;
    return fg_aero_body_init(b, &c, &why);
}

static void symmetry(void **state)
{
    (void)state;
    static const double square[] = {0, 0, 2, 0, 2, 2, 0, 2};                 /* anywhere */
    static const double rect[] = {3, 0, -1, 0, -1, 1, 3, 1};                 /* clockwise */
    static const double tri[] = {0, 1, -0.8660254037844386, -0.5, 0.8660254037844386, -0.5};
    static const double isoceles[] = {0, 2, -0.5, 0, 0.5, 0};               /* axis at 90 */
    static const double lopsided[] = {0, 0, 3, 0, 2.5, 1, 0.3, 1.4};
    /* a sword's cross-section: a flattened hexagon, thicker to one side */
    static const double blade[] = {-0.02, 0, -0.012, -0.002, 0.012, -0.002, 0.02, 0,
                                   0.012, 0.002, -0.012, 0.002};
    static const struct {
        const double *xy;
        uint32_t n, order, mirror;
        double beta_deg;
        uint32_t directions;
    } cases[] = {{square, 4, 4, 1, 0, 10},   {rect, 4, 2, 1, 0, 19},
                 {tri, 3, 3, 1, 30, 13},      {isoceles, 3, 1, 1, 90, 37},
                 {lopsided, 4, 1, 0, 0, 72},  {blade, 6, 2, 1, 0, 19}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        fg_aero_body b;
        assert_int_equal(body_of(cases[k].xy, cases[k].n, &b), FG_OK);
        if (b.rotation_order != cases[k].order || b.mirror != cases[k].mirror ||
            fabs(b.mirror_angle_rad / DEG - cases[k].beta_deg) > 1e-6)
            fail_msg("case %zu: order %u mirror %u at %g deg", k, b.rotation_order, b.mirror,
                     b.mirror_angle_rad / DEG);
        fg_aero_config c = {0};
        double angles[FG_AERO_MAX_DIRECTIONS];
        assert_int_equal(fg_aero_body_directions(&b, &c, angles), cases[k].directions);
        /* centred on the area centroid, counter-clockwise */
        double cx = 0, cy = 0, area = 0;
        for (uint32_t i = 0; i < b.vertices; i++) {
            uint32_t j = (i + 1) % b.vertices;
            double w = b.polygon[2 * i] * b.polygon[2 * j + 1] - b.polygon[2 * j] * b.polygon[2 * i + 1];
            area += 0.5 * w;
            cx += (b.polygon[2 * i] + b.polygon[2 * j]) * w;
            cy += (b.polygon[2 * i + 1] + b.polygon[2 * j + 1]) * w;
        }
        assert_true(area > 0 && fabs(cx) < 1e-12 && fabs(cy) < 1e-12);
        fg_aero_body_deinit(&b);
    }
    /* given angles, mapped into the range, repeats dropped */
    fg_aero_body b;
    assert_int_equal(body_of(square, 4, &b), FG_OK);
    double given[] = {100 * DEG, 10 * DEG, 80 * DEG, 30 * DEG}, angles[FG_AERO_MAX_DIRECTIONS];
    fg_aero_config c = {.directions_rad = given, .direction_count = 4};
    assert_int_equal(fg_aero_body_directions(&b, &c, angles), 2);
    assert_float_equal(angles[0], 10 * DEG, 1e-12);
    assert_float_equal(angles[1], 30 * DEG, 1e-12);
    /* the frontal width: the side at 0 degrees, the diagonal at 45 */
    assert_float_equal(fg_aero_body_frontal(&b, 0.0), 2.0, 1e-12);
    assert_float_equal(fg_aero_body_frontal(&b, 45 * DEG), 2.0 * sqrt(2.0), 1e-12);
    fg_aero_body_deinit(&b);
}

/* Shapes refused, and the sizes a config must have. */
static void shape_checks(void **state)
{
    (void)state;
    static const double bowtie[] = {0, 0, 1, 1, 1, 0, 0, 1};
    static const double repeated[] = {0, 0, 1, 0, 1, 0, 0, 1};
    static const double flat[] = {0, 0, 1, 0, 2, 0};
    static const double touching[] = {0, 0, 2, 0, 2, 2, 1, 0, 0, 2}; /* a vertex on an edge */
    static const double nan_xy[] = {0, 0, 1, 0, NAN, 1};
    static const struct {
        const double *xy;
        uint32_t n;
        fg_result want;
        fg_aero_polygon_fault fault;
        uint32_t index, other;
    } polys[] = {{bowtie, 4, FG_ERR_ARGUMENT, FG_AERO_POLYGON_CROSSING, 0, 2},
                 {repeated, 4, FG_ERR_ARGUMENT, FG_AERO_POLYGON_REPEATED, 2, 0},
                 {flat, 3, FG_ERR_ARGUMENT, FG_AERO_POLYGON_NO_AREA, 0, 0},
                 {touching, 5, FG_ERR_ARGUMENT, FG_AERO_POLYGON_CROSSING, 0, 2},
                 {nan_xy, 3, FG_ERR_NOT_FINITE, FG_AERO_POLYGON_NOT_FINITE, 2, 0},
                 {bowtie, 2, FG_ERR_ARGUMENT, FG_AERO_POLYGON_COUNT, 2, 0},
                 {NULL, 4, FG_ERR_NULL, FG_AERO_POLYGON_OK, 0, 0},
                 {bowtie, FG_AERO_MAX_POLYGON + 1, FG_ERR_ARGUMENT, FG_AERO_POLYGON_COUNT,
                  FG_AERO_MAX_POLYGON + 1, 0}};
    for (size_t k = 0; k < sizeof polys / sizeof polys[0]; k++) {
        fg_aero_config c = {.shape = FG_AERO_POLYGON, .polygon_xy = polys[k].xy,
                            .polygon_vertices = polys[k].n, .speed_m_s = 10};
        fg_aero_check why;
        fg_result r = fg_aero_config_check(&c, &why);
        if (r != polys[k].want || why.field != FG_AERO_FIELD_POLYGON ||
            why.polygon != polys[k].fault || why.index != polys[k].index ||
            why.other != polys[k].other)
            fail_msg("polygon %zu: got %d (fault %d at %u, %u), expected %d (fault %d at %u, %u)",
                     k, r, why.polygon, why.index, why.other, polys[k].want, polys[k].fault,
                     polys[k].index, polys[k].other);
    }
    static const struct {
        fg_aero_config c;
        fg_result want;
        fg_aero_field field;
    } configs[] = {
        {{.shape = FG_AERO_CIRCLE, .speed_m_s = 10}, FG_ERR_ARGUMENT, FG_AERO_FIELD_SIZE}, /* no size */
        {{.shape = FG_AERO_CLUB, .length_m = 0.04, .diameter_m = {0.02, 0.05}, .speed_m_s = 10},
         FG_ERR_ARGUMENT, FG_AERO_FIELD_SIZE}, /* fatter than long */
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01}, FG_ERR_ARGUMENT, FG_AERO_FIELD_SPEED},
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = NAN}, FG_ERR_NOT_FINITE,
         FG_AERO_FIELD_SPEED},
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .cells_per_length = 2},
         FG_ERR_ARGUMENT, FG_AERO_FIELD_CELLS},
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .cfl = 5}, FG_ERR_ARGUMENT,
         FG_AERO_FIELD_CFL},
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .threads = 100},
         FG_ERR_ARGUMENT, FG_AERO_FIELD_THREADS},
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .sources = 4},
         FG_ERR_ARGUMENT, FG_AERO_FIELD_SOURCES},
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .sample_rate_hz = 100},
         FG_ERR_ARGUMENT, FG_AERO_FIELD_RATE}, /* < 8 a period */
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .direction_count = 3},
         FG_ERR_NULL, FG_AERO_FIELD_DIRECTIONS},
        {{.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .transient_s = 2,
          .max_transient_s = 1}, FG_ERR_ARGUMENT, FG_AERO_FIELD_MAX_TRANSIENT},
        {{.shape = FG_AERO_SPHERE, .length_m = 10, .speed_m_s = 10, .cells_per_length = 1000},
         FG_ERR_ARGUMENT, FG_AERO_FIELD_GRID}, /* over 2^27 cells */
        {{.shape = (fg_aero_shape)0, .length_m = 0.01, .speed_m_s = 10}, FG_ERR_ARGUMENT,
         FG_AERO_FIELD_SHAPE},
    };
    for (size_t k = 0; k < sizeof configs / sizeof configs[0]; k++) {
        fg_aero_texture *t = (fg_aero_texture *)&configs[k];
        fg_result r = fg_aero_generate(&configs[k].c, NULL, NULL, &t);
        fg_aero_check why;
        fg_result checked = fg_aero_config_check(&configs[k].c, &why);
        if (r != configs[k].want || checked != r || why.field != configs[k].field)
            fail_msg("config %zu: got %d (check %d, field %d), expected %d (field %d)", k, r,
                     checked, why.field, configs[k].want, configs[k].field);
        assert_ptr_equal(t, (fg_aero_texture *)&configs[k]);
    }
    assert_int_equal(fg_aero_generate(NULL, NULL, NULL, NULL), FG_ERR_NULL);
}

/* The club: zero distance at its two ends on the axis and at a tangent
 * point, and its silhouette area against the exact one: the trapezoid
 * between the four tangent points and the two circles' segments beyond. */
static void club(void **state)
{
    (void)state;
    fg_aero_config c = {.shape = FG_AERO_CLUB, .length_m = 0.5, .diameter_m = {0.03, 0.06},
                        .speed_m_s = 10};
    fg_aero_body b;
    fg_aero_check why;
    assert_int_equal(fg_aero_body_init(&b, &c, &why), FG_OK);
    double r0 = 0.015, r1 = 0.03, za = 0.015, zb = 0.47, len = zb - za;
    double s = (r1 - r0) / len, cs = sqrt(1 - s * s); /* the tangents' slope */
    double points[][3] = {{0, 0, 0}, {0, 0, 0.5}, {r0 * cs, 0, za - r0 * s}, {0, r1 * cs, zb - r1 * s}};
    for (int i = 0; i < 4; i++)
        assert_float_equal(fg_aero_body_sdf(points[i], &b), 0.0, 1e-12);
    double inside[3] = {0, 0, 0.25}, outside[3] = {0.05, 0, 0.25};
    assert_true(fg_aero_body_sdf(inside, &b) < -0.015);
    assert_true(fg_aero_body_sdf(outside, &b) > 0.0);
    assert_float_equal(b.reference_m, 0.06, 1e-15);
    double trapezoid = (r0 + r1) * cs * (len - (r1 - r0) * s);
    double segment_a = r0 * r0 * (acos(s) - s * cs);              /* the smaller segment */
    double segment_b = FG_PI * r1 * r1 - r1 * r1 * (acos(s) - s * cs); /* the larger one */
    double exact = trapezoid + segment_a + segment_b;
    double area = fg_aero_body_area(&b);
    print_message("club silhouette %.6e m^2, exact %.6e (%+.4f %%)\n", area, exact,
                  100 * (area / exact - 1));
    assert_float_equal(area / exact, 1.0, 1e-3);
    fg_aero_body_deinit(&b);
}

/* --- the loop ----------------------------------------------------------- */

/* A shedding-like signal: f0 with a third harmonic, a slow wander and a
 * ripple near 8 f0 (a shear layer's, which would add crossings of the
 * mean); the drag at 2 f0. */
static double signal(double t, double f0, int drag)
{
    double w = 2.0 * FG_PI * f0 * t;
    if (drag)
        return 1.3 + 0.05 * cos(2.0 * w + 0.3);
    return 0.33 * sin(w) + 0.02 * sin(3.0 * w + 1.0) + 0.004 * sin(0.137 * w) +
           0.03 * sin(7.77 * w + 0.5);
}

static void period_and_loop(void **state)
{
    (void)state;
    double rate = 16000, f0 = 207.3;
    size_t n = 2600;
    double *x = malloc(n * sizeof(double)), *loop_x = malloc(n * sizeof(double));
    float *g = malloc(n * sizeof(float));
    for (size_t i = 0; i < n; i++)
        x[i] = signal(i / rate, f0, 0);
    double period = fg_aero_dominant_period(x, n, rate, 10, 4000);
    assert_float_equal(1.0 / period, f0, 0.001 * f0);
    fg_aero_loop loop;
    assert_int_equal(fg_aero_loop_plan(x, n, rate, 10, 4000, 24, &loop), 0);
    /* 2600 samples hold 33.7 periods of 77.2 samples: 24 asked for, 24 given */
    assert_int_equal(loop.periods, 24);
    assert_true(fabs(loop.frames - 24.0 * rate / f0) <= 0.25 * rate / f0);
    assert_int_equal(loop.fade, (uint32_t)lround(rate / f0));
    assert_int_equal(fg_aero_loop_plan(x, n, rate, 10, 4000, 0, &loop), 0);
    assert_int_equal(loop.periods, 32);
    fg_aero_loop_crossfade(x, &loop, loop_x);
    fg_aero_loop_derivative(loop_x, loop.frames, rate, g, 1);
    /* the seam's step is no larger than 1.5 x the largest step inside */
    double inside = 0.0;
    for (uint32_t i = 0; i + 1 < loop.frames; i++)
        inside = fmax(inside, fabs((double)g[i + 1] - g[i]));
    double seam = fabs((double)g[0] - g[loop.frames - 1]);
    print_message("seam step %.4g, largest step inside %.4g (%.2fx)\n", seam, inside,
                  seam / inside);
    assert_true(seam <= 1.5 * inside);
    /* g is the derivative: past the fade, close to the exact one */
    double worst = 0.0, w = 2.0 * FG_PI * f0;
    for (uint32_t i = loop.fade + 1; i + 1 < loop.frames; i++) {
        double t = i / rate, exact = 0.33 * w * cos(w * t) + 0.06 * w * cos(3 * w * t + 1.0) +
                                     0.004 * 0.137 * w * cos(0.137 * w * t) +
                                     0.03 * 7.77 * w * cos(7.77 * w * t + 0.5);
        worst = fmax(worst, fabs(g[i] - exact));
    }
    /* the centred difference's response sin(w dt) / (w dt) takes 6.6 % off
     * the ripple at 1.6 kHz (16 kHz rate): 4.7 % of the peak */
    assert_true(worst < 0.055 * 0.33 * w);
    /* too short for two periods and the fade: refused */
    assert_int_equal(fg_aero_loop_plan(x, 200, rate, 10, 4000, 0, &loop), -1);
    /* no oscillation: no period */
    for (size_t i = 0; i < n; i++)
        x[i] = 1.0;
    assert_true(fg_aero_dominant_period(x, n, rate, 10, 4000) == 0.0);
    /* noise alone: no clear peak either */
    uint64_t r = 1;
    for (size_t i = 0; i < n; i++) {
        r = r * 6364136223846793005ull + 1442695040888963407ull;
        x[i] = (double)(r >> 11) / 9007199254740992.0 - 0.5;
    }
    assert_true(fg_aero_dominant_period(x, n, rate, 10, 4000) == 0.0);
    free(x);
    free(loop_x);
    free(g);
}

/* The generator on two threads against one: the same texture, bit for
 * bit (each direction's flow is computed alone, whichever thread runs it),
 * and progress reported from the calling thread, its fraction rising to 1.
 * A coarse square prism (6 cells/D, 2 directions, a short loop): seconds,
 * and the threads are what ThreadSanitizer watches here. */
typedef struct progress_log {
    int calls;
    double last;
    int fell;
} progress_log;

static void on_progress(const fg_aero_progress *p, void *user)
{
    progress_log *log = user;
    log->fell |= p->fraction < log->last - 0.35; /* estimates may be revised, not collapse */
    log->last = p->fraction;
    log->calls++;
    assert_true(p->directions == 2 && p->directions_done <= 2);
}

static void threads(void **state)
{
    (void)state;
    double angles[2] = {0.0, 30 * DEG};
    fg_aero_config c = {.shape = FG_AERO_RECTANGLE, .length_m = 0.01, .speed_m_s = 0.2,
                        .cells_per_length = 6, .domain = {4, 6, 3}, .transient_s = 1.5,
                        .seconds = 0.5, .directions_rad = angles, .direction_count = 2};
    fg_aero_texture *one, *two;
    progress_log log = {0};
    c.threads = 1;
    assert_int_equal(fg_aero_generate(&c, NULL, NULL, &one), FG_OK);
    c.threads = 2;
    assert_int_equal(fg_aero_generate(&c, on_progress, &log, &two), FG_OK);
    const fg_aero_texture_desc *a = fg_aero_texture_get(one), *b = fg_aero_texture_get(two);
    assert_int_equal(a->directions, 2);
    assert_int_equal(b->directions, 2);
    for (uint32_t i = 0; i < 2; i++) {
        assert_int_equal(a->direction[i].frames, b->direction[i].frames);
        assert_memory_equal(a->direction[i].samples, b->direction[i].samples,
                            (size_t)a->direction[i].frames * 2 * sizeof(float));
        assert_true(a->direction[i].strouhal > 0.1 && a->direction[i].strouhal < 0.3);
    }
    assert_true(log.calls >= 1 && !log.fell);
    assert_float_equal(log.last, 1.0, 1e-9);
    fg_aero_texture_destroy(one);
    fg_aero_texture_destroy(two);
}

/* Below Re 47 a cylinder does not shed (Fey et al.'s law starts there):
 * the direction is quiet, frequency 0, and its g is the steady force's
 * small fluctuation; a texture all the same, not an error. */
static void quiet(void **state)
{
    (void)state;
    double D = 0.01, v0 = 30 * 1.5e-5 / D; /* Re 30 */
    fg_aero_config c = {.shape = FG_AERO_CIRCLE, .length_m = D, .speed_m_s = v0,
                        .cells_per_length = 6, .domain = {4, 6, 3}, .transient_s = 10 * D / v0,
                        .max_transient_s = 20 * D / v0, .seconds = 10 * D / v0};
    fg_aero_texture *t;
    assert_int_equal(fg_aero_generate(&c, NULL, NULL, &t), FG_OK);
    const fg_aero_direction *d = &fg_aero_texture_get(t)->direction[0];
    assert_true(d->frequency_hz == 0.0 && d->strouhal == 0.0 && d->periods == 0);
    assert_true(d->frames > 0 && d->drag_mean > 1.5); /* a steady drag; 2.3 at 6 cells/D
                                                          between close walls */
    /* g of the lift: against what a shedding cylinder's would be, 2 pi f L */
    double q = 0.5 * 1.204 * v0 * v0 * D, shedding = 2 * FG_PI * 0.2 * v0 / D * 0.3 * q, most = 0;
    for (uint32_t i = 0; i < d->frames; i++)
        most = fmax(most, fabs(d->samples[2 * i + 1]));
    print_message("quiet: drag %.3f, largest lift g %.3g of a shedding one's\n", d->drag_mean,
                  most / shedding);
    assert_true(most < 0.1 * shedding); /* measured 0.047: the start-up still fading */
    fg_aero_texture_destroy(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lookup),         cmocka_unit_test(level_law),
        cmocka_unit_test(texture_checks), cmocka_unit_test(symmetry),
        cmocka_unit_test(shape_checks),   cmocka_unit_test(club),
        cmocka_unit_test(period_and_loop), cmocka_unit_test(threads),
        cmocka_unit_test(quiet),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
