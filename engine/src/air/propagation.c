#include <math.h>

#include "fg_rules.h"
#include "fulgur/propagation.h"

fg_result fg_propagation_config_resolve(const fg_propagation_config *in,
                                        fg_propagation_config *out)
{
    if (!in || !out)
        return FG_ERR_NULL;
    const fg_propagation_config *p = in;
    if (!isfinite(p->refraction_radius_m) || !isfinite(p->turbulence_s) ||
        !isfinite(p->turbulence_length_m) || !isfinite(p->abe_fir_distance_m) ||
        !isfinite(p->ground_reflection))
        return FG_ERR_NOT_FINITE;
    double r = p->refraction_radius_m;
    if ((r != 0 && (r < FG_REFRACTION_MIN_M || r > FG_REFRACTION_MAX_M)) || p->turbulence_s < 0 ||
        p->turbulence_s >= 1.0 ||
        (p->turbulence_length_m != 0 && p->turbulence_length_m < FG_TURBULENCE_MIN_LENGTH_M) ||
        p->abe_fir_distance_m < 0 ||
        p->ground_reflection < 0 || p->ground_reflection > 1 ||
        ((unsigned)p->absorption > FG_ABSORPTION_ABE_FIR))
        return FG_ERR_ARGUMENT;
    fg_propagation_config c = *in;
    if (c.turbulence_s > 0)
        c.turbulence_length_m = FG_DEF(c.turbulence_length_m, FG_TURBULENCE_DEFAULT_LENGTH_M);
    if (c.absorption == FG_ABSORPTION_ABE_FIR)
        c.abe_fir_distance_m = FG_DEF(c.abe_fir_distance_m, FG_ABE_FIR_DEFAULT_DISTANCE_M);
    *out = c;
    return FG_OK;
}
