/* The seam between a scene's "generator" object and the engine's pattern
 * generators. Each generator type parses its own JSON object and fills a
 * tree; generator.c holds the table of types. */
#ifndef HOST_SCENE_GENERATOR_H
#define HOST_SCENE_GENERATOR_H

#include <stddef.h>
#include <stdint.h>

#include <cjson/cJSON.h>

#include "fulgur/field.h"
#include "fulgur/tree.h"
#include "scene.h"

typedef struct gen_context {
    uint64_t seed;              /* the discharge's seed */
    double listener_m[3];       /* listener position at the discharge's time */
    double speed_of_sound_m_s;
} gen_context;

/* Fills out (empty on entry) from spec, the JSON object at path (e.g.
 * "discharges[2].generator"). Returns 0, or -1 with a message in err that
 * starts with the JSON path of the offending field, e.g.
 * "discharges[2].generator.grid.size: must be 9..257". */
typedef int gen_fn(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
                   char *err, size_t err_size);

/* The generators, by their "type":
 *   generator_lightning.c  "lightning" (statistical, designer thunder) and
 *                          "charges" (a point-charge leader);
 *                          docs/generators-lightning.md
 *   generator_field.c      "spark_gap" and "plasma_ball" (the engine's
 *                          presets) and "field" (grid, shapes and growth
 *                          from the scene); docs/generators-field.md */
gen_fn gen_lightning, gen_charges, gen_spark_gap, gen_plasma_ball, gen_field;

/* The conductors a field generator grows its tree among (in its own
 * frame, as fg_field_set_shapes takes them), into shapes[0 .. *count)
 * (at most FG_FIELD_MAX_SHAPES), and the grid's box in *box_min_m,
 * *box_max_m. Returns 0, or -1 with a message as gen_fn's. */
typedef int gen_shapes_fn(const cJSON *spec, const char *path, fg_shape *shapes, size_t *count,
                          double box_min_m[3], double box_max_m[3], char *err, size_t err_size);

gen_shapes_fn gen_spark_gap_shapes, gen_plasma_ball_shapes, gen_field_shapes;

typedef struct gen_entry {
    const char *type;  /* the value of "type" in the generator object */
    gen_fn *generate;
    gen_shapes_fn *shapes; /* NULL: it grows in no field (lightning, charges) */
    scene_apparatus_kind apparatus; /* what its shapes are, for the picture */
} gen_entry;

/* The entry for a type name, or NULL. */
const gen_entry *gen_find(const char *type);

/* The known type names, comma-separated, for error messages. */
const char *gen_type_list(void);

#endif
