/* fulgur render --manifest: one JSON object per rendered file, one a line
 * (JSON Lines), so that the lines of many runs (GNU parallel's jobs, a
 * Slurm array's tasks) concatenate into one manifest:
 *
 *   {"scene":"base.json","set":["seed=7"],"output":"out/7.wav","seed":7,
 *    "sample_rate":48000,"channels":2,"frames":828432,"duration_s":17.259,
 *    "peak":0.0123,"gain":1,"pa_per_unit":1}
 *
 * scene and set as given on the command line; seed the scene's; duration_s
 * = frames / sample_rate; peak the largest |sample| in the file; gain the
 * scene's, and pa_per_unit = 1 / scale the calibration that turns the file's
 * samples back into pascals. Nothing that varies between equal renders
 * (no wall time), so equal renders give equal lines. [main-thread] */
#ifndef HOST_CLI_RENDER_MANIFEST_H
#define HOST_CLI_RENDER_MANIFEST_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "scene/scene.h"

typedef struct manifest_row {
    const char *scene_path;
    const char *const *sets;
    size_t set_count;
    const char *output;
    const scene *s;
    uint64_t frames;
    float peak;
    float scale; /* a sample = pascals x scale (the gain and --gain-db/--normalize) */
} manifest_row;

/* Writes the row's line to `to`. Returns 0, or -1 (out of memory or a
 * write error). */
int manifest_write(FILE *to, const manifest_row *row);

#endif
