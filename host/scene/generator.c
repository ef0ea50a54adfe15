/* The table of scene generator types. Each generator adds its entry here
 * (its "type" name, the function that fills the tree, and for a field
 * generator the one that gives its conductors). */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "generator.h"

static const gen_entry table[] = {
    {"lightning", gen_lightning, NULL, SCENE_APPARATUS_NONE},
    {"charges", gen_charges, NULL, SCENE_APPARATUS_NONE},
    {"spark_gap", gen_spark_gap, gen_spark_gap_shapes, SCENE_APPARATUS_SPARK_GAP},
    {"plasma_ball", gen_plasma_ball, gen_plasma_ball_shapes, SCENE_APPARATUS_PLASMA_BALL},
    {"field", gen_field, gen_field_shapes, SCENE_APPARATUS_FIELD},
    {NULL, NULL, NULL, SCENE_APPARATUS_NONE}, /* the end */
};

const gen_entry *gen_find(const char *type)
{
    for (const gen_entry *g = table; g->type; g++)
        if (strcmp(g->type, type) == 0)
            return g;
    return NULL;
}

const char *gen_type_list(void)
{
    static char list[256];
    if (list[0])
        return list;
    for (const gen_entry *g = table; g->type; g++)
        snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", g == table ? "" : ", ",
                 g->type);
    if (!list[0])
        snprintf(list, sizeof list, "none yet");
    return list;
}
