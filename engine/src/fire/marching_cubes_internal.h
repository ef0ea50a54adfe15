/* Marching cubes (Lorensen & Cline 1987) with a table derived here, not
 * copied: for each of the 256 inside/outside patterns of a cube's corners
 * the contour is drawn on each face, the segments are chained into closed
 * loops and each loop is fanned into triangles.
 *
 * Corner c of a cube is (c & 1, (c >> 1) & 1, (c >> 2) & 1); "inside"
 * means value > iso. Edge e = 4 a + q runs along axis a from its corner
 * with bit a clear to the one with bit a set; q numbers the other two
 * bits. On a face whose four edges are all crossed (diagonal corners
 * alike: the ambiguous case) the segments always cut off the inside
 * corners. The rule depends only on the face's own four corners, so the
 * two cubes that share a face draw the same segments there and the
 * surface is watertight: every triangle edge is shared by exactly two
 * triangles, in opposite directions. Triangles wind counter-clockwise seen
 * from outside (their normal points from inside to outside). */
#ifndef FULGUR_FIRE_MARCHING_CUBES_INTERNAL_H
#define FULGUR_FIRE_MARCHING_CUBES_INTERNAL_H

#include <stdint.h>

#define FG_MC_MAX_TRIANGLES 12

typedef struct fg_mc_table {
    uint8_t count[256];                           /* triangles per pattern */
    uint8_t edges[256][3 * FG_MC_MAX_TRIANGLES];  /* their edges, 3 per triangle */
    uint8_t edge_corner[12][2];                   /* each edge's two corners */
    uint8_t edge_axis[12];
} fg_mc_table;

/* Builds the table (pure computation, a few microseconds). */
void fg_mc_table_build(fg_mc_table *t);

#endif
