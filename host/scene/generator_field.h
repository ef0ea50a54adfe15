/* The field generators of scene/generator_field.c, for the table in
 * scene/generator.c: {"spark_gap", gen_spark_gap}, {"plasma_ball",
 * gen_plasma_ball}, {"field", gen_field}. Each is a gen_fn (generator.h);
 * the JSON is in docs/generators-field.md. */
#ifndef HOST_SCENE_GENERATOR_FIELD_H
#define HOST_SCENE_GENERATOR_FIELD_H

#include "generator.h"

int gen_spark_gap(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
                  char *err, size_t err_size);
int gen_plasma_ball(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
                    char *err, size_t err_size);
int gen_field(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
              char *err, size_t err_size);

#endif
