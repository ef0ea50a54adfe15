/* Copying the field's nodes in and out: the boundary description and the
 * potential, for a solver outside the engine (gpu/) and for tests. */
#include <math.h>
#include <string.h>

#include "fg_rules.h"
#include "field_internal.h"

size_t fg_field_node_count(const fg_field *f)
{
    FG_REQUIRE_OR(f, 0);
    return f->level[0].count;
}

fg_result fg_field_get_labels(const fg_field *f, uint8_t *labels)
{
    if (!f || !labels)
        return FG_ERR_NULL;
    memcpy(labels, f->label, f->level[0].count);
    return FG_OK;
}

fg_result fg_field_get_potential(const fg_field *f, double *phi)
{
    if (!f || !phi)
        return FG_ERR_NULL;
    memcpy(phi, f->phi, f->level[0].count * sizeof *phi);
    return FG_OK;
}

fg_result fg_field_set_potential(fg_field *f, const double *phi)
{
    if (!f || !phi)
        return FG_ERR_NULL;
    size_t count = f->level[0].count;
    for (size_t i = 0; i < count; i++)
        if (f->label[i] == FG_REGION_FREE && !isfinite(phi[i]))
            return FG_ERR_NOT_FINITE;
    for (size_t i = 0; i < count; i++)
        if (f->label[i] == FG_REGION_FREE)
            f->phi[i] = phi[i];
    return FG_OK;
}
