/* The force on the solids: the momentum the scheme exchanges with them.
 *
 * Pressure: the projection pushes the fluid of a cut cell with -grad p over
 * its fluid faces; what the closed cell boundary leaves over is the solid
 * surface inside the cell, of vector area sum_f w_f A_f n_f (outward from
 * the solid). The force on the solid is -p_c times that, summed over the cut
 * cells: exactly the impulse the projection gives the fluid, reversed.
 * Viscous: the wall shear of the implicit viscous step (fluid_viscosity.c).
 * A surface integral of interpolated pressure and velocity gradients would
 * be the textbook alternative; on an immersed boundary it needs values
 * extrapolated across the wall and is noisier, and a control-volume
 * momentum balance is not exact under semi-Lagrangian advection (which is
 * not in flux form) — both would add noise that g = dF/dt amplifies. */
#include <string.h>

#include "fluid_state_internal.h"

void fg_fluid_pressure_force(fg_fluid *f)
{
    for (size_t i = 0; i < f->cut_count; i++) {
        double p = f->pressure[f->cut[i].cell];
        for (int b = 0; b < 3; b++)
            f->cut_force[3 * i + (size_t)b] = -p * f->cut[i].area_normal[b];
    }
}

static int inside(const fg_fluid *f, const double x[3], const double *lo, const double *hi)
{
    if (!lo || !hi)
        return 1;
    for (int b = 0; b < f->dims; b++)
        if (!(x[b] >= lo[b] && x[b] < hi[b]))
            return 0;
    return 1;
}

void fg_fluid_solid_force(const fg_fluid *f, const double lo[3], const double hi[3],
                          fg_fluid_force *out)
{
    memset(out, 0, sizeof *out);
    for (size_t i = 0; i < f->cut_count; i++) {
        size_t c = f->cut[i].cell;
        int ijk[3] = {(int)(c % (size_t)f->n[0]), (int)(c / (size_t)f->n[0] % (size_t)f->n[1]),
                      (int)(c / ((size_t)f->n[0] * (size_t)f->n[1]))};
        double x[3];
        for (int b = 0; b < 3; b++)
            x[b] = f->config.origin_m[b] + f->h * (ijk[b] + 0.5);
        if (!inside(f, x, lo, hi))
            continue;
        for (int b = 0; b < 3; b++)
            out->pressure_n[b] += f->cut_force[3 * i + (size_t)b];
    }
    for (size_t l = 0; l < f->link_count; l++) {
        const fg_fluid_wall_link *k = &f->links[l];
        const int *m = f->fsize[k->component];
        int ijk[3] = {(int)(k->face % (size_t)m[0]), (int)(k->face / (size_t)m[0] % (size_t)m[1]),
                      (int)(k->face / ((size_t)m[0] * (size_t)m[1]))};
        double x[3];
        fg_fluid_face_position(f, k->component, ijk[0], ijk[1], ijk[2], x);
        x[k->dir_axis] += (k->dir_side ? 1.0 : -1.0) * k->theta * f->h;
        if (!inside(f, x, lo, hi))
            continue;
        out->viscous_n[k->component] += f->link_force[l];
    }
}
