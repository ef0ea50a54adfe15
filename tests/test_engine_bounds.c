/* The audio thread's bounds (docs/limits.md): the per-block work bound,
 * counted to the unit; repeats that find the block's work spent; the
 * repeat loop that ends; and finite output whatever a voice does: the
 * inputs that once turned into NaN, hung or leaked voices are refused and
 * leave a valid spark beside them bit-identical, a voice whose wave turns
 * non-finite on the audio thread is retired before it reaches a bus, and a
 * bus that receives a non-finite sample from a model outside the library
 * is dropped for the block without poisoning its filters. */
#define _POSIX_C_SOURCE 200809L /* alarm */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "core/source_internal.h"
#include "engine_fixture.h"
#include "fg_math.h"
#include "sound/discharge_internal.h"

#define FS 48000.0
#define BLOCK 256
#define FRAMES (282 * BLOCK) /* 1.5 s */

static float left_a[FRAMES], right_a[FRAMES], left_b[FRAMES], right_b[FRAMES];

static const fg_listener listener = {.position = {0, 0, 1.7}, .forward = {0, 1, 0},
                                     .up = {0, 0, 1}};

static fg_engine *engine(uint32_t voices, uint32_t block, uint32_t work_per_frame)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = block,
                            .max_voices = voices, .work_per_frame = work_per_frame};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    assert_int_equal(fg_engine_set_listener(e, &listener), FG_OK);
    return e;
}

/* A 2 cm spark of 4 segments 1 m ahead at emit_s, through Abe's FIR
 * (from 0.5 m on) or ISO 9613-1 absorption: its sound goes through a filter
 * bus shared by every voice, whose state a NaN would poison. */
static fg_node spark_nodes[5];

static fg_discharge spark(double emit_s, fg_absorption absorption)
{
    for (int i = 0; i < 5; i++)
        spark_nodes[i] = (fg_node){0.001 * sin(2.0 * i), 1.0, 1.71 - 0.005 * i, i - 1, 0};
    fg_discharge d = {.nodes = spark_nodes, .node_count = 5, .emit_time_s = emit_s,
                      .strokes = 1, .seed = 3,
                      .propagation = {.absorption = absorption, .abe_fir_distance_m = 0.5}};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    return d;
}

static void render_all(fg_engine *e, float *left, float *right)
{
    float *planes[2] = {left, right};
    for (size_t at = 0; at < FRAMES; at += BLOCK) {
        float *p[2] = {planes[0] + at, planes[1] + at};
        assert_int_equal(fg_engine_render(e, p, BLOCK), FG_OK);
        fg_engine_collect(e);
    }
}

static void assert_all_finite(const float *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(x[k]))
            fail_msg("sample %zu is not finite", k);
}

/* Renders the valid spark at 1 s alone, into the a planes. */
static void valid_alone(fg_absorption absorption)
{
    fg_engine *e = engine(8, BLOCK, 0);
    fg_discharge d = spark(1.0, absorption);
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    render_all(e, left_a, right_a);
    fg_engine_destroy(e);
    assert_true(fx_peak(left_a, FRAMES) > 0.01f); /* a click at 1 m, low-passed */
}

/* ---- hostile inputs at the post -------------------------------------- */

typedef struct hostile_case {
    const char *name;
    void (*make)(fg_discharge *d, fg_node *n);
    fg_result want;
} hostile_case;

/* node 0 lies at x = 0, where such small differences are representable */
static void segment_1e160(fg_discharge *d, fg_node *n)
{
    n[1] = (fg_node){1e-160, n[0].y, n[0].z, 0, 0};
    (void)d;
}

static void segment_1e162(fg_discharge *d, fg_node *n)
{
    n[1] = (fg_node){1e-162, n[0].y, n[0].z, 0, 0};
    (void)d;
}

static void t0_1e308(fg_discharge *d, fg_node *n)
{
    (void)n;
    d->sound.t0_s = 1e-308;
}

static void slow_return_stroke(fg_discharge *d, fg_node *n)
{
    (void)n;
    d->sound.return_stroke_speed_m_s = 1e-300;
}

static void repeat_1e300(fg_discharge *d, fg_node *n)
{
    (void)n;
    d->continuous = 1;
    d->strokes = 1;
    d->repeat_min_s = d->repeat_max_s = 1e-300;
    d->duration_s = 0.1;
}

static const hostile_case hostile[] = {
    {"a 1e-160 m segment (NaN into the ISO buses)", segment_1e160, FG_ERR_TREE},
    {"a 1e-162 m segment (a voice that never ends)", segment_1e162, FG_ERR_TREE},
    {"T0 = 1e-308 s", t0_1e308, FG_ERR_ARGUMENT},
    {"a return stroke at 1e-300 m/s", slow_return_stroke, FG_ERR_ARGUMENT},
    {"repeats every 1e-300 s (render never returned)", repeat_1e300, FG_ERR_ARGUMENT},
};

/* Each hostile discharge at 0 s, eight times into an eight-voice engine,
 * then the valid spark at 1 s: the hostile ones are refused with their
 * code, the spark is accepted (no voice leaked) and renders bit-identical
 * to the spark alone. */
static void hostile_leaves_valid_identical(void **state)
{
    (void)state;
    valid_alone(FG_ABSORPTION_ABE_FIR);
    for (size_t ci = 0; ci < sizeof hostile / sizeof hostile[0]; ci++) {
        const hostile_case *hc = &hostile[ci];
        fg_engine *e = engine(8, BLOCK, 0);
        for (int k = 0; k < 8; k++) {
            fg_discharge d = spark(0.0, FG_ABSORPTION_ABE_FIR);
            fg_node n[5];
            memcpy(n, spark_nodes, sizeof n);
            d.nodes = n;
            hc->make(&d, n);
            fg_result r = fg_engine_post(e, &d, NULL);
            if (r != hc->want)
                fail_msg("%s: post returned %d (%s), not %d", hc->name, r, fg_result_str(r),
                         hc->want);
        }
        fg_discharge d = spark(1.0, FG_ABSORPTION_ABE_FIR);
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        render_all(e, left_b, right_b);
        fg_engine_report rep;
        fg_engine_get_report(e, &rep);
        fg_engine_destroy(e);
        if (memcmp(left_a, left_b, sizeof left_a) || memcmp(right_a, right_b, sizeof right_a))
            fail_msg("%s: the valid spark beside it renders differently", hc->name);
        assert_int_equal(rep.posted, 1);
        assert_int_equal(rep.collected, 1);
        assert_int_equal(rep.dropped_posts, 0);
    }
}

/* ---- a wave that turns non-finite on the audio thread ---------------- */

/* A second spark, 2 m to the left at 0.5 s, whose first event is made to
 * lie at NaN after its post (as memory gone bad would), with its geometry
 * due again on the audio thread: the voice is retired there before it adds
 * a sample, counted, and collected; the valid spark renders as alone. */
static void non_finite_voice_retired(void **state)
{
    (void)state;
    valid_alone(FG_ABSORPTION_ISO9613);
    fg_engine *e = engine(8, BLOCK, 0);
    fg_discharge bad = spark(0.5, FG_ABSORPTION_ISO9613);
    fg_node n[5];
    for (int i = 0; i < 5; i++)
        n[i] = (fg_node){spark_nodes[i].x - 2.0, spark_nodes[i].y, spark_nodes[i].z,
                         spark_nodes[i].parent, 0};
    bad.nodes = n;
    fg_voice_id id;
    assert_int_equal(fg_engine_post(e, &bad, &id), FG_OK);
    fg_discharge_voice *v = fg_engine_voice_state(e, id, &fg_discharge_kind);
    assert_non_null(v);
    v->events[0].mid[0] = NAN;
    v->events[0].serial ^= 2u; /* not the pose's: recomputed at its first block */
    fg_discharge good = spark(1.0, FG_ABSORPTION_ISO9613);
    assert_int_equal(fg_engine_post(e, &good, NULL), FG_OK);
    render_all(e, left_b, right_b);
    fg_engine_report rep;
    fg_engine_get_report(e, &rep);
    fg_engine_destroy(e);
    assert_int_equal(rep.non_finite_voices, 1);
    assert_int_equal(rep.non_finite_blocks, 0);
    assert_int_equal(rep.finished, 2);
    assert_int_equal(rep.collected, 2);
    assert_all_finite(left_b, FRAMES);
    assert_memory_equal(left_a, left_b, sizeof left_a);
    assert_memory_equal(right_a, right_b, sizeof right_a);
}

/* ---- the last guard: a model outside the library writes NaN ---------- */

typedef struct nan_voice {
    uint32_t blocks_left;
} nan_voice;

static fg_result nan_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                             const fg_post_context *post)
{
    (void)ops;
    (void)post;
    ((nan_voice *)voice)->blocks_left = *(const uint32_t *)desc;
    return FG_OK;
}

static void nan_adopt(void *voice, const fg_block_context *block)
{
    (void)voice;
    (void)block;
}

/* NaN into sample 7 of the FIR bus and its shadowed twin, both ears */
static bool nan_render(void *voice, bool stopping, const fg_block_context *block)
{
    (void)stopping;
    nan_voice *v = voice;
    for (unsigned b = FG_BUS_FIR; b < block->buses->count; b += FG_BUS_PLAIN)
        for (unsigned ch = 0; ch < block->ears->count; ch++)
            fg_bus_pre(block->buses, b, ch)[7] = NAN;
    return --v->blocks_left == 0;
}

static const fg_source_kind nan_kind = {.name = "test nan", .voice_bytes = sizeof(nan_voice)};
static const fg_source_ops nan_ops = {
    .name = "nan", .kind = &nan_kind, .prepare = nan_prepare, .adopt = nan_adopt,
    .render = nan_render};

/* Three blocks of NaN on the FIR buses, then the valid spark at 1 s
 * through that same FIR: every dropped block is counted, the output stays
 * finite, and the spark renders as alone (the FIR kept its state). */
static void bus_guard_keeps_filters(void **state)
{
    (void)state;
    valid_alone(FG_ABSORPTION_ABE_FIR);
    const fg_source_kind *kinds[] = {&nan_kind};
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = BLOCK, .max_voices = 8};
    fg_engine *e;
    assert_int_equal(fg_engine_create_with(&cfg, kinds, 1, &e), FG_OK);
    assert_int_equal(fg_engine_set_listener(e, &listener), FG_OK);
    fg_discharge good = spark(1.0, FG_ABSORPTION_ABE_FIR);
    assert_int_equal(fg_engine_post(e, &good, NULL), FG_OK);
    uint32_t blocks = 3;
    assert_int_equal(fg_engine_post_source(e, &nan_ops, &blocks, NULL), FG_OK);
    render_all(e, left_b, right_b);
    fg_engine_report rep;
    fg_engine_get_report(e, &rep);
    fg_engine_destroy(e);
    assert_int_equal(rep.non_finite_blocks, 3 * 2 * 2); /* blocks x (FIR, twin) x ears */
    assert_all_finite(left_b, FRAMES);
    assert_all_finite(right_b, FRAMES);
    assert_memory_equal(left_a, left_b, sizeof left_a);
    assert_memory_equal(right_a, right_b, sizeof right_a);
}

/* ---- the work bound --------------------------------------------------- */

#define RING 5000

/* A closed ring of RING segments 1 m around the listener's centre: every
 * segment arrives within 0.3 ms of every other, all in the first block. */
static fg_node ring_nodes[RING + 1];

static fg_discharge ring(void)
{
    for (int i = 0; i <= RING; i++) {
        double a = 2.0 * FG_PI * i / (RING + 0.5);
        ring_nodes[i] = (fg_node){cos(a), sin(a), 1.7, i - 1, 0};
    }
    fg_discharge d = {.nodes = ring_nodes, .node_count = RING + 1, .emit_time_s = 0,
                      .strokes = 1, .seed = 5};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    return d;
}

/* Blocks of 4096 frames with work_per_frame 1: 4096 + 4096 units a block.
 * The ring needs 2 ears x 5000 events. Block 0 plays events 0..4095 and
 * skips the rest (2 x 904 units); block 1, a chunk that follows block 0's
 * whole, does not visit those 4096 (written to their end) and finds the
 * 904 ended. 1808 units skipped, to the unit; with the default bound
 * none. (Visited every block, the 4096 would spend block 1 again and skip
 * the 904 once more.) */

static void work_bound_counted(void **state)
{
    (void)state;
    enum { BIG = 4096 };
    static float l[3 * BIG], r[3 * BIG];
    float *planes[2] = {l, r};
    static float full_l[3 * BIG];
    uint64_t skipped[2];
    for (int bounded = 0; bounded < 2; bounded++) {
        fg_engine *e = engine(4, BIG, bounded ? 1 : 0);
        fg_discharge d = ring();
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        fx_render(e, planes, 2, 3 * BIG, BIG);
        fg_engine_report rep;
        fg_engine_get_report(e, &rep);
        fg_engine_destroy(e);
        assert_int_equal(rep.finished, 1);
        skipped[bounded] = rep.skipped_work;
        assert_all_finite(l, 3 * BIG);
        if (!bounded)
            memcpy(full_l, l, sizeof full_l);
    }
    assert_int_equal(skipped[0], 0);
    assert_int_equal(skipped[1], 2 * (RING - BIG));
    /* the 904 skipped events are missing from the sound */
    assert_true(memcmp(full_l, l, sizeof l) != 0);
}

/* A continuous spark rendered after the ring has spent the block: its
 * repeats due in that block are skipped and counted, though instance
 * slots are free; without the ring none is. */
static void repeats_skipped_when_work_spent(void **state)
{
    (void)state;
    enum { BIG = 4096 };
    static float l[BIG], r[BIG];
    float *planes[2] = {l, r};
    uint64_t skipped[2];
    for (int with_ring = 0; with_ring < 2; with_ring++) {
        fg_engine *e = engine(4, BIG, 1);
        if (with_ring) {
            fg_discharge d = ring();
            assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        }
        fg_discharge c = spark(0.0, FG_ABSORPTION_OFF);
        c.continuous = 1;
        c.repeat_min_s = c.repeat_max_s = 0.002;
        c.duration_s = 0.08;
        assert_int_equal(fg_engine_post(e, &c, NULL), FG_OK);
        fx_render(e, planes, 2, BIG, BIG);
        fg_engine_report rep;
        fg_engine_get_report(e, &rep);
        fg_engine_destroy(e);
        skipped[with_ring] = rep.skipped_repeats;
    }
    assert_int_equal(skipped[0], 0);
    /* 0.08 s of repeats every 2 ms, the first at 2 ms: 39 due in block 0 */
    assert_int_equal(skipped[1], 39);
}

/* Abe's series is priced by what it costs (docs/limits.md): one unit per
 * ear, and (harmonics + 16) / 32 units per sample it renders into each bus
 * of each channel, 16 harmonics: one unit a sample. Eight continuous
 * 24-node Abe voices 2-8 m away repeating every 0.1 ms, like the scene that
 * took 40 ms of CPU per 5.3 ms block when a unit stood for 32 samples: with
 * work_per_frame 8 no block spends more than 8 x 256 + 4096 units, the work
 * left undone is counted, and without the bound the same blocks need more
 * than it. */
#define ABE_NODES 24

static fg_node abe_nodes[8][ABE_NODES];

static void post_abe_voices(fg_engine *e)
{
    for (int v = 0; v < 8; v++) {
        for (int i = 0; i < ABE_NODES; i++)
            abe_nodes[v][i] =
                (fg_node){v - 3.5 + 0.05 * sin(1.7 * i), 2.0, 2.0 + 0.25 * i, i - 1, 0};
        fg_discharge d = {.nodes = abe_nodes[v], .node_count = ABE_NODES, .emit_time_s = 0,
                          .strokes = 1, .seed = (uint64_t)v + 1, .continuous = 1,
                          .repeat_min_s = FG_REPEAT_MIN_S, .repeat_max_s = FG_REPEAT_MIN_S,
                          .model = FG_MODEL_ABE};
        assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound), FG_OK);
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    }
}

static void abe_bound_holds_each_block(void **state)
{
    (void)state;
    float *planes[2] = {left_a, right_a};
    const uint64_t bound = 8 * BLOCK + FG_WORK_BLOCK_FLOOR;
    uint64_t peak[2], skipped[2];
    for (int bounded = 0; bounded < 2; bounded++) {
        fg_engine *e = engine(8, BLOCK, bounded ? 8 : FG_WORK_PER_FRAME_MAX);
        post_abe_voices(e);
        uint64_t before = 0, most = 0;
        /* unbounded, five blocks show the need (sound from the second on) */
        for (int b = 0; b < (bounded ? 100 : 5); b++) {
            assert_int_equal(fg_engine_render(e, planes, BLOCK), FG_OK);
            fg_engine_report rep;
            fg_engine_get_report(e, &rep);
            uint64_t spent = rep.work_units - before;
            before = rep.work_units;
            if (bounded)
                assert_true(spent <= bound);
            most = spent > most ? spent : most;
            assert_all_finite(left_a, BLOCK);
        }
        fg_engine_report rep;
        fg_engine_get_report(e, &rep);
        fg_engine_destroy(e);
        assert_int_equal(rep.peak_block_work, most);
        peak[bounded] = most;
        skipped[bounded] = rep.skipped_work;
    }
    assert_int_equal(skipped[0], 0);
    assert_true(peak[0] > 4 * bound); /* the scene needs far more than the bound */
    assert_true(skipped[1] > 0);
    assert_true(peak[1] > bound - 1000); /* the bound is spent, not left idle */
}

/* One Abe source (one segment) 20 m away heard through a 4096-frame block
 * it fills: each ear costs 1 + 4096 x (16 + 16) / 32 = 4097 units. With
 * work_per_frame 1 (4096 + 4096 units) the first ear fits and the second
 * is skipped and counted at its price; with the default both are spent. */
static void abe_price_counted(void **state)
{
    (void)state;
    enum { BIG = 4096 };
    static float l[BIG], r[BIG];
    float *planes[2] = {l, r};
    static fg_node two[2] = {{0, 20.0, 1.7, -1, 0}, {0, 20.0, 1.72, 0, 0}};
    uint64_t spent[2], skipped[2];
    for (int bounded = 0; bounded < 2; bounded++) {
        fg_engine *e = engine(1, BIG, bounded ? 1 : 0);
        fg_discharge d = {.nodes = two, .node_count = 2, .emit_time_s = 0, .strokes = 1,
                          .seed = 1, .model = FG_MODEL_ABE};
        assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound), FG_OK);
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        fx_render(e, planes, 2, BIG, BIG); /* arrives at 58 ms: part of block 0 */
        fg_engine_report before;
        fg_engine_get_report(e, &before);
        fx_render(e, planes, 2, BIG, BIG); /* 85 .. 171 ms: all of it sounds */
        fg_engine_report rep;
        fg_engine_get_report(e, &rep);
        fg_engine_destroy(e);
        spent[bounded] = rep.work_units - before.work_units;
        skipped[bounded] = rep.skipped_work - before.skipped_work;
    }
    assert_int_equal(spent[0], 2 * 4097);
    assert_int_equal(skipped[0], 0);
    assert_int_equal(spent[1], 4097);
    assert_int_equal(skipped[1], 4097);
}

/* The repeat loop's last guard: a voice whose next repeat lies where
 * adding an interval no longer moves the clock (1e17 s on, a state no
 * valid post reaches in a lifetime) ends its repeats instead of looping
 * for ever. The alarm fails the test if render does not return. */
static void repeat_loop_ends(void **state)
{
    (void)state;
    alarm(30);
    fg_engine *e = engine(4, BLOCK, 0);
    fg_discharge c = spark(FG_EMIT_NOW, FG_ABSORPTION_OFF);
    c.continuous = 1;
    fg_voice_id id;
    assert_int_equal(fg_engine_post(e, &c, &id), FG_OK);
    float *planes[2] = {left_b, right_b};
    fx_render(e, planes, 2, BLOCK, BLOCK);
    fg_discharge_voice *v = fg_engine_voice_state(e, id, &fg_discharge_kind);
    assert_non_null(v);
    v->next_repeat_s = 1e17;
    v->emit_frame = BLOCK - 2e17 * FS; /* its emission 2e17 s ago */
    fx_render(e, planes, 2, BLOCK, BLOCK);
    assert_true(v->next_repeat_s < 0);
    fg_engine_destroy(e);
    alarm(0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hostile_leaves_valid_identical),
        cmocka_unit_test(non_finite_voice_retired),
        cmocka_unit_test(bus_guard_keeps_filters),
        cmocka_unit_test(work_bound_counted),
        cmocka_unit_test(repeats_skipped_when_work_spent),
        cmocka_unit_test(abe_bound_holds_each_block),
        cmocka_unit_test(abe_price_counted),
        cmocka_unit_test(repeat_loop_ends),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
