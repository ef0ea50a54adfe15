/* The real-time proof: ten seconds of rendering with every feature of the
 * engine in use makes no allocation, lock, sleep or I/O call. The rt_guard
 * is armed around every fg_engine_render call and the counter read after it.
 *
 * Every propagation effect and both voice models are in use.
 * Three threads, as a host would have them:
 *   main      the audio thread: 48 kHz, 256-frame blocks, two ears (and
 *             again in third-order ambisonics, 16 channels, and in
 *             binaural through a synthetic HRIR set);
 *   producer  the sim thread: posts on a schedule kept on the engine clock
 *             (multi-stroke lightning, sparks, a continuous plasma ball it
 *             stops midway) and collects;
 *   mover     walks the listener round a circle, on the engine clock.
 * The producer runs concurrently with rendering; the main thread only waits
 * (disarmed, between blocks) if the producer falls more than LAG_S behind,
 * so every post happens with its emit time still ahead. */
#define _POSIX_C_SOURCE 200809L /* nanosleep */
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <time.h>

#include <cmocka.h>

#include "engine_fixture.h"
#include "fulgur/fulgur.h"
#include "random_tree.h"
#include "rt_guard.h"
#include "sound/discharge_internal.h" /* FG_MAX_INSTANCES */

#define FS 48000.0
#define BLOCK 256
#define SECONDS 10
#define BLOCKS (SECONDS * 48000 / BLOCK)
#define LAG_S 0.02        /* how far the producer may fall behind the clock */
#define EMIT_AHEAD_S 0.1  /* explicit emit times lie this far after the post */
#define MAX_NODES 400
#define ORBIT_M 2.0       /* the listener's circle, radius */
#define ORBIT_RAD_S 0.5   /* and angular speed: 1 m/s */
#define MOVES 20          /* the listener moves at least this often */

typedef enum post_kind { POST_LIGHTNING, POST_SPARK, POST_PLASMA, POST_STOP_PLASMA } post_kind;

typedef struct scheduled {
    double at_s;       /* engine time of the post (or stop) */
    post_kind kind;
    uint32_t strokes;  /* lightning: 0 draws from the log-series law */
    double duration_s; /* plasma: 0 sounds until POST_STOP_PLASMA */
} scheduled;

#define SPARK_FIRST_S 0.05
#define SPARK_EVERY_S 0.05
#define SPARKS 180 /* until 9 s: every voice has ended by the tenth second */

static const scheduled plan[] = {
    {0.2, POST_LIGHTNING, 0, 0},
    {1.0, POST_PLASMA, 0, 0},
    {1.5, POST_LIGHTNING, 4, 0},
    {3.0, POST_LIGHTNING, 6, 0},
    {5.0, POST_STOP_PLASMA, 0, 0},
    {6.0, POST_PLASMA, 0, 0.5},
};
#define PLAN_LEN (sizeof plan / sizeof plan[0])

typedef struct shared {
    fg_engine *engine;
    atomic_int quit;
    atomic_uint_least64_t producer_frames;  /* the clock the producer has caught up with */
    /* producer's results, read after join */
    uint64_t posts, post_errors, collected;
    fg_result stop_result;
    /* mover's */
    atomic_uint_least64_t poses;            /* poses published so far */
    uint64_t pose_errors;
} shared;

static void pause_briefly(void)
{
    struct timespec t = {0, 100000};
    nanosleep(&t, NULL);
}

/* Marks the main channel: the path from the root to the lowest node. */
static void flag_main_channel(fg_node *nodes, size_t count)
{
    size_t low = 0;
    for (size_t i = 1; i < count; i++)
        if (nodes[i].z < nodes[low].z)
            low = i;
    for (size_t i = low; i != 0; i = (size_t)nodes[i].parent)
        nodes[i].flags |= FG_NODE_MAIN;
    nodes[0].flags |= FG_NODE_MAIN;
}

/* Posts s; key seeds its tree, so every run posts the same trees whatever
 * the threads' timing. */
static fg_result post(fg_engine *e, const scheduled *s, uint64_t key, fg_voice_id *id)
{
    fg_rng rng;
    fg_rng_seed(&rng, key);
    fg_node nodes[MAX_NODES];
    fg_discharge d = {.nodes = nodes,
                      .emit_time_s = s->at_s + EMIT_AHEAD_S,
                      .strokes = s->strokes,
                      .seed = fg_rng_next(&rng)};
    const double down[3] = {0, 0, -1.2}, around[3] = {0, 0, 0};
    fg_preset preset = FG_PRESET_SPARK_BALLS;
    if (s->kind == POST_LIGHTNING) {
        /* a bolt from 500 m up, a few hundred metres away */
        const double root[3] = {150 + 50 * fg_rng_uniform(&rng), 100, 500};
        d.node_count = MAX_NODES;
        random_tree(&rng, nodes, d.node_count, root, 3.0, down, 0.1);
        flag_main_channel(nodes, d.node_count);
        preset = FG_PRESET_LIGHTNING;
    } else if (s->kind == POST_PLASMA) {
        const double root[3] = {0, 0, 1.2};
        d.node_count = 80;
        random_tree(&rng, nodes, d.node_count, root, 0.02, around, 0.3);
        d.continuous = 1;
        d.duration_s = s->duration_s;
        preset = FG_PRESET_PLASMA_BALL;
    } else {
        /* sparks 1-2 m from the centre of the listener's circle, half of
         * them emitted "now" */
        const double root[3] = {fg_rng_range(&rng, -1, 1), 1 + fg_rng_uniform(&rng), 1.5};
        d.node_count = 2 + (size_t)(fg_rng_uniform(&rng) * 39);
        random_tree(&rng, nodes, d.node_count, root, 0.002, down, 0.1);
        if (fg_rng_uniform(&rng) < 0.5)
            d.emit_time_s = FG_EMIT_NOW;
    }
    /* every propagation effect, on every other post; one spark in Abe's
     * model (its waves are long: one keeps the run short) */
    if (key % 2 == 0)
        d.propagation = (fg_propagation_config){
            .refraction_radius_m = FG_REFRACTION_STORM_M,
            .turbulence_s = 0.002,
            .absorption = key % 4 == 0 ? FG_ABSORPTION_ISO9613 : FG_ABSORPTION_ABE_FIR,
            .abe_fir_distance_m = 1.0,
            .ground_reflection = 0.8,
            .head_shadow = 1,
        };
    if (key == PLAN_LEN + 1)
        d.model = FG_MODEL_ABE;
    fg_result res = fg_preset_sound(preset, &d.sound);
    return res != FG_OK ? res : fg_engine_post(e, &d, id);
}

static void *producer_main(void *arg)
{
    shared *sh = arg;
    size_t next_plan = 0, next_spark = 0;
    fg_voice_id plasma = 0;
    while (!atomic_load_explicit(&sh->quit, memory_order_acquire)) {
        uint64_t frames = fg_engine_frames(sh->engine);
        double now_s = (double)frames / FS;
        while (next_plan < PLAN_LEN && plan[next_plan].at_s <= now_s) {
            const scheduled *s = &plan[next_plan];
            uint64_t key = next_plan++;
            if (s->kind == POST_STOP_PLASMA) {
                sh->stop_result = fg_engine_stop(sh->engine, plasma);
                continue;
            }
            bool stopped_by_plan = s->kind == POST_PLASMA && s->duration_s == 0;
            fg_result r = post(sh->engine, s, key, stopped_by_plan ? &plasma : NULL);
            sh->posts++;
            sh->post_errors += r != FG_OK;
        }
        while (next_spark < SPARKS && SPARK_FIRST_S + SPARK_EVERY_S * next_spark <= now_s) {
            const scheduled spark = {SPARK_FIRST_S + SPARK_EVERY_S * next_spark, POST_SPARK, 1, 0};
            fg_result r = post(sh->engine, &spark, PLAN_LEN + next_spark, NULL);
            next_spark++;
            sh->posts++;
            sh->post_errors += r != FG_OK;
        }
        sh->collected += fg_engine_collect(sh->engine);
        atomic_store_explicit(&sh->producer_frames, frames, memory_order_release);
        pause_briefly();
    }
    return NULL;
}

static void *mover_main(void *arg)
{
    shared *sh = arg;
    while (!atomic_load_explicit(&sh->quit, memory_order_acquire)) {
        double a = ORBIT_RAD_S * fg_engine_time_s(sh->engine);
        fg_listener pose = {
            .position = {ORBIT_M * cos(a), ORBIT_M * sin(a), 1.7},
            .forward = {-sin(a), cos(a), 0},
            .up = {0, 0, 1},
            .velocity = {-ORBIT_M * ORBIT_RAD_S * sin(a), ORBIT_M * ORBIT_RAD_S * cos(a), 0},
        };
        sh->pose_errors += fg_engine_set_listener(sh->engine, &pose) != FG_OK;
        atomic_fetch_add_explicit(&sh->poses, 1, memory_order_release);
        pause_briefly();
    }
    return NULL;
}

/* Renders one block with the guard armed and reads the counters after it,
 * as a host's meter would; adds what the guard counted to *total. */
static fg_result render_armed(fg_engine *e, float *const *planes, uint32_t frames,
                              fg_engine_report *meter, rt_guard_counts *total)
{
    rt_guard_arm();
    fg_result r = fg_engine_render(e, planes, frames);
    fg_engine_get_report(e, meter);
    rt_guard_counts c = rt_guard_disarm();
    total->alloc += c.alloc;
    total->lock += c.lock;
    total->io += c.io;
    total->sleep += c.sleep;
    if (!total->first)
        total->first = c.first;
    return r;
}

static void assert_guard_clean(const rt_guard_counts *total)
{
    print_message("render calls: alloc %lu lock %lu io %lu sleep %lu (first: %s)\n", total->alloc,
                  total->lock, total->io, total->sleep, total->first ? total->first : "none");
    assert_int_equal(total->alloc, 0);
    assert_int_equal(total->lock, 0);
    assert_int_equal(total->io, 0);
    assert_int_equal(total->sleep, 0);
}

/* Ten seconds in a layout: channels 0 and 1 are kept (the ears, or W and
 * Y), the others rendered into scratch. */
/* A synthetic HRIR set for the binaural run: 64 directions on a spiral,
 * each ear a pulse delayed by Woodworth's way around an 8.75 cm head and
 * a 32-tap decay, 256 taps at 48 kHz. */
#define SYN_COUNT 64
#define SYN_TAPS 256
static double syn_direction[SYN_COUNT * 3];
static float syn_left[SYN_COUNT * SYN_TAPS], syn_right[SYN_COUNT * SYN_TAPS];
static const fg_hrir_set synthetic_hrirs = {FS, SYN_COUNT, SYN_TAPS, syn_direction, syn_left,
                                            syn_right};

static void make_synthetic_hrirs(void)
{
    for (int s = 0; s < SYN_COUNT; s++) {
        double z = 1.0 - (2.0 * s + 1.0) / SYN_COUNT, r = sqrt(1.0 - z * z);
        double a = 2.399963229728653 * s; /* the golden angle */
        double *d = syn_direction + 3 * s;
        d[0] = r * cos(a);
        d[1] = r * sin(a);
        d[2] = z;
        double lateral = asin(d[1]); /* to the left */
        for (int ear = 0; ear < 2; ear++) {
            double th = ear == 0 ? lateral : -lateral; /* towards this ear */
            double delay = 0.0875 / 343.0 * (th < 0 ? -th - sin(-th) : 0.0) + 0.0875 / 343.0;
            float *ir = (ear == 0 ? syn_left : syn_right) + s * SYN_TAPS;
            int at = 10 + (int)(delay * FS + 0.5);
            for (int k = 0; k < 32; k++)
                ir[at + k] = (float)(exp(-k / 6.0) * (th < 0 ? 0.5 : 1.0));
        }
    }
}

static void ten_seconds_armed(fg_layout layout, uint32_t order)
{
    fg_engine_config cfg;
    if (layout == FG_LAYOUT_BINAURAL)
        make_synthetic_hrirs();
    assert_int_equal(fg_engine_config_resolve(
                         &(fg_engine_config){.layout = layout, .ambisonic_order = order,
                                             .hrirs = layout == FG_LAYOUT_BINAURAL
                                                          ? &synthetic_hrirs
                                                          : NULL},
                         &cfg),
                     FG_OK);
    cfg.max_block_frames = BLOCK;
    static float scratch[16][BLOCK];
    shared sh = {.stop_result = FG_ERR_ARGUMENT};
    /* the guard sees the statically linked engine's calls: creating allocates */
    rt_guard_arm();
    fg_result created = fg_engine_create(&cfg, &sh.engine);
    rt_guard_counts create_counts = rt_guard_disarm();
    assert_int_equal(created, FG_OK);
    assert_true(create_counts.alloc > 0);
    fg_engine *e = sh.engine;
    pthread_t producer, mover;
    assert_int_equal(pthread_create(&producer, NULL, producer_main, &sh), 0);
    assert_int_equal(pthread_create(&mover, NULL, mover_main, &sh), 0);

    static float left[BLOCKS * BLOCK], right[BLOCKS * BLOCK];
    rt_guard_counts total = {0};
    uint64_t waits = 0;
    for (int b = 0; b < BLOCKS; b++) {
        uint64_t lag = (uint64_t)(LAG_S * FS);
        while (atomic_load_explicit(&sh.producer_frames, memory_order_acquire) + lag <
               (uint64_t)b * BLOCK) {
            waits++;
            sched_yield();
        }
        /* however the threads are scheduled, the listener moves during the run */
        if (b % (BLOCKS / MOVES) == 0) {
            uint64_t seen = atomic_load_explicit(&sh.poses, memory_order_acquire);
            while (atomic_load_explicit(&sh.poses, memory_order_acquire) == seen)
                sched_yield();
        }
        float *planes[16] = {left + (size_t)b * BLOCK, right + (size_t)b * BLOCK};
        for (uint32_t ch = 2; ch < cfg.channels; ch++)
            planes[ch] = scratch[ch];
        fg_engine_report meter;
        assert_int_equal(render_armed(e, planes, BLOCK, &meter, &total), FG_OK);
        assert_int_equal(meter.blocks, (uint64_t)b + 1);
    }
    atomic_store_explicit(&sh.quit, 1, memory_order_release);
    assert_int_equal(pthread_join(producer, NULL), 0);
    assert_int_equal(pthread_join(mover, NULL), 0);
    /* both have ended: this thread is the sim thread now */
    sh.collected += fg_engine_collect(e);

    fg_engine_report st;
    fg_engine_get_report(e, &st);
    print_message("%llu posts, %llu adopted, %llu finished, %llu late events, %llu poses, "
                  "%llu waits for the producer\n",
                  (unsigned long long)sh.posts, (unsigned long long)st.adopted,
                  (unsigned long long)st.finished, (unsigned long long)st.late_events,
                  (unsigned long long)atomic_load(&sh.poses), (unsigned long long)waits);

    /* the proof */
    assert_guard_clean(&total);

    /* everything that was planned happened */
    assert_int_equal(sh.posts, PLAN_LEN - 1 + SPARKS);
    assert_int_equal(sh.post_errors, 0);
    assert_int_equal(sh.stop_result, FG_OK);
    assert_int_equal(sh.pose_errors, 0);
    assert_true(atomic_load(&sh.poses) >= MOVES);
    assert_int_equal(st.blocks, BLOCKS);
    assert_int_equal(st.posted, sh.posts);
    assert_int_equal(st.adopted, sh.posts);
    assert_int_equal(st.finished, sh.posts); /* both plasma balls stopped */
    assert_int_equal(st.collected, sh.posts);
    assert_int_equal(sh.collected, sh.posts);
    assert_int_equal(st.late_events, 0);

    /* the sound: finite (an energy is finite only if every sample is), two
     * different ears, and every second of it heard */
    size_t differ = 0;
    for (size_t i = 0; i < (size_t)BLOCKS * BLOCK; i++)
        differ += left[i] != right[i];
    for (int s = 0; s < SECONDS; s++) {
        double el = fx_energy(left, (size_t)s * 48000, (size_t)(s + 1) * 48000);
        double er = fx_energy(right, (size_t)s * 48000, (size_t)(s + 1) * 48000);
        print_message("second %d: energy %.3g / %.3g Pa^2\n", s, el, er);
        assert_true(isfinite(el) && el > 0);
        assert_true(isfinite(er) && er > 0);
    }
    assert_true(differ > (size_t)BLOCKS * BLOCK / 100);
    fg_engine_destroy(e);
}

static void test_ten_seconds_armed(void **state)
{
    (void)state;
    ten_seconds_armed(FG_LAYOUT_STEREO, 0);
}

/* The same in third-order ambisonics: 16 channels, the field turned with
 * the moving listener, wave by wave. */
static void test_ten_seconds_armed_ambisonic(void **state)
{
    (void)state;
    ten_seconds_armed(FG_LAYOUT_AMBISONICS, 3);
}

/* The same in binaural: 50 loudspeaker channels on the buses, each
 * convolved with its pair (a synthetic set: the guard is the point). */
static void test_ten_seconds_armed_binaural(void **state)
{
    (void)state;
    ten_seconds_armed(FG_LAYOUT_BINAURAL, 0);
}

/* The render paths a smooth run never takes, armed: zero frames, too many
 * frames, a burst of posts beyond the per-block adoption limit, a voice that
 * is late, and a continuous voice whose repeats overlap more than
 * FG_MAX_INSTANCES times and which is then stopped. The sim-thread calls
 * are made from this thread between blocks. */
#define BURST 20
#define CHAIN 80
#define REPEAT_S 0.001

static void test_rare_paths_armed(void **state)
{
    (void)state;
    fg_engine_config cfg;
    assert_int_equal(fg_engine_config_resolve(NULL, &cfg), FG_OK);
    cfg.max_block_frames = BLOCK;
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    float left[BLOCK + 1], right[BLOCK + 1], *planes[2] = {left, right};
    rt_guard_counts total = {0};
    fg_engine_report m;

    assert_int_equal(render_armed(e, planes, 0, &m, &total), FG_OK);
    assert_int_equal(render_armed(e, planes, BLOCK + 1, &m, &total), FG_ERR_BLOCK_SIZE);
    assert_int_equal(m.blocks, 0);
    assert_int_equal(fg_engine_frames(e), 0);

    /* a spark a metre ahead (the listener is at the origin, facing +y) */
    const fg_node spark[] = {{0, 1, 0.01, -1, 0}, {0.004, 1, 0, 0, 0}, {0, 1, -0.01, 1, 0}};
    fg_discharge d = {.nodes = spark, .node_count = 3, .emit_time_s = FG_EMIT_NOW, .strokes = 1};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    for (int k = 0; k < BURST; k++)
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    for (uint32_t b = 1; b <= 3; b++) {
        assert_int_equal(render_armed(e, planes, BLOCK, &m, &total), FG_OK);
        uint32_t expect = b * cfg.max_adopt_per_block;
        assert_int_equal(m.adopted, expect < BURST ? expect : BURST);
    }

    /* late: emitted at 0 s, posted at about 0.5 s */
    while (fg_engine_time_s(e) < 0.5) {
        assert_int_equal(render_armed(e, planes, BLOCK, &m, &total), FG_OK);
        fg_engine_collect(e);
    }
    d.emit_time_s = 0;
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    assert_int_equal(render_armed(e, planes, BLOCK, &m, &total), FG_OK);
    assert_int_equal(m.late_events, 2);
    assert_true(m.late_samples > 0);

    /* repeats: a chain running straight away from the listener, 1 m to
     * 40 m, sounds for ~0.11 s per emission; one emission per millisecond */
    fg_node chain[CHAIN];
    for (int k = 0; k < CHAIN; k++)
        chain[k] = (fg_node){0, 1 + 0.5 * k, 0, k - 1, 0};
    double spread_s = (chain[CHAIN - 1].y - chain[0].y) / cfg.speed_of_sound_m_s;
    assert_true(spread_s / REPEAT_S > 1.5 * FG_MAX_INSTANCES);
    fg_discharge held = {.nodes = chain, .node_count = CHAIN, .emit_time_s = FG_EMIT_NOW,
                         .continuous = 1, .repeat_min_s = REPEAT_S, .repeat_max_s = REPEAT_S};
    assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &held.sound), FG_OK);
    fg_voice_id id;
    assert_int_equal(fg_engine_post(e, &held, &id), FG_OK);
    double stop_at_s = fg_engine_time_s(e) + 0.3;
    while (fg_engine_time_s(e) < stop_at_s)
        assert_int_equal(render_armed(e, planes, BLOCK, &m, &total), FG_OK);
    assert_true(m.skipped_repeats > 0);
    assert_int_equal(m.finished, m.adopted - 1);
    assert_int_equal(fg_engine_stop(e, id), FG_OK);
    /* the sounding emissions end within their spread */
    for (int b = 0; b * BLOCK < 2 * spread_s * FS && m.finished < m.posted; b++)
        assert_int_equal(render_armed(e, planes, BLOCK, &m, &total), FG_OK);
    print_message("%llu posted, %llu adopted, %llu finished, %llu late events (%llu samples), "
                  "%llu skipped repeats\n",
                  (unsigned long long)m.posted, (unsigned long long)m.adopted,
                  (unsigned long long)m.finished, (unsigned long long)m.late_events,
                  (unsigned long long)m.late_samples, (unsigned long long)m.skipped_repeats);
    assert_int_equal(m.posted, BURST + 2);
    assert_int_equal(m.finished, m.posted);
    assert_int_equal(fg_engine_collect(e) + m.collected, m.posted);
    assert_guard_clean(&total);
    fg_engine_destroy(e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ten_seconds_armed),
        cmocka_unit_test(test_ten_seconds_armed_ambisonic),
        cmocka_unit_test(test_ten_seconds_armed_binaural),
        cmocka_unit_test(test_rare_paths_armed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
