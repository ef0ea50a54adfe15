/* Per-ear geometry of one segment: distance, angle and the WM-wave shape. */
#include <math.h>

#include "engine_internal.h"

void fg_event_geometry(const fg_engine *e, const fg_sound_params *p, fg_event *ev,
                       const double ear[3], int k)
{
    double d[3] = {ear[0] - ev->mid[0], ear[1] - ev->mid[1], ear[2] - ev->mid[2]};
    double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    /* sin(theta), theta from the segment's normal: |cos| of the angle to
     * the segment's axis */
    double s = r > 0 ? fabs(d[0] * ev->dir[0] + d[1] * ev->dir[1] + d[2] * ev->dir[2]) / r : 0.0;
    if (s > 1.0)
        s = 1.0;
    double c = e->cfg.speed_of_sound_m_s;
    ev->shape[k] = wm_shape_at(p, ev->t0_s, r, s, ev->half_len_m, c, NULL);
    /* eqs. 3-4 clamp r to r0; the wave still travels the true distance */
    ev->center_s[k] = ev->emit_s + r / c;
}
