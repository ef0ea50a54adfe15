/* The spark-ball and plasma-ball scenes of fulgur/field_scene.h. The branch
 * parameters are tuned so that the mean segment count over seeds is near
 * Matsuyama's table 2 (72 for spark balls, 78 for the plasma ball); the
 * figures measured are in bench/results/field_solve.csv. */
#include <string.h>

#include "fg_rules.h"
#include "fulgur/field_scene.h"

#define SPARK_RADIUS_M 0.01
#define SPARK_GAP_M 0.02
#define SPARK_HALF_BOX_M 0.035
#define SPARK_BRANCH_PROBABILITY 0.115
#define SPARK_BRANCH_STEPS 6

#define PLASMA_ELECTRODE_M 0.03
#define PLASMA_GLASS_M 0.20
#define PLASMA_HALF_BOX_M 0.21
#define PLASMA_BRANCH_PROBABILITY 0.415
#define PLASMA_BRANCH_STEPS 12

static fg_grid_config cube(int size, double half_m)
{
    return (fg_grid_config){.size = {size, size, size},
                            .min_m = {-half_m, -half_m, -half_m},
                            .max_m = {half_m, half_m, half_m}};
}

fg_result fg_field_scene_preset(fg_preset preset, int size, fg_field_scene *out)
{
    if (!out)
        return FG_ERR_NULL;
    fg_preset_scale scale;
    size = FG_DEF(size, FG_FIELD_DEFAULT_SIZE);
    if (size < FG_FIELD_MIN_SIZE || size > FG_FIELD_MAX_SIZE ||
        fg_preset_get_scale(preset, &scale) != FG_OK)
        return FG_ERR_ARGUMENT;
    double step = 2.0 * scale.half_step_m;
    fg_field_scene s;
    memset(&s, 0, sizeof s);
    if (preset == FG_PRESET_SPARK_BALLS) {
        double cx = 0.5 * SPARK_GAP_M + SPARK_RADIUS_M;
        s.grid = cube(size, SPARK_HALF_BOX_M);
        s.shapes[0] = (fg_shape){.kind = FG_SHAPE_SPHERE, .role = FG_ROLE_ORIGIN,
                                 .centre_m = {-cx, 0, 0}, .radius_m = SPARK_RADIUS_M};
        s.shapes[1] = (fg_shape){.kind = FG_SHAPE_SPHERE, .role = FG_ROLE_TARGET,
                                 .centre_m = {cx, 0, 0}, .radius_m = SPARK_RADIUS_M};
        s.shape_count = 2;
        s.growth = (fg_growth_config){.step_m = step,
                                      .branch_probability = SPARK_BRANCH_PROBABILITY,
                                      .branch_length_m = SPARK_BRANCH_STEPS * step};
    } else if (preset == FG_PRESET_PLASMA_BALL) {
        s.grid = cube(size, PLASMA_HALF_BOX_M);
        s.shapes[0] = (fg_shape){.kind = FG_SHAPE_SPHERE, .role = FG_ROLE_ORIGIN,
                                 .radius_m = PLASMA_ELECTRODE_M};
        s.shapes[1] = (fg_shape){.kind = FG_SHAPE_SPHERE, .role = FG_ROLE_TARGET,
                                 .radius_m = PLASMA_GLASS_M, .outside = 1};
        s.shape_count = 2;
        s.growth = (fg_growth_config){.step_m = step,
                                      .branch_probability = PLASMA_BRANCH_PROBABILITY,
                                      .branch_length_m = PLASMA_BRANCH_STEPS * step,
                                      .all_tips_connect = 1};
    } else {
        return FG_ERR_ARGUMENT;
    }
    *out = s;
    return FG_OK;
}
