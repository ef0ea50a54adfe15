/* The one render loop: a built scene through a fresh real-time engine,
 * block by block, exactly as a device callback would drive it. fulgur
 * render (a WAV) and libfulgur-scene (the Python package's samples) both
 * render through it, so equal scenes give equal samples in both.
 *
 * Each block: the listener's pose at the block's start time, the
 * discharges due before the block's end plus SCENE_POST_LEAD_S posted in
 * time order (so that the engine prepares them off the audio path, as a
 * simulation thread would), fg_engine_render, the block handed to the sink,
 * fg_engine_collect. Aero objects are posted as the discharges are, and
 * their poses published with the listener's, sampled from their motion.
 * Fires are posted likewise, their flux turned into sound and pushed as
 * far ahead as their rings take (scene_fire_render.h). A scene without a
 * duration ends with the block in which the last discharge fell silent,
 * or at SCENE_MAX_DURATION_S. */
#ifndef HOST_SCENE_SCENE_RENDER_H
#define HOST_SCENE_SCENE_RENDER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "scene.h"
#include "scene_fire_render.h"

/* Discharges are posted this long before their emit time. */
#define SCENE_POST_LEAD_S 0.5

/* The block a render takes when the scene gives none: no device plays it
 * as it comes, and a longer block visits each sounding wave fewer times
 * (10^6 segments' whole process 13 % less CPU than at 256, the same peak;
 * 1024 saves more but maps 2 MiB more). The samples do not depend on it
 * but for rounding (docs/scene-format.md). */
#define SCENE_RENDER_BLOCK_FRAMES 512

/* Its chunk (fg_engine_config.chunk_frames): a still listener's WM-waves
 * are visited once in 1024 frames, not once a block, so that a long wave
 * costs about what a short one does (bench/results/whole_process.md,
 * "Chunks"). 1024: stereo's accumulator planes, with 512-frame blocks'
 * floats, still fit the 2 MiB huge page the 512-frame planes took; 2048
 * would map 2 MiB more. */
#define SCENE_RENDER_CHUNK_FRAMES 1024

/* Where the blocks go. */
typedef struct scene_render_sink {
    /* Takes frames of each of the scene's channels, planes[ch][0..frames),
     * in pascals (the scene's gain is the sink's to apply). Returns FG_OK to
     * go on, or the reason to stop the render (FG_ERR_IO, FG_ERR_NO_MEMORY)
     * with a message in err. */
    fg_result (*block)(void *context, float *const *planes, uint32_t frames, char *err,
                       size_t err_size);
    void *context;
} scene_render_sink;

typedef struct scene_render_report {
    uint64_t frames;           /* rendered and handed to the sink */
    size_t segments;           /* of every discharge's tree */
    bool capped;               /* no duration, and still sounding at SCENE_MAX_DURATION_S */
    size_t aero_beyond_range;  /* aero objects that met a speed outside their texture's
                                * Reynolds range (fg_aero_report.beyond_range_blocks) */
    uint64_t fire_underrun_frames; /* frames of the fires' streams that came too late
                                * (fg_fire_voice_report.underrun_frames, summed) */
    fg_engine_report engine;   /* the engine's counters at the end */
} scene_render_report;

/* The most frames scene_render gives for s: its duration, else the
 * SCENE_MAX_DURATION_S cap. [main-thread] */
uint64_t scene_frame_limit(const scene *s);

/* The frames of each of scene_render's blocks: the scene's "block" when
 * it gives one, else SCENE_RENDER_BLOCK_FRAMES. [any-thread] */
uint32_t scene_render_block_frames(const scene *s);

/* Renders s, which scene_build has built, into sink; *report (may be NULL)
 * receives what was rendered, also on an error. Returns FG_OK, or with a
 * message in err: the engine's code when it could not be made for the
 * scene or refused a discharge or a listener pose ("discharges[3]: the
 * engine refused it: ..."); FG_ERR_NO_MEMORY; the sink's code when it
 * stopped. [main-thread] */
fg_result scene_render(const scene *s, const scene_render_sink *sink,
                       scene_render_report *report, char *err, size_t err_size);

#endif
