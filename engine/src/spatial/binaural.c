#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "binaural_internal.h"
#include "dsp/fft_internal.h"
#include "fg_math.h"

/* The band whose diffuse-field average is scaled to unit gain. */
#define LEVEL_LO_HZ 500.0
#define LEVEL_HI_HZ 2000.0
#define RINGS 7
#define RING_STEP_DEG 30.0

/* Loudspeakers per ring, from -90 degrees up, and the index of each
 * ring's first. */
static const unsigned ring_count[RINGS] = {1, 6, 12, 12, 12, 6, 1};
static const unsigned ring_first[RINGS] = {0, 1, 7, 19, 31, 43, 49};

void fg_binaural_speaker(unsigned k, double dir[3])
{
    unsigned j = 0;
    while (j + 1 < RINGS && ring_first[j + 1] <= k)
        j++;
    double el = (-90.0 + RING_STEP_DEG * j) * FG_PI / 180.0;
    double az = 2.0 * FG_PI * (double)(k - ring_first[j]) / (double)ring_count[j];
    dir[0] = cos(el) * cos(az);
    dir[1] = cos(el) * sin(az);
    dir[2] = sin(el);
}

/* Ring j's two loudspeakers around azimuth az_turns (in turns, [0, 1))
 * with weight w, at index[0..) and gain[0..) in ascending order; returns
 * how many (none for w 0, one on a pole's ring of one). */
static unsigned pan_ring(unsigned j, double az_turns, double w, unsigned *index, double *gain)
{
    if (w == 0.0)
        return 0;
    unsigned n = ring_count[j];
    if (n == 1) {
        index[0] = ring_first[j];
        gain[0] = w;
        return 1;
    }
    double p = az_turns * n, i = floor(p), frac = p - i;
    unsigned i0 = (unsigned)i % n, i1 = (i0 + 1) % n;
    unsigned lo = i1 < i0; /* where i0's entry goes: after i1's when i1 wrapped to 0 */
    index[lo] = ring_first[j] + i0;
    gain[lo] = w * (1.0 - frac);
    index[1 - lo] = ring_first[j] + i1;
    gain[1 - lo] = w * frac;
    return 2;
}

unsigned fg_binaural_pan(const double dir[3], unsigned index[4], double gain[4])
{
    double z = dir[2] > 1.0 ? 1.0 : dir[2] < -1.0 ? -1.0 : dir[2];
    double el = asin(z) * 180.0 / FG_PI + 90.0; /* 0 .. 180 */
    double az = atan2(dir[1], dir[0]) / (2.0 * FG_PI);
    if (!isfinite(el) || !isfinite(az)) {
        index[0] = ring_first[RINGS / 2]; /* no direction: ahead (never an index from NaN) */
        gain[0] = 1.0;
        return 1;
    }
    az = az < 0.0 ? az + 1.0 : az;
    az = az >= 1.0 ? 0.0 : az;
    double r = el > 0.0 ? el / RING_STEP_DEG : 0.0, jf = floor(r);
    unsigned j = jf >= RINGS - 1 ? RINGS - 2 : (unsigned)jf;
    double t = r - (double)j;
    t = t > 1.0 ? 1.0 : t;
    unsigned count = pan_ring(j, az, 1.0 - t, index, gain);
    return count + pan_ring(j + 1, az, t, index + count, gain + count);
}

void fg_binaural_gains(const double dir[3], double *gain)
{
    for (unsigned k = 0; k < FG_BINAURAL_SPEAKERS; k++)
        gain[k] = 0.0;
    unsigned index[4];
    double g[4];
    unsigned count = fg_binaural_pan(dir, index, g);
    for (unsigned k = 0; k < count; k++)
        gain[index[k]] += g[k];
}

fg_result fg_binaural_check(const fg_hrir_set *h, double fs_hz)
{
    if (!h->direction || !h->left || !h->right)
        return FG_ERR_NULL;
    if (h->count < FG_BINAURAL_MIN_DIRECTIONS || h->count > FG_HRIR_MAX_COUNT ||
        h->length == 0 || h->length > FG_HRIR_MAX_LENGTH)
        return FG_ERR_ARGUMENT;
    if (!isfinite(h->sample_rate_hz))
        return FG_ERR_NOT_FINITE;
    if (h->sample_rate_hz != fs_hz)
        return FG_ERR_SAMPLE_RATE;
    for (size_t s = 0; s < h->count; s++) {
        const double *d = h->direction + 3 * s;
        if (!isfinite(d[0]) || !isfinite(d[1]) || !isfinite(d[2]))
            return FG_ERR_NOT_FINITE;
        if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
            return FG_ERR_ARGUMENT;
    }
    size_t taps = (size_t)h->count * h->length;
    for (size_t k = 0; k < taps; k++)
        if (!isfinite(h->left[k]) || !isfinite(h->right[k]))
            return FG_ERR_NOT_FINITE;
    return FG_OK;
}

void fg_binaural_deinit(fg_binaural *b)
{
    fg_convolver_deinit(&b->conv);
}

size_t fg_hrir_nearest(const fg_hrir_set *h, const double u[3])
{
    size_t best = 0;
    double best_cos = -2.0;
    for (size_t s = 0; s < h->count; s++) {
        const double *d = h->direction + 3 * s;
        double c = (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) /
                   sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (c > best_cos) {
            best_cos = c;
            best = s;
        }
    }
    return best;
}

/* The mean energy per bin of the set's responses, both ears, in
 * LEVEL_LO_HZ .. LEVEL_HI_HZ; 0 when out of memory. */
static double diffuse_level(const fg_hrir_set *h)
{
    size_t n = FG_FFT_MIN_SIZE;
    while (n < 2 * (size_t)h->length || h->sample_rate_hz / (double)n > 50.0)
        n *= 2;
    fg_fft fft;
    double *x = malloc((n + 2) * sizeof *x);
    if (!x || !fg_fft_init(&fft, n)) {
        free(x);
        return 0.0;
    }
    double level = 0.0;
    size_t bins = 0;
    for (size_t s = 0; s < 2 * (size_t)h->count; s++) {
        const float *ir = (s < h->count ? h->left : h->right) + (s % h->count) * h->length;
        memset(x, 0, (n + 2) * sizeof *x);
        for (size_t k = 0; k < h->length; k++)
            x[k] = ir[k];
        fg_fft_forward(&fft, x, x);
        for (size_t k = 0; k <= n / 2; k++) {
            double f = (double)k * h->sample_rate_hz / (double)n;
            if (f >= LEVEL_LO_HZ && f < LEVEL_HI_HZ) {
                level += x[2 * k] * x[2 * k] + x[2 * k + 1] * x[2 * k + 1];
                bins++;
            }
        }
    }
    fg_fft_deinit(&fft);
    free(x);
    return bins ? level / (double)bins : 0.0;
}

fg_result fg_binaural_init(fg_binaural *b, const fg_hrir_set *h)
{
    memset(b, 0, sizeof *b);
    const size_t len = h->length;
    double level = diffuse_level(h);
    double *filter = calloc((size_t)FG_BINAURAL_SPEAKERS * 2 * len, sizeof *filter);
    bool ok = filter && level > 0.0;
    if (ok) {
        double scale = 1.0 / sqrt(level);
        for (unsigned k = 0; k < FG_BINAURAL_SPEAKERS; k++) {
            double u[3];
            fg_binaural_speaker(k, u);
            size_t s = fg_hrir_nearest(h, u);
            for (unsigned e = 0; e < 2; e++) {
                const float *ir = (e == 0 ? h->left : h->right) + s * len;
                double *out = filter + ((size_t)k * 2 + e) * len;
                for (size_t t = 0; t < len; t++)
                    out[t] = scale * ir[t];
            }
        }
        ok = fg_convolver_init(&b->conv, FG_BINAURAL_SPEAKERS, 2, len,
                               FG_BINAURAL_LATENCY_FRAMES, filter);
    }
    free(filter);
    return ok ? FG_OK : FG_ERR_NO_MEMORY;
}
