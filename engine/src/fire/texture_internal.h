/* Sound texture synthesis (section 5): what training and synthesis share.
 *
 * Windows. On level l, window i has centre c = i h and covers c - h ..
 * c + h, weighted by the hat (h - |n - c|) / h (the paper's W_i over h, so
 * the windows sum to one).
 *
 * Features. The feature of window i on level l is
 *   fine:   G(l) at c - 2 h h_f .. c - h           (2 h h_f - h + 1 samples)
 *   coarse: G(l + 1) at c/2 - h h_f .. c/2 + h h_f (2 h h_f + 1 samples,
 *           linearly interpolated where c/2 is not an integer)
 * 21 + 25 = 46 dimensions for h = 4, h_f = 3: the 46 of the paper's text.
 * Its printed eq. 15 reads c - h h_f .. c - h, 9 samples, which gives 34;
 * we read h h_f in eq. 15 as counted in samples of the coarser level, as
 * eq. 16 counts it, i.e. 2 h h_f samples of level l: then the fine part
 * covers the same past as the coarse part (12 coarse samples = 24 fine
 * ones before the window), as Wei & Levoy's multiresolution neighbourhoods
 * do, and the count is the text's 46. docs/fire-sound.md says more.
 *
 * The fine part lies wholly before the window, so it is complete when the
 * window is synthesised (windows go in order of i); the coarse part is a
 * finished coarser level, both before and after c/2. */
#ifndef FULGUR_FIRE_TEXTURE_INTERNAL_H
#define FULGUR_FIRE_TEXTURE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "kdtree_internal.h"
#include "fulgur/fire.h"

#define FG_TEXTURE_MAX_LEVELS 8

typedef struct fg_texture_shape {
    int levels, h, hf;
    int fine_len, coarse_len, dims, value_len;
} fg_texture_shape;

void fg_texture_shape_init(fg_texture_shape *s, int levels, int h, int hf);

/* A level's samples as the feature builder reads them: index i is
 * data[i & mask]; indices below `first` read as 0 (before the start). */
typedef struct fg_level_view {
    const double *data;
    uint64_t mask;
    int64_t first;
} fg_level_view;

/* The feature of the window centred at c (level l samples) from fine =
 * level l and coarse = level l + 1, the coarse part multiplied by
 * coarse_scale, into out[0 .. dims). */
void fg_texture_feature(const fg_texture_shape *s, const fg_level_view *fine,
                        const fg_level_view *coarse, int64_t c, double coarse_scale, float *out);

/* The mean magnitude of the coarse part's samples (eq. 17's p_abs,avg). */
double fg_texture_coarse_mean(const fg_texture_shape *s, const fg_level_view *coarse, int64_t c);

/* Linear interpolation of a sorted array as a distribution: the fraction
 * of values at or below v (ties at their middle), and its inverse. */
double fg_sorted_cdf(const double *sorted, size_t n, double v);
double fg_sorted_quantile(const double *sorted, size_t n, double q);

typedef struct fg_texture_dictionary {
    size_t count;
    float *values;       /* count * value_len: the windows' samples */
    fg_kdtree tree;      /* over their features */
} fg_texture_dictionary;

struct fg_fire_texture {
    fg_fire_texture_config config;   /* samples NULL */
    fg_texture_shape shape;
    fg_texture_dictionary dict[FG_TEXTURE_MAX_LEVELS - 1]; /* D_1 .. D_{L-1} */
    double *amplitudes;              /* |G_T(L)|, sorted: F_T */
    size_t amplitude_count;
    double amplitude_floor;          /* the least p_abs,training used */
    size_t bytes;
};

#endif
