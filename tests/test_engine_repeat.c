/* Voices that emit more than once, measured from the rendered output:
 * continuous discharges repeat every repeat_min..repeat_max until stopped or
 * until their duration; lightning strokes after the first (dart leaders)
 * re-emit only the main channel. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>
#include <math.h>

#include "engine_fixture.h"

#define C_M_S 343.0

#define CHECK(cond, ...)            \
    do {                            \
        if (!(cond))                \
            fail_msg(__VA_ARGS__);  \
    } while (0)

/* A plasma-ball filament: a bent chain of 1 cm segments about 0.5 m ahead
 * of the listener. One emission lasts well under a millisecond. */
#define FILAMENT 8
static void filament(fg_node nodes[FILAMENT])
{
    for (int i = 0; i < FILAMENT; i++)
        nodes[i] = (fg_node){0.004 * sin(1.3 * i), 0.5 + 0.002 * i, 0.02 * i, i - 1, 0};
}

static fg_engine *make_engine(double fs, uint32_t channels)
{
    fg_engine_config cfg = {.sample_rate_hz = fs, .channels = channels,
                            .speed_of_sound_m_s = C_M_S};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    return e;
}

typedef struct repeat_case {
    const char *name;
    double repeat_min_s, repeat_max_s; /* 0: the default 10..50 ms */
    double duration_s;                 /* 0: until fg_engine_stop */
    double stop_at_s;                  /* when the test calls stop; 0: never */
    uint32_t block;
    uint64_t seed;
} repeat_case;

static const repeat_case repeat_cases[] = {
    {"default range, stop", 0, 0, 0, 0.6, 256, 11},
    {"default range, stop, block 37", 0, 0, 0, 0.45, 37, 12},
    {"20-25 ms, stop", 0.020, 0.025, 0, 0.5, 1024, 13},
    {"every 10 ms, stop", 0.010, 0.010, 0, 0.3, 64, 14},
    {"duration 0.25 s", 0, 0, 0.25, 0, 512, 15},
    {"duration 0.1 s, 40-50 ms", 0.040, 0.050, 0.1, 0, 128, 16},
};

static void test_continuous(void **state)
{
    (void)state;
    const double fs = 48000;
    const double total_s = 1.0;
    const size_t frames = (size_t)(fs * total_s);
    float *x = calloc(frames, sizeof(float));
    size_t *on = calloc(frames, sizeof(size_t));
    assert_true(x && on);
    for (size_t ci = 0; ci < sizeof repeat_cases / sizeof repeat_cases[0]; ci++) {
        const repeat_case *rc = &repeat_cases[ci];
        fg_engine *e = make_engine(fs, 1);
        fg_node nodes[FILAMENT];
        filament(nodes);
        fg_discharge d = {.nodes = nodes, .node_count = FILAMENT, .emit_time_s = 0.005,
                          .continuous = 1, .repeat_min_s = rc->repeat_min_s,
                          .repeat_max_s = rc->repeat_max_s, .duration_s = rc->duration_s,
                          .seed = rc->seed};
        assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound), FG_OK);
        fg_voice_id id;
        assert_int_equal(fg_engine_post(e, &d, &id), FG_OK);

        size_t stop_frame = rc->stop_at_s > 0 ? (size_t)(fs * rc->stop_at_s) : frames;
        float *planes[2] = {x, NULL};
        fx_render(e, planes, 1, stop_frame, rc->block);
        fg_engine_report st;
        if (rc->stop_at_s > 0) {
            fg_engine_get_report(e, &st);
            CHECK(st.finished == 0, "%s: finished before stop", rc->name);
            assert_int_equal(fg_engine_stop(e, id), FG_OK);
            float *tail[2] = {x + stop_frame, NULL};
            fx_render(e, tail, 1, frames - stop_frame, rc->block);
        }

        double lo = rc->repeat_min_s > 0 ? rc->repeat_min_s : 0.010;
        double hi = rc->repeat_max_s > 0 ? rc->repeat_max_s : 0.050;
        float peak = fx_peak(x, frames);
        CHECK(peak > 0, "%s: silent", rc->name);
        /* quiet gaps of 5 ms separate the emissions (each < 1 ms) */
        size_t n = fx_onsets(x, frames, 1e-4f * peak, (size_t)(0.005 * fs), on, frames);
        /* the last emission starts before this, on the engine clock */
        double end_s = rc->stop_at_s > 0 ? rc->stop_at_s : 0.005 + rc->duration_s;
        size_t min_count = (size_t)floor((end_s - 0.005) / hi);
        CHECK(n >= min_count && n <= (size_t)ceil(end_s / lo) + 2,
              "%s: %zu emissions in %.3f s", rc->name, n, end_s);
        double sum = 0;
        for (size_t k = 1; k < n; k++) {
            double gap = (double)(on[k] - on[k - 1]);
            sum += gap / fs;
            CHECK(gap >= lo * fs - 1 && gap <= hi * fs + 1,
                  "%s: emissions %zu and %zu are %.1f ms apart, outside %.0f-%.0f ms", rc->name,
                  k - 1, k, 1e3 * gap / fs, 1e3 * lo, 1e3 * hi);
        }
        if (n > 10 && hi > lo)
            CHECK(fabs(sum / (n - 1) - 0.5 * (lo + hi)) < 0.25 * (hi - lo),
                  "%s: mean interval %.1f ms", rc->name, 1e3 * sum / (n - 1));
        /* the first at t_emit + r/c, the last before the end plus the
         * sound's own travel and one block */
        double r_c = 0.51 / C_M_S;
        CHECK(fabs(on[0] / fs - (0.005 + r_c)) < 0.001, "%s: first onset at %.4f s", rc->name,
              on[0] / fs);
        double last_allowed = end_s + (rc->block + 2) / fs + r_c + 0.001;
        CHECK(on[n - 1] / fs <= last_allowed, "%s: an emission at %.4f s, after %.4f s",
              rc->name, on[n - 1] / fs, last_allowed);
        /* then silence: exact zeros once the voice has retired */
        size_t quiet_from = (size_t)(fs * (last_allowed + 0.005));
        for (size_t k = quiet_from; k < frames; k++)
            CHECK(x[k] == 0.0f, "%s: %.3g Pa at %.4f s after the end", rc->name, x[k], k / fs);
        fg_engine_get_report(e, &st);
        CHECK(st.finished == 1 && st.adopted == 1, "%s: finished %llu adopted %llu", rc->name,
              (unsigned long long)st.finished, (unsigned long long)st.adopted);
        CHECK(fg_engine_collect(e) == 1, "%s: nothing to collect", rc->name);
        fg_engine_destroy(e);
    }
    free(x);
    free(on);
}

/* A continuous voice with a duration ends with its last emission that
 * sounds: one whose repeats are drawn from 0.1 ms .. 10 s and that lasts
 * 0.05 s frees its slot within 0.2 s (its last wave has arrived 1.5 ms
 * after its emission), not when the repeat past its duration would have
 * been due: such a voice once held its slot for 5.4 s (seed 1). */
static void test_duration_frees_voice(void **state)
{
    (void)state;
    const double fs = 48000;
    const uint32_t block = 256;
    float x[256];
    for (uint64_t seed = 1; seed <= 8; seed++) {
        fg_engine *e = make_engine(fs, 1);
        fg_node nodes[FILAMENT];
        filament(nodes);
        fg_discharge d = {.nodes = nodes, .node_count = FILAMENT, .emit_time_s = 0.005,
                          .continuous = 1, .repeat_min_s = FG_REPEAT_MIN_S,
                          .repeat_max_s = FG_REPEAT_MAX_S, .duration_s = 0.05, .seed = seed};
        assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound), FG_OK);
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        float *planes[2] = {x, NULL};
        fg_engine_report st = {0};
        double peak = 0;
        while (fg_engine_time_s(e) < 0.2) {
            assert_int_equal(fg_engine_render(e, planes, block), FG_OK);
            peak = fmax(peak, fx_peak(x, block));
            fg_engine_get_report(e, &st);
            if (st.finished)
                break;
        }
        CHECK(peak > 0, "seed %llu: silent", (unsigned long long)seed);
        CHECK(st.finished == 1, "seed %llu: still alive at %.3f s", (unsigned long long)seed,
              fg_engine_time_s(e));
        fg_engine_destroy(e);
    }
}

/* Lightning with strokes: a vertical main channel (flagged FG_NODE_MAIN)
 * with side branches. The first stroke sounds like the whole tree rendered
 * alone; every later stroke like the main channel alone. */
#define MAIN_NODES 6
#define BRANCH_NODES 10
#define TREE_NODES (MAIN_NODES + BRANCH_NODES)

static void lightning_tree(fg_node *nodes, int with_branches)
{
    for (int i = 0; i < MAIN_NODES; i++)
        nodes[i] = (fg_node){0.01 * sin(2.0 * i), 1.0, 0.8 - 0.02 * i, i - 1, FG_NODE_MAIN};
    if (!with_branches)
        return;
    for (int i = 0; i < BRANCH_NODES; i++) {
        int j = MAIN_NODES + i;
        int parent = i == 0 ? 1 : i == 5 ? 3 : j - 1;
        double side = i < 5 ? 1.0 : -1.0;
        const fg_node *p = &nodes[parent];
        nodes[j] = (fg_node){p->x + side * 0.015, p->y + 0.004, p->z - 0.01, parent, 0};
    }
}

typedef struct stroke_case {
    const char *name;
    uint32_t strokes;
    uint64_t seed;
} stroke_case;

static const stroke_case stroke_cases[] = {
    {"2 strokes", 2, 5},
    {"4 strokes", 4, 6},
    {"7 strokes", 7, 7},
    {"drawn from the law", 0, 3}, /* 0: as many as the seed draws */
};

static double render_energy(const fg_node *nodes, size_t count, uint32_t strokes, uint64_t seed,
                            float *x, size_t frames)
{
    fg_engine *e = make_engine(192000, 1);
    fg_discharge d = {.nodes = nodes, .node_count = count, .emit_time_s = 0.002,
                      .strokes = strokes, .seed = seed};
    assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound), FG_OK);
    d.sound.t0_jitter = 0; /* the same segments whichever tree they sit in */
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    float *planes[2] = {x, NULL};
    fx_render(e, planes, 1, frames, 1000);
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.finished, 1);
    fg_engine_destroy(e);
    return fx_energy(x, 0, frames);
}

static void test_dart_leaders(void **state)
{
    (void)state;
    const double fs = 192000;
    /* 7 strokes with up to 240 ms between them */
    const size_t frames = (size_t)(fs * 1.7);
    float *x = calloc(frames, sizeof(float));
    size_t on[64];
    assert_non_null(x);
    fg_node full[TREE_NODES], main_only[MAIN_NODES];
    lightning_tree(full, 1);
    lightning_tree(main_only, 0);
    double e_full = render_energy(full, TREE_NODES, 1, 1, x, frames / 8);
    double e_main = render_energy(main_only, MAIN_NODES, 1, 1, x, frames / 8);
    CHECK(e_full > 1.5 * e_main, "the branches carry too little (%.3g vs %.3g) to tell apart",
          e_full, e_main);
    for (size_t ci = 0; ci < sizeof stroke_cases / sizeof stroke_cases[0]; ci++) {
        const stroke_case *sc = &stroke_cases[ci];
        /* the published schedule is the one the engine plays */
        fg_discharge published = {.strokes = sc->strokes, .seed = sc->seed};
        double offset_s[FG_MAX_STROKES];
        uint32_t want_n = fg_discharge_stroke_offsets(&published, offset_s, FG_MAX_STROKES);
        CHECK(want_n >= 2 && (sc->strokes == 0 || want_n == sc->strokes),
              "%s: %u strokes published", sc->name, want_n);
        render_energy(full, TREE_NODES, sc->strokes, sc->seed, x, frames);
        float peak = fx_peak(x, frames);
        size_t n = fx_onsets(x, frames, 1e-4f * peak, (size_t)(0.005 * fs), on, 64);
        CHECK(n == want_n, "%s: %zu bursts, %u published", sc->name, n, want_n);
        for (size_t k = 0; k < n; k++) {
            size_t a = on[k] > 100 ? on[k] - 100 : 0;
            size_t b = k + 1 < n ? on[k + 1] - 100 : frames;
            double ek = fx_energy(x, a, b);
            double want = k == 0 ? e_full : e_main;
            CHECK(fabs(ek / want - 1.0) < 0.02, "%s: stroke %zu energy %.4g, %s alone %.4g",
                  sc->name, k + 1, ek, k == 0 ? "the whole tree" : "the main channel", want);
            if (k > 0) {
                /* onsets follow the stroke times, give or take which
                 * segment arrives first (< 0.2 ms here) */
                double gap = (double)(on[k] - on[k - 1]) / fs;
                double want_gap = offset_s[k] - offset_s[k - 1];
                CHECK(fabs(gap - want_gap) < 2e-4 && gap >= 0.0098 && gap <= 0.2402,
                      "%s: strokes %.2f ms apart, published %.2f ms", sc->name, 1e3 * gap,
                      1e3 * want_gap);
            }
        }
    }
    free(x);
}

/* fg_engine_stop on a lightning voice: no further stroke starts. Stopped
 * 2 ms after the first stroke is heard (strokes are >= 10 ms apart), only
 * the first stroke sounds, and the voice retires. */
static void test_stop_lightning(void **state)
{
    (void)state;
    const double fs = 48000;
    const size_t frames = (size_t)(fs * 1.0);
    float *x = calloc(frames, sizeof(float));
    size_t on[64];
    assert_non_null(x);
    fg_node full[TREE_NODES];
    lightning_tree(full, 1);
    for (uint64_t seed = 1; seed <= 3; seed++) {
        fg_engine *e = make_engine(fs, 1);
        fg_discharge d = {.nodes = full, .node_count = TREE_NODES, .emit_time_s = 0.002,
                          .strokes = 5, .seed = seed};
        assert_int_equal(fg_preset_sound(FG_PRESET_PLASMA_BALL, &d.sound), FG_OK);
        fg_voice_id id;
        assert_int_equal(fg_engine_post(e, &d, &id), FG_OK);
        /* the first stroke is heard at 2 ms + ~3.7 ms of travel */
        size_t stop_frame = (size_t)(fs * 0.008);
        float *planes[2] = {x, NULL};
        fx_render(e, planes, 1, stop_frame, 64);
        assert_int_equal(fg_engine_stop(e, id), FG_OK);
        float *tail[2] = {x + stop_frame, NULL};
        fx_render(e, tail, 1, frames - stop_frame, 64);
        float peak = fx_peak(x, frames);
        size_t n = fx_onsets(x, frames, 1e-4f * peak, (size_t)(0.005 * fs), on, 64);
        CHECK(n == 1 && on[0] < stop_frame, "seed %llu: %zu bursts after stop",
              (unsigned long long)seed, n);
        fg_engine_report st;
        fg_engine_get_report(e, &st);
        CHECK(st.finished == 1, "seed %llu: not retired after stop", (unsigned long long)seed);
        fg_engine_destroy(e);
    }
    free(x);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_continuous),
        cmocka_unit_test(test_duration_frees_voice),
        cmocka_unit_test(test_dart_leaders),
        cmocka_unit_test(test_stop_lightning),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
