/* The operators of the levels below the grid: the finite-volume Laplacian
 * rediscretised at each level's spacing, with the Dirichlet boundary
 * where the grid has it.
 *
 * A coarse node is Dirichlet when the grid node at the same place is
 * (injection). Rediscretising with only that would put the boundary on the
 * coarse lattice: a sphere shrinks or swells by up to a coarse cell, a
 * thin tree between coarse nodes vanishes, and the coarse correction is
 * wrong where it matters most. Plain V-cycles then stalled (0.98 per cycle
 * on the spark-ball scene at 65^3) or diverged (the thin tree of the
 * tests), and only conjugate gradient made them converge. So each coarse
 * edge looks along its line at the grid's own nodes: where a Dirichlet
 * node lies at a fraction theta of the edge from a free end, the edge is
 * cut there, and the free end sees the boundary at theta H: its diagonal
 * takes c / theta instead of c and the coupling across goes
 * (Shortley & Weller 1938, "The numerical solution of Laplace's equation",
 * J. Appl. Phys. 9, 334). Cutting removes a coupling from both ends and
 * only adds to diagonals, so the operator stays symmetric, and positive
 * definite where every free region touches a boundary. Box faces halve the
 * edges lying in them, as on the grid. */
#include <string.h>

#include "field_internal.h"

/* The first of the grid's nodes from (including) g + step to g + m step
 * that is Dirichlet, counted in steps; m + 1 if none is. */
static int first_dirichlet(const uint8_t *label, size_t g, ptrdiff_t step, int m)
{
    for (int t = 1; t <= m; t++)
        if (label[(size_t)((ptrdiff_t)g + t * step)])
            return t;
    return m + 1;
}

static inline double face(int i, int n)
{
    return i == 0 || i == n - 1 ? 0.5 : 1.0;
}

static void assemble_level(const fg_level *G, fg_level *C, int m)
{
    const uint8_t *label = G->mask;
    const ptrdiff_t gstep[3] = {m, (ptrdiff_t)m * G->n[0], (ptrdiff_t)m * G->n[0] * G->n[1]};
    const ptrdiff_t cstep[3] = {1, C->n[0], (ptrdiff_t)C->n[0] * C->n[1]};
    for (int k = 0; k < C->n[2]; k++)
        for (int j = 0; j < C->n[1]; j++)
            for (int i = 0; i < C->n[0]; i++) {
                size_t id = fg_level_index(C, i, j, k);
                C->mask[id] = label[fg_level_index(G, m * i, m * j, m * k)] != 0;
            }
    memset(C->diag, 0, C->count * sizeof *C->diag);
    const int at_end[3] = {C->n[0] - 1, C->n[1] - 1, C->n[2] - 1};
    for (int k = 0; k < C->n[2]; k++)
        for (int j = 0; j < C->n[1]; j++)
            for (int i = 0; i < C->n[0]; i++) {
                const int p[3] = {i, j, k};
                size_t id = fg_level_index(C, i, j, k);
                size_t g = fg_level_index(G, m * i, m * j, m * k);
                for (int a = 0; a < 3; a++) {
                    if (p[a] == at_end[a]) {
                        C->w[a][id] = 0.0f;
                        continue;
                    }
                    size_t nb = id + (size_t)cstep[a];
                    double c = C->c[a] * face(p[(a + 1) % 3], C->n[(a + 1) % 3]) *
                               face(p[(a + 2) % 3], C->n[(a + 2) % 3]);
                    int from_lo = first_dirichlet(label, g, gstep[a] / m, m);
                    if (!C->mask[id] && !C->mask[nb] && from_lo > m) {
                        C->w[a][id] = (float)c;
                        C->diag[id] += (float)c;
                        C->diag[nb] += (float)c;
                        continue;
                    }
                    C->w[a][id] = 0.0f;
                    if (!C->mask[id])
                        C->diag[id] += (float)(c * m / from_lo);
                    if (!C->mask[nb])
                        C->diag[nb] += (float)(c * m /
                                               first_dirichlet(label, g + (size_t)gstep[a],
                                                               -gstep[a] / m, m));
                }
            }
    for (size_t id = 0; id < C->count; id++)
        C->inv_diag[id] = C->mask[id] ? 0.0f : 1.0f / C->diag[id];
}

void fg_multigrid_assemble(fg_field *f)
{
    fg_level *L = &f->level[0];
    const float inv = (float)(1.0 / (2.0 * (L->c[0] + L->c[1] + L->c[2])));
    const int n = L->n[0], ne = (n + 1) / 2;
    for (size_t row = 0; row < L->count; row += (size_t)n) {
        const uint8_t *m = L->mask + row;
        float *even = L->inv_diag + row, *odd = even + ne;
        for (int u = 0; u < ne; u++)
            even[u] = m[2 * u] ? 0.0f : inv;
        for (int u = 0; u < n / 2; u++)
            odd[u] = m[2 * u + 1] ? 0.0f : inv;
    }
    for (int l = 1; l < f->levels; l++)
        assemble_level(&f->level[0], &f->level[l], 1 << l);
    f->operators_dirty = 0;
}
