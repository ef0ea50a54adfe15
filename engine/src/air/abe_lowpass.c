#include <math.h>
#include <string.h>

#include "abe_lowpass_internal.h"
#include "fg_math.h"

#define MASK (FG_ABE_FIR_HISTORY - 1)

fg_result fg_abe_fir_init(fg_abe_fir *f, double fs_hz)
{
    if (!(fs_hz >= 8000.0 && fs_hz <= 384000.0))
        return FG_ERR_SAMPLE_RATE;
    f->stride = (unsigned)floor(fs_hz / FG_ABE_FIR_MODEL_MIN_HZ);
    double fc = FG_ABE_FIR_CUTOFF_HZ / (fs_hz / f->stride); /* cycles per model sample */
    double sum = 0.0, mid = 0.5 * (FG_ABE_FIR_TAPS - 1);
    for (int k = 0; k < FG_ABE_FIR_TAPS; k++) {
        double t = k - mid;
        double sinc = 2.0 * fc * sin(2.0 * FG_PI * fc * t) / (2.0 * FG_PI * fc * t);
        double window = 0.54 - 0.46 * cos(2.0 * FG_PI * k / (FG_ABE_FIR_TAPS - 1));
        f->h[k] = sinc * window;
        sum += f->h[k];
    }
    for (int k = 0; k < FG_ABE_FIR_TAPS; k++)
        f->h[k] /= sum;
    fg_abe_fir_reset(f);
    return FG_OK;
}

void fg_abe_fir_reset(fg_abe_fir *f)
{
    memset(f->box, 0, sizeof f->box);
    memset(f->hist, 0, sizeof f->hist);
    f->box_sum[0] = f->box_sum[1] = 0.0;
    f->box_pos = 0;
    f->pos = 0;
}

/* Pushes x through the two moving averages. */
static double smooth(fg_abe_fir *f, double x)
{
    const unsigned m = f->stride, b = f->box_pos;
    for (int s = 0; s < 2; s++) {
        f->box_sum[s] += x - f->box[s][b];
        f->box[s][b] = x;
        x = f->box_sum[s] / m;
    }
    if (++f->box_pos == m) {
        /* re-sum exactly so rounding never accumulates */
        f->box_pos = 0;
        for (int s = 0; s < 2; s++) {
            double sum = 0.0;
            for (unsigned k = 0; k < m; k++)
                sum += f->box[s][k];
            f->box_sum[s] = sum;
        }
    }
    return x;
}

void fg_abe_fir_process(fg_abe_fir *f, float *buf, size_t n)
{
    const unsigned m = f->stride;
    for (size_t i = 0; i < n; i++) {
        f->hist[f->pos & MASK] = (float)smooth(f, buf[i]);
        double y = 0.0;
        for (unsigned k = 0; k < FG_ABE_FIR_TAPS; k++)
            y += f->h[k] * f->hist[(f->pos - k * m) & MASK];
        f->pos++;
        buf[i] = (float)y;
    }
}
