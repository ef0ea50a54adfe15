/* Where fulgur render writes each scene's file: -o (and --png) name one
 * file for one scene, or, for any number of scenes, a directory (an
 * existing one, or a name ending in '/') that gets NAME.wav for each
 * SCENE (NAME is the scene file's name without its extension), or a
 * pattern in which {name} becomes NAME and {index} the scene's position
 * among the operands, from 1. [main-thread] */
#ifndef HOST_CLI_RENDER_OUTPUT_H
#define HOST_CLI_RENDER_OUTPUT_H

#include <stddef.h>

/* Fills paths[0..count) (each malloc'ed; the caller frees them) from
 * target for scenes[0..count), with extension (".wav") for a directory.
 * Returns 0, or -1 with a message (paths then all NULL): several scenes
 * and a target that is neither a directory nor a pattern, or two scenes
 * that would write one file. */
int render_output_paths(const char *option, const char *target, const char *const *scenes,
                        size_t count, const char *extension, char **paths, char *err,
                        size_t err_size);

/* Makes the directory target names when it ends in '/' and is not there
 * (its parent must be). Returns 0, or -1 with a message. */
int render_output_make_directory(const char *option, const char *target, char *err,
                                 size_t err_size);

/* Frees paths[0..count). */
void render_output_free(char **paths, size_t count);

#endif
