/* The table of scene generator types. Each generator adds its entry here
 * (its "type" name and the function that fills the tree). */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "generator.h"

static const gen_entry table[] = {
    {"lightning", gen_lightning},
    {"charges", gen_charges},
    {"spark_gap", gen_spark_gap},
    {"plasma_ball", gen_plasma_ball},
    {"field", gen_field},
    {NULL, NULL}, /* the end */
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
