#include <math.h>

#include "mitchell_internal.h"

/* Mitchell & Netravali (1988), eq. 8, times 6:
 *   |x| < 1:      (12 - 9B - 6C)|x|^3 + (-18 + 12B + 6C)|x|^2 + (6 - 2B)
 *   1 <= |x| < 2: (-B - 6C)|x|^3 + (6B + 30C)|x|^2 + (-12B - 48C)|x| + (8B + 24C) */
#define P3 (12.0 - 9.0 * FG_MN_B - 6.0 * FG_MN_C)
#define P2 (-18.0 + 12.0 * FG_MN_B + 6.0 * FG_MN_C)
#define P0 (6.0 - 2.0 * FG_MN_B)
#define Q3 (-FG_MN_B - 6.0 * FG_MN_C)
#define Q2 (6.0 * FG_MN_B + 30.0 * FG_MN_C)
#define Q1 (-12.0 * FG_MN_B - 48.0 * FG_MN_C)
#define Q0 (8.0 * FG_MN_B + 24.0 * FG_MN_C)

double fg_mn_kernel(double x)
{
    double a = fabs(x);
    if (a < 1.0)
        return ((P3 * a + P2) * a * a + P0) / 6.0;
    if (a < 2.0)
        return (((Q3 * a + Q2) * a + Q1) * a + Q0) / 6.0;
    return 0.0;
}

double fg_mn_kernel_derivative(double x)
{
    double a = fabs(x), d;
    if (a < 1.0)
        d = (3.0 * P3 * a + 2.0 * P2) * a / 6.0;
    else if (a < 2.0)
        d = ((3.0 * Q3 * a + 2.0 * Q2) * a + Q1) / 6.0;
    else
        return 0.0;
    return x < 0.0 ? -d : d;
}

void fg_mn_init(fg_mn_stream *s, double sim_rate_hz, double sample_rate_hz)
{
    *s = (fg_mn_stream){.sim_rate_hz = sim_rate_hz, .sample_rate_hz = sample_rate_hz};
}

size_t fg_mn_max_frames_per_step(const fg_mn_stream *s)
{
    return (size_t)ceil(s->sample_rate_hz / s->sim_rate_hz) + 1;
}

/* I_i, held at I_0 before the start. */
static double flux_at(const fg_mn_stream *s, int64_t i)
{
    if (i < 0)
        i = 0;
    return s->flux[(uint64_t)i % FG_MN_HISTORY];
}

size_t fg_mn_push(fg_mn_stream *s, double flux, double *p)
{
    s->flux[s->steps % FG_MN_HISTORY] = flux;
    s->steps++;
    int64_t last = (int64_t)s->steps - 1;
    double ratio = s->sim_rate_hz / s->sample_rate_hz;
    size_t made = 0;
    for (;;) {
        double x = (double)s->next_frame * ratio;
        int64_t base = (int64_t)floor(x);
        if (base + 2 > last)
            break;
        /* Sum of k' is 0: subtracting I_base removes the common part
         * before the sum, so a large mean flux costs no precision. */
        double ref = flux_at(s, base), sum = 0.0;
        for (int64_t i = base - 1; i <= base + 2; i++)
            sum += fg_mn_kernel_derivative(x - (double)i) * (flux_at(s, i) - ref);
        p[made++] = sum * s->sim_rate_hz;
        s->next_frame++;
    }
    return made;
}
