#include <math.h>

#include "fg_math.h"
#include "filter_reference.h"

double ref_quadratic_root_radius(double c1, double c2)
{
    double disc = c1 * c1 - 4.0 * c2;
    if (disc < 0.0)
        return sqrt(c2); /* complex pair: |x|^2 = c2 */
    double r = sqrt(disc);
    double a = fabs(-c1 + r) / 2.0, b = fabs(-c1 - r) / 2.0;
    return a > b ? a : b;
}

double ref_abe_fir_db(const fg_abe_fir *f, double f_hz, double fs_hz)
{
    double w = 2.0 * FG_PI * f_hz / fs_hz, re = 0.0, im = 0.0;
    for (int k = 0; k < FG_ABE_FIR_TAPS; k++) {
        re += f->h[k] * cos(w * k * f->stride);
        im -= f->h[k] * sin(w * k * f->stride);
    }
    double m = f->stride, half = 0.5 * w;
    double box = fabs(sin(half) * m) < 1e-300 ? 1.0 : sin(half * m) / (m * sin(half));
    return 10.0 * log10(re * re + im * im) + 40.0 * log10(fabs(box));
}

double ref_abe_fir_delay_frames(const fg_abe_fir *f)
{
    return 0.5 * (FG_ABE_FIR_TAPS - 1) * f->stride + (f->stride - 1.0);
}
