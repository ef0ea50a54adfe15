/* Designer thunder: reshaping a skeleton so that features of clap, rumble and
 * roar happen (Glassner part 2). The rules are in fulgur/lightning.h. */
#ifndef FULGUR_DESIGNER_INTERNAL_H
#define FULGUR_DESIGNER_INTERNAL_H

#include "fg_rules.h"
#include "fulgur/lightning.h"
#include "skeleton_internal.h"

/* A feature's shaping strength: its amplitude, 0 meaning 1. */
static inline double fg_thunder_amplitude(const fg_thunder_feature *f)
{
    return FG_DEF(f->amplitude, 1.0);
}

/* A feature's stretch on the reshaped skeleton. */
typedef struct fg_stretch {
    double s0, s1;      /* arclength on the reshaped skeleton, metres */
    double radius_m;    /* listener to the stretch's start (clap: the arc radius) */
} fg_stretch;

/* Builds out (empty on entry) from in for the features (already checked by
 * fg_lightning_config_resolve) and fills stretches[i] for features[i].
 * Errors: FG_ERR_ARGUMENT a clap stretch starting on the listener or longer
 * than half its circle, or a shape taking the skeleton below the ground;
 * FG_ERR_NO_MEMORY. */
fg_result fg_designer_shape(const fg_skeleton *in, const fg_thunder_feature *features, size_t count,
                            fg_vec3 listener, fg_skeleton *out, fg_stretch *stretches);

#endif
