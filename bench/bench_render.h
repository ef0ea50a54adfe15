/* Timing one discharge through the engine's real path: post, then pull
 * blocks offline as fast as possible until the voice has finished. */
#ifndef FULGUR_BENCH_RENDER_H
#define FULGUR_BENCH_RENDER_H

#include <stddef.h>

#include "fulgur/fulgur.h"

/* fulgur render's chunk (SCENE_RENDER_CHUNK_FRAMES, fg_engine_config.chunk_frames) */
#define BENCH_CHUNK_FRAMES 1024

typedef struct bench_run {
    double post_s;     /* fg_engine_post: preparation and the arrival sort */
    double render_s;   /* every fg_engine_render call until the voice ended */
    double post_cpu_s; /* the same two in the thread's CPU time */
    double render_cpu_s;
    double sound_s;    /* length of the sound produced */
} bench_run;

/* Renders nodes[0..count) as one discharge with params heard from
 * listener, in blocks of block frames at 48 kHz, in chunks of
 * BENCH_CHUNK_FRAMES as fulgur render renders. Exits on an engine error. */
bench_run bench_render_tree(const fg_node *nodes, size_t count, const fg_sound_config *params,
                            const fg_listener *listener, unsigned block);

/* The same, a chunk a block (as a host paced by a device renders), with
 * propagation effects and a voice model. */
bench_run bench_render_tree_with(const fg_node *nodes, size_t count, const fg_sound_config *params,
                                 const fg_propagation_config *prop, fg_voice_model model,
                                 const fg_listener *listener, unsigned block);

/* The same, a chunk a block, in an output layout (fg_engine_config.layout,
 * ambisonic_order, hrirs: NULL but for binaural). */
bench_run bench_render_tree_layout(const fg_node *nodes, size_t count,
                                   const fg_sound_config *params, const fg_propagation_config *prop,
                                   fg_voice_model model, fg_layout layout, uint32_t order,
                                   const fg_hrir_set *hrirs, const fg_listener *listener,
                                   unsigned block);

#endif
