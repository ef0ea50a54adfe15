#include <math.h>

#include "fulgur/propagation.h"

fg_result fg_propagation_config_check(const fg_propagation_config *p)
{
    if (!p)
        return FG_ERR_NULL;
    if (!isfinite(p->refraction_radius_m) || !isfinite(p->turbulence_s) ||
        !isfinite(p->turbulence_length_m) || !isfinite(p->abe_fir_distance_m) ||
        !isfinite(p->ground_reflection))
        return FG_ERR_NOT_FINITE;
    double r = p->refraction_radius_m;
    if ((r != 0 && (r < FG_REFRACTION_MIN_M || r > FG_REFRACTION_MAX_M)) || p->turbulence_s < 0 ||
        p->turbulence_s >= 1.0 || p->turbulence_length_m < 0 || p->abe_fir_distance_m < 0 ||
        p->ground_reflection < 0 || p->ground_reflection > 1 ||
        ((unsigned)p->absorption > FG_ABSORPTION_ABE_FIR))
        return FG_ERR_ARGUMENT;
    return FG_OK;
}
