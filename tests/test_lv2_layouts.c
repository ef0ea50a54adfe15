/* fulgur.lv2's plugins in every output layout, through liblilv:
 *   - the binaural plugin's render of a note equals the engine's own
 *     binaural render of the same discharge through the same SOFA file
 *     (the MIT KEMAR set, read at the host's rate, as fulgur render reads
 *     it), at 48 and 44.1 kHz, and is not the stereo plugin's;
 *   - the ambisonic plugins have (N+1)^2 outputs, each equal to the
 *     engine's ambisonic render of order N, and the same W (ACN 0) in every
 *     order;
 *   - a SOFA file named through the parameter that is missing or not SOFA
 *     is refused through the host's log, the notify port keeps the file in
 *     use, and the previous engine plays on: the output is the one without
 *     the request;
 *   - a good file swaps the engine in while the old one plays its notes
 *     out: a note played before the swap is not cut, one after it sounds
 *     through the new engine, and the output is the one without the swap;
 *     a held note sounds through it until its note-off;
 *   - the state carries the file to a fresh instance; one whose file has
 *     gone says so and plays on; one restored while a swap's reply is on
 *     its way wins over it;
 *   - swapped-out engines are destroyed once played out;
 *   - the binaural plugin reports its delay (FG_BINAURAL_LATENCY_FRAMES)
 *     on its latency port, which the other plugins do not have.
 * run() and the responses never allocate or lock (the guard), the swap
 * included. */
#define _POSIX_C_SOURCE 200809L /* mkstemp */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "fulgur/fulgur.h"
#include "lv2_fixture.h"
#include "sofa_hrir.h"

/* The host's rate: 48 kHz (the KEMAR file's 44.1 kHz converted at load),
 * and 44.1 kHz for one case (read as it is). */
static double rate_hz = 48000.0;
#define BLOCK 256
#define BLOCKS 282        /* 1.5 s */
#define NOTE_BLOCK 1      /* the note-on's block */
#define NOTE_FRAME 7      /* its frame in it */
#define KEY 60
#define VELOCITY 100
#define DISTANCE_M 100.0  /* the distance control: note 60 at 100 m */
#define AZIMUTH_DEG 50.0
#define SEED 3
/* the plugin's output against the engine's, relative to its peak */
#define MATCH_TOLERANCE 1e-6
#define SOFA_URI FULGUR_LV2_URI "#sofa"
/* The same KEMAR file by another name (Debian's link): a real swap to the
 * same responses. */
#define KEMAR_LINK "/usr/share/libmysofa/default.sofa"

typedef struct take {
    float *plane[LV2_HOST_CHANNELS_MAX];
    unsigned channels;
    size_t frames;
} take;

static void take_init(take *t, unsigned channels)
{
    t->channels = channels;
    t->frames = (size_t)BLOCKS * BLOCK;
    for (unsigned k = 0; k < channels; k++) {
        t->plane[k] = calloc(t->frames, sizeof(float));
        assert_non_null(t->plane[k]);
    }
}

static void take_free(take *t)
{
    for (unsigned k = 0; k < t->channels; k++)
        free(t->plane[k]);
}

static float take_peak(const take *t)
{
    float m = 0;
    for (unsigned k = 0; k < t->channels; k++)
        for (size_t i = 0; i < t->frames; i++)
            m = fmaxf(m, fabsf(t->plane[k][i]));
    return m;
}

/* The largest difference of channel ka of a and kb of b. */
static float plane_diff(const take *a, unsigned ka, const take *b, unsigned kb)
{
    float m = 0;
    for (size_t i = 0; i < a->frames; i++)
        m = fmaxf(m, fabsf(a->plane[ka][i] - b->plane[kb][i]));
    return m;
}

static float take_diff(const take *a, const take *b)
{
    assert_int_equal(a->channels, b->channels);
    float m = 0;
    for (unsigned k = 0; k < a->channels; k++)
        m = fmaxf(m, plane_diff(a, k, b, k));
    return m;
}

static lv2_host *open_plugin(const char *suffix)
{
    char uri[256];
    snprintf(uri, sizeof uri, "%s%s", FULGUR_LV2_URI, suffix);
    lv2_host *h = lv2_host_create_plugin(uri, rate_hz);
    assert_non_null(h);
    lv2_host_set(h, "gain", 0); /* pascals */
    lv2_host_set(h, "preset", FG_PRESET_LIGHTNING);
    lv2_host_set(h, "distance", DISTANCE_M);
    lv2_host_set(h, "azimuth", AZIMUTH_DEG);
    lv2_host_set(h, "strokes", 1);
    lv2_host_set(h, "seed", SEED);
    return h;
}

/* What happens at the start of a block of a run: */
typedef struct cue {
    int block;
    int key;            /* a note-on of this key, or 0 */
    const char *sofa;   /* a patch:Set of the SOFA file, or NULL */
    int off_key;        /* a note-off of this key, or 0 */
} cue;

/* Plays blocks with the cues into t (the plugin's channels), the worker
 * after each block; returns what the guard counted in run(). */
static unsigned long play(lv2_host *h, const cue *cues, size_t cue_count, take *t)
{
    take_init(t, lv2_host_channels(h));
    unsigned long rt_calls = 0;
    for (int b = 0; b < BLOCKS; b++) {
        for (size_t c = 0; c < cue_count; c++) {
            if (cues[c].block != b)
                continue;
            if (cues[c].key)
                assert_int_equal(lv2_host_midi(h, NOTE_FRAME, 0x90, (uint8_t)cues[c].key,
                                               VELOCITY), 0);
            if (cues[c].sofa)
                assert_int_equal(lv2_host_set_path(h, SOFA_URI, cues[c].sofa), 0);
            if (cues[c].off_key)
                assert_int_equal(lv2_host_midi(h, NOTE_FRAME, 0x80, (uint8_t)cues[c].off_key, 0),
                                 0);
        }
        float *planes[LV2_HOST_CHANNELS_MAX];
        for (unsigned k = 0; k < t->channels; k++)
            planes[k] = t->plane[k] + (size_t)b * BLOCK;
        rt_guard_arm();
        lv2_host_run_planes(h, BLOCK, planes);
        rt_guard_counts counts = rt_guard_disarm();
        rt_calls += rt_guard_total(&counts);
        lv2_work_on_thread(h, NULL);
    }
    return rt_calls;
}

static void play_note(const char *suffix, take *t)
{
    lv2_host *h = open_plugin(suffix);
    const cue note = {NOTE_BLOCK, KEY, NULL, 0};
    assert_int_equal(play(h, &note, 1, t), 0);
    assert_true(lv2_host_get(h, "discharges") == 1);
    assert_true(lv2_host_get(h, "failures") == 0);
    /* the binaural plugin reports its filters' delay; the others have none */
    if (!strcmp(suffix, "-binaural"))
        assert_true(lv2_host_get(h, "latency") == (float)FG_BINAURAL_LATENCY_FRAMES);
    else
        assert_true(isnan(lv2_host_get(h, "latency")));
    lv2_host_destroy(h);
}

/* The plugin's note, rendered by the engine directly: the bolt the note
 * map grows (lightning strikes DISTANCE_M away at AZIMUTH_DEG, the listener
 * 1.7 m up facing +y), posted at the start of the block after the note's,
 * as the worker posts it. */
static void engine_note(const fg_engine_config *config, take *t)
{
    fg_engine *e;
    assert_int_equal(fg_engine_create(config, &e), FG_OK);
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    fg_tree *tree;
    assert_int_equal(fg_tree_create(1024, &tree), FG_OK);
    double az = AZIMUTH_DEG * 3.14159265358979323846 / 180;
    fg_lightning_config lp = {.strike_m = {DISTANCE_M * sin(az), DISTANCE_M * cos(az)},
                              .seed = (uint64_t)SEED << 32}; /* the instance's first note */
    assert_int_equal(fg_lightning_generate(&lp, tree, NULL), FG_OK);
    fg_discharge d = {.emit_time_s = FG_EMIT_NOW, .seed = lp.seed, .strokes = 1,
                      .nodes = fg_tree_nodes(tree), .node_count = fg_tree_count(tree)};
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), FG_OK);
    d.sound.ps0_pa *= VELOCITY / 127.0;
    take_init(t, config->channels);
    for (int b = 0; b < BLOCKS; b++) {
        if (b == NOTE_BLOCK + 1)
            assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        float *planes[LV2_HOST_CHANNELS_MAX];
        for (unsigned k = 0; k < t->channels; k++)
            planes[k] = t->plane[k] + (size_t)b * BLOCK;
        assert_int_equal(fg_engine_render(e, planes, BLOCK), FG_OK);
    }
    fg_tree_destroy(tree);
    fg_engine_destroy(e);
}

static void test_binaural_is_the_engines(void **state)
{
    rate_hz = *(const double *)*state;
    take plugin, stereo, engine;
    play_note("-binaural", &plugin);
    assert_int_equal(plugin.channels, 2);
    sofa_hrirs hrirs;
    char err[600];
    assert_int_equal(sofa_hrirs_read(SOFA_DEFAULT_FILE, rate_hz, &hrirs, err, sizeof err), 0);
    fg_engine_config config = {.sample_rate_hz = rate_hz, .channels = 2,
                               .layout = FG_LAYOUT_BINAURAL, .hrirs = &hrirs.set};
    engine_note(&config, &engine);
    sofa_hrirs_free(&hrirs);
    play_note("", &stereo);
    float peak = take_peak(&engine), diff = take_diff(&plugin, &engine);
    float from_stereo = take_diff(&plugin, &stereo);
    fprintf(stderr,
            "binaural at %.0f Hz: peak %g Pa, plugin - engine %g (%.2g of the peak), "
            "plugin - stereo plugin %g\n",
            rate_hz, (double)peak, (double)diff, (double)(diff / peak), (double)from_stereo);
    assert_true(peak > 1e-3);
    assert_true(diff <= MATCH_TOLERANCE * peak);
    /* the measured head is not the spherical one */
    assert_true(from_stereo > 0.1f * peak);
    take_free(&plugin);
    take_free(&stereo);
    take_free(&engine);
    rate_hz = 48000.0;
}

static void test_ambisonics_are_the_engines(void **state)
{
    (void)state;
    take w[3];
    for (uint32_t order = 1; order <= 3; order++) {
        char suffix[32];
        snprintf(suffix, sizeof suffix, "-ambisonics%u", order);
        take plugin, engine;
        play_note(suffix, &plugin);
        assert_int_equal(plugin.channels, (order + 1) * (order + 1));
        fg_engine_config config = {.sample_rate_hz = rate_hz,
                                   .channels = (order + 1) * (order + 1),
                                   .layout = FG_LAYOUT_AMBISONICS, .ambisonic_order = order};
        engine_note(&config, &engine);
        float peak = take_peak(&engine), diff = take_diff(&plugin, &engine);
        fprintf(stderr, "ambisonics %u: %u channels, peak %g Pa, plugin - engine %g\n", order,
                plugin.channels, (double)peak, (double)diff);
        assert_true(peak > 1e-3);
        assert_true(diff <= MATCH_TOLERANCE * peak);
        /* a direction channel has sound too (the bolt is off the axes) */
        assert_true(plane_diff(&plugin, 1, &plugin, 0) > 0);
        w[order - 1] = plugin;
        take_free(&engine);
    }
    /* W, the pressure at the head's centre, does not depend on the order */
    float wpeak = 0;
    for (size_t i = 0; i < w[0].frames; i++)
        wpeak = fmaxf(wpeak, fabsf(w[0].plane[0][i]));
    for (int o = 1; o < 3; o++) {
        float d = plane_diff(&w[0], 0, &w[o], 0);
        fprintf(stderr, "W of order %d - W of order 1: %g (peak %g)\n", o + 1, (double)d,
                (double)wpeak);
        assert_true(wpeak > 1e-3);
        assert_true(d <= MATCH_TOLERANCE * wpeak);
    }
    for (int o = 0; o < 3; o++)
        take_free(&w[o]);
}

/* A bad file after the note: refused, logged, the same sound as without. */
static void test_bad_sofa_plays_on(void **state)
{
    (void)state;
    char not_sofa[] = "/tmp/fulgur_lv2_not_sofaXXXXXX";
    int fd = mkstemp(not_sofa);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, "not a SOFA file\n", 16), 16);
    close(fd);
    take reference, bad;
    play_note("-binaural", &reference);
    lv2_host *h = open_plugin("-binaural");
    const cue cues[] = {{NOTE_BLOCK, KEY, NULL, 0},
                        {40, 0, "/nonexistent/kemar.sofa", 0},
                        {41, 0, not_sofa, 0}};
    assert_int_equal(play(h, cues, 3, &bad), 0);
    const char *log = lv2_host_last_log(h);
    fprintf(stderr, "logged: %s", log);
    assert_non_null(strstr(log, not_sofa));
    assert_non_null(strstr(log, "the previous file plays on"));
    assert_string_equal(lv2_host_notified_path(h), SOFA_DEFAULT_FILE);
    assert_true(lv2_host_get(h, "discharges") == 1);
    float diff = take_diff(&reference, &bad);
    fprintf(stderr, "bad files: output - output without them %g\n", (double)diff);
    assert_true(diff == 0);
    lv2_host_destroy(h);
    unlink(not_sofa);
    take_free(&reference);
    take_free(&bad);
}

/* The first note sounds through the swap; the second is played by the new
 * engine: with the same responses, the output is the one without the swap. */
static void test_swap_keeps_notes(void **state)
{
    (void)state;
    const cue plain[] = {{NOTE_BLOCK, KEY, NULL, 0}, {100, KEY + 5, NULL, 0}};
    const cue swapped[] = {
        {NOTE_BLOCK, KEY, NULL, 0}, {60, 0, KEMAR_LINK, 0}, {100, KEY + 5, NULL, 0}};
    take reference, swap;
    lv2_host *h = open_plugin("-binaural");
    assert_int_equal(play(h, plain, 2, &reference), 0);
    lv2_host_destroy(h);
    h = open_plugin("-binaural");
    assert_int_equal(play(h, swapped, 3, &swap), 0);
    assert_string_equal(lv2_host_notified_path(h), KEMAR_LINK);
    assert_true(lv2_host_get(h, "discharges") == 2);
    assert_true(lv2_host_get(h, "failures") == 0);
    float peak = take_peak(&reference), diff = take_diff(&reference, &swap);
    fprintf(stderr, "swap: peak %g Pa, output - output without the swap %g\n", (double)peak,
            (double)diff);
    assert_true(peak > 1e-3);
    assert_true(diff <= MATCH_TOLERANCE * peak);

    /* the state carries the file: a fresh instance restored plays it */
    LilvState *snap = lv2_host_save(h);
    assert_non_null(snap);
    lv2_host *fresh = open_plugin("-binaural");
    lv2_host_restore(fresh, snap);
    take after;
    const cue none = {-1, 0, NULL, 0};
    assert_int_equal(play(fresh, &none, 1, &after), 0);
    assert_string_equal(lv2_host_notified_path(fresh), KEMAR_LINK);
    lilv_state_free(snap);
    lv2_host_destroy(fresh);
    lv2_host_destroy(h);
    take_free(&after);
    take_free(&reference);
    take_free(&swap);
}

/* A new name (from the template link, ending in XXXXXX) for the KEMAR set:
 * a symbolic link the test can take away. */
static void link_to_kemar(char *link)
{
    int fd = mkstemp(link);
    assert_true(fd >= 0);
    close(fd);
    unlink(link);
    assert_int_equal(symlink(SOFA_DEFAULT_FILE, link), 0);
}

/* A state naming a file that has gone since: the restore says so through
 * the log, and the fresh instance plays the file it had. */
static void test_restore_missing_file(void **state)
{
    (void)state;
    char link[] = "/tmp/fulgur_lv2_kemarXXXXXX";
    link_to_kemar(link);
    lv2_host *h = open_plugin("-binaural");
    const cue swap = {0, 0, link, 0};
    take t;
    assert_int_equal(play(h, &swap, 1, &t), 0);
    take_free(&t);
    assert_string_equal(lv2_host_notified_path(h), link);
    LilvState *snap = lv2_host_save(h);
    assert_non_null(snap);
    unlink(link);
    lv2_host *fresh = open_plugin("-binaural");
    lv2_host_restore(fresh, snap);
    fprintf(stderr, "restore logged: %s", lv2_host_last_log(fresh));
    assert_non_null(strstr(lv2_host_last_log(fresh), link));
    assert_non_null(strstr(lv2_host_last_log(fresh), "the previous file plays on"));
    const cue none = {-1, 0, NULL, 0};
    assert_int_equal(play(fresh, &none, 1, &t), 0);
    assert_string_equal(lv2_host_notified_path(fresh), SOFA_DEFAULT_FILE);
    take_free(&t);
    lilv_state_free(snap);
    lv2_host_destroy(fresh);
    lv2_host_destroy(h);
}

/* A restore between a swap's work and its reply: the reply names an engine
 * restore has destroyed, and is dropped; the restored file plays. */
static void test_restore_during_swap(void **state)
{
    (void)state;
    char link[] = "/tmp/fulgur_lv2_kemarXXXXXX";
    link_to_kemar(link);
    lv2_host *saved = open_plugin("-binaural");
    const cue to_link = {0, 0, link, 0};
    take t;
    assert_int_equal(play(saved, &to_link, 1, &t), 0);
    take_free(&t);
    LilvState *snap = lv2_host_save(saved);
    assert_non_null(snap);

    lv2_host *h = open_plugin("-binaural");
    float l[BLOCK], r[BLOCK];
    assert_int_equal(lv2_host_set_path(h, SOFA_URI, KEMAR_LINK), 0);
    lv2_host_run(h, BLOCK, l, r);
    assert_int_equal(lv2_work_on_thread(h, NULL), 1); /* the new engine, its reply queued */
    lv2_host_restore(h, snap);
    const cue note = {2, KEY, NULL, 0};
    assert_int_equal(play(h, &note, 1, &t), 0);
    assert_string_equal(lv2_host_notified_path(h), link);
    assert_true(lv2_host_get(h, "discharges") == 1);
    assert_true(take_peak(&t) > 1e-3);
    take_free(&t);
    lilv_state_free(snap);
    lv2_host_destroy(h);
    lv2_host_destroy(saved);
    unlink(link);
}

/* A plasma ball held through a swap: it sounds on in the old engine, its
 * note-off ends it there, and the old engine is then retired. */
static void test_held_note_through_swap(void **state)
{
    (void)state;
    lv2_host *h = open_plugin("-binaural");
    lv2_host_set(h, "preset", FG_PRESET_PLASMA_BALL);
    lv2_host_set(h, "distance", 1);
    lv2_host_set(h, "gain", 0);
    const cue cues[] = {{NOTE_BLOCK, KEY, NULL, 0}, {20, 0, KEMAR_LINK, 0}, {100, 0, NULL, KEY}};
    take t;
    assert_int_equal(play(h, cues, 3, &t), 0);
    /* sounding between the swap and the note-off, silent 0.3 s after it */
    float held = 0, after = 0;
    for (unsigned k = 0; k < 2; k++)
        for (size_t i = 0; i < t.frames; i++) {
            if (i >= 30 * BLOCK && i < 100 * BLOCK)
                held = fmaxf(held, fabsf(t.plane[k][i]));
            if (i >= 100 * BLOCK + (size_t)(0.3 * rate_hz))
                after = fmaxf(after, fabsf(t.plane[k][i]));
        }
    fprintf(stderr, "held through the swap: peak %g Pa, after its note-off %g Pa, %u worker "
                    "calls\n",
            (double)held, (double)after, lv2_host_work_calls(h));
    assert_true(held > 1e-4);
    assert_true(after < 1e-6);
    assert_true(lv2_host_get(h, "failures") == 0);
    /* the note-on, the file, the note-off, the old engine retired */
    assert_int_equal(lv2_host_work_calls(h), 4);
    lv2_host_destroy(h);
    take_free(&t);
}

/* Swapped-out engines are destroyed once played out: four swaps in a row
 * (a short spark before them) all succeed though the plugin holds four
 * engines at most, and each ends in a retire request to the worker. */
static void test_swaps_retire(void **state)
{
    (void)state;
    lv2_host *h = open_plugin("-binaural");
    lv2_host_set(h, "preset", FG_PRESET_SPARK_BALLS);
    lv2_host_set(h, "distance", 2);
    const cue cues[] = {{NOTE_BLOCK, KEY, NULL, 0},
                        {10, 0, KEMAR_LINK, 0},
                        {80, 0, SOFA_DEFAULT_FILE, 0},
                        {150, 0, KEMAR_LINK, 0},
                        {220, 0, SOFA_DEFAULT_FILE, 0}};
    take t;
    assert_int_equal(play(h, cues, 5, &t), 0);
    fprintf(stderr, "swaps: %u worker calls, log \"%s\"\n", lv2_host_work_calls(h),
            lv2_host_last_log(h));
    assert_string_equal(lv2_host_last_log(h), "");
    assert_string_equal(lv2_host_notified_path(h), SOFA_DEFAULT_FILE);
    /* the note, four files, four engines retired (0.25 s after each swap) */
    assert_int_equal(lv2_host_work_calls(h), 1 + 4 + 4);
    assert_true(lv2_host_get(h, "failures") == 0);
    assert_true(take_peak(&t) > 1e-3);
    lv2_host_destroy(h);
    take_free(&t);
}

static double rate_48k = 48000, rate_44k = 44100;

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_prestate(test_binaural_is_the_engines, &rate_48k),
        cmocka_unit_test_prestate(test_binaural_is_the_engines, &rate_44k),
        cmocka_unit_test(test_ambisonics_are_the_engines),
        cmocka_unit_test(test_bad_sofa_plays_on),
        cmocka_unit_test(test_swap_keeps_notes),
        cmocka_unit_test(test_restore_missing_file),
        cmocka_unit_test(test_restore_during_swap),
        cmocka_unit_test(test_held_note_through_swap),
        cmocka_unit_test(test_swaps_retire),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
