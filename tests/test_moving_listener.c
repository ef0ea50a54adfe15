/* A moving listener hears each wave from where its ears are when the wave
 * arrives: the engine's output at any block size, with poses published as
 * a renderer or a 90 Hz VR host publishes them, against a per-sample
 * reference computed here from the path itself (the retarded time of every
 * sample edge, the geometry at every sample), and no high-frequency energy
 * gathered at block edges. A still listener, with the whole atmosphere on,
 * is unchanged by a host republishing its pose, at any block size. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "core/listener_internal.h"
#include "core/trajectory_internal.h"
#include "fulgur/fulgur.h"
#include "sound/wmwave_internal.h"
#include "spatial/spherical_head_internal.h"

#define FS 48000.0
#define C 343.0
#define SECONDS 3.0
#define FRAMES ((size_t)(SECONDS * FS))
#define SPEED 30.0
#define REPEAT_S 0.0037
#define HALF_SPACING 0.0875 /* the default head */

/* A vertical lightning segment of the preset's reference length, its
 * midpoint 11.5 m up; the listener drives past it, 20 m to the side. */
static const double mid[3] = {0.0, 0.0, 11.5};
static const double half_len = 1.5;

static fg_listener pose_at(double t)
{
    return (fg_listener){.position = {-45.0 + SPEED * t, 20.0, 1.7}, .forward = {0, -1, 0},
                         .up = {0, 0, 1}, .velocity = {SPEED, 0, 0}, .time_s = t};
}

/* ear 0 left, 1 right: right = forward x up = (-1, 0, 0) */
static void ear_at(int ch, double t, double out[3])
{
    fg_listener p = pose_at(t);
    double side = ch == 0 ? HALF_SPACING : -HALF_SPACING;
    out[0] = p.position[0] + side;
    out[1] = p.position[1];
    out[2] = p.position[2];
}

static double dist(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* The way from the source to ear ch at time t: the straight line, or
 * around the spherical head (spatial/spherical_head_internal.h). */
static double path_len(int ch, double t)
{
    fg_listener p = pose_at(t);
    double ear[3], u[3] = {ch == 0 ? 1.0 : -1.0, 0.0, 0.0}, zero[3] = {0, 0, 0};
    ear_at(ch, t, ear);
    return dist(ear, mid) + fg_head_excess_m(mid, p.position, u, HALF_SPACING, zero, zero, NULL);
}

/* Table 1's short lightning wave (T0 = 500 us): the hardest for continuity
 * at block edges, and the reference's +-200 samples hold all of it. */
static fg_sound_config sound(void)
{
    fg_sound_config p;
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING_TABLE1, &p), FG_OK);
    p.t0_jitter = 0;
    return p;
}

/* The repeating discharge: the first emission at 0, then every REPEAT_S
 * (summed as the engine sums them) until 0.9 SECONDS. */
static size_t emissions(double *at, size_t max)
{
    size_t n = 0;
    at[n++] = 0.0;
    for (double t = REPEAT_S; t < 0.9 * SECONDS && n < max; t += REPEAT_S)
        at[n++] = t;
    return n;
}

/* The reference: for every instance and sample, the wave's tau at the
 * sample's two edges from the retarded time (c (t - e) - r(ear(t))) / l,
 * the shape from the geometry at the sample's centre, the average the
 * integral's difference over the tau the sample spans. */
static void reference(double *out[2])
{
    fg_sound_config p = sound();
    const double l = half_len, emit_delay = 0.5 * 2.0 * l / p.return_stroke_speed_m_s;
    static double at[1024];
    size_t n = emissions(at, 1024);
    for (int ch = 0; ch < 2; ch++) {
        memset(out[ch], 0, FRAMES * sizeof(double));
        for (size_t i = 0; i < n; i++) {
            double e = at[i] + emit_delay, t = e;
            for (int it = 0; it < 50; it++) /* fixed point: v / c < 0.1 */
                t = e + path_len(ch, t) / C;
            long centre = lround(t * FS);
            for (long k = centre - 200; k <= centre + 200; k++) {
                if (k < 0 || k >= (long)FRAMES)
                    continue;
                double tc = k / FS, ta = (k - 0.5) / FS, tb = (k + 0.5) / FS, ec[3];
                ear_at(ch, tc, ec);
                double r = dist(ec, mid), s = fabs(ec[2] - mid[2]) / r;
                fg_wm_shape w = fg_wm_shape_at(&p, p.t0_s, r, s, l, C, NULL);
                double tau_a = (C * (ta - e) - path_len(ch, ta)) / l;
                double tau_b = (C * (tb - e) - path_len(ch, tb)) / l;
                out[ch][k] += (fg_wm_integral(&w, tau_b) - fg_wm_integral(&w, tau_a)) / (tau_b - tau_a);
            }
        }
    }
}

typedef enum publish {
    AHEAD_100HZ,     /* a renderer: 100 Hz poses 0.2 s ahead of the audio */
    VR_90HZ,         /* a VR host: at each 90 Hz frame, the next frame's pose */
    VR_90HZ_NO_VELOCITY,
} publish;

static float *planes_new(size_t frames)
{
    return calloc(frames, sizeof(float));
}

/* Renders the passing listener in blocks of `block`, publishing poses as
 * `how` says. */
static void render(uint32_t block, publish how, float *out[2])
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .speed_of_sound_m_s = C,
                            .max_block_frames = block};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_listener start = pose_at(0);
    assert_int_equal(fg_engine_set_listener(e, &start), FG_OK);
    fg_node nodes[2] = {{mid[0], mid[1], mid[2] + half_len, -1, 0},
                        {mid[0], mid[1], mid[2] - half_len, 0, 0}};
    fg_discharge d = {.nodes = nodes, .node_count = 2, .sound = sound(), .emit_time_s = 0,
                      .continuous = 1, .repeat_min_s = REPEAT_S, .repeat_max_s = REPEAT_S,
                      .duration_s = 0.9 * SECONDS, .seed = 3};
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    uint64_t next = 1;
    for (size_t at = 0; at < FRAMES; at += block) {
        uint32_t n = at + block <= FRAMES ? block : (uint32_t)(FRAMES - at);
        double now = at / FS;
        if (how == AHEAD_100HZ) {
            for (; next / 100.0 <= now + n / FS + 0.2; next++) {
                fg_listener p = pose_at(next / 100.0);
                assert_int_equal(fg_engine_set_listener(e, &p), FG_OK);
            }
        } else {
            for (; (next - 1) / 90.0 <= now; next++) {
                fg_listener p = pose_at(next / 90.0);
                if (how == VR_90HZ_NO_VELOCITY)
                    memset(p.velocity, 0, sizeof p.velocity);
                assert_int_equal(fg_engine_set_listener(e, &p), FG_OK);
            }
        }
        float *planes[2] = {out[0] + at, out[1] + at};
        assert_int_equal(fg_engine_render(e, planes, n), FG_OK);
        fg_engine_collect(e);
    }
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.late_events, 0);
    assert_int_equal(st.skipped_repeats, 0);
    fg_engine_destroy(e);
}

static double error_db(float *got[2], double *want[2])
{
    double err = 0, sig = 0;
    for (int ch = 0; ch < 2; ch++)
        for (size_t k = 0; k < FRAMES; k++) {
            double d = got[ch][k] - want[ch][k];
            err += d * d;
            sig += want[ch][k] * want[ch][k];
        }
    assert_true(sig > 0);
    return 10 * log10(err / sig);
}

/* High-frequency energy (first differences squared) on the first sample of
 * each block, against its mean over every position in the block. */
static double edge_ratio(float *x[2], uint32_t block)
{
    double *by = calloc(block, sizeof *by);
    for (int ch = 0; ch < 2; ch++)
        for (size_t k = 1; k < FRAMES; k++) {
            double d = (double)x[ch][k] - x[ch][k - 1];
            by[k % block] += d * d;
        }
    double mean = 0;
    for (uint32_t j = 0; j < block; j++)
        mean += by[j] / block;
    double r = by[0] / mean;
    free(by);
    return r;
}

static void moving_listener_any_block(void **state)
{
    (void)state;
    double *want[2] = {malloc(FRAMES * sizeof(double)), malloc(FRAMES * sizeof(double))};
    reference(want);
    static const struct {
        uint32_t block;
        publish how;
        const char *name;
    } cases[] = {
        {1, AHEAD_100HZ, "block 1, 100 Hz poses ahead"},
        {64, AHEAD_100HZ, "block 64, 100 Hz poses ahead"},
        {256, AHEAD_100HZ, "block 256, 100 Hz poses ahead"},
        {64, VR_90HZ, "block 64, 90 Hz frames"},
        {256, VR_90HZ, "block 256, 90 Hz frames"},
        {256, VR_90HZ_NO_VELOCITY, "block 256, 90 Hz frames without velocity"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        float *got[2] = {planes_new(FRAMES), planes_new(FRAMES)};
        render(cases[i].block, cases[i].how, got);
        double db = error_db(got, want);
        print_message("%s: error %.1f dB", cases[i].name, db);
        if (cases[i].block > 1) {
            double edge = edge_ratio(got, cases[i].block);
            print_message(", high-frequency energy at block edges %.2fx the mean\n", edge);
            assert_true(edge <= 2.0);
        } else {
            print_message("\n");
        }
        assert_true(db <= -40.0);
        free(got[0]);
        free(got[1]);
    }
    free(want[0]);
    free(want[1]);
}

/* Renders the bolt heard from a still head at 4 s in blocks of `block`,
 * the host republishing the pose before every block or only once. */
static void render_still(fg_tree *tree, uint32_t block, bool republish, size_t frames,
                         float *out[2])
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = block};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_listener head = {.position = {3, -2, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    fg_discharge d = {.nodes = fg_tree_nodes(tree), .node_count = fg_tree_count(tree),
                      .emit_time_s = 0.1, .strokes = 3, .seed = 9,
                      .propagation = {.refraction_radius_m = FG_REFRACTION_STORM_M,
                                      .turbulence_s = FG_TURBULENCE_DEFAULT_S,
                                      .absorption = FG_ABSORPTION_ISO9613,
                                      .ground_reflection = FG_GROUND_DEFAULT_REFLECTION,
                                      .head_shadow = 1}};
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), FG_OK);
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    for (size_t at = 0; at < frames; at += block) {
        uint32_t n = at + block <= frames ? block : (uint32_t)(frames - at);
        if (republish)
            assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
        float *planes[2] = {out[0] + at, out[1] + at};
        assert_int_equal(fg_engine_render(e, planes, n), FG_OK);
    }
    fg_engine_destroy(e);
}

/* A bolt of a few hundred segments with every effect on, a still
 * listener: a host republishing the still pose every block changes no
 * byte, and every block size gives the block-1 render to float rounding.
 * (Bytes differ across block sizes in the last bits, as before the
 * trajectory: the buses round per block; tests/sound_hashes.sh proves
 * the still renders unchanged.) */
static void still_listener_any_block(void **state)
{
    (void)state;
    fg_tree *tree;
    assert_int_equal(fg_tree_create(1024, &tree), FG_OK);
    fg_lightning_config lc = {.height_m = 600, .strike_m = {0, 400}, .seed = 5};
    assert_int_equal(fg_lightning_generate(&lc, tree, NULL), FG_OK);
    const size_t frames = (size_t)(4.0 * FS);
    float *first[2] = {planes_new(frames), planes_new(frames)};
    render_still(tree, 1, false, frames, first);
    double peak = 0;
    for (size_t k = 0; k < frames; k++)
        peak = fmax(peak, fabs(first[0][k]));
    assert_true(peak > 0.01);
    static const uint32_t blocks[] = {1, 7, 64, 256, 4096};
    for (size_t b = 0; b < sizeof blocks / sizeof blocks[0]; b++) {
        float *out[2] = {planes_new(frames), planes_new(frames)};
        float *again[2] = {planes_new(frames), planes_new(frames)};
        render_still(tree, blocks[b], true, frames, out);
        render_still(tree, blocks[b], false, frames, again);
        double err = 0;
        for (int ch = 0; ch < 2; ch++) {
            assert_memory_equal(out[ch], again[ch], frames * sizeof(float));
            for (size_t k = 0; k < frames; k++)
                err = fmax(err, fabs((double)out[ch][k] - first[ch][k]));
        }
        print_message("block %u: republished pose byte-identical, largest difference from "
                      "block 1 %.2g of the peak\n", blocks[b], err / peak);
        assert_true(err <= 1e-6 * peak);
        for (int ch = 0; ch < 2; ch++) {
            free(out[ch]);
            free(again[ch]);
        }
    }
    free(first[0]);
    free(first[1]);
    fg_tree_destroy(tree);
}

static fg_listener at_rest_at(double x, double t)
{
    return (fg_listener){.position = {x, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1},
                         .time_s = t};
}

/* The pose queue drops a pose at rest sent again only where the
 * trajectory holds the body at rest: not the first repeat of a pose
 * reached by moving (it would run on along the chord's velocity), nor a
 * repeat at the same time (it replaces the newest, which keeps its
 * chord); yes after a pose that replaced all the others, and after a
 * pose told at rest (velocity_given), reached by moving or not. */
static void pose_queue_repeats_at_rest(void **state)
{
    (void)state;
    static fg_pose_queue q;
    fg_listener a = at_rest_at(0, 0);
    fg_pose_queue_init(&q, &a);
    fg_listener p = at_rest_at(0, 0.01);
    assert_false(fg_pose_queue_push(&q, &p)); /* the first pose, alone */
    p = at_rest_at(1, 0.02);
    assert_true(fg_pose_queue_push(&q, &p)); /* moved: the chord from 0 */
    p.time_s = 0.03;
    assert_true(fg_pose_queue_push(&q, &p)); /* its first repeat stops it */
    p.time_s = 0.04;
    assert_false(fg_pose_queue_push(&q, &p));
    p = at_rest_at(2, 0.05);
    assert_true(fg_pose_queue_push(&q, &p));
    assert_true(fg_pose_queue_push(&q, &p)); /* same time: still the chord from 1 */
    p.time_s = 0.06;
    assert_true(fg_pose_queue_push(&q, &p));
    p.time_s = 0.07;
    assert_false(fg_pose_queue_push(&q, &p));
    p = at_rest_at(3, 0.0);
    assert_true(fg_pose_queue_push(&q, &p)); /* replaces every pose: alone */
    p.time_s = 0.08;
    assert_false(fg_pose_queue_push(&q, &p));
    fg_listener moving = at_rest_at(3, 0.09);
    moving.velocity[0] = 1.0;
    assert_true(fg_pose_queue_push(&q, &moving));
    assert_true(fg_pose_queue_push(&q, &moving)); /* moving poses are all published */
    p = at_rest_at(4, 0.10);
    p.velocity_given = 1;
    assert_true(fg_pose_queue_push(&q, &p)); /* moved, and told at rest: it stops here */
    p.time_s = 0.11;
    assert_false(fg_pose_queue_push(&q, &p));
    p.velocity_given = 0;
    p.time_s = 0.12;
    assert_false(fg_pose_queue_push(&q, &p)); /* the same, velocity not known */
}

static void absorb(const fg_listener *pose, uint64_t number, void *trajectory)
{
    fg_trajectory_push(trajectory, pose, number);
}

/* A body at rest whose pose is sent again every 10 ms until it moves: the
 * repeats are held back, and the latest of them is published just before
 * the first pose that moves, so the path rests until 0.1 s and moves
 * from there, not from the rest's first pose (0 s to 0.11 s, when the
 * queue published the move alone). */
static void pose_queue_rest_until_move(void **state)
{
    (void)state;
    static fg_pose_queue q;
    fg_listener a = at_rest_at(0, 0);
    fg_pose_queue_init(&q, &a);
    for (int k = 1; k <= 10; k++) {
        fg_listener p = at_rest_at(0, 0.01 * k);
        assert_false(fg_pose_queue_push(&q, &p));
    }
    fg_listener moving = at_rest_at(0.01, 0.11);
    moving.velocity[0] = 1.0;
    assert_true(fg_pose_queue_push(&q, &moving));
    static fg_trajectory path;
    fg_trajectory_init(&path, &a, 1);
    uint64_t seen = 1;
    fg_pose_queue_drain(&q, &seen, absorb, &path);
    assert_int_equal(seen, 3); /* the rest's latest repeat, then the move */
    for (int k = 0; k <= 20; k++) {
        fg_head h;
        fg_trajectory_head(&path, 0.005 * k, &h);
        assert_true(h.position[0] == 0.0 && h.velocity[0] == 0.0);
    }
    fg_head h;
    fg_trajectory_head(&path, 0.105, &h);
    assert_true(h.position[0] > 0.0 && h.position[0] < 0.01 && h.velocity[0] > 0.0);
    /* a pose that replaces the rest from an earlier time takes no repeat
     * along: nothing after it rested */
    fg_listener p = at_rest_at(0.01, 0.12);
    p.velocity_given = 1;
    assert_true(fg_pose_queue_push(&q, &p));
    p.time_s = 0.13;
    assert_false(fg_pose_queue_push(&q, &p));
    fg_listener back = at_rest_at(5, 0.125);
    assert_true(fg_pose_queue_push(&q, &back));
    fg_pose_queue_drain(&q, &seen, absorb, &path);
    assert_int_equal(seen, 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(moving_listener_any_block),
        cmocka_unit_test(still_listener_any_block),
        cmocka_unit_test(pose_queue_repeats_at_rest),
        cmocka_unit_test(pose_queue_rest_until_move),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
