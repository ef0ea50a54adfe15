/* The "lightning" (statistical, designer thunder) and "charges" (point-
 * charge leader) scene generators; JSON in docs/generators-lightning.md. */
#ifndef HOST_SCENE_GENERATOR_LIGHTNING_H
#define HOST_SCENE_GENERATOR_LIGHTNING_H

#include "generator.h"

int gen_lightning(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
                  char *err, size_t err_size);
int gen_charges(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
                char *err, size_t err_size);

#endif
