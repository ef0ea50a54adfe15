#include <math.h>

#include "abe_voice_internal.h"
#include "fg_math.h"

#define SIXTY_DB 6.907755278982137 /* ln 1000 */
#define MIN_DISTANCE_M 1.0

const fg_abe_config fg_abe_defaults = {80.0, 20.0, 0.5, 0.12, 16, 5e-9, 1000.0, 1.0};

static double speed_at(double temp_c)
{
    return 331.5 + 0.6 * temp_c;
}

double fg_abe_fundamental_hz(const fg_abe_config *p, double height_m)
{
    double t = p->ground_temp_c - FG_ABE_LAPSE_K_PER_M * height_m;
    return p->f_ground_hz * speed_at(t) / speed_at(p->ground_temp_c);
}

void fg_abe_wave_init(fg_abe_wave *w, const fg_abe_config *p, const double src[3],
                      const double ear[3], double emit_s, double c_m_s)
{
    double d2 = 0.0;
    for (int k = 0; k < 3; k++)
        d2 += (src[k] - ear[k]) * (src[k] - ear[k]);
    double r = fmax(sqrt(d2), MIN_DISTANCE_M);
    w->arrival_s = emit_s + r / c_m_s;
    w->f0_hz = fg_abe_fundamental_hz(p, src[2] - ear[2]);
    w->peak_pa = p->ref_peak_pa * p->ref_distance_m / r;
    w->gamma = p->atten_db_m_hz2 * r * log(10.0) / 20.0;
    w->rate = 1.0;
    fg_abe_wave_set_decay(w, p);
}

void fg_abe_wave_set_decay(fg_abe_wave *w, const fg_abe_config *p)
{
    w->freq_decay_s = p->freq_decay_s;
    w->amp_decay_s = p->amp_decay_s;
    w->duration_s = p->amp_decay_s * SIXTY_DB;
    w->harmonics = p->harmonics;
}

/* Sample indices beyond 2^62 are no block's. */
#define SAMPLE_INDEX_LIMIT 4.6e18

bool fg_abe_wave_in_range(const fg_abe_wave *w, double fs_hz)
{
    if (!isfinite(w->arrival_s) || !isfinite(w->f0_hz) || !isfinite(w->peak_pa) ||
        !isfinite(w->gamma) || !(w->freq_decay_s > 0) || !(w->amp_decay_s > 0) ||
        !(w->duration_s >= 0) || !isfinite(w->duration_s))
        return false;
    return fabs(w->arrival_s * fs_hz) + w->duration_s * fs_hz < SAMPLE_INDEX_LIMIT;
}

void fg_abe_wave_span(const fg_abe_wave *w, double fs_hz, int64_t *first, int64_t *last)
{
    *first = (int64_t)ceil(w->arrival_s * fs_hz);
    *last = (int64_t)floor((w->arrival_s + w->duration_s * w->rate) * fs_hz);
}

/* The pressure t_s after arrival (0 <= t_s <= duration). */
static double pressure(const fg_abe_wave *w, double t_s, double nyquist_hz)
{
    double ef = exp(-t_s / w->freq_decay_s);
    double f = w->f0_hz * ef;
    double x = 2.0 * FG_PI * w->f0_hz * w->freq_decay_s * (1.0 - ef);
    double q = exp(-w->gamma * f * f), q2 = q * q;
    unsigned n_max = w->harmonics;
    if (n_max * f >= 0.9 * nyquist_hz)
        n_max = (unsigned)ceil(0.9 * nyquist_hz / f) - 1;
    /* sin(n x) by the Chebyshev recurrence, gain q^(n^2) by q^(2n+1) steps */
    double two_cos = 2.0 * cos(x), s_prev = 0.0, s = sin(x);
    double gain = q, step = q * q2, sum = 0.0;
    for (unsigned n = 1; n <= n_max; n++) {
        sum += gain * s / n;
        double s_next = two_cos * s - s_prev;
        s_prev = s;
        s = s_next;
        gain *= step;
        step *= q2;
    }
    return w->peak_pa * exp(-t_s / w->amp_decay_s) * (2.0 / FG_PI) * sum;
}

bool fg_abe_wave_render(const fg_abe_wave *w, double fs_hz, int64_t block_start, float *out,
                        size_t n)
{
    int64_t first, last;
    fg_abe_wave_span(w, fs_hz, &first, &last);
    int64_t lo = first > block_start ? first : block_start;
    int64_t hi = block_start + (int64_t)n - 1;
    hi = last < hi ? last : hi;
    for (int64_t k = lo; k <= hi; k++) {
        float p = (float)pressure(w, ((double)k / fs_hz - w->arrival_s) / w->rate, 0.5 * fs_hz);
        if (!isfinite(p))
            return false;
        out[k - block_start] += p;
    }
    return true;
}
