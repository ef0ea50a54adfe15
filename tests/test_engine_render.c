/* The engine's output equals the sum of independently computed WM-waves:
 * geometry, return-stroke timing and the block scheduler are checked
 * against a direct evaluation of every segment, for a still listener, for
 * block sizes that split waveforms anywhere. (A moving listener is checked
 * against a per-sample reference in test_moving_listener.c.) */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fulgur/fulgur.h"
#include "sound/wmwave_internal.h"
#include "spatial/spherical_head_internal.h"
#include "wm_reference.h"

#define FS 48000.0
#define C 343.0
#define NODES 40
#define FRAMES 9600
#define HALF_SPACING 0.0875 /* the default head's radius */

typedef struct scene {
    fg_node nodes[NODES];
    fg_sound_config sound;
    double emit_s;
} scene;

/* A bent chain with a side branch: root at the top, strike node last on
 * the chain (farthest from the root). */
static void make_scene(scene *s)
{
    for (int i = 0; i < 30; i++)
        s->nodes[i] = (fg_node){0.02 * sin(0.7 * i), 1.0 + 0.01 * i, 2.0 - 0.03 * i, i - 1, 0};
    for (int i = 30; i < NODES; i++) {
        int parent = i == 30 ? 12 : i - 1;
        s->nodes[i] = (fg_node){0.015 * (i - 29), 1.1 + 0.004 * (i - 29), s->nodes[12].z - 0.01 * (i - 29),
                                parent, 0};
    }
    assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &s->sound), FG_OK);
    s->sound.t0_jitter = 0;
    /* the slowest the engine accepts: up to 11 us (half a sample) along the
     * chain, a shift the 1e-5 comparison with the direct sum resolves */
    s->sound.return_stroke_speed_m_s = FG_SOUND_MIN_RETURN_STROKE_M_S;
    s->emit_s = 0.01;
}

static double dist(const fg_node *a, const fg_node *b)
{
    return sqrt((a->x - b->x) * (a->x - b->x) + (a->y - b->y) * (a->y - b->y) +
                (a->z - b->z) * (a->z - b->z));
}

/* Path length from the strike node (29) to node k: down the chain, or via
 * the junction 12 for the branch. */
static double to_strike(const scene *s, int k)
{
    double chain[NODES] = {0};
    for (int i = 1; i < 30; i++)
        chain[i] = chain[i - 1] + dist(&s->nodes[i], &s->nodes[i - 1]);
    if (k < 30)
        return chain[29] - chain[k];
    double d = chain[29] - chain[12];
    for (int i = 30; i <= k; i++)
        d += dist(&s->nodes[i], &s->nodes[s->nodes[i].parent]);
    return d;
}

/* Adds segment i's wave for an ear at e on the head centred at centre
 * (the way around it: spatial/spherical_head_internal.h) into out[0..n),
 * with out[0] at frame first. */
static void add_segment(const scene *s, int i, const double e[3], const double centre[3],
                        double first, double *out, size_t n)
{
    const fg_node *a = &s->nodes[i], *b = &s->nodes[s->nodes[i].parent];
    double mid[3] = {(a->x + b->x) / 2, (a->y + b->y) / 2, (a->z + b->z) / 2};
    double len = dist(a, b);
    double d[3] = {e[0] - mid[0], e[1] - mid[1], e[2] - mid[2]};
    double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double sn = fabs(d[0] * (a->x - b->x) + d[1] * (a->y - b->y) + d[2] * (a->z - b->z)) / (len * r);
    fg_wm_shape w = fg_wm_shape_at(&s->sound, s->sound.t0_s, r, sn, len / 2, C, NULL);
    w.b *= (len / 2) / s->sound.ref_half_len_m; /* the line integral */
    double emit = s->emit_s + 0.5 * (to_strike(s, i) + to_strike(s, s->nodes[i].parent)) /
                                  s->sound.return_stroke_speed_m_s;
    double u[3], zero[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        u[k] = (e[k] - centre[k]) / HALF_SPACING;
    double around = fg_head_excess_m(mid, centre, u, HALF_SPACING, zero, zero, NULL);
    fg_wm_event ev = {w, (emit + (r + around) / C) * FS - first, FS * (len / 2) / C};
    ref_wm_add_direct(&ev, out, n);
}

static void ears_of(const fg_listener *p, double ears[2][3])
{
    /* right = forward x up, ears 0.175 m apart */
    double r[3] = {p->forward[1] * p->up[2] - p->forward[2] * p->up[1],
                   p->forward[2] * p->up[0] - p->forward[0] * p->up[2],
                   p->forward[0] * p->up[1] - p->forward[1] * p->up[0]};
    double norm = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; k++) {
        ears[0][k] = p->position[k] - HALF_SPACING * r[k] / norm;
        ears[1][k] = p->position[k] + HALF_SPACING * r[k] / norm;
    }
}

/* the still head */
static const fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};

/* Renders the scene in blocks of block frames, in chunks of chunk
 * (fg_engine_config.chunk_frames), against the reference; returns the
 * work units spent (fg_engine_report.work_units). */
static uint64_t run(uint32_t block, uint32_t chunk)
{
    scene s;
    make_scene(&s);
    fg_engine *e;
    fg_engine_config cfg = {.sample_rate_hz = FS,
                            .max_block_frames = 4096,
                            .speed_of_sound_m_s = C,
                            .chunk_frames = chunk};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    fg_discharge d = {.nodes = s.nodes, .node_count = NODES, .sound = s.sound,
                      .emit_time_s = s.emit_s, .strokes = 1, .seed = 7};
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);

    static float got[2][FRAMES];
    static double want[2][FRAMES];
    memset(want, 0, sizeof want);
    for (uint32_t at = 0; at < FRAMES; at += block) {
        uint32_t n = at + block <= FRAMES ? block : FRAMES - at;
        assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
        float *planes[2] = {&got[0][at], &got[1][at]};
        assert_int_equal(fg_engine_render(e, planes, n), FG_OK);
        double ears[2][3];
        ears_of(&head, ears);
        for (int ch = 0; ch < 2; ch++)
            for (int i = 1; i < NODES; i++)
                add_segment(&s, i, ears[ch], head.position, at, &want[ch][at], n);
    }
    double peak = 0, err = 0;
    for (int ch = 0; ch < 2; ch++)
        for (int k = 0; k < FRAMES; k++) {
            peak = fmax(peak, fabs(want[ch][k]));
            err = fmax(err, fabs(want[ch][k] - got[ch][k]));
        }
    assert_true(peak > 1e-3);
    assert_true(err <= 1e-5 * peak);
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.late_events, 0);
    assert_int_equal(st.finished, 1);
    fg_engine_destroy(e);
    return st.work_units;
}

/* Any block gives the reference, in chunks or without; and in chunks of
 * 4096 frames each ear's wave is visited once a chunk
 * (core/bus_internal.h), not once a block: the blocks of one frame cost
 * no more units than the 4096-frame blocks, in which every wave lies in
 * one block or two. Without chunks, visited every block, the 30-360-sample
 * waves cost tens of units each at one frame. */
static void still_listener_any_block(void **state)
{
    (void)state;
    static const uint32_t blocks[] = {4096, 1, 7, 64, 333};
    uint64_t whole = 0;
    for (size_t i = 0; i < sizeof blocks / sizeof blocks[0]; i++) {
        uint64_t units = run(blocks[i], 4096), unchunked = run(blocks[i], 0);
        print_message("blocks of %u: %llu units in chunks, %llu without\n", blocks[i],
                      (unsigned long long)units, (unsigned long long)unchunked);
        if (i == 0)
            whole = units;
        else
            assert_true(units <= whole);
        if (blocks[i] == 1)
            assert_true(unchunked > 10 * whole);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(still_listener_any_block),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
