/* fulgur — ready-made discharge scenes: the field, its shapes and the growth
 * parameters for the spark-ball and plasma-ball presets, at the scale of
 * Matsuyama's table 1 (step = 2 l, the preset's segment length).
 *
 *   spark balls: two spheres of radius 1 cm, 2 cm apart (surface to
 *     surface) on the x axis, origin at -x, target at +x, in a 7 cm cube.
 *   plasma ball: an electrode sphere of radius 3 cm (origin) at the centre
 *     of a glass sphere of radius 20 cm (target: everything outside it), in
 *     a 42 cm cube; every filament grows until it reaches the glass.
 */
#ifndef FULGUR_DISCHARGE_H
#define FULGUR_DISCHARGE_H

#include <stddef.h>

#include "fulgur/defs.h"
#include "fulgur/field.h"
#include "fulgur/growth.h"
#include "fulgur/result.h"
#include "fulgur/sound.h"

#define FG_DISCHARGE_MAX_SHAPES 4

typedef struct fg_discharge_setup {
    fg_grid_config grid;
    fg_shape shapes[FG_DISCHARGE_MAX_SHAPES];
    size_t shape_count;
    fg_growth_config growth;   /* seed 0; set your own */
} fg_discharge_setup;

/* Fills *out for FG_PRESET_SPARK_BALLS or FG_PRESET_PLASMA_BALL on a grid of
 * size nodes per axis (0 means 65). [any-thread]
 * Errors: FG_ERR_NULL out; FG_ERR_ARGUMENT another preset (lightning is not
 * grown in a field) or a size outside 9..257. */
FG_API FG_NODISCARD fg_result fg_discharge_preset(fg_preset preset, int size,
                                                  fg_discharge_setup *out);

#endif
