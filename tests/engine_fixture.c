#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>
#include <math.h>

#include "engine_fixture.h"

void fx_render(fg_engine *e, float *const *planes, uint32_t channels, size_t frames,
               uint32_t block)
{
    for (size_t at = 0; at < frames; at += block) {
        uint32_t n = frames - at < block ? (uint32_t)(frames - at) : block;
        float *p[16] = {NULL};
        for (uint32_t ch = 0; ch < channels && ch < 16; ch++)
            p[ch] = planes[ch] + at;
        assert_int_equal(fg_engine_render(e, p, n), FG_OK);
    }
}

long fx_first_nonzero(const float *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (x[k] != 0.0f)
            return (long)k;
    return -1;
}

size_t fx_onsets(const float *x, size_t n, float threshold, size_t min_gap, size_t *out,
                 size_t max)
{
    size_t found = 0, quiet = min_gap;
    for (size_t k = 0; k < n; k++) {
        if (fabsf(x[k]) > threshold) {
            if (quiet >= min_gap && found < max)
                out[found++] = k;
            quiet = 0;
        } else {
            quiet++;
        }
    }
    return found;
}

double fx_energy(const float *x, size_t a, size_t b)
{
    double sum = 0;
    for (size_t k = a; k < b; k++)
        sum += (double)x[k] * x[k];
    return sum;
}

float fx_peak(const float *x, size_t n)
{
    float m = 0;
    for (size_t k = 0; k < n; k++)
        m = fmaxf(m, fabsf(x[k]));
    return m;
}

void fx_segment(fg_node nodes[2], const double mid[3], const double dir[3], double half_len_m)
{
    double norm = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    double u[3] = {dir[0] / norm, dir[1] / norm, dir[2] / norm};
    nodes[0] = (fg_node){mid[0] - half_len_m * u[0], mid[1] - half_len_m * u[1],
                         mid[2] - half_len_m * u[2], -1, 0};
    nodes[1] = (fg_node){mid[0] + half_len_m * u[0], mid[1] + half_len_m * u[1],
                         mid[2] + half_len_m * u[2], 0, 0};
}
