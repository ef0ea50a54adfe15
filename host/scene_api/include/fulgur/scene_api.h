/* libfulgur-scene — scene files rendered as fulgur render renders them, as
 * a C library for bindings (the Python package) and batch programs.
 *
 * The same scene parser (every error names the JSON path), the same --set
 * overrides, the same generators and the same block loop as the fulgur
 * program, so a scene gives the same samples here as in fulgur render's
 * WAV, to the bit. Samples are interleaved 32-bit floats, frame after frame,
 * in pascals times the scene's "gain".
 *
 * Threads: a scene object belongs to one thread at a time; different scenes
 * may be parsed and rendered on different threads at once. Each render
 * makes and drives its own engine (libfulgur). Prefix fgs_; results are
 * fulgur's (fulgur/result.h). A scene's "solver": "gpu" field generators
 * are not available in this library (FG_ERR_ARGUMENT naming the path). */
#ifndef FULGUR_SCENE_API_H
#define FULGUR_SCENE_API_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/aero.h"
#include "fulgur/engine.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(FULGUR_SCENE_BUILDING) && defined(__GNUC__)
#define FGS_API __attribute__((visibility("default")))
#else
#define FGS_API
#endif

typedef struct fgs_scene fgs_scene;

/* What a parsed scene asks for (docs/scene-format.md). */
typedef struct fgs_scene_info {
    double sample_rate_hz;
    uint32_t channels;         /* 1 or 2 */
    uint32_t block_frames;     /* frames per fg_engine_render call of the render: the
                                * scene's "block", else 512 */
    double duration_s;         /* 0: until every discharge has finished sounding */
    uint64_t seed;
    double gain;               /* samples are pascals times gain */
    size_t discharge_count;
} fgs_scene_info;

/* What a render did. */
typedef struct fgs_render_report {
    uint64_t frames;           /* frames of sound, each of info.channels samples */
    size_t segments;           /* of every discharge's tree */
    float peak;                /* the largest |sample| */
    int capped;                /* non-zero: no duration, still sounding at 3600 s */
    fg_engine_report engine;   /* the engine's counters at the end (late events, ...) */
} fgs_render_report;

/* Parses size bytes of scene JSON (need not be NUL-terminated), then sets
 * each of sets[0..set_count) in it, in order, before checking it: "KEY=VALUE"
 * with KEY a JSON path (discharges[0].offset[1]) and VALUE JSON, or else a
 * string, exactly as fulgur render --set. *out is owned by the caller until
 * fgs_scene_destroy. err (may be NULL when err_size is 0) receives the
 * message of a failure, NUL-terminated. [any-thread]
 * Errors: FG_ERR_NULL json (with size > 0), sets (with set_count > 0) or
 * out; FG_ERR_ARGUMENT the text is not a scene or a --set cannot be applied
 * (the message names the JSON path: "discharges[2].tree.nodes[7]: parent 9
 * is not before node 7"); FG_ERR_NO_MEMORY. *out is NULL on any error. */
FGS_API FG_NODISCARD fg_result fgs_scene_parse(const char *json, size_t size,
                                               const char *const *sets, size_t set_count,
                                               fgs_scene **out, char *err, size_t err_size);

/* As fgs_scene_parse, for the file at path. [any-thread]
 * Errors: those of fgs_scene_parse; FG_ERR_IO the file cannot be opened
 * or read (the message names it). */
FGS_API FG_NODISCARD fg_result fgs_scene_load(const char *path, const char *const *sets,
                                              size_t set_count, fgs_scene **out, char *err,
                                              size_t err_size);

/* Frees the scene and its samples. NULL is a no-op. */
FGS_API void fgs_scene_destroy(fgs_scene *scene);

/* What the scene asks for. A NULL argument is a programmer error
 * (fulgur/defs.h). */
FGS_API void fgs_scene_get_info(const fgs_scene *scene, fgs_scene_info *out);

/* Runs the scene's generators (the first time) and renders it as fulgur
 * render does, into samples the scene holds (fgs_scene_samples). A second
 * render gives the same samples. report may be NULL. [the scene's thread]
 * Errors: FG_ERR_NULL scene; FG_ERR_ARGUMENT a generator refused its
 * parameters (the message names its path); FG_ERR_NO_MEMORY; the engine's
 * code when it refused the scene's engine, a discharge or a listener pose
 * (the message says which). The samples are then none. */
FGS_API FG_NODISCARD fg_result fgs_scene_render(fgs_scene *scene, fgs_render_report *report,
                                                char *err, size_t err_size);

/* The last render's samples: *frames frames of info.channels interleaved
 * floats, valid until the next render or fgs_scene_destroy; NULL (and 0
 * frames) before a successful render. frames may be NULL. */
FGS_API const float *fgs_scene_samples(const fgs_scene *scene, uint64_t *frames);

/* Writes frames of channels interleaved samples as fulgur render writes its
 * WAVs (32-bit float, no PEAK chunk: equal samples give equal bytes), under
 * a temporary name renamed to path when complete. [any-thread]
 * Errors: FG_ERR_NULL path or samples (with frames > 0); FG_ERR_ARGUMENT
 * channels not 1 or 2, a rate outside 8000..384000 Hz; FG_ERR_IO the file
 * cannot be written (no file is left; an older one at path is untouched). */
FGS_API FG_NODISCARD fg_result fgs_wav_write(const char *path, const float *samples,
                                             uint64_t frames, uint32_t channels,
                                             double sample_rate_hz, char *err, size_t err_size);

/* Reads the aerodynamic sound texture file at path
 * (docs/aero-texture-format.md; what fulgur aerotex writes and a scene's
 * "texture" names) into a texture of libfulgur's, for
 * fg_aero_object_post. *out is the caller's until fg_aero_texture_destroy.
 * [any-thread]
 * Errors: FG_ERR_NULL path or out; FG_ERR_IO the file cannot be opened;
 * FG_ERR_ARGUMENT it is not a valid texture (truncated, corrupt, another
 * version: the message names the file and what is wrong) or memory ran
 * out. *out is untouched on any error. */
FGS_API FG_NODISCARD fg_result fgs_aero_texture_load(const char *path, fg_aero_texture **out,
                                                     char *err, size_t err_size);

#ifdef __cplusplus
}
#endif

#endif
