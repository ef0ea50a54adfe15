/* fulgur.lv2 through liblilv as a host would drive it: discovered on
 * LV2_PATH, instantiated at 44.1 and 48 kHz, played for 10 s from a scripted
 * MIDI sequence with the worker on its own thread. Each note is silent
 * until its sound has travelled from where the note map puts it, and
 * sounds after; run() never allocates or locks; a held plasma-ball note
 * sounds until its note-off. Rates the engine cannot run at fail to
 * instantiate. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>
#include <lilv/lilv.h>

#include "lv2_fixture.h"

#define BLOCK 256
#define SECONDS 10
#define C_M_S 343.0
#define DISTANCE_M 10.0  /* the distance control: note 60 is heard at 10 m */
#define AUDIBLE_PA 1e-4  /* a stretch with a sample above this sounds */
#define SILENT_PA 1e-6   /* one with none above this is silent (absorption's
                            filters leave tails far below it) */

typedef struct note {
    double on_s, off_s;
    int preset;          /* 0 spark balls, 1 plasma ball, 2 lightning */
    uint8_t key, velocity;
    float azimuth_deg;
    float strokes;       /* the strokes control: a spark's later strokes would
                            sound over the next note */
    double distance_m;   /* where the note map puts it */
    double extent_m;     /* how much nearer than that the tree may come, ears included */
    double lead_s;       /* how long before its arrival a wave may begin: half
                            the longest N-wave (lightning: T0 2.5 ms + 10 %) */
} note;

/* Earlier notes have fallen silent before each next one. */
static const note script[] = {
    {0.50, 0.60, 0, 60, 100, 0, 1, 10.0, 0.15, 0.0},
    {1.50, 1.60, 0, 48, 127, 90, 1, 20.0, 0.15, 0.0},
    {2.50, 3.50, 1, 72, 90, -45, 0, 5.0, 0.30, 0.0},
    {5.00, 5.20, 2, 60, 127, 30, 0, 10.0, 6.0, 1.4e-3},
};
#define NOTES (sizeof script / sizeof script[0])

typedef struct run_result {
    float *left, *right;
    size_t frames;
    unsigned long rt_calls;
    unsigned work_calls, responses;
    float discharges, failures;
    unsigned long worker_allocs;
} run_result;

static size_t frame_of(double t_s, double rate_hz) { return (size_t)lround(t_s * rate_hz); }

static void play(double rate_hz, run_result *out)
{
    lv2_host *h = lv2_host_create(rate_hz);
    assert_non_null(h);
    lv2_host_set(h, "gain", 0);   /* the output in pascals */
    lv2_host_set(h, "distance", DISTANCE_M);
    lv2_host_set(h, "absorption", 1);
    lv2_host_set(h, "refraction", 1);
    size_t blocks = (size_t)(SECONDS * rate_hz) / BLOCK;
    out->frames = blocks * BLOCK;
    out->left = calloc(out->frames, sizeof(float));
    out->right = calloc(out->frames, sizeof(float));
    out->rt_calls = 0;
    out->worker_allocs = 0;
    for (size_t b = 0; b < blocks; b++) {
        size_t start = b * BLOCK;
        for (size_t i = 0; i < NOTES; i++) {
            const note *n = &script[i];
            size_t on = frame_of(n->on_s, rate_hz), off = frame_of(n->off_s, rate_hz);
            if (on >= start && on < start + BLOCK) {
                lv2_host_set(h, "preset", (float)n->preset);
                lv2_host_set(h, "azimuth", n->azimuth_deg);
                lv2_host_set(h, "strokes", n->strokes);
                lv2_host_midi(h, (uint32_t)(on - start), 0x90, n->key, n->velocity);
            }
            if (off >= start && off < start + BLOCK)
                lv2_host_midi(h, (uint32_t)(off - start), 0x80, n->key, 0);
        }
        out->rt_calls += lv2_run_guarded(h, BLOCK, out->left + start, out->right + start);
        lv2_work_on_thread(h, &out->worker_allocs);
    }
    out->work_calls = lv2_host_work_calls(h);
    out->responses = lv2_host_responses(h);
    out->discharges = lv2_host_get(h, "discharges");
    out->failures = lv2_host_get(h, "failures");
    lv2_host_destroy(h);
}

/* The first frame in [from, to) where either ear is not silent, or to. */
static size_t first_sound(const run_result *r, size_t from, size_t to)
{
    for (size_t i = from; i < to; i++)
        if (fabsf(r->left[i]) > SILENT_PA || fabsf(r->right[i]) > SILENT_PA)
            return i;
    return to;
}

static float peak(const run_result *r, size_t from, size_t to)
{
    float m = 0;
    for (size_t i = from; i < to && i < r->frames; i++) {
        m = fmaxf(m, fabsf(r->left[i]));
        m = fmaxf(m, fabsf(r->right[i]));
    }
    return m;
}

static void test_play(void **state)
{
    double rate_hz = *(const double *)*state;
    run_result r;
    play(rate_hz, &r);
    assert_int_equal(r.rt_calls, 0);
    /* every note-on and note-off went through the worker; each note-on and
     * the plasma ball's note-off came back as a response */
    assert_int_equal(r.work_calls, 2 * NOTES);
    assert_int_equal(r.responses, NOTES + 1);
    assert_true(r.discharges == (float)NOTES);
    assert_true(r.failures == 0);
    /* the guard sees calls made inside the loaded module */
    assert_true(r.worker_allocs > 0);
    for (size_t i = 0; i < NOTES; i++) {
        const note *n = &script[i];
        size_t on = frame_of(n->on_s, rate_hz);
        /* the tree is posted by the worker after the note's block, and
         * sounds from the start of the next one */
        size_t emit = (on / BLOCK + 1) * BLOCK;
        size_t earliest =
            emit + (size_t)(((n->distance_m - n->extent_m) / C_M_S - n->lead_s) * rate_hz);
        size_t latest = emit + (size_t)((n->distance_m + n->extent_m) / C_M_S * rate_hz) + 1;
        size_t first = first_sound(&r, on, latest + 1);
        fprintf(stderr,
                "%.0f Hz note %zu: first sound %.2f ms after emission (%.2f..%.2f), peak %g\n",
                rate_hz, i, 1e3 * (double)(first - emit) / rate_hz,
                1e3 * (double)(earliest - emit) / rate_hz, 1e3 * (double)(latest - emit) / rate_hz,
                (double)peak(&r, first, first + (size_t)(0.05 * rate_hz)));
        assert_true(first >= earliest);
        assert_true(first <= latest);
        assert_true(peak(&r, first, first + (size_t)(0.05 * rate_hz)) > AUDIBLE_PA);
    }
    /* the held plasma ball sounds in every 60 ms until its note-off, and is
     * silent 0.3 s after it */
    const note *ball = &script[2];
    size_t hold_end = frame_of(ball->off_s, rate_hz);
    for (size_t f = frame_of(ball->on_s + 0.05, rate_hz); f + (size_t)(0.06 * rate_hz) < hold_end;
         f += (size_t)(0.06 * rate_hz))
        assert_true(peak(&r, f, f + (size_t)(0.06 * rate_hz)) > AUDIBLE_PA);
    assert_true(peak(&r, frame_of(ball->off_s + 0.3, rate_hz), frame_of(script[3].on_s, rate_hz)) <=
                SILENT_PA);
    free(r.left);
    free(r.right);
}

/* Rates the engine refuses: instantiate fails (with a message) rather than
 * returning an instance that cannot play. */
static void test_unsupported_rates(void **state)
{
    (void)state;
    assert_null(lv2_host_create(4000));
    assert_null(lv2_host_create(500000));
    /* 0 once gave an instance that silently ran at 48 kHz */
    assert_null(lv2_host_create(0));
    assert_null(lv2_host_create(-48000));
    lv2_host *h = lv2_host_create(8000);
    assert_non_null(h);
    lv2_host_destroy(h);
}

/* A host whose feature list holds an entry with a NULL URI (lv2file's):
 * instantiate skips it instead of crashing in strcmp, then refuses for
 * the missing map and worker features. */
static void test_null_feature_uri(void **state)
{
    (void)state;
    LilvWorld *world = lilv_world_new();
    assert_non_null(world);
    lilv_world_load_all(world); /* LV2_PATH */
    LilvNode *uri = lilv_new_uri(world, FULGUR_LV2_URI);
    const LilvPlugin *plugin = lilv_plugins_get_by_uri(lilv_world_get_all_plugins(world), uri);
    assert_non_null(plugin);
    static const LV2_Feature broken = {NULL, NULL};
    const LV2_Feature *const features[] = {&broken, NULL};
    LilvInstance *in = lilv_plugin_instantiate(plugin, 48000, features);
    assert_null(in);
    lilv_node_free(uri);
    lilv_world_free(world);
}

static double rate_44k = 44100, rate_48k = 48000;

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_prestate(test_play, &rate_44k),
        cmocka_unit_test_prestate(test_play, &rate_48k),
        cmocka_unit_test(test_unsupported_rates),
        cmocka_unit_test(test_null_feature_uri),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
