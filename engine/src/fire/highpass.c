#include <math.h>

#include "highpass_internal.h"
#include "fg_math.h"

void fg_fire_highpass_design(fg_iir *f, double cutoff_hz, double sample_rate_hz)
{
    double k = tan(FG_PI * cutoff_hz / sample_rate_hz), q = sqrt(0.5);
    double norm = 1.0 / (1.0 + k / q + k * k);
    *f = (fg_iir){.sections = 1};
    f->sec[0] = (fg_biquad){
        .b0 = norm,
        .b1 = -2.0 * norm,
        .b2 = norm,
        .a1 = 2.0 * (k * k - 1.0) * norm,
        .a2 = (1.0 - k / q + k * k) * norm,
    };
    fg_iir_reset(f);
}
