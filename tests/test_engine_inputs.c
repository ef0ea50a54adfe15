/* The bad-input sweep. Every call that takes input from outside is fed bad
 * values; each must return its documented code and change nothing: the
 * stats (but for dropped_posts where documented), the clock and the
 * listener are as before, and a following valid post and render give the
 * same id and the same output bytes as on an engine that never saw the bad
 * call (one given the same valid history). */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "engine_fixture.h"

#define CHECK(cond, ...)            \
    do {                            \
        if (!(cond))                \
            fail_msg(__VA_ARGS__);  \
    } while (0)

#define BLOCK 256
#define VOICES 3
#define SEGMENTS 64
#define VALID_NODES 6
#define REF_BLOCKS 3

static const fg_engine_config base_cfg = {
    .sample_rate_hz = 48000, .max_block_frames = BLOCK, .channels = 2,
    .max_voices = VOICES, .segment_capacity = SEGMENTS, .speed_of_sound_m_s = 343,
};

/* A short crackle about 0.6 m ahead, emitted at the block that adopts it:
 * it sounds within the next REF_BLOCKS blocks whatever came before. */
static void valid_tree(fg_node *n, size_t count)
{
    for (size_t i = 0; i < count; i++)
        n[i] = (fg_node){0.003 * sin(1.7 * i), 0.6, 0.01 * i, (int32_t)i - 1, 0};
}

static void valid_discharge(fg_discharge *d, fg_node *n)
{
    valid_tree(n, VALID_NODES);
    *d = (fg_discharge){.nodes = n, .node_count = VALID_NODES, .emit_time_s = FG_EMIT_NOW,
                        .strokes = 1, .seed = 9};
    fg_result r = fg_preset_sound(FG_PRESET_PLASMA_BALL, &d->sound);
    assert_int_equal(r, FG_OK);
}

static fg_result post_valid(fg_engine *e, fg_voice_id *id)
{
    fg_node n[VALID_NODES];
    fg_discharge d;
    valid_discharge(&d, n);
    return fg_engine_post(e, &d, id);
}

static void render_blocks(fg_engine *e, float out[2][REF_BLOCKS * BLOCK], int blocks)
{
    float *planes[2] = {out[0], out[1]};
    fx_render(e, planes, 2, (size_t)blocks * BLOCK, BLOCK);
}

/* --- valid histories ------------------------------------------------- */

static fg_voice_id history_id;

static void post_one(fg_engine *e)
{
    assert_int_equal(post_valid(e, &history_id), FG_OK);
}

static void post_and_render(fg_engine *e)
{
    static float scratch[2][REF_BLOCKS * BLOCK];
    post_one(e);
    render_blocks(e, scratch, 1);
}

static const fg_listener moved = {.position = {0.1, -0.2, 0.05}, .forward = {0.2, 1, 0},
                                  .up = {0, 0.1, 1}};

static void move_and_post(fg_engine *e)
{
    assert_int_equal(fg_engine_set_listener(e, &moved), FG_OK);
    post_one(e);
}

/* every voice posted (the inbox, rounded up to 4, still has room) */
static void fill_pool(fg_engine *e)
{
    for (int i = 0; i < VOICES; i++)
        post_one(e);
}

/* with max_voices = 2 the inbox ring holds 2: two posts not yet adopted
 * fill it */
static void fill_queue(fg_engine *e)
{
    post_one(e);
    post_one(e);
}

/* 50 of the 64 segments taken */
static void take_segments(fg_engine *e)
{
    fg_node n[51];
    valid_tree(n, 51);
    fg_discharge d = {.nodes = n, .node_count = 51, .emit_time_s = 0.001, .strokes = 1};
    assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound), FG_OK);
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
}

/* a voice played to the end and collected: its id is dead */
static void finish_and_collect(fg_engine *e)
{
    static float scratch[2][REF_BLOCKS * BLOCK];
    post_one(e);
    for (int i = 0; i < 4; i++)
        render_blocks(e, scratch, REF_BLOCKS);
    assert_int_equal(fg_engine_collect(e), 1);
}

/* --- bad calls ------------------------------------------------------- */

#define POST_BAD(fn, ...)                      \
    static fg_result fn(fg_engine *e)          \
    {                                          \
        fg_node n[VALID_NODES];                \
        fg_discharge d;                        \
        valid_discharge(&d, n);                \
        __VA_ARGS__;                                  \
        fg_voice_id id = 77;                   \
        fg_result r = fg_engine_post(e, &d, &id); \
        CHECK(id == 77, "a refused post wrote the id"); \
        return r;                              \
    }

static fg_result post_null_engine(fg_engine *e)
{
    (void)e;
    fg_node n[VALID_NODES];
    fg_discharge d;
    valid_discharge(&d, n);
    return fg_engine_post(NULL, &d, NULL);
}

static fg_result post_null_discharge(fg_engine *e)
{
    return fg_engine_post(e, NULL, NULL);
}

POST_BAD(post_null_nodes, d.nodes = NULL)
POST_BAD(post_nan_x, n[3].x = NAN)
POST_BAD(post_inf_z, n[5].z = INFINITY)
POST_BAD(post_nan_root, n[0].y = NAN)
POST_BAD(post_self_parent, n[3].parent = 3)
POST_BAD(post_forward_parent, n[2].parent = 4)
POST_BAD(post_cycle, {
    n[2].parent = 3;
    n[3].parent = 2;
})
POST_BAD(post_parent_minus2, n[4].parent = -2)
POST_BAD(post_root_has_parent, n[0].parent = 0)
POST_BAD(post_second_root, n[3].parent = -1)
POST_BAD(post_zero_length, n[4] = (fg_node){n[3].x, n[3].y, n[3].z, 3, 0})
POST_BAD(post_one_node, d.node_count = 1)
POST_BAD(post_no_nodes, d.node_count = 0)
POST_BAD(post_t0_zero, d.sound.t0_s = 0)
POST_BAD(post_t0_negative, d.sound.t0_s = -30e-6)
POST_BAD(post_ps0_nan, d.sound.ps0_pa = NAN)
POST_BAD(post_r0_inf, d.sound.r0_m = INFINITY)
POST_BAD(post_sigma_negative, d.sound.sigma0 = -0.1)
POST_BAD(post_jitter_one, d.sound.t0_jitter = 1.0)
POST_BAD(post_return_speed_zero, d.sound.return_stroke_speed_m_s = 0)
POST_BAD(post_strokes_33, d.strokes = FG_MAX_STROKES + 1)
POST_BAD(post_strokes_huge, d.strokes = UINT32_MAX)
POST_BAD(post_continuous_strokes, {
    d.continuous = 1;
    d.strokes = 2;
})
POST_BAD(post_emit_negative, d.emit_time_s = -0.5)
POST_BAD(post_emit_nan, d.emit_time_s = NAN)
POST_BAD(post_repeat_inverted, {
    d.continuous = 1;
    d.repeat_min_s = 0.04;
    d.repeat_max_s = 0.02;
})
POST_BAD(post_repeat_too_long, {
    d.continuous = 1;
    d.repeat_max_s = 11.0;
})
POST_BAD(post_repeat_nan, {
    d.continuous = 1;
    d.repeat_min_s = NAN;
})
POST_BAD(post_duration_negative, {
    d.continuous = 1;
    d.duration_s = -1.0;
})
/* the physical limits (docs/limits.md): each case once crashed, hung or
 * rendered NaN on the audio thread */
/* node 0 lies at x = 0, where such small differences are representable */
POST_BAD(post_segment_1e160, n[1] = (fg_node){1e-160, n[0].y, n[0].z, 0, 0})
POST_BAD(post_segment_1e162, n[1] = (fg_node){-1e-162, n[0].y, n[0].z, 0, 0})
POST_BAD(post_segment_1um_less, n[1] = (fg_node){0.99e-6, n[0].y, n[0].z, 0, 0})
POST_BAD(post_node_far, n[4].y = 1.0001e7)
POST_BAD(post_t0_1e308, d.sound.t0_s = 1e-308)
POST_BAD(post_t0_short, d.sound.t0_s = 0.99e-7)
POST_BAD(post_t0_long, d.sound.t0_s = 0.11)
POST_BAD(post_t0_5e289, d.sound.t0_s = 5e289)
POST_BAD(post_r0_far, d.sound.r0_m = 1001)
POST_BAD(post_ps0_huge, d.sound.ps0_pa = 1.01e7)
POST_BAD(post_sigma_huge, d.sound.sigma0 = 10.5)
POST_BAD(post_return_speed_tiny, d.sound.return_stroke_speed_m_s = 1e-300)
POST_BAD(post_return_speed_light, d.sound.return_stroke_speed_m_s = 3.1e8)
POST_BAD(post_repeat_1e300, {
    d.continuous = 1;
    d.repeat_min_s = 1e-300;
    d.repeat_max_s = 1e-300;
})
POST_BAD(post_repeat_1us, {
    d.continuous = 1;
    d.repeat_min_s = 1e-6;
})
POST_BAD(post_repeat_negative, {
    d.continuous = 1;
    d.repeat_min_s = -0.01;
})

/* more segments than the engine holds, ever: refused before the tree is
 * walked, so a wild count over a short array is safe */
static fg_result post_over_capacity(fg_engine *e)
{
    static fg_node n[SEGMENTS + 2];
    valid_tree(n, SEGMENTS + 2);
    fg_discharge d;
    fg_node small[VALID_NODES];
    valid_discharge(&d, small);
    d.nodes = n;
    d.node_count = SEGMENTS + 2;
    return fg_engine_post(e, &d, NULL);
}

static fg_result post_wild_count(fg_engine *e)
{
    fg_node n[VALID_NODES];
    fg_discharge d;
    valid_discharge(&d, n);
    d.node_count = SIZE_MAX;
    return fg_engine_post(e, &d, NULL);
}

static fg_result post_after_fill(fg_engine *e)
{
    fg_voice_id id = 77;
    fg_result r = post_valid(e, &id);
    CHECK(id == 77, "a refused post wrote the id");
    return r;
}

/* 20 segments when 14 are free */
static fg_result post_too_many_segments(fg_engine *e)
{
    fg_node n[21];
    valid_tree(n, 21);
    fg_discharge d;
    fg_node small[VALID_NODES];
    valid_discharge(&d, small);
    d.nodes = n;
    d.node_count = 21;
    return fg_engine_post(e, &d, NULL);
}

static float render_sink[2][BLOCK + 1];

static fg_result render_null_engine(fg_engine *e)
{
    (void)e;
    float *planes[2] = {render_sink[0], render_sink[1]};
    return fg_engine_render(NULL, planes, 16);
}

static fg_result render_null_out(fg_engine *e)
{
    return fg_engine_render(e, NULL, 16);
}

static fg_result render_null_plane(fg_engine *e)
{
    float *planes[2] = {render_sink[0], NULL};
    return fg_engine_render(e, planes, 16);
}

static fg_result render_too_long(fg_engine *e)
{
    for (int c = 0; c < 2; c++)
        for (int k = 0; k <= BLOCK; k++)
            render_sink[c][k] = 1.0f;
    float *planes[2] = {render_sink[0], render_sink[1]};
    fg_result r = fg_engine_render(e, planes, BLOCK + 1);
    for (int c = 0; c < 2; c++)
        for (int k = 0; k <= BLOCK; k++)
            CHECK(render_sink[c][k] == 0.0f, "refused block: plane %d frame %d not zeroed", c, k);
    return r;
}

/* not an error, and not a block either: nothing is adopted, the clock
 * stays */
static fg_result render_zero_frames(fg_engine *e)
{
    float *planes[2] = {render_sink[0], render_sink[1]};
    return fg_engine_render(e, planes, 0);
}

#define LISTENER_BAD(fn, ...)                     \
    static fg_result fn(fg_engine *e)             \
    {                                             \
        fg_listener p = {.position = {1, 2, 3}, .forward = {0, 1, 0}, .up = {0, 0, 1}}; \
        __VA_ARGS__;                                     \
        return fg_engine_set_listener(e, &p);     \
    }

static fg_result listener_null_engine(fg_engine *e)
{
    (void)e;
    return fg_engine_set_listener(NULL, &moved);
}

static fg_result listener_null_pose(fg_engine *e)
{
    return fg_engine_set_listener(e, NULL);
}

LISTENER_BAD(listener_nan_position, p.position[1] = NAN)
LISTENER_BAD(listener_inf_velocity, p.velocity[2] = -INFINITY)
LISTENER_BAD(listener_nan_up, p.up[0] = NAN)
LISTENER_BAD(listener_zero_forward, p.forward[1] = 0)
LISTENER_BAD(listener_zero_up, p.up[2] = 0)
LISTENER_BAD(listener_parallel_up, {
    p.up[1] = 2;
    p.up[2] = 0;
})
LISTENER_BAD(listener_antiparallel_up, {
    p.up[1] = -0.5;
    p.up[2] = 0;
})
LISTENER_BAD(listener_nearly_parallel, {
    p.up[1] = 1;
    p.up[2] = 1e-9;
})
LISTENER_BAD(listener_far, p.position[0] = -1.0001e7)
LISTENER_BAD(listener_forward_huge, p.forward[1] = 1e200)
LISTENER_BAD(listener_up_tiny, p.up[2] = 1e-60)
LISTENER_BAD(listener_nan_turn, p.angular_velocity[0] = NAN)
LISTENER_BAD(listener_turn_too_fast, p.angular_velocity[2] = 1.0001e4)

static fg_result stop_null(fg_engine *e)
{
    (void)e;
    return fg_engine_stop(NULL, history_id);
}

static fg_result stop_zero(fg_engine *e)
{
    return fg_engine_stop(e, 0);
}

static fg_result stop_unknown(fg_engine *e)
{
    return fg_engine_stop(e, ((fg_voice_id)5 << 32) | 2u);
}

static fg_result stop_slot_out_of_range(fg_engine *e)
{
    return fg_engine_stop(e, ((fg_voice_id)1 << 32) | (VOICES + 5u));
}

static fg_result stop_collected(fg_engine *e)
{
    return fg_engine_stop(e, history_id);
}

/* --- the sweep ------------------------------------------------------- */

typedef struct input_case {
    const char *name;
    void (*history)(fg_engine *e);
    fg_result (*bad)(fg_engine *e);
    fg_result want;
    uint64_t dropped; /* dropped_posts the bad call adds (pool/queue full) */
    uint32_t voices;  /* 0: VOICES */
} input_case;

static const input_case cases[] = {
    {"post: NULL engine", post_one, post_null_engine, FG_ERR_NULL, 0, 0},
    {"post: NULL discharge", post_one, post_null_discharge, FG_ERR_NULL, 0, 0},
    {"post: NULL nodes", NULL, post_null_nodes, FG_ERR_NULL, 0, 0},
    {"post: NaN x", post_and_render, post_nan_x, FG_ERR_TREE, 0, 0},
    {"post: inf z", NULL, post_inf_z, FG_ERR_TREE, 0, 0},
    {"post: NaN root", NULL, post_nan_root, FG_ERR_TREE, 0, 0},
    {"post: own parent", post_one, post_self_parent, FG_ERR_TREE, 0, 0},
    {"post: forward parent", NULL, post_forward_parent, FG_ERR_TREE, 0, 0},
    {"post: 2-cycle", NULL, post_cycle, FG_ERR_TREE, 0, 0},
    {"post: parent -2", NULL, post_parent_minus2, FG_ERR_TREE, 0, 0},
    {"post: root has a parent", NULL, post_root_has_parent, FG_ERR_TREE, 0, 0},
    {"post: second root", NULL, post_second_root, FG_ERR_TREE, 0, 0},
    {"post: zero-length segment", NULL, post_zero_length, FG_ERR_TREE, 0, 0},
    {"post: one node", NULL, post_one_node, FG_ERR_TREE, 0, 0},
    {"post: no nodes", NULL, post_no_nodes, FG_ERR_TREE, 0, 0},
    {"post: T0 = 0", NULL, post_t0_zero, FG_ERR_ARGUMENT, 0, 0},
    {"post: T0 < 0", NULL, post_t0_negative, FG_ERR_ARGUMENT, 0, 0},
    {"post: ps0 NaN", NULL, post_ps0_nan, FG_ERR_NOT_FINITE, 0, 0},
    {"post: r0 inf", NULL, post_r0_inf, FG_ERR_NOT_FINITE, 0, 0},
    {"post: sigma0 < 0", NULL, post_sigma_negative, FG_ERR_ARGUMENT, 0, 0},
    {"post: jitter 1", NULL, post_jitter_one, FG_ERR_ARGUMENT, 0, 0},
    {"post: return stroke speed 0", NULL, post_return_speed_zero, FG_ERR_ARGUMENT, 0, 0},
    {"post: 33 strokes", post_one, post_strokes_33, FG_ERR_ARGUMENT, 0, 0},
    {"post: 2^32-1 strokes", NULL, post_strokes_huge, FG_ERR_ARGUMENT, 0, 0},
    {"post: continuous with 2 strokes", NULL, post_continuous_strokes, FG_ERR_ARGUMENT, 0, 0},
    {"post: emit -0.5 s", NULL, post_emit_negative, FG_ERR_ARGUMENT, 0, 0},
    {"post: emit NaN", NULL, post_emit_nan, FG_ERR_NOT_FINITE, 0, 0},
    {"post: repeat min > max", NULL, post_repeat_inverted, FG_ERR_ARGUMENT, 0, 0},
    {"post: repeat max 11 s", NULL, post_repeat_too_long, FG_ERR_ARGUMENT, 0, 0},
    {"post: repeat NaN", NULL, post_repeat_nan, FG_ERR_NOT_FINITE, 0, 0},
    {"post: duration < 0", NULL, post_duration_negative, FG_ERR_ARGUMENT, 0, 0},
    {"post: a 1e-160 m segment", post_and_render, post_segment_1e160, FG_ERR_TREE, 0, 0},
    {"post: a 1e-162 m segment", NULL, post_segment_1e162, FG_ERR_TREE, 0, 0},
    {"post: a 0.99 um segment", NULL, post_segment_1um_less, FG_ERR_TREE, 0, 0},
    {"post: a node 1e7 m out", NULL, post_node_far, FG_ERR_TREE, 0, 0},
    {"post: T0 1e-308 s", post_one, post_t0_1e308, FG_ERR_ARGUMENT, 0, 0},
    {"post: T0 0.99e-7 s", NULL, post_t0_short, FG_ERR_ARGUMENT, 0, 0},
    {"post: T0 0.11 s", NULL, post_t0_long, FG_ERR_ARGUMENT, 0, 0},
    {"post: T0 5e289 s", NULL, post_t0_5e289, FG_ERR_ARGUMENT, 0, 0},
    {"post: r0 1001 m", NULL, post_r0_far, FG_ERR_ARGUMENT, 0, 0},
    {"post: ps0 1.01e7 Pa", NULL, post_ps0_huge, FG_ERR_ARGUMENT, 0, 0},
    {"post: sigma0 10.5", NULL, post_sigma_huge, FG_ERR_ARGUMENT, 0, 0},
    {"post: return stroke 1e-300 m/s", NULL, post_return_speed_tiny, FG_ERR_ARGUMENT, 0, 0},
    {"post: return stroke 3.1e8 m/s", NULL, post_return_speed_light, FG_ERR_ARGUMENT, 0, 0},
    {"post: repeat 1e-300 s", post_and_render, post_repeat_1e300, FG_ERR_ARGUMENT, 0, 0},
    {"post: repeat 1e-6 s", NULL, post_repeat_1us, FG_ERR_ARGUMENT, 0, 0},
    {"post: repeat -0.01 s", NULL, post_repeat_negative, FG_ERR_ARGUMENT, 0, 0},
    {"post: tree over capacity", post_one, post_over_capacity, FG_ERR_CAPACITY, 0, 0},
    {"post: node_count SIZE_MAX", NULL, post_wild_count, FG_ERR_CAPACITY, 0, 0},
    {"post: voice pool full", fill_pool, post_after_fill, FG_ERR_POOL_FULL, 1, 0},
    {"post: inbox full", fill_queue, post_after_fill, FG_ERR_QUEUE_FULL, 1, 2},
    {"post: segments full", take_segments, post_too_many_segments, FG_ERR_POOL_FULL, 1, 0},
    {"render: NULL engine", post_one, render_null_engine, FG_ERR_NULL, 0, 0},
    {"render: NULL out", post_one, render_null_out, FG_ERR_NULL, 0, 0},
    {"render: NULL plane", post_one, render_null_plane, FG_ERR_NULL, 0, 0},
    {"render: nframes > max block", post_one, render_too_long, FG_ERR_BLOCK_SIZE, 0, 0},
    {"render: 0 frames", post_one, render_zero_frames, FG_OK, 0, 0},
    {"listener: NULL engine", move_and_post, listener_null_engine, FG_ERR_NULL, 0, 0},
    {"listener: NULL pose", move_and_post, listener_null_pose, FG_ERR_NULL, 0, 0},
    {"listener: NaN position", move_and_post, listener_nan_position, FG_ERR_NOT_FINITE, 0, 0},
    {"listener: inf velocity", move_and_post, listener_inf_velocity, FG_ERR_NOT_FINITE, 0, 0},
    {"listener: NaN up", NULL, listener_nan_up, FG_ERR_NOT_FINITE, 0, 0},
    {"listener: NaN angular velocity", NULL, listener_nan_turn, FG_ERR_NOT_FINITE, 0, 0},
    {"listener: turning above 1e4 rad/s", move_and_post, listener_turn_too_fast, FG_ERR_ARGUMENT,
     0, 0},
    {"listener: zero forward", move_and_post, listener_zero_forward, FG_ERR_ARGUMENT, 0, 0},
    {"listener: zero up", NULL, listener_zero_up, FG_ERR_ARGUMENT, 0, 0},
    {"listener: up parallel", move_and_post, listener_parallel_up, FG_ERR_ARGUMENT, 0, 0},
    {"listener: up antiparallel", NULL, listener_antiparallel_up, FG_ERR_ARGUMENT, 0, 0},
    {"listener: up within 1e-9 rad", NULL, listener_nearly_parallel, FG_ERR_ARGUMENT, 0, 0},
    {"listener: 1e7 m out", move_and_post, listener_far, FG_ERR_ARGUMENT, 0, 0},
    {"listener: forward 1e200 long", NULL, listener_forward_huge, FG_ERR_ARGUMENT, 0, 0},
    {"listener: up 1e-60 long", move_and_post, listener_up_tiny, FG_ERR_ARGUMENT, 0, 0},
    {"stop: NULL engine", post_one, stop_null, FG_ERR_NULL, 0, 0},
    {"stop: id 0", post_one, stop_zero, FG_ERR_NOT_FOUND, 0, 0},
    {"stop: unknown id", post_one, stop_unknown, FG_ERR_NOT_FOUND, 0, 0},
    {"stop: slot out of range", NULL, stop_slot_out_of_range, FG_ERR_NOT_FOUND, 0, 0},
    {"stop: collected voice", finish_and_collect, stop_collected, FG_ERR_NOT_FOUND, 0, 0},
};

/* blocks_over_budget depends on the machine's speed: not compared */
static void stats_equal(const char *name, const char *when, fg_engine_report a, fg_engine_report b)
{
    a.blocks_over_budget = b.blocks_over_budget = 0;
    CHECK(memcmp(&a, &b, sizeof a) == 0,
          "%s, %s: stats differ (posted %llu/%llu dropped %llu/%llu adopted %llu/%llu "
          "finished %llu/%llu collected %llu/%llu late %llu/%llu blocks %llu/%llu)",
          name, when, (unsigned long long)a.posted, (unsigned long long)b.posted,
          (unsigned long long)a.dropped_posts, (unsigned long long)b.dropped_posts,
          (unsigned long long)a.adopted, (unsigned long long)b.adopted,
          (unsigned long long)a.finished, (unsigned long long)b.finished,
          (unsigned long long)a.collected, (unsigned long long)b.collected,
          (unsigned long long)a.late_events, (unsigned long long)b.late_events,
          (unsigned long long)a.blocks, (unsigned long long)b.blocks);
}

static void test_sweep(void **state)
{
    (void)state;
    static float out_a[2][REF_BLOCKS * BLOCK], out_b[2][REF_BLOCKS * BLOCK];
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
        const input_case *ic = &cases[ci];
        fg_engine_config cfg = base_cfg;
        if (ic->voices)
            cfg.max_voices = ic->voices;
        fg_engine *a, *b;
        assert_int_equal(fg_engine_create(&cfg, &a), FG_OK);
        assert_int_equal(fg_engine_create(&cfg, &b), FG_OK);
        if (ic->history) {
            ic->history(a);
            ic->history(b);
        }
        fg_result got = ic->bad(a);
        CHECK(got == ic->want, "%s: returned %d (%s), documented %d (%s)", ic->name, got,
              fg_result_str(got), ic->want, fg_result_str(ic->want));

        fg_engine_report sa, sb;
        fg_engine_get_report(a, &sa);
        fg_engine_get_report(b, &sb);
        sb.dropped_posts += ic->dropped;
        stats_equal(ic->name, "after the bad call", sa, sb);
        CHECK(fg_engine_frames(a) == fg_engine_frames(b), "%s: the clock moved", ic->name);
        fg_listener la, lb;
        /* the struct has padding after velocity_given: zero it to compare */
        memset(&la, 0, sizeof la);
        memset(&lb, 0, sizeof lb);
        fg_engine_get_listener(a, &la);
        fg_engine_get_listener(b, &lb);
        CHECK(memcmp(&la, &lb, sizeof la) == 0, "%s: the listener changed", ic->name);

        /* then the same valid post and render on both */
        fg_voice_id ida = 0, idb = 0;
        fg_result ra = post_valid(a, &ida), rb = post_valid(b, &idb);
        CHECK(ra == rb && ida == idb, "%s: next post %d id %llx, fresh %d id %llx", ic->name, ra,
              (unsigned long long)ida, rb, (unsigned long long)idb);
        memset(out_a, 0xff, sizeof out_a);
        memset(out_b, 0, sizeof out_b);
        render_blocks(a, out_a, REF_BLOCKS);
        render_blocks(b, out_b, REF_BLOCKS);
        CHECK(fx_peak(out_b[0], REF_BLOCKS * BLOCK) > 0, "%s: the reference is silent", ic->name);
        CHECK(memcmp(out_a, out_b, sizeof out_a) == 0, "%s: output differs from a fresh engine",
              ic->name);
        fg_engine_get_report(a, &sa);
        fg_engine_get_report(b, &sb);
        sb.dropped_posts += ic->dropped;
        stats_equal(ic->name, "after the next render", sa, sb);
        fg_engine_destroy(a);
        fg_engine_destroy(b);
    }
}

/* --- creation -------------------------------------------------------- */

typedef struct create_case {
    const char *name;
    double rate;
    uint32_t channels, block;
    double speed, spacing, lookahead;
    fg_result want;
    double want_rate;     /* on success, the rate in use */
    uint32_t want_channels;
} create_case;

static const create_case create_cases[] = {
    {"rate 0 = default", 0, 2, 256, 343, 0, 0, FG_OK, 48000, 2},
    {"rate 8000", 8000, 2, 256, 343, 0, 0, FG_OK, 8000, 2},
    {"rate 384000", 384000, 2, 256, 343, 0, 0, FG_OK, 384000, 2},
    {"rate 7999", 7999, 2, 256, 343, 0, 0, FG_ERR_SAMPLE_RATE, 0, 0},
    {"rate 384001", 384001, 2, 256, 343, 0, 0, FG_ERR_SAMPLE_RATE, 0, 0},
    {"rate -48000", -48000, 2, 256, 343, 0, 0, FG_ERR_SAMPLE_RATE, 0, 0},
    {"rate NaN", NAN, 2, 256, 343, 0, 0, FG_ERR_NOT_FINITE, 0, 0},
    {"rate inf", INFINITY, 2, 256, 343, 0, 0, FG_ERR_NOT_FINITE, 0, 0},
    {"channels 0 = default", 48000, 0, 256, 343, 0, 0, FG_OK, 48000, 2},
    {"channels 1", 48000, 1, 256, 343, 0, 0, FG_OK, 48000, 1},
    {"channels 3", 48000, 3, 256, 343, 0, 0, FG_ERR_ARGUMENT, 0, 0},
    {"channels 2^32-1", 48000, UINT32_MAX, 256, 343, 0, 0, FG_ERR_ARGUMENT, 0, 0},
    {"block 65537", 48000, 2, 65537, 343, 0, 0, FG_ERR_ARGUMENT, 0, 0},
    {"speed -343", 48000, 2, 256, -343, 0, 0, FG_ERR_ARGUMENT, 0, 0},
    {"speed NaN", 48000, 2, 256, NAN, 0, 0, FG_ERR_NOT_FINITE, 0, 0},
    {"speed 1e-300", 48000, 2, 256, 1e-300, 0, 0, FG_ERR_ARGUMENT, 0, 0},
    {"speed 99", 48000, 2, 256, 99, 0, 0, FG_ERR_ARGUMENT, 0, 0},
    {"speed 1001", 48000, 2, 256, 1001, 0, 0, FG_ERR_ARGUMENT, 0, 0},
    {"speed 100", 48000, 2, 256, 100, 0, 0, FG_OK, 48000, 2},
    {"ear spacing -0.1", 48000, 2, 256, 343, -0.1, 0, FG_ERR_ARGUMENT, 0, 0},
    {"look-ahead inf", 48000, 2, 256, 343, 0, INFINITY, FG_ERR_NOT_FINITE, 0, 0},
    {"look-ahead -1", 48000, 2, 256, 343, 0, -1, FG_ERR_ARGUMENT, 0, 0},
};

/* Field by field: a struct's padding is no part of its value. */
static bool same_config(const fg_engine_config *a, const fg_engine_config *b)
{
    return a->sample_rate_hz == b->sample_rate_hz && a->max_block_frames == b->max_block_frames &&
           a->channels == b->channels && a->max_voices == b->max_voices &&
           a->segment_capacity == b->segment_capacity &&
           a->speed_of_sound_m_s == b->speed_of_sound_m_s && a->ear_spacing_m == b->ear_spacing_m &&
           a->max_lookahead_s == b->max_lookahead_s &&
           a->max_adopt_per_block == b->max_adopt_per_block &&
           a->air_temperature_k == b->air_temperature_k &&
           a->air_humidity_pct == b->air_humidity_pct &&
           a->air_pressure_kpa == b->air_pressure_kpa && a->work_per_frame == b->work_per_frame &&
           a->layout == b->layout && a->ambisonic_order == b->ambisonic_order &&
           a->chunk_frames == b->chunk_frames;
}

static void test_create(void **state)
{
    (void)state;
    assert_int_equal(fg_engine_create(NULL, NULL), FG_ERR_NULL);
    for (size_t ci = 0; ci < sizeof create_cases / sizeof create_cases[0]; ci++) {
        const create_case *cc = &create_cases[ci];
        fg_engine_config cfg = {.sample_rate_hz = cc->rate, .channels = cc->channels,
                                .max_block_frames = cc->block, .speed_of_sound_m_s = cc->speed,
                                .ear_spacing_m = cc->spacing, .max_lookahead_s = cc->lookahead};
        fg_engine *e = (fg_engine *)&cfg; /* not NULL: must be overwritten */
        fg_result r = fg_engine_create(&cfg, &e);
        CHECK(r == cc->want, "%s: returned %d (%s), documented %d", cc->name, r,
              fg_result_str(r), cc->want);
        if (r != FG_OK) {
            CHECK(e == NULL, "%s: *out not cleared on failure", cc->name);
            continue;
        }
        fg_engine_config used;
        fg_engine_get_config(e, &used);
        CHECK(used.sample_rate_hz == cc->want_rate && used.channels == cc->want_channels,
              "%s: in use %g Hz, %u channels", cc->name, used.sample_rate_hz, used.channels);
        fg_engine_destroy(e);
    }
    /* NULL config: every default as the header documents it */
    fg_engine *e;
    assert_int_equal(fg_engine_create(NULL, &e), FG_OK);
    fg_engine_config used, dflt, got_chunk;
    fg_engine_get_config(e, &used);
    assert_int_equal(fg_engine_config_resolve(NULL, &dflt), FG_OK);
    fg_engine_destroy(e);
    CHECK(same_config(&used, &dflt), "create(NULL) differs from the defaults");
    const fg_engine_config documented = {
        .sample_rate_hz = 48000, .max_block_frames = 4096, .channels = 2, .max_voices = 64,
        .segment_capacity = 131072, .speed_of_sound_m_s = 343, .ear_spacing_m = 0.175,
        .max_lookahead_s = 0.25, .max_adopt_per_block = 8,
        .work_per_frame = FG_WORK_PER_FRAME_DEFAULT,
    };
    CHECK(dflt.sample_rate_hz == documented.sample_rate_hz &&
              dflt.max_block_frames == documented.max_block_frames &&
              dflt.channels == documented.channels && dflt.max_voices == documented.max_voices &&
              dflt.speed_of_sound_m_s == documented.speed_of_sound_m_s &&
              dflt.ear_spacing_m == documented.ear_spacing_m &&
              dflt.max_lookahead_s == documented.max_lookahead_s &&
              dflt.max_adopt_per_block == documented.max_adopt_per_block &&
              dflt.work_per_frame == 64 && dflt.chunk_frames == 0,
          "a default differs from engine.h");
    /* a chunk up to the longest block; longer is refused, as a block is */
    fg_engine_config chunked = {.chunk_frames = 65536}, too_long = {.chunk_frames = 65537};
    assert_int_equal(fg_engine_config_resolve(&chunked, &got_chunk), FG_OK);
    assert_int_equal(got_chunk.chunk_frames, 65536);
    assert_int_equal(fg_engine_config_resolve(&too_long, &got_chunk), FG_ERR_ARGUMENT);
    CHECK(dflt.segment_capacity == documented.segment_capacity,
          "default segment_capacity %u, engine.h documents %u", dflt.segment_capacity,
          documented.segment_capacity);

    /* resolve: the defaults for zero fields, errors as create's, *out
     * untouched on error */
    fg_engine_config some = {.sample_rate_hz = 44100, .channels = 1}, got;
    assert_int_equal(fg_engine_config_resolve(&some, &got), FG_OK);
    CHECK(got.sample_rate_hz == 44100 && got.channels == 1 &&
              got.max_block_frames == dflt.max_block_frames && got.max_voices == dflt.max_voices,
          "resolve kept %g Hz, %u channels, filled %u frames", got.sample_rate_hz, got.channels,
          got.max_block_frames);
    fg_engine_config bad = {.sample_rate_hz = 1000}, untouched = got;
    assert_int_equal(fg_engine_config_resolve(&bad, &got), FG_ERR_SAMPLE_RATE);
    CHECK(same_config(&got, &untouched), "a failed resolve wrote *out");
    assert_int_equal(fg_engine_config_resolve(NULL, NULL), FG_ERR_NULL);

    /* the no-op on NULL */
    fg_engine_destroy(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sweep),
        cmocka_unit_test(test_create),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
