/* How many strokes a lightning flash has, and the time between them
 * (Matsuyama fig. 8, Abe fig. 3).
 *
 * Count: a log-series law P(k) = -p^k / (k ln(1 - p)), p = 0.85, cut at
 * FG_MAX_STROKES: single strokes are the most frequent (45 %), 4-6 strokes
 * common (15 %), more than 10 possible (3.8 %); mean 3.0.
 * Interval: Poisson-shaped, 10 ms * (1 + k + u) with k ~ Poisson(2.5) and u
 * uniform in [0, 1): range 10-240 ms, mode 30-40 ms, mean 40 ms. */
#ifndef FULGUR_STROKES_INTERNAL_H
#define FULGUR_STROKES_INTERNAL_H

#include <stdint.h>

#include "fg_rng.h"

#define FG_STROKE_LOGSERIES_P 0.85
#define FG_STROKE_INTERVAL_UNIT_S 0.010
#define FG_STROKE_INTERVAL_POISSON_MEAN 2.5
#define FG_STROKE_INTERVAL_MAX_K 22 /* 10 ms * (1 + 22 + 1) = 240 ms */

/* A stroke count (1..FG_MAX_STROKES) drawn from the cut law. */
uint32_t fg_strokes_draw_count(fg_rng *rng);

/* An interval between strokes, seconds, drawn from its law. */
double fg_strokes_draw_interval_s(fg_rng *rng);

#endif
