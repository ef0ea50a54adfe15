/* Three threads at the engine's limits, as a host has them: a sim thread
 * posts discharges whose every parameter sits at an edge of its accepted
 * range (docs/limits.md: T0 1e-7 and 0.1 s, r0 1000 m, ps0 1e7 Pa, sigma0
 * 0 and 10, return strokes at 1e5 and 3e8 m/s, 1 µm segments, repeats every
 * 0.1 ms, 32 strokes, turbulence just under 1 s, refraction radii 20 and
 * 200 km, ground reflection 1, ISO 9613-1 and Abe's FIR, both models; one
 * tree at the 1e7 m coordinate limit, posted first) while the audio thread
 * (this one) renders and a frame thread moves the listener along a path
 * with poses ahead in time, velocities and forward/up of length 1e-50 and
 * 1e50 (just inside).
 * Asserted: every valid post is accepted or refused only for a full pool or
 * queue; every listener pose is accepted; every sample is finite; after the
 * threads stop, every voice but the far one finishes and is collected.
 * It runs FULGUR_STRESS_SECONDS of wall time (default 15, the CI setting;
 * FULGUR_STRESS_SECONDS=60 for the long run docs/limits.md describes),
 * under ThreadSanitizer and ASan+UBSan in scripts/test.sh. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, nanosleep */
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#include <cmocka.h>

#include "fg_rng.h"
#include "fulgur/fulgur.h"

#define BLOCK 256
#define NODES 24
#define DRAIN_S 20.0 /* engine time for the voices left to finish: turbulence
                      * (< 1 s), 32 strokes, a 0.1 s T0, 200 m of travel */
#define DEFAULT_SECONDS 15.0
/* A tight work bound (units per frame): these voices spend any bound, and
 * this one keeps a block's render near its own length on one core */
#define WORK 8

static double wall_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec * 1e-9;
}

static double stress_seconds(void)
{
    const char *s = getenv("FULGUR_STRESS_SECONDS");
    double v = s ? strtod(s, NULL) : DEFAULT_SECONDS;
    return isfinite(v) && v > 0 ? v : DEFAULT_SECONDS;
}

typedef struct shared {
    fg_engine *engine;
    double stop_at_s; /* wall time */
    atomic_int sim_done, frame_done;
    /* the sim thread's, read after join */
    uint64_t attempts, posted, full, refused, collected;
    fg_result first_refusal;
    /* the frame thread's */
    uint64_t poses, poses_refused;
} shared;

static double pick(fg_rng *rng, const double *values, size_t count)
{
    return values[fg_rng_next(rng) % count];
}
#define PICK(rng, array) pick(rng, array, sizeof array / sizeof array[0])

/* A random walk of NODES nodes from 0.3..3 m ahead of the origin, each
 * segment of length step (from just over the 1 µm limit to 5 cm). */
static void edge_tree(fg_rng *rng, fg_node *nodes, double step)
{
    double x = fg_rng_range(rng, 0.3, 3.0), y = fg_rng_range(rng, -3.0, 3.0), z = 0.0;
    for (int i = 0; i < NODES; i++) {
        double a = fg_rng_range(rng, 0, 6.283185307179586), b = fg_rng_range(rng, -1, 1);
        if (i > 0) {
            x += step * cos(a) * sqrt(1 - b * b);
            y += step * sin(a) * sqrt(1 - b * b);
            z += step * b;
        }
        nodes[i] = (fg_node){x, y, z, i - 1, 0};
    }
}

static void *sim_main(void *arg)
{
    shared *s = arg;
    fg_rng rng;
    fg_rng_seed(&rng, 20261202);
    static const double t0[] = {1e-7, 1e-5, 0.1};
    static const double r0[] = {1e-3, 0.05, 1000.0};
    static const double ps0[] = {1e-6, 1e3, 1e7};
    static const double sigma0[] = {0.0, 0.524, 10.0};
    static const double speed[] = {1e5, 3e8};
    static const double step[] = {1.0000001e-6, 1e-3, 0.05};
    static const double refraction[] = {0.0, 20e3, 200e3};
    static const double turbulence[] = {0.0, 0.002, 0.999};
    static const double turbulence_length[] = {0.0, 1e-3, 1e4};
    static const double ground[] = {0.0, 1e-6, 1.0};
    static const fg_absorption absorption[] = {FG_ABSORPTION_OFF, FG_ABSORPTION_ISO9613,
                                               FG_ABSORPTION_ABE_FIR};
    fg_node nodes[NODES];
    while (wall_s() < s->stop_at_s) {
        edge_tree(&rng, nodes, PICK(&rng, step));
        fg_discharge d = {.nodes = nodes, .node_count = NODES, .emit_time_s = FG_EMIT_NOW,
                          .seed = fg_rng_next(&rng)};
        if (fg_preset_sound((fg_preset)(fg_rng_next(&rng) % FG_PRESET_COUNT), &d.sound) != FG_OK)
            s->refused++;
        d.sound.t0_s = PICK(&rng, t0);
        d.sound.r0_m = PICK(&rng, r0);
        d.sound.ps0_pa = PICK(&rng, ps0);
        d.sound.sigma0 = PICK(&rng, sigma0);
        d.sound.return_stroke_speed_m_s = PICK(&rng, speed);
        /* one voice in four Abe's, continuous or not: the work bound
         * prices its series by what it costs (docs/limits.md) */
        d.model = fg_rng_next(&rng) % 4 ? FG_MODEL_WM : FG_MODEL_ABE;
        if (fg_rng_next(&rng) % 2 == 0) {
            d.continuous = 1;
            d.strokes = 1;
            d.repeat_min_s = FG_REPEAT_MIN_S;
            /* up to FG_REPEAT_MAX_S: the voice ends with its last emission
             * inside its duration, not when the repeat past it is due */
            d.repeat_max_s = fg_rng_next(&rng) % 2 ? FG_REPEAT_MIN_S : FG_REPEAT_MAX_S;
            d.duration_s = 0.05;
        } else {
            d.strokes = fg_rng_next(&rng) % 4 ? 1 + (uint32_t)(fg_rng_next(&rng) % 2)
                                              : FG_MAX_STROKES;
        }
        d.propagation.refraction_radius_m = PICK(&rng, refraction);
        d.propagation.turbulence_s = PICK(&rng, turbulence);
        d.propagation.turbulence_length_m = PICK(&rng, turbulence_length);
        d.propagation.absorption = absorption[fg_rng_next(&rng) % 3];
        d.propagation.ground_reflection = PICK(&rng, ground);
        d.propagation.head_shadow = (int)(fg_rng_next(&rng) % 2);
        s->attempts++;
        fg_result r = fg_engine_post(s->engine, &d, NULL);
        s->collected += fg_engine_collect(s->engine);
        if (r == FG_OK) {
            s->posted++;
        } else if (r == FG_ERR_POOL_FULL || r == FG_ERR_QUEUE_FULL) {
            s->full++;
            sched_yield();
        } else {
            if (!s->refused)
                s->first_refusal = r;
            s->refused++;
        }
    }
    atomic_store_explicit(&s->sim_done, 1, memory_order_release);
    return NULL;
}

static void *frame_main(void *arg)
{
    shared *s = arg;
    fg_rng rng;
    fg_rng_seed(&rng, 90);
    static const double length[] = {1.000001e-50, 1.0, 0.999999e50};
    const struct timespec frame = {0, 1000000}; /* 1 kHz, the highest frame rate run takes */
    for (uint64_t k = 0; wall_s() < s->stop_at_s; k++) {
        double a = k * 0.01, l = PICK(&rng, length);
        fg_listener pose = {
            .position = {2.0 * sin(a), 2.0 * cos(a), 1.7},
            .forward = {l * cos(a), -l * sin(a), 0},
            .up = {0, 0, PICK(&rng, length)},
            .velocity = {2.0 * cos(a), -2.0 * sin(a), 0},
            .time_s = k % 2 ? fg_engine_time_s(s->engine) + 0.02 : 0.0,
        };
        s->poses++;
        if (fg_engine_set_listener(s->engine, &pose) != FG_OK)
            s->poses_refused++;
        nanosleep(&frame, NULL);
    }
    atomic_store_explicit(&s->frame_done, 1, memory_order_release);
    return NULL;
}

static void stress_at_the_limits(void **state)
{
    (void)state;
    fg_engine_config cfg = {.max_block_frames = BLOCK, .max_voices = 32, .work_per_frame = WORK};
    shared s = {0};
    assert_int_equal(fg_engine_create(&cfg, &s.engine), FG_OK);
    fg_engine_get_config(s.engine, &cfg);
    /* One tree at the coordinate limit, 1e7 m up (its sound arrives in
     * 29 000 s, after the test), through ISO 9613-1: the post designs the
     * engine's absorption filters on this thread once (seconds under load),
     * before the clock starts. */
    fg_node far[NODES];
    for (int i = 0; i < NODES; i++)
        far[i] = (fg_node){1.0, 0.0, FG_TREE_MAX_COORDINATE_M - (NODES - i) * 0.05, i - 1, 0};
    fg_discharge d = {.nodes = far, .node_count = NODES, .emit_time_s = FG_EMIT_NOW,
                      .strokes = FG_MAX_STROKES,
                      .propagation = {.absorption = FG_ABSORPTION_ISO9613}};
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), FG_OK);
    assert_int_equal(fg_engine_post(s.engine, &d, NULL), FG_OK);
    s.stop_at_s = wall_s() + stress_seconds();
    double engine_start_s = fg_engine_time_s(s.engine);
    pthread_t sim, frame;
    assert_int_equal(pthread_create(&sim, NULL, sim_main, &s), 0);
    assert_int_equal(pthread_create(&frame, NULL, frame_main, &s), 0);

    float left[BLOCK], right[BLOCK], *planes[2] = {left, right};
    uint64_t blocks = 0, bad_samples = 0;
    double drain_until = INFINITY;
    for (;;) {
        assert_int_equal(fg_engine_render(s.engine, planes, BLOCK), FG_OK);
        blocks++;
        for (int f = 0; f < BLOCK; f++)
            bad_samples += !isfinite(left[f]) + !isfinite(right[f]);
        if (!atomic_load_explicit(&s.sim_done, memory_order_acquire) ||
            !atomic_load_explicit(&s.frame_done, memory_order_acquire))
            continue;
        if (drain_until == INFINITY) {
            drain_until = fg_engine_time_s(s.engine) + DRAIN_S;
            print_message("%.0f s of wall time rendered %.1f s\n", stress_seconds(),
                          fg_engine_time_s(s.engine) - engine_start_s);
        }
        fg_engine_report rep;
        fg_engine_get_report(s.engine, &rep);
        if (rep.finished + 1 == rep.posted || fg_engine_time_s(s.engine) > drain_until)
            break;
    }
    assert_int_equal(pthread_join(sim, NULL), 0);
    assert_int_equal(pthread_join(frame, NULL), 0);
    /* both threads have ended: this one is the sim thread now */
    s.collected += fg_engine_collect(s.engine);
    fg_engine_report rep;
    fg_engine_get_report(s.engine, &rep);
    print_message("%.0f s: %llu attempts, %llu posted, %llu pool/queue full, %llu poses, "
                  "%llu blocks; skipped work %llu, skipped repeats %llu, late events %llu, "
                  "non-finite voices %llu, adopted %llu, finished %llu\n",
                  stress_seconds(), (unsigned long long)s.attempts,
                  (unsigned long long)s.posted, (unsigned long long)s.full,
                  (unsigned long long)s.poses, (unsigned long long)blocks,
                  (unsigned long long)rep.skipped_work, (unsigned long long)rep.skipped_repeats,
                  (unsigned long long)rep.late_events, (unsigned long long)rep.non_finite_voices,
                  (unsigned long long)rep.adopted, (unsigned long long)rep.finished);
    if (s.refused)
        fail_msg("%llu valid posts refused, the first with %s", (unsigned long long)s.refused,
                 fg_result_str(s.first_refusal));
    assert_int_equal(s.poses_refused, 0);
    assert_int_equal(bad_samples, 0);
    assert_true(s.posted > cfg.max_voices); /* slots were reused (a sanitizer is slow) */
    assert_int_equal(rep.posted, s.posted + 1);
    assert_int_equal(s.posted + s.full + s.refused, s.attempts);
    /* no voice leaked: all but the far one (29 000 s away) finished */
    assert_int_equal(rep.finished + 1, rep.posted);
    assert_int_equal(s.collected, rep.finished);
    fg_engine_destroy(s.engine);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stress_at_the_limits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
