#include <math.h>

#include "iir_internal.h"

#define SNAP 1e-30

void fg_iir_reset(fg_iir *f)
{
    for (unsigned k = 0; k < FG_IIR_MAX_SECTIONS; k++)
        f->z[k][0] = f->z[k][1] = 0.0;
}

static double snap(double v)
{
    return fabs(v) < SNAP ? 0.0 : v;
}

void fg_iir_process(fg_iir *f, float *buf, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        double x = buf[i];
        for (unsigned k = 0; k < f->sections; k++) {
            const fg_biquad *s = &f->sec[k];
            double *z = f->z[k];
            double y = s->b0 * x + z[0];
            z[0] = snap(s->b1 * x - s->a1 * y + z[1]);
            z[1] = snap(s->b2 * x - s->a2 * y);
            x = y;
        }
        buf[i] = (float)x;
    }
}

/* count (1..FG_IIR_LANES) lanes of `sections` sections; the state and
 * coefficients in local arrays, lanes innermost. */
static void process_lanes(fg_iir *const *f, float *const *buf, unsigned count,
                          unsigned sections, size_t n)
{
    double b0[FG_IIR_MAX_SECTIONS][FG_IIR_LANES], b1[FG_IIR_MAX_SECTIONS][FG_IIR_LANES],
        b2[FG_IIR_MAX_SECTIONS][FG_IIR_LANES], a1[FG_IIR_MAX_SECTIONS][FG_IIR_LANES],
        a2[FG_IIR_MAX_SECTIONS][FG_IIR_LANES], z0[FG_IIR_MAX_SECTIONS][FG_IIR_LANES],
        z1[FG_IIR_MAX_SECTIONS][FG_IIR_LANES];
    for (unsigned k = 0; k < sections; k++) {
        for (unsigned j = 0; j < count; j++) {
            const fg_biquad *s = &f[j]->sec[k];
            b0[k][j] = s->b0;
            b1[k][j] = s->b1;
            b2[k][j] = s->b2;
            a1[k][j] = s->a1;
            a2[k][j] = s->a2;
            z0[k][j] = f[j]->z[k][0];
            z1[k][j] = f[j]->z[k][1];
        }
    }
    for (size_t i = 0; i < n; i++) {
        double x[FG_IIR_LANES];
        for (unsigned j = 0; j < count; j++)
            x[j] = buf[j][i];
        for (unsigned k = 0; k < sections; k++) {
            for (unsigned j = 0; j < count; j++) {
                double y = b0[k][j] * x[j] + z0[k][j];
                z0[k][j] = snap(b1[k][j] * x[j] - a1[k][j] * y + z1[k][j]);
                z1[k][j] = snap(b2[k][j] * x[j] - a2[k][j] * y);
                x[j] = y;
            }
        }
        for (unsigned j = 0; j < count; j++)
            buf[j][i] = (float)x[j];
    }
    for (unsigned k = 0; k < sections; k++) {
        for (unsigned j = 0; j < count; j++) {
            f[j]->z[k][0] = z0[k][j];
            f[j]->z[k][1] = z1[k][j];
        }
    }
}

void fg_iir_process_lanes(fg_iir *const *f, float *const *buf, unsigned count, size_t n)
{
    if (count == 0)
        return;
    /* a constant lane count lets the compiler unroll and interleave them */
    const unsigned sections = f[0]->sections;
    switch (count) {
    case 1: process_lanes(f, buf, 1, sections, n); break;
    case 2: process_lanes(f, buf, 2, sections, n); break;
    case 3: process_lanes(f, buf, 3, sections, n); break;
    default: process_lanes(f, buf, FG_IIR_LANES, sections, n); break;
    }
}

fg_phasor fg_phasor_at(double w)
{
    return (fg_phasor){cos(w), sin(w), cos(2.0 * w), sin(2.0 * w)};
}

/* |c0 + c1 e^{-jw} + c2 e^{-2jw}|^2 */
static double poly_mag2(double c0, double c1, double c2, const fg_phasor *e)
{
    double re = c0 + c1 * e->c1 + c2 * e->c2;
    double im = c1 * e->s1 + c2 * e->s2;
    return re * re + im * im;
}

static double biquad_mag2(const fg_biquad *s, const fg_phasor *e)
{
    return poly_mag2(s->b0, s->b1, s->b2, e) / poly_mag2(1.0, s->a1, s->a2, e);
}

double fg_iir_db(const fg_iir *f, double w)
{
    fg_phasor e = fg_phasor_at(w);
    double m2 = 1.0;
    for (unsigned k = 0; k < f->sections; k++)
        m2 *= biquad_mag2(&f->sec[k], &e);
    return 10.0 * log10(m2);
}
