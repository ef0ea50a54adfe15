/* fulgur — ready-made field scenes: the grid, its shapes and the growth
 * configuration a spark-ball or plasma-ball discharge grows in, at the
 * scale of Matsuyama's table 1 (step = 2 l, the preset's segment length).
 *
 *   spark balls: two spheres of radius 1 cm, 2 cm apart (surface to
 *     surface) on the x axis, origin at -x, target at +x, in a 7 cm cube.
 *   plasma ball: an electrode sphere of radius 3 cm (origin) at the centre
 *     of a glass sphere of radius 20 cm (target: everything outside it), in
 *     a 42 cm cube; every filament grows until it reaches the glass.
 */
#ifndef FULGUR_FIELD_SCENE_H
#define FULGUR_FIELD_SCENE_H

#include <stddef.h>

#include "fulgur/defs.h"
#include "fulgur/field.h"
#include "fulgur/growth.h"
#include "fulgur/result.h"
#include "fulgur/sound.h"

#define FG_FIELD_SCENE_MAX_SHAPES 4

/* What a discharge grows in: a field and how the leader grows in it. */
typedef struct fg_field_scene {
    fg_grid_config grid;
    fg_shape shapes[FG_FIELD_SCENE_MAX_SHAPES];
    size_t shape_count;
    fg_growth_config growth;   /* seed 0; set your own */
} fg_field_scene;

/* Fills *out for FG_PRESET_SPARK_BALLS or FG_PRESET_PLASMA_BALL on a grid of
 * size nodes per axis (0 means 65). [any-thread]
 * Errors: FG_ERR_NULL out; FG_ERR_ARGUMENT another preset (lightning is not
 * grown in a field) or a size outside 9..257. */
FG_API FG_NODISCARD fg_result fg_field_scene_preset(fg_preset preset, int size,
                                                  fg_field_scene *out);

#endif
