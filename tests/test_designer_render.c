/* Designer thunder through the engine, measured from the rendered sound: a
 * clap feature is the loudest moment at its designed time, its stretch alone
 * sounds for a few milliseconds, a rumble's stretch for about its length / c,
 * and a roar's stretch is louder per metre than the plain channel. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "fulgur/fulgur.h"

#define RATE 24000.0
#define BLOCK 2048
#define WINDOW 240 /* 10 ms */

static const double skeleton[] = {0, 0, 5000, 0, 0, 0};
static const fg_thunder_feature features[] = {{FG_THUNDER_ROAR, 0.1, 0.25, 1},
                                          {FG_THUNDER_CLAP, 0.3, 0.45, 1},
                                          {FG_THUNDER_RUMBLE, 0.55, 0.8, 1}};
static const double listener[3] = {3000, 0, 1.7};

static fg_tree *design(size_t feature_count, fg_lightning_report *info)
{
    fg_lightning_config lp = {.skeleton_m = skeleton,
                              .skeleton_points = 2,
                              .features = features,
                              .feature_count = feature_count,
                              .listener_m = {listener[0], listener[1], listener[2]},
                              .seed = 2026};
    fg_tree *tree;
    assert_int_equal(fg_tree_create(0, &tree), FG_OK);
    assert_int_equal(fg_lightning_generate(&lp, tree, info), FG_OK);
    return tree;
}

/* Renders the nodes (one stroke, emitted at 0, heard at the listener, one
 * ear) for `seconds`, into the running energy sum e[0..frames] (Pa^2 s). */
static double *render_energy(const fg_node *nodes, size_t count, double seconds, size_t *frames)
{
    fg_engine *e;
    fg_engine_config cfg = {.sample_rate_hz = RATE, .channels = 1, .max_block_frames = BLOCK};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_listener head = {.position = {listener[0], listener[1], listener[2]},
                        .forward = {-1, 0, 0},
                        .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    fg_discharge d = {.nodes = nodes, .node_count = count, .strokes = 1, .seed = 1};
    /* table 1's short wave (T0 = 500 us): the geometry's timing, not the
     * wave's length, sets the durations measured here */
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING_TABLE1, &d.sound), FG_OK);
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    size_t n = (size_t)(seconds * RATE);
    n += BLOCK - n % BLOCK;
    double *energy = malloc((n + 1) * sizeof *energy);
    float feature[BLOCK], *plane[1] = {feature};
    assert_non_null(energy);
    energy[0] = 0;
    for (size_t at = 0; at < n; at += BLOCK) {
        assert_int_equal(fg_engine_render(e, plane, BLOCK), FG_OK);
        for (size_t i = 0; i < BLOCK; i++)
            energy[at + i + 1] = energy[at + i] + (double)feature[i] * feature[i] / RATE;
    }
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.late_events, 0);
    fg_engine_destroy(e);
    *frames = n;
    return energy;
}

/* The main-channel nodes first-1 .. last as a tree of their own. */
static fg_node *stretch(const fg_node *n, const fg_lightning_stretch *s, size_t *count)
{
    *count = s->last_node - s->first_node + 2;
    fg_node *out = malloc(*count * sizeof *out);
    assert_non_null(out);
    for (size_t i = 0; i < *count; i++) {
        out[i] = n[s->first_node - 1 + i];
        out[i].parent = (int32_t)i - 1;
    }
    return out;
}

/* Seconds between 5 % and 95 % of the energy. */
static double energy_duration_s(const double *e, size_t frames)
{
    size_t a = 0, b = 0;
    while (e[a] < 0.05 * e[frames])
        a++;
    while (e[b] < 0.95 * e[frames])
        b++;
    return (double)(b - a) / RATE;
}

static void clap_heard_at_designed_time(void **state)
{
    (void)state;
    fg_lightning_report info;
    fg_tree *tree = design(3, &info);
    double designed_s = info.features[1].distance_m / 343.0;
    size_t frames;
    double *e = render_energy(fg_tree_nodes(tree), fg_tree_count(tree), designed_s + 1.5, &frames);
    /* the loudest 10 ms of the whole sound, in 1 ms steps */
    size_t best = 0;
    double best_e = -1;
    for (size_t i = 0; i + WINDOW <= frames; i += 24)
        if (e[i + WINDOW] - e[i] > best_e)
            best_e = e[i + WINDOW] - e[i], best = i;
    double peak_s = (best + WINDOW / 2) / RATE;
    assert_float_equal(peak_s, designed_s, 0.005);
    /* and it stands out: nothing else within a factor 3 away from it */
    for (size_t i = 0; i + WINDOW <= frames; i += 24)
        if (fabs((i + WINDOW / 2) / RATE - peak_s) >= 0.1)
            assert_true(e[i + WINDOW] - e[i] < best_e / 3);
    free(e);
    fg_tree_destroy(tree);
}

static void stretches_sound_as_designed(void **state)
{
    (void)state;
    fg_lightning_report info, plain_info;
    fg_tree *tree = design(3, &info), *plain = design(0, &plain_info);
    const fg_node *n = fg_tree_nodes(tree);
    size_t count, frames;

    /* clap: its 750 m of channel sound within a few ms */
    fg_node *clap = stretch(n, &info.features[1], &count);
    double *e = render_energy(clap, count, 15, &frames);
    assert_true(energy_duration_s(e, frames) < 0.005);
    free(e);
    free(clap);

    /* rumble: 1250 m nearly end-on, heard for about 1250 m / c = 3.6 s */
    fg_node *rumble = stretch(n, &info.features[2], &count);
    e = render_energy(rumble, count, 15, &frames);
    double rumble_s = energy_duration_s(e, frames);
    assert_true(rumble_s > 0.6 * 1250 / 343.0 && rumble_s < 1.2 * 1250 / 343.0);
    free(e);
    free(rumble);

    /* roar: more sound per segment than the same stretch of a plain walk
     * (its sharper kinks cancel less between neighbours) */
    size_t roar_n, plain_n, f2;
    fg_node *roar = stretch(n, &info.features[0], &roar_n);
    e = render_energy(roar, roar_n, 18, &frames);
    fg_lightning_stretch same = {0, 0, 0};
    for (size_t i = 1; i < plain_info.main_nodes; i++) { /* heights 4500 .. 3750 m */
        double z = fg_tree_nodes(plain)[i].z;
        if (z <= 4500 && !same.first_node)
            same.first_node = i;
        if (z >= 3750)
            same.last_node = i;
    }
    fg_node *flat = stretch(fg_tree_nodes(plain), &same, &plain_n);
    double *e2 = render_energy(flat, plain_n, 18, &f2);
    double ratio = (e[frames] / (double)roar_n) / (e2[f2] / (double)plain_n);
    assert_true(ratio > 3);
    free(e);
    free(e2);
    free(roar);
    free(flat);
    fg_tree_destroy(tree);
    fg_tree_destroy(plain);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(clap_heard_at_designed_time),
        cmocka_unit_test(stretches_sound_as_designed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
