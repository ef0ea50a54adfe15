/* A producer thread posts 10 000 random trees and collects while the main
 * thread renders: every post is accepted or refused with a retryable code,
 * every accepted voice is adopted, finished and collected, none is late.
 * Run under ThreadSanitizer by scripts/test.sh. */
#include <pthread.h>
#include <sched.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "engine_fixture.h"
#include "fulgur/fulgur.h"
#include "random_tree.h"

#define TREES 10000
#define MIN_NODES 2
#define MAX_NODES 300
#define BLOCK 256
#define DRAIN_BLOCKS 2000 /* ~10 s of audio after the last post */

typedef struct producer {
    fg_engine *engine;
    uint64_t seed;
    /* written by the producer, read after join */
    uint64_t attempts, posted, refused, other_errors, collected, nodes;
    atomic_int done;
} producer;

/* Sparks 0.5-1 m from the listener at the origin: each voice sounds for a
 * few milliseconds. */
static void *producer_main(void *arg)
{
    producer *p = arg;
    fg_rng rng;
    fg_rng_seed(&rng, p->seed);
    fg_node nodes[MAX_NODES];
    fg_discharge d = {.nodes = nodes, .emit_time_s = FG_EMIT_NOW, .strokes = 1};
    fg_result r = fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound);
    if (r != FG_OK)
        p->other_errors++;
    const double drift[3] = {0, 0, -0.5};
    for (int t = 0; t < TREES; t++) {
        double root[3] = {fg_rng_range(&rng, 0.35, 0.7), fg_rng_range(&rng, 0.35, 0.7),
                          fg_rng_range(&rng, 0.0, 0.3)};
        d.node_count = MIN_NODES + (size_t)(fg_rng_uniform(&rng) * (MAX_NODES - MIN_NODES + 1));
        d.seed = fg_rng_next(&rng);
        random_tree(&rng, nodes, d.node_count, root, 0.002, drift, 0.1);
        p->nodes += d.node_count;
        for (;;) {
            p->attempts++;
            r = fg_engine_post(p->engine, &d, NULL);
            p->collected += fg_engine_collect(p->engine);
            if (r == FG_OK) {
                p->posted++;
                break;
            }
            if (r != FG_ERR_POOL_FULL && r != FG_ERR_QUEUE_FULL) {
                p->other_errors++;
                break;
            }
            p->refused++;
            sched_yield();
        }
    }
    atomic_store_explicit(&p->done, 1, memory_order_release);
    return NULL;
}

static void test_post_while_rendering(void **state)
{
    (void)state;
    fg_engine_config cfg;
    assert_int_equal(fg_engine_config_resolve(NULL, &cfg), FG_OK);
    cfg.max_block_frames = BLOCK;
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);

    producer p = {.engine = e, .seed = 20261122};
    pthread_t th;
    assert_int_equal(pthread_create(&th, NULL, producer_main, &p), 0);

    float left[BLOCK], right[BLOCK], *planes[2] = {left, right};
    double energy = 0;
    uint64_t blocks = 0, drain = 0;
    fg_engine_report st;
    for (;;) {
        assert_int_equal(fg_engine_render(e, planes, BLOCK), FG_OK);
        blocks++;
        energy += fx_energy(left, 0, BLOCK) + fx_energy(right, 0, BLOCK);
        if (!atomic_load_explicit(&p.done, memory_order_acquire))
            continue;
        fg_engine_get_report(e, &st);
        if (st.finished == st.posted || ++drain > DRAIN_BLOCKS)
            break;
    }
    assert_int_equal(pthread_join(th, NULL), 0);
    /* the producer has ended: this thread is the sim thread now */
    p.collected += fg_engine_collect(e);
    fg_engine_get_report(e, &st);
    print_message("%llu attempts, %llu posted, %llu refused, %llu nodes, %llu blocks, "
                  "energy %.3g Pa^2\n",
                  (unsigned long long)p.attempts, (unsigned long long)p.posted,
                  (unsigned long long)p.refused, (unsigned long long)p.nodes,
                  (unsigned long long)blocks, energy);

    assert_int_equal(p.other_errors, 0);
    assert_int_equal(p.posted, TREES);
    assert_int_equal(p.posted + p.refused, p.attempts);
    assert_int_equal(st.posted, p.posted);
    assert_int_equal(st.dropped_posts, p.refused);
    assert_int_equal(st.adopted, p.posted);
    assert_int_equal(st.finished, p.posted);
    assert_int_equal(st.collected, p.posted);
    assert_int_equal(p.collected, p.posted);
    assert_int_equal(st.late_events, 0);
    assert_int_equal(st.blocks, blocks);
    assert_true(energy > 0);
    fg_engine_destroy(e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_post_while_rendering),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
