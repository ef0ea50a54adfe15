#include <stdio.h>
#include <stdlib.h>

#include "bench_render.h"
#include "bench_util.h"

static void check(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "%s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

/* The render in chunks of chunk frames (fg_engine_config.chunk_frames). */
static bench_run render_tree(const fg_node *nodes, size_t count, const fg_sound_config *params,
                             const fg_propagation_config *prop, fg_voice_model model,
                             fg_layout layout, uint32_t order, const fg_hrir_set *hrirs,
                             const fg_listener *listener, unsigned block, uint32_t chunk)
{
    fg_engine_config cfg = {.sample_rate_hz = 48000,
                            .max_block_frames = block,
                            .segment_capacity = (uint32_t)(2 * count),
                            .max_voices = 1,
                            .layout = layout,
                            .ambisonic_order = order,
                            .hrirs = hrirs,
                            .chunk_frames = chunk};
    fg_engine *e;
    check(fg_engine_create(&cfg, &e), "create");
    check(fg_engine_set_listener(e, listener), "listener");
    fg_engine_get_config(e, &cfg);
    float *planes[16];
    for (uint32_t ch = 0; ch < cfg.channels; ch++)
        planes[ch] = malloc(block * sizeof(float));
    fg_discharge d = {.nodes = nodes, .node_count = count, .sound = *params, .strokes = 1,
                      .emit_time_s = 0, .seed = 1, .propagation = *prop, .model = model};
    bench_run run = {0};
    double t0 = bench_now_s(), c0 = bench_cpu_s();
    check(fg_engine_post(e, &d, NULL), "post");
    double t1 = bench_now_s(), c1 = bench_cpu_s();
    fg_engine_report st = {0};
    uint64_t frames = 0;
    while (st.finished == 0) {
        check(fg_engine_render(e, planes, block), "render");
        frames += block;
        fg_engine_get_report(e, &st);
    }
    double t2 = bench_now_s(), c2 = bench_cpu_s();
    run.post_s = t1 - t0;
    run.render_s = t2 - t1;
    run.post_cpu_s = c1 - c0;
    run.render_cpu_s = c2 - c1;
    run.sound_s = (double)frames / 48000.0;
    for (uint32_t ch = 0; ch < cfg.channels; ch++)
        free(planes[ch]);
    fg_engine_destroy(e);
    return run;
}

bench_run bench_render_tree(const fg_node *nodes, size_t count, const fg_sound_config *params,
                            const fg_listener *listener, unsigned block)
{
    return render_tree(nodes, count, params, &(fg_propagation_config){0}, FG_MODEL_WM,
                       FG_LAYOUT_STEREO, 0, NULL, listener, block, BENCH_CHUNK_FRAMES);
}

bench_run bench_render_tree_with(const fg_node *nodes, size_t count, const fg_sound_config *params,
                                 const fg_propagation_config *prop, fg_voice_model model,
                                 const fg_listener *listener, unsigned block)
{
    return render_tree(nodes, count, params, prop, model, FG_LAYOUT_STEREO, 0, NULL, listener,
                       block, 0);
}

bench_run bench_render_tree_layout(const fg_node *nodes, size_t count,
                                   const fg_sound_config *params, const fg_propagation_config *prop,
                                   fg_voice_model model, fg_layout layout, uint32_t order,
                                   const fg_hrir_set *hrirs, const fg_listener *listener,
                                   unsigned block)
{
    return render_tree(nodes, count, params, prop, model, layout, order, hrirs, listener, block, 0);
}
