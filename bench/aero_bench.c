/* Sound-texture precompute time per shape, against the paper's: a circular
 * cylinder, a square prism with its 10 directions (0-45 degrees), a sword's
 * cross-section with its 19 (0-90 degrees), all at D = 1 cm and 10 m/s
 * (Re 6 667), and a sphere of 10 cm (the paper's figure 11) at 10 m/s in
 * 3-D. Dobashi et al. (2003) report 45 min for the cylinder and 4 h for the
 * square prism's 8 directions (finite elements, 4 processors of an SGI
 * Origin 2000), about 1 h in 2-D and 10 h in 3-D (finite differences, a
 * 1.3 GHz Pentium III). Writes bench/results/aero_precompute.csv and .md.
 *
 * The grids are this machine's (2 shared cores): --grid 24 in 2-D (the
 * command's default is 32), 8 cells per diameter for the sphere (12), and
 * 12 shedding periods per loop (24); --full uses the command's defaults
 * (hours). Both threads compute directions at once. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "fulgur/aero.h"

typedef struct shape_case {
    const char *name;
    fg_aero_config c;
    const char *paper;
} shape_case;

/* A sword's cross-section: a flattened hexagon, 20 mm by 4 mm. */
static const double blade[] = {-0.010, 0, -0.006, -0.002, 0.006, -0.002,
                               0.010,  0, 0.006,  0.002,  -0.006, 0.002};

static void run(FILE *csv, FILE *md, const shape_case *s, int full)
{
    fg_aero_config c = s->c;
    c.threads = 2;
    if (!full) {
        c.cells_per_length = c.shape == FG_AERO_SPHERE ? 8 : 24;
        c.seconds = 12.0 / (0.2 * c.speed_m_s / (c.reference_m > 0 ? c.reference_m : c.length_m));
    }
    double wall0 = bench_now_s();
    clock_t cpu0 = clock();
    fg_aero_texture *t;
    fg_result r = fg_aero_generate(&c, NULL, NULL, &t);
    double wall = bench_now_s() - wall0, cpu = (double)(clock() - cpu0) / CLOCKS_PER_SEC;
    if (r != FG_OK) {
        fprintf(stderr, "aero_bench: %s: %s\n", s->name, fg_result_str(r));
        fprintf(csv, "%s,failed: %s\n", s->name, fg_result_str(r));
        return;
    }
    const fg_aero_texture_desc *d = fg_aero_texture_get(t);
    double st_lo = 1e9, st_hi = 0, frames = 0;
    for (uint32_t i = 0; i < d->directions; i++) {
        st_lo = fmin(st_lo, d->direction[i].strouhal);
        st_hi = fmax(st_hi, d->direction[i].strouhal);
        frames += d->direction[i].frames;
    }
    /* docs/aero-texture-format.md: header, polygon, sources, directions,
     * samples, CRC */
    double bytes = 160 + 16.0 * (d->polygon_vertices + d->sources) + 64.0 * d->directions +
                   4.0 * frames * d->sources * d->components + 4;
    printf("%-10s %2u-D, %3u direction(s), %4.0f cells/D, Re %5.0f: %7.1f s wall, %6.1f CPU min, "
           "St %.3f-%.3f\n",
           s->name, d->dims, d->directions, d->cells_per_length, d->reynolds, wall, cpu / 60.0,
           st_lo, st_hi);
    fprintf(csv, "%s,%u,%u,%u,%.0f,%.0f,%.1f,%.2f,%.4f,%.4f,%.0f\n", s->name, d->dims,
            d->directions, d->sources, d->cells_per_length, d->reynolds, wall, cpu / 60.0, st_lo,
            st_hi, bytes);
    fprintf(md, "| %s | %u-D | %u | %.0f | %.0f | %.1f min | %.1f min | %.3f–%.3f | %.0f KB | %s |\n",
            s->name, d->dims, d->directions, d->cells_per_length, d->reynolds, wall / 60.0,
            cpu / 60.0, st_lo, st_hi, bytes / 1024.0, s->paper);
    fflush(csv);
    fflush(md);
    fg_aero_texture_destroy(t);
}

int main(int argc, char **argv)
{
    int full = argc > 1 && strcmp(argv[1], "--full") == 0;
    const shape_case cases[] = {
        {"circle", {.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10},
         "45 min (FEM, 4 CPUs); ~1 h 2-D (FD, P-III)"},
        {"square", {.shape = FG_AERO_RECTANGLE, .length_m = 0.01, .speed_m_s = 10},
         "4 h for 8 directions (FEM, 4 CPUs)"},
        {"blade", {.shape = FG_AERO_POLYGON, .polygon_xy = blade, .polygon_vertices = 6,
                   .reference_m = 0.01, .speed_m_s = 10},
         "~1 h per 2-D shape (FD, P-III)"},
        {"sphere", {.shape = FG_AERO_SPHERE, .length_m = 0.1, .speed_m_s = 10},
         "~10 h 3-D (FD, P-III)"},
    };
    FILE *csv = bench_open_result("aero_precompute.csv");
    FILE *md = bench_open_result("aero_precompute.md");
    char machine[256];
    bench_machine(machine, sizeof machine);
    fprintf(csv, "# %s; %s grids\n", machine, full ? "the command's default" : "bench");
    fprintf(csv, "shape,dims,directions,sources,cells_per_d,reynolds,wall_s,cpu_min,st_min,"
                 "st_max,texture_bytes\n");
    fprintf(md, "# Sound-texture precompute time\n\n`build-bench/bench/bench_aero%s` on %s "
                "(two threads). D = 1 cm (sphere 10 cm), v0 = 10 m/s; %s.\n\n",
            full ? " --full" : "", machine,
            full ? "the command's default grids and loops"
                 : "2-D at 24 cells/D, the sphere at 8, loops of 12 periods");
    fprintf(md, "| shape | | directions | cells/D | Re | wall | CPU | St | texture | paper "
                "(Dobashi et al. 2003) |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        run(csv, md, &cases[i], full);
    fclose(csv);
    fclose(md);
    return 0;
}
