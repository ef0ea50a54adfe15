/* The domain box: fixed normal velocities on its closed and inflow faces,
 * and interpolation that knows what lies beyond each face. */
#include "fluid_state_internal.h"

void fg_fluid_impose_box(fg_fluid *f)
{
    for (int a = 0; a < f->dims; a++) {
        const int *m = f->fsize[a];
        for (int side = 0; side < 2; side++) {
            fg_fluid_boundary b = f->config.boundary[a][side];
            if (b == FG_FLUID_OPEN)
                continue;
            double v = b == FG_FLUID_INFLOW ? f->config.inflow_m_s[a] : 0.0;
            int i = side ? m[a] - 1 : 0;
            /* the plane of faces {index_a = i} of component a */
            int p = (a + 1) % 3, q = (a + 2) % 3;
            for (int y = 0; y < m[q]; y++)
                for (int x = 0; x < m[p]; x++) {
                    int ijk[3];
                    ijk[a] = i;
                    ijk[p] = x;
                    ijk[q] = y;
                    f->u[a][fg_fluid_face_index(f, a, ijk[0], ijk[1], ijk[2])] = v;
                }
        }
    }
}

fg_fluid_sampler fg_fluid_make_sampler(const fg_fluid *f, const double *arr, int a,
                                       double inflow_value)
{
    const int *m = a >= 0 ? f->fsize[a] : f->n;
    fg_fluid_sampler s = {.arr = arr, .dims = f->dims, .inflow_value = inflow_value};
    s.sy = (size_t)m[0];
    s.sz = (size_t)m[0] * (size_t)m[1];
    for (int b = 0; b < 3; b++) {
        s.top[b] = m[b] - 1;
        s.off[b] = b == a ? 0.0 : 0.5;
        s.box[b] = f->n[b];
        s.inflow_lo[b] = b < f->dims && f->config.boundary[b][0] == FG_FLUID_INFLOW;
        s.inflow_hi[b] = b < f->dims && f->config.boundary[b][1] == FG_FLUID_INFLOW;
        s.any_inflow |= s.inflow_lo[b] | s.inflow_hi[b];
    }
    return s;
}

double fg_fluid_interpolate(const fg_fluid *f, const double *arr, int a, const double x[3],
                            double inflow_value)
{
    fg_fluid_sampler s = fg_fluid_make_sampler(f, arr, a, inflow_value);
    double g[3] = {0, 0, 0};
    for (int b = 0; b < f->dims; b++)
        g[b] = (x[b] - f->config.origin_m[b]) / f->h;
    return f->dims == 2 ? fg_fluid_sample(&s, 2, g, NULL, NULL) : fg_fluid_sample(&s, 3, g, NULL, NULL);
}
