/* Designer thunder through the engine: a clap block is heard as the
 * loudest moment of the rendered thunder, at the designed time. */
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

static void clap_heard_at_designed_time(void **state)
{
    (void)state;
    static const double skeleton[] = {0, 0, 5000, 0, 0, 0};
    const fg_thunder_block blocks[] = {{FG_THUNDER_ROAR, 0.1, 0.25, 0.5},
                                       {FG_THUNDER_CLAP, 0.3, 0.45, 1},
                                       {FG_THUNDER_RUMBLE, 0.55, 0.8, 1}};
    fg_lightning_params lp = {.skeleton_m = skeleton,
                              .skeleton_points = 2,
                              .blocks = blocks,
                              .block_count = 3,
                              .listener_m = {3000, 0, 1.7},
                              .seed = 2026};
    fg_tree *tree;
    fg_lightning_info info;
    assert_int_equal(fg_tree_create(0, &tree), FG_OK);
    assert_int_equal(fg_lightning_generate(&lp, tree, &info), FG_OK);

    fg_engine *e;
    fg_engine_config cfg = {.sample_rate_hz = RATE, .channels = 1, .max_block_frames = BLOCK};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_engine_get_config(e, &cfg);
    fg_listener head = {.position = {3000, 0, 1.7}, .forward = {-1, 0, 0}, .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    fg_discharge d = {.nodes = fg_tree_nodes(tree),
                      .node_count = fg_tree_count(tree),
                      .emit_time_s = 0,
                      .strokes = 1,
                      .seed = 1};
    assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), FG_OK);
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);

    double designed_s = info.blocks[1].distance_m / cfg.speed_of_sound_m_s;
    size_t frames = (size_t)((designed_s + 1.5) * RATE);
    frames -= frames % BLOCK;
    float *out = malloc(frames * sizeof *out);
    double *energy = malloc((frames + 1) * sizeof *energy);
    assert_non_null(out);
    assert_non_null(energy);
    for (size_t at = 0; at < frames; at += BLOCK) {
        float *plane[1] = {out + at};
        assert_int_equal(fg_engine_render(e, plane, BLOCK), FG_OK);
    }
    energy[0] = 0;
    for (size_t i = 0; i < frames; i++)
        energy[i + 1] = energy[i] + (double)out[i] * out[i];

    /* the loudest 10 ms of the whole sound */
    size_t best = 0;
    double best_e = -1;
    for (size_t i = 0; i + WINDOW <= frames; i += 24) {
        double w = energy[i + WINDOW] - energy[i];
        if (w > best_e)
            best_e = w, best = i;
    }
    double peak_s = (best + WINDOW / 2) / RATE;
    assert_float_equal(peak_s, designed_s, 0.005);
    /* and it stands out: nothing else within a factor 3 away from it */
    for (size_t i = 0; i + WINDOW <= frames; i += 24) {
        if (fabs((i + WINDOW / 2) / RATE - peak_s) < 0.1)
            continue;
        assert_true(energy[i + WINDOW] - energy[i] < best_e / 3);
    }
    fg_engine_stats st;
    fg_engine_get_stats(e, &st);
    assert_int_equal(st.late_events, 0);
    free(out);
    free(energy);
    fg_engine_destroy(e);
    fg_tree_destroy(tree);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(clap_heard_at_designed_time),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
