/* The ambisonic layout (AmbiX: ACN, SN3D), orders 1 to 3.
 * - The encoder's gains against the real spherical harmonics computed
 *   independently, from the associated Legendre functions by their
 *   recurrence and the SN3D factor sqrt((2 - d_m0) (n - |m|)! / (n + |m|)!).
 * - A spark at a known direction decodes, by the first-order intensity
 *   vector (W times X, Y, Z summed over the render), to that direction
 *   within 5 degrees.
 * - The total encoded energy does not depend on the direction (within
 *   +-0.1 dB), for every order.
 * - Rotating the listener by theta renders what rotating the source by
 *   -theta renders.
 * - A head turning under a 90 Hz pose stream turns the field without a
 *   click, whatever the block size.
 * - Bad configurations are refused. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "engine_fixture.h"
#include "fulgur/fulgur.h"
#include "spatial/ambisonics_internal.h"

#define FS 48000.0
#define C 343.0
#define PI 3.14159265358979323846
#define FRAMES 1200
#define MAXCH 16

/* P_n^m(x) without the Condon-Shortley phase, m >= 0. */
static double legendre(int n, int m, double x)
{
    double pmm = 1.0, s = sqrt(fmax(0.0, 1.0 - x * x));
    for (int i = 1; i <= m; i++)
        pmm *= (2.0 * i - 1.0) * s;
    if (n == m)
        return pmm;
    double pm1 = x * (2.0 * m + 1.0) * pmm;
    if (n == m + 1)
        return pm1;
    double pn = 0.0;
    for (int l = m + 2; l <= n; l++) {
        pn = (x * (2.0 * l - 1.0) * pm1 - (l + m - 1.0) * pmm) / (l - m);
        pmm = pm1;
        pm1 = pn;
    }
    return pn;
}

static double factorial(int k)
{
    double f = 1.0;
    for (int i = 2; i <= k; i++)
        f *= i;
    return f;
}

/* SN3D real spherical harmonic, azimuth az (from x towards y), elevation el. */
static double sn3d(int n, int m, double az, double el)
{
    int am = abs(m);
    double norm = sqrt((m == 0 ? 1.0 : 2.0) * factorial(n - am) / factorial(n + am));
    double p = legendre(n, am, sin(el));
    return norm * p * (m > 0 ? cos(am * az) : m < 0 ? sin(am * az) : 1.0);
}

static void gains_are_the_sn3d_harmonics(void **state)
{
    (void)state;
    for (double az = -170.0; az < 180.0; az += 37.0) {
        for (double el = -80.0; el <= 80.0; el += 20.0) {
            double a = az * PI / 180.0, e = el * PI / 180.0;
            double dir[3] = {cos(e) * cos(a), cos(e) * sin(a), sin(e)}, g[MAXCH];
            fg_ambisonic_gains(dir, 3, g);
            for (int n = 0; n <= 3; n++) {
                double order_sum = 0.0;
                for (int m = -n; m <= n; m++) {
                    int acn = n * n + n + m;
                    double want = sn3d(n, m, a, e);
                    if (fabs(g[acn] - want) > 1e-12)
                        fail_msg("az %.0f el %.0f ACN %d: %.15f, want %.15f", az, el, acn,
                                 g[acn], want);
                    order_sum += g[acn] * g[acn];
                }
                assert_true(fabs(order_sum - 1.0) < 1e-12);
            }
        }
    }
}

typedef struct scene {
    unsigned order;
    double az_deg, el_deg, r_m;
    double forward[3];
} scene;

/* Renders a spark at (az, el, r) from a listener at the origin facing
 * forward (up +z). The segment lies across the line of sight, so every
 * direction hears it broadside. */
static unsigned render(const scene *sc, float **planes)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .speed_of_sound_m_s = C,
                            .max_block_frames = 256, .layout = FG_LAYOUT_AMBISONICS,
                            .ambisonic_order = sc->order};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_engine_config used;
    fg_engine_get_config(e, &used);
    unsigned channels = (sc->order + 1) * (sc->order + 1);
    assert_int_equal(used.channels, channels);
    fg_listener head = {.position = {0, 0, 0}, .forward = {1, 0, 0}, .up = {0, 0, 1}};
    if (sc->forward[0] != 0 || sc->forward[1] != 0)
        memcpy(head.forward, sc->forward, sizeof head.forward);
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    double a = sc->az_deg * PI / 180.0, el = sc->el_deg * PI / 180.0;
    double u[3] = {cos(el) * cos(a), cos(el) * sin(a), sin(el)};
    /* across the line of sight: u x (a vector not along u) */
    double t[3] = {-sin(a), cos(a), 0.0};
    fg_node nodes[2];
    fx_segment(nodes, (double[]){sc->r_m * u[0], sc->r_m * u[1], sc->r_m * u[2]}, t, 1e-3);
    fg_discharge d = {.nodes = nodes, .node_count = 2, .strokes = 1, .seed = 3};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    d.sound.t0_jitter = 0;
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    for (unsigned ch = 0; ch < channels; ch++)
        memset(planes[ch], 0, FRAMES * sizeof(float));
    fx_render(e, planes, channels, FRAMES, 256);
    fg_engine_destroy(e);
    return channels;
}

static float **alloc_planes(void)
{
    float **p = calloc(MAXCH, sizeof *p);
    for (int i = 0; i < MAXCH; i++)
        p[i] = calloc(FRAMES, sizeof **p);
    return p;
}

static void free_planes(float **p)
{
    for (int i = 0; i < MAXCH; i++)
        free(p[i]);
    free(p);
}

static double dot_planes(const float *a, const float *b)
{
    double s = 0.0;
    for (size_t i = 0; i < FRAMES; i++)
        s += (double)a[i] * b[i];
    return s;
}

static void intensity_decodes_to_the_direction(void **state)
{
    (void)state;
    float **p = alloc_planes();
    double worst = 0.0;
    for (unsigned order = 1; order <= 3; order++) {
        for (double az = -150.0; az <= 180.0; az += 30.0) {
            for (double el = -60.0; el <= 60.0; el += 30.0) {
                scene sc = {.order = order, .az_deg = az, .el_deg = el, .r_m = 2.0};
                render(&sc, p);
                /* ACN 1, 2, 3 are Y, Z, X */
                double ix = dot_planes(p[0], p[3]), iy = dot_planes(p[0], p[1]),
                       iz = dot_planes(p[0], p[2]);
                double a = az * PI / 180.0, e = el * PI / 180.0;
                double want[3] = {cos(e) * cos(a), cos(e) * sin(a), sin(e)};
                double len = sqrt(ix * ix + iy * iy + iz * iz);
                double c = (ix * want[0] + iy * want[1] + iz * want[2]) / len;
                double err = acos(fmin(1.0, c)) * 180.0 / PI;
                worst = fmax(worst, err);
                if (!(err < 5.0))
                    fail_msg("order %u az %.0f el %.0f: decoded %.2f deg off", order, az, el,
                             err);
            }
        }
    }
    print_message("intensity vector: worst %.2g deg off\n", worst);
    free_planes(p);
}

static void energy_does_not_depend_on_direction(void **state)
{
    (void)state;
    float **p = alloc_planes();
    for (unsigned order = 1; order <= 3; order++) {
        double lo = INFINITY, hi = -INFINITY;
        for (double az = -165.0; az <= 180.0; az += 30.0) {
            for (double el = -75.0; el <= 75.0; el += 25.0) {
                scene sc = {.order = order, .az_deg = az, .el_deg = el, .r_m = 2.0};
                unsigned n = render(&sc, p);
                double total = 0.0;
                for (unsigned ch = 0; ch < n; ch++)
                    total += fx_energy(p[ch], 0, FRAMES);
                double db = 10.0 * log10(total);
                lo = fmin(lo, db);
                hi = fmax(hi, db);
            }
        }
        print_message("order %u: total energy spread over directions %.4f dB\n", order, hi - lo);
        assert_true(hi - lo <= 0.2); /* +-0.1 dB */
        assert_true(isfinite(lo));
    }
    free_planes(p);
}

static void listener_rotation_is_source_counter_rotation(void **state)
{
    (void)state;
    float **a = alloc_planes(), **b = alloc_planes();
    static const double thetas[] = {30.0, 90.0, -135.0};
    for (size_t i = 0; i < 3; i++) {
        double th = thetas[i] * PI / 180.0;
        /* the listener turned by theta (counter-clockwise seen from above)
         * hears the source at azimuth az as the still listener hears it
         * at az - theta */
        scene turned = {.order = 3, .az_deg = 40.0, .el_deg = 20.0, .r_m = 3.0,
                        .forward = {cos(th), sin(th), 0}};
        scene moved = {.order = 3, .az_deg = 40.0 - thetas[i], .el_deg = 20.0, .r_m = 3.0};
        unsigned n = render(&turned, a);
        render(&moved, b);
        for (unsigned ch = 0; ch < n; ch++) {
            double peak = fx_peak(b[0], FRAMES), err = 0.0;
            for (size_t k = 0; k < FRAMES; k++)
                err = fmax(err, fabs(a[ch][k] - b[ch][k]));
            if (err > 1e-5 * peak)
                fail_msg("theta %.0f, ACN %u: differs by %.3g of the peak", thetas[i], ch,
                         err / peak);
        }
    }
    free_planes(a);
    free_planes(b);
}

/* A head turning at 180 degrees per second, its pose published by a 90 Hz
 * frame loop a frame ahead of the audio, with a spark repeating every
 * 3.7 ms 2 m away: rendered in blocks of 256 and of 37 frames, the two
 * agree (the field turns wave by wave, not block by block), and no block
 * edge carries more high-frequency energy than the samples between. */
#define TURN_RAD_S 3.14159265358979323846
#define TURN_FRAMES 48000

static void render_turning(uint32_t block, float **planes)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .speed_of_sound_m_s = C,
                            .max_block_frames = 256, .layout = FG_LAYOUT_AMBISONICS,
                            .ambisonic_order = 1};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_listener head = {.forward = {1, 0, 0}, .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    fg_node nodes[2];
    fx_segment(nodes, (double[]){0, 2.0, 0.3}, (double[]){1, 0, 0}, 1e-3);
    fg_discharge d = {.nodes = nodes, .node_count = 2, .seed = 3, .continuous = 1,
                      .repeat_min_s = 0.0037, .repeat_max_s = 0.0037, .duration_s = 0.9};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    d.sound.t0_jitter = 0;
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    unsigned frame = 1;
    for (uint32_t at = 0; at < TURN_FRAMES; at += block) {
        uint32_t n = TURN_FRAMES - at < block ? TURN_FRAMES - at : block;
        /* the frames due by this block's end publish the next frame's pose */
        for (; (frame - 1) / 90.0 <= (at + n) / FS; frame++) {
            double t = frame / 90.0, a = TURN_RAD_S * t;
            fg_listener p = {.forward = {cos(a), sin(a), 0}, .up = {0, 0, 1}, .time_s = t};
            assert_int_equal(fg_engine_set_listener(e, &p), FG_OK);
        }
        float *out[4] = {planes[0] + at, planes[1] + at, planes[2] + at, planes[3] + at};
        assert_int_equal(fg_engine_render(e, out, n), FG_OK);
    }
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.late_events, 0);
    fg_engine_destroy(e);
}

static void turning_head_is_click_free(void **state)
{
    (void)state;
    float *a[4], *b[4];
    for (int ch = 0; ch < 4; ch++) {
        a[ch] = calloc(TURN_FRAMES, sizeof(float));
        b[ch] = calloc(TURN_FRAMES, sizeof(float));
    }
    render_turning(256, a);
    render_turning(37, b);
    double err = 0, sig = 0, edge[256] = {0}, mean = 0;
    for (int ch = 0; ch < 4; ch++) {
        for (size_t k = 0; k < TURN_FRAMES; k++) {
            err += (a[ch][k] - b[ch][k]) * (a[ch][k] - (double)b[ch][k]);
            sig += (double)a[ch][k] * a[ch][k];
            if (k > 0) {
                double dd = (double)a[ch][k] - a[ch][k - 1];
                edge[k % 256] += dd * dd;
            }
        }
    }
    for (int j = 0; j < 256; j++)
        mean += edge[j] / 256;
    double db = 10 * log10(err / sig);
    print_message("turning head: blocks of 256 against 37 %.1f dB, high-frequency energy at "
                  "block edges %.2fx the mean\n", db, edge[0] / mean);
    assert_true(sig > 0);
    assert_true(db <= -60.0);
    assert_true(edge[0] / mean <= 2.0);
    /* the field did turn: the source, on the left at first (W Y > 0), is
     * on the right after half a turn (W Y < 0) */
    double early = 0, late = 0;
    for (size_t k = 0; k < 4800; k++) {
        early += (double)a[0][k] * a[1][k];
        late += (double)a[0][TURN_FRAMES - 4800 + k] * a[1][TURN_FRAMES - 4800 + k];
    }
    assert_true(early > 0 && late < 0);
    for (int ch = 0; ch < 4; ch++) {
        free(a[ch]);
        free(b[ch]);
    }
}

static void bad_configurations_are_refused(void **state)
{
    (void)state;
    fg_engine_config out, cfg = {.layout = FG_LAYOUT_AMBISONICS, .ambisonic_order = 4};
    assert_int_equal(fg_engine_config_resolve(&cfg, &out), FG_ERR_ARGUMENT);
    cfg.ambisonic_order = 2;
    cfg.channels = 4;
    assert_int_equal(fg_engine_config_resolve(&cfg, &out), FG_ERR_ARGUMENT);
    cfg.channels = 9;
    assert_int_equal(fg_engine_config_resolve(&cfg, &out), FG_OK);
    assert_int_equal(out.channels, 9);
    cfg.channels = 0;
    cfg.ambisonic_order = 0;
    assert_int_equal(fg_engine_config_resolve(&cfg, &out), FG_OK);
    assert_int_equal(out.ambisonic_order, 1);
    assert_int_equal(out.channels, 4);
    cfg = (fg_engine_config){.layout = FG_LAYOUT_STEREO, .ambisonic_order = 1};
    assert_int_equal(fg_engine_config_resolve(&cfg, &out), FG_ERR_ARGUMENT);
    cfg = (fg_engine_config){.layout = (fg_layout)7};
    assert_int_equal(fg_engine_config_resolve(&cfg, &out), FG_ERR_ARGUMENT);
    fg_engine *e = NULL;
    cfg = (fg_engine_config){.layout = FG_LAYOUT_AMBISONICS, .ambisonic_order = 9};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_ARGUMENT);
    assert_null(e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gains_are_the_sn3d_harmonics),
        cmocka_unit_test(intensity_decodes_to_the_direction),
        cmocka_unit_test(energy_does_not_depend_on_direction),
        cmocka_unit_test(listener_rotation_is_source_counter_rotation),
        cmocka_unit_test(turning_head_is_click_free),
        cmocka_unit_test(bad_configurations_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
