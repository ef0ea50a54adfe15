/* Skeleton polylines: storage, arclength queries, the random skeleton and
 * the in-cloud course. */
#include <math.h>
#include <stdlib.h>

#include "fg_array.h"
#include "skeleton_internal.h"

#define PROJECT_WINDOW 16
#define RANDOM_PIECES 8

fg_result fg_skeleton_push(fg_skeleton *k, fg_vec3 q)
{
    double s = 0;
    if (k->n > 0) {
        double d = fg_v3_len(fg_v3_sub(q, k->p[k->n - 1]));
        if (d == 0)
            return FG_OK;
        s = k->s[k->n - 1] + d;
    }
    /* two arrays of one capacity: the second grows to the first's */
    size_t cap = k->cap, cap_s = k->cap;
    fg_vec3 *p = fg_array_grow(k->p, &cap, k->n + 1, sizeof *p, 64);
    if (!p)
        return FG_ERR_NO_MEMORY;
    k->p = p;
    double *sv = fg_array_grow(k->s, &cap_s, cap, sizeof *sv, 64);
    if (!sv)
        return FG_ERR_NO_MEMORY;
    k->s = sv;
    k->cap = cap;
    k->p[k->n] = q;
    k->s[k->n] = s;
    k->n++;
    return FG_OK;
}

void fg_skeleton_free(fg_skeleton *k)
{
    free(k->p);
    free(k->s);
    *k = (fg_skeleton){0};
}

fg_vec3 fg_skeleton_at(const fg_skeleton *k, double s)
{
    if (s <= 0)
        return k->p[0];
    if (s >= fg_skeleton_length(k))
        return k->p[k->n - 1];
    size_t lo = 0, hi = k->n - 1; /* s[lo] <= s < s[hi] */
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (k->s[mid] <= s)
            lo = mid;
        else
            hi = mid;
    }
    double w = (s - k->s[lo]) / (k->s[hi] - k->s[lo]);
    return fg_v3_add(k->p[lo], fg_v3_scale(fg_v3_sub(k->p[hi], k->p[lo]), w));
}

double fg_skeleton_project(const fg_skeleton *k, fg_vec3 q, size_t *hint)
{
    size_t end = *hint + PROJECT_WINDOW < k->n - 1 ? *hint + PROJECT_WINDOW : k->n - 1;
    double best_d2 = INFINITY, best_s = k->s[*hint];
    size_t best = *hint;
    for (size_t i = *hint; i < end; i++) {
        fg_vec3 a = k->p[i], ab = fg_v3_sub(k->p[i + 1], a);
        double len = k->s[i + 1] - k->s[i];
        double t = fg_v3_dot(fg_v3_sub(q, a), ab) / (len * len);
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        fg_vec3 d = fg_v3_sub(q, fg_v3_add(a, fg_v3_scale(ab, t)));
        double d2 = fg_v3_dot(d, d);
        if (d2 < best_d2) {
            best_d2 = d2;
            best = i;
            best_s = k->s[i] + t * len;
        }
    }
    *hint = best;
    return best_s;
}

/* Appends RANDOM_PIECES - 1 joints on the line from the skeleton's last
 * point a to b, each moved up to 0.08 side in x and in y and 0.04 up
 * either way, then b. */
static fg_result jittered_pieces(fg_skeleton *k, fg_rng *rng, fg_vec3 a, fg_vec3 b,
                                 double side, double up)
{
    fg_result r = FG_OK;
    for (int j = 1; j < RANDOM_PIECES && r == FG_OK; j++) {
        double w = (double)j / RANDOM_PIECES;
        fg_vec3 q = fg_v3_add(a, fg_v3_scale(fg_v3_sub(b, a), w));
        q.x += fg_rng_range(rng, -0.08, 0.08) * side;
        q.y += fg_rng_range(rng, -0.08, 0.08) * side;
        q.z += fg_rng_range(rng, -0.04, 0.04) * up;
        r = fg_skeleton_push(k, q);
    }
    return r == FG_OK ? fg_skeleton_push(k, b) : r;
}

fg_result fg_skeleton_random(fg_skeleton *k, fg_rng *rng, double x, double y, double h)
{
    fg_vec3 strike = fg_v3(x, y, 0);
    fg_vec3 root = fg_v3(x + fg_rng_range(rng, -0.2, 0.2) * h,
                         y + fg_rng_range(rng, -0.2, 0.2) * h, h);
    fg_result r = fg_skeleton_push(k, root);
    return r == FG_OK ? jittered_pieces(k, rng, root, strike, h, h) : r;
}

fg_result fg_skeleton_course(fg_skeleton *k, fg_rng *rng, fg_vec3 from, fg_vec3 to)
{
    double length = fg_v3_len(fg_v3_sub(to, from));
    fg_result r = fg_skeleton_push(k, from);
    return r == FG_OK ? jittered_pieces(k, rng, from, to, length, fmin(length, from.z)) : r;
}
