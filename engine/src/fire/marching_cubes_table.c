#include <assert.h>
#include <string.h>

#include "marching_cubes_internal.h"

static int corner_on_edge(int a, int q, int side)
{
    int b = (a + 1) % 3, c = (a + 2) % 3;
    return ((q & 1) << b) | (((q >> 1) & 1) << c) | (side << a);
}

/* The edge joining corners u and v (which differ in one bit). */
static int edge_between(const fg_mc_table *t, int u, int v)
{
    for (int e = 0; e < 12; e++)
        if ((t->edge_corner[e][0] == u && t->edge_corner[e][1] == v) ||
            (t->edge_corner[e][0] == v && t->edge_corner[e][1] == u))
            return e;
    assert(0);
    return -1;
}

static void edge_midpoint(const fg_mc_table *t, int e, double p[3])
{
    int c = t->edge_corner[e][0];
    for (int k = 0; k < 3; k++)
        p[k] = (double)((c >> k) & 1);
    p[t->edge_axis[e]] = 0.5;
}

/* Adds the segment between edges ea and eb on a face of outward normal
 * `normal` (axis a, sign), oriented so that normal x (B - A) points away
 * from the inside corner `inside`. */
static void add_segment(const fg_mc_table *t, int ea, int eb, int axis, double sign, int inside,
                        int next[12])
{
    double pa[3], pb[3], n[3] = {0, 0, 0}, d[3], cr[3], in[3];
    edge_midpoint(t, ea, pa);
    edge_midpoint(t, eb, pb);
    n[axis] = sign;
    for (int k = 0; k < 3; k++) {
        d[k] = pb[k] - pa[k];
        in[k] = (double)((inside >> k) & 1) - pa[k];
    }
    cr[0] = n[1] * d[2] - n[2] * d[1];
    cr[1] = n[2] * d[0] - n[0] * d[2];
    cr[2] = n[0] * d[1] - n[1] * d[0];
    double toward = cr[0] * in[0] + cr[1] * in[1] + cr[2] * in[2];
    if (toward > 0.0) {
        int s = ea;
        ea = eb;
        eb = s;
    }
    assert(next[ea] < 0);
    next[ea] = eb;
}

static void build_pattern(fg_mc_table *t, int mask)
{
    int next[12];
    for (int e = 0; e < 12; e++)
        next[e] = -1;
    for (int axis = 0; axis < 3; axis++) {
        for (int side = 0; side < 2; side++) {
            /* the face's corners in cyclic order, and its edges */
            int corner[4], edge[4], in[4];
            for (int k = 0; k < 4; k++) {
                static const int cyc[4] = {0, 1, 3, 2};
                corner[k] = corner_on_edge(axis, cyc[k], side);
            }
            for (int k = 0; k < 4; k++) {
                edge[k] = edge_between(t, corner[k], corner[(k + 1) % 4]);
                in[k] = (mask >> corner[k]) & 1;
            }
            int crossed[4], n = 0, inside_corner = -1;
            for (int k = 0; k < 4; k++) {
                if (in[k] != in[(k + 1) % 4])
                    crossed[n++] = k;
                if (in[k])
                    inside_corner = corner[k];
            }
            double sign = side ? 1.0 : -1.0;
            if (n == 2) {
                add_segment(t, edge[crossed[0]], edge[crossed[1]], axis, sign, inside_corner,
                            next);
            } else if (n == 4) {
                /* ambiguous: cut off each inside corner k, between the
                 * edges k - 1 and k that meet at it */
                for (int k = 0; k < 4; k++)
                    if (in[k])
                        add_segment(t, edge[(k + 3) % 4], edge[k], axis, sign, corner[k], next);
            }
        }
    }
    /* chain the segments into loops; fan each loop */
    int used[12] = {0};
    uint8_t *out = t->edges[mask];
    int tris = 0;
    for (int start = 0; start < 12; start++) {
        if (next[start] < 0 || used[start])
            continue;
        int loop[12], len = 0;
        for (int e = start; !used[e]; e = next[e]) {
            assert(next[e] >= 0);
            used[e] = 1;
            loop[len++] = e;
        }
        assert(len >= 3);
        for (int k = 1; k + 1 < len; k++) {
            assert(tris < FG_MC_MAX_TRIANGLES);
            out[3 * tris] = (uint8_t)loop[0];
            out[3 * tris + 1] = (uint8_t)loop[k];
            out[3 * tris + 2] = (uint8_t)loop[k + 1];
            tris++;
        }
    }
    t->count[mask] = (uint8_t)tris;
}

void fg_mc_table_build(fg_mc_table *t)
{
    memset(t, 0, sizeof *t);
    for (int a = 0; a < 3; a++)
        for (int q = 0; q < 4; q++) {
            int e = 4 * a + q;
            t->edge_axis[e] = (uint8_t)a;
            t->edge_corner[e][0] = (uint8_t)corner_on_edge(a, q, 0);
            t->edge_corner[e][1] = (uint8_t)corner_on_edge(a, q, 1);
        }
    for (int mask = 0; mask < 256; mask++)
        build_pattern(t, mask);
}
