/* The skeleton a lightning walk follows: a polyline with its arclength. */
#ifndef FULGUR_SKELETON_INTERNAL_H
#define FULGUR_SKELETON_INTERNAL_H

#include <stddef.h>

#include "fulgur/result.h"
#include "fg_vec3.h"

typedef struct fg_skeleton {
    fg_vec3 *p;    /* points, root first */
    double *s;     /* s[i]: arclength from the root to p[i], metres */
    size_t n, cap;
} fg_skeleton;

/* Appends q; a point equal to the last one is skipped. */
fg_result fg_skeleton_push(fg_skeleton *k, fg_vec3 q);
void fg_skeleton_free(fg_skeleton *k);

static inline double fg_skeleton_length(const fg_skeleton *k)
{
    return k->s[k->n - 1];
}

/* The point at arclength s, clamped to [0, length]. */
fg_vec3 fg_skeleton_at(const fg_skeleton *k, double s);

/* The arclength of the point of the skeleton closest to q, searching
 * forward from segment *hint over a short window (the walk moves forward);
 * *hint is updated. */
double fg_skeleton_project(const fg_skeleton *k, fg_vec3 q, size_t *hint);

/* A random cloud-to-ground skeleton: root at height h, drifted up to 0.2 h
 * sideways from the strike point (x, y, 0), eight pieces with sideways
 * jitter of up to 0.08 h and height jitter of up to 0.04 h. */
fg_result fg_skeleton_random(fg_skeleton *k, fg_rng *rng, double x, double y, double h);

/* A course from `from` to `to` (of length L) with the random skeleton's
 * pieces: seven joints jittered up to 0.08 L in x and in y and
 * 0.04 min(L, from.z) up or down (so never below 0.96 from.z). */
fg_result fg_skeleton_course(fg_skeleton *k, fg_rng *rng, fg_vec3 from, fg_vec3 to);

#endif
