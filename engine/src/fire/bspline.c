#include <math.h>

#include "bspline_internal.h"

double fg_bspline_phi(double t)
{
    double a = fabs(t);
    if (a <= 1.0) {
        double tau = 1.0 - a;
        return (((-3.0 * tau + 3.0) * tau + 3.0) * tau + 1.0) / 6.0;
    }
    if (a <= 2.0) {
        double tau = 1.0 - a;
        return (1.0 + tau) * (1.0 + tau) * (1.0 + tau) / 6.0;
    }
    return 0.0;
}

void fg_bspline_taps(int n, int subdivision, fg_bspline_tap *taps)
{
    int nodes = fg_bspline_lattice_nodes(n, subdivision);
    for (int m = 0; m < nodes; m++) {
        /* u = -2 + m / s exactly: the integer and fractional parts from m */
        int whole = m / subdivision - 2, rem = m % subdivision;
        double frac = (double)rem / (double)subdivision;
        fg_bspline_tap *tap = &taps[m];
        int first = whole - 1; /* cells whole - 1 .. whole + 2 */
        int clamped = first < 0 ? 0 : first;
        if (clamped > n - 4 && n >= 4)
            clamped = n - 4;
        if (n < 4)
            clamped = 0;
        tap->first = clamped;
        for (int q = 0; q < 4; q++)
            tap->w[q] = 0.0;
        for (int q = 0; q < 4; q++) {
            int cell = first + q;
            if (cell < 0 || cell >= n)
                continue;
            /* cell - clamped is in 0 .. 3: clamping moves the window of
             * 4 only past cells that are outside the grid */
            tap->w[cell - clamped] = fg_bspline_phi(frac + 1.0 - (double)q);
        }
    }
}

void fg_bspline_prepare(fg_bspline_volume *v, const double *burn)
{
    int nx = v->n[0], ny = v->n[1], nz = v->n[2], lx = v->lattice[0], ly = v->lattice[1];
    int wx = nx < 4 ? nx : 4, wy = ny < 4 ? ny : 4;
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++) {
            const double *row = burn + (size_t)nx * ((size_t)j + (size_t)ny * (size_t)k);
            double *out = v->along_x + (size_t)lx * ((size_t)j + (size_t)ny * (size_t)k);
            for (int m = 0; m < lx; m++) {
                const fg_bspline_tap *t = &v->taps[0][m];
                double s = 0.0;
                for (int q = 0; q < wx; q++)
                    s += t->w[q] * row[t->first + q];
                out[m] = s;
            }
        }
    for (int k = 0; k < nz; k++)
        for (int m = 0; m < ly; m++) {
            const fg_bspline_tap *t = &v->taps[1][m];
            double *out = v->along_xy + (size_t)lx * ((size_t)m + (size_t)ly * (size_t)k);
            for (int x = 0; x < lx; x++)
                out[x] = 0.0;
            for (int q = 0; q < wy; q++) {
                double w = t->w[q];
                if (w == 0.0)
                    continue;
                const double *in =
                    v->along_x + (size_t)lx * ((size_t)(t->first + q) + (size_t)ny * (size_t)k);
                for (int x = 0; x < lx; x++)
                    out[x] += w * in[x];
            }
        }
}

void fg_bspline_slice(const fg_bspline_volume *v, int mz, double *slice)
{
    size_t plane = (size_t)v->lattice[0] * (size_t)v->lattice[1];
    int nz = v->n[2], wz = nz < 4 ? nz : 4;
    const fg_bspline_tap *t = &v->taps[2][mz];
    for (size_t x = 0; x < plane; x++)
        slice[x] = 0.0;
    for (int q = 0; q < wz; q++) {
        double w = t->w[q];
        if (w == 0.0)
            continue;
        const double *in = v->along_xy + plane * (size_t)(t->first + q);
        for (size_t x = 0; x < plane; x++)
            slice[x] += w * in[x];
    }
}
