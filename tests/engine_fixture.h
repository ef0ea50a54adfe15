/* Helpers shared by the engine tests: render into planes, find onsets,
 * measure energy. Test code only. */
#ifndef FULGUR_TEST_ENGINE_FIXTURE_H
#define FULGUR_TEST_ENGINE_FIXTURE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/fulgur.h"

/* Renders frames frames into planes[ch][0..frames) (channels <= 16) in
 * blocks of block (the last one shorter), asserting FG_OK. */
void fx_render(fg_engine *e, float *const *planes, uint32_t channels, size_t frames,
               uint32_t block);

/* The first index with x != 0, or -1. */
long fx_first_nonzero(const float *x, size_t n);

/* Onsets: indices where |x| first exceeds threshold after at least
 * min_gap samples at or below it (or at the start). Writes at most max and
 * returns how many were found. */
size_t fx_onsets(const float *x, size_t n, float threshold, size_t min_gap, size_t *out,
                 size_t max);

/* Sum of x^2 over [a, b). */
double fx_energy(const float *x, size_t a, size_t b);

/* max |x| over [0, n). */
float fx_peak(const float *x, size_t n);

/* A two-node tree: one segment from mid - l dir to mid + l dir (root
 * first). */
void fx_segment(fg_node nodes[2], const double mid[3], const double dir[3], double half_len_m);

#endif
