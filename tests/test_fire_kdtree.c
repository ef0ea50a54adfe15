/* The kd-tree of the texture synthesis against brute force, on clustered
 * 46-dimensional points with duplicates: eps = 0 finds a nearest point
 * (its distance equals the true minimum), eps = 1 one within twice the
 * minimum distance; a query equal to a stored point finds distance 0. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "fire/kdtree_internal.h"
#include "fg_rng.h"

#define DIM 46
#define COUNT 20000
#define QUERIES 400

static double dist2(const float *a, const float *b)
{
    double s = 0.0;
    for (int d = 0; d < DIM; d++)
        s += ((double)a[d] - b[d]) * ((double)a[d] - b[d]);
    return s;
}

static void test_against_brute_force(void **state)
{
    (void)state;
    fg_rng rng;
    fg_rng_seed(&rng, 9);
    float *pts = malloc(sizeof(float) * COUNT * DIM), centres[16][DIM];
    for (int c = 0; c < 16; c++)
        for (int d = 0; d < DIM; d++)
            centres[c][d] = (float)fg_rng_range(&rng, -1.0, 1.0);
    for (int i = 0; i < COUNT; i++) {
        if (i % 97 == 1) { /* exact duplicates of the point before */
            for (int d = 0; d < DIM; d++)
                pts[i * DIM + d] = pts[(i - 1) * DIM + d];
            continue;
        }
        int c = (int)(fg_rng_uniform(&rng) * 16);
        for (int d = 0; d < DIM; d++)
            pts[i * DIM + d] = centres[c][d] + (float)(0.2 * fg_rng_range(&rng, -1.0, 1.0) /
                                                       (1.0 + d));
    }
    fg_kdtree t;
    assert_true(fg_kdtree_build(&t, pts, COUNT, DIM));
    float q[DIM];
    int exact_hits = 0;
    double worst_ratio = 1.0;
    for (int k = 0; k < QUERIES; k++) {
        int c = (int)(fg_rng_uniform(&rng) * 16);
        for (int d = 0; d < DIM; d++)
            q[d] = centres[c][d] + (float)(0.25 * fg_rng_range(&rng, -1.0, 1.0) / (1.0 + d));
        double best = INFINITY;
        for (int i = 0; i < COUNT; i++)
            best = fmin(best, dist2(q, pts + (size_t)i * DIM));
        double d0, d1;
        size_t i0 = fg_kdtree_nearest(&t, q, 0.0, &d0);
        size_t i1 = fg_kdtree_nearest(&t, q, 1.0, &d1);
        assert_true(i0 < COUNT && i1 < COUNT);
        /* what it reports is what the point is, to float summation */
        assert_true(fabs(dist2(q, pts + i0 * DIM) - d0) <= 1e-5 * best);
        assert_true(fabs(dist2(q, pts + i0 * DIM) - best) <= 1e-5 * best);
        assert_true(dist2(q, pts + i1 * DIM) <= 4.0 * best * (1.0 + 1e-5));
        worst_ratio = fmax(worst_ratio, sqrt(dist2(q, pts + i1 * DIM) / best));
        exact_hits += dist2(q, pts + i1 * DIM) <= best * (1.0 + 1e-6);
    }
    print_message("eps = 1: worst distance ratio %.3f, exact in %d of %d\n", worst_ratio,
                  exact_hits, QUERIES);
    /* stored points are found at distance 0, whatever eps */
    for (int i = 0; i < COUNT; i += 1231) {
        double d;
        size_t j = fg_kdtree_nearest(&t, pts + (size_t)i * DIM, 1.0, &d);
        assert_true(d == 0.0);
        assert_true(dist2(pts + (size_t)i * DIM, pts + j * DIM) == 0.0);
    }
    fg_kdtree_free(&t);
    /* refusals */
    assert_false(fg_kdtree_build(&t, pts, 0, DIM));
    assert_false(fg_kdtree_build(&t, pts, 10, FG_KD_MAX_DIM + 1));
    free(pts);
}

/* One point, and fewer points than a leaf. */
static void test_small(void **state)
{
    (void)state;
    float p[3 * DIM] = {0};
    for (int d = 0; d < DIM; d++) {
        p[DIM + d] = 1.0f;
        p[2 * DIM + d] = -1.0f;
    }
    fg_kdtree t;
    assert_true(fg_kdtree_build(&t, p, 3, DIM));
    float q[DIM];
    for (int d = 0; d < DIM; d++)
        q[d] = 0.8f;
    double d2;
    assert_int_equal(fg_kdtree_nearest(&t, q, 0.0, &d2), 1);
    assert_true(fabs(d2 - DIM * 0.04) < 1e-5);
    fg_kdtree_free(&t);
    assert_true(fg_kdtree_build(&t, p, 1, DIM));
    assert_int_equal(fg_kdtree_nearest(&t, q, 1.0, NULL), 0);
    fg_kdtree_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_brute_force),
        cmocka_unit_test(test_small),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
