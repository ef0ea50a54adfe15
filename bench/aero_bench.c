/* Sound-texture precompute time per shape, against the paper's. By
 * default the shipped textures of examples/aero/ (README.md there gives
 * their commands) with exactly the options they were made with: the
 * 1 cm rod and the 4 mm wire (circles, 12 cells/D, 10 m/s) and the
 * sword's blade (a 22.5 x 5 mm rectangle, 12 cells across 22.5 mm,
 * 20 m/s, directions every 30 degrees); and in 3-D, where nothing is
 * shipped, a sphere of 10 cm (the paper's figure 11) at 10 m/s on a
 * grid this machine (2 shared cores) allows: 6 cells/D, the start-up
 * capped at 1.5x its least, a loop of 4 periods. --full: the same
 * shapes at the command's defaults (32 cells/D in 2-D, 12 in 3-D, 24
 * periods, a direction every 5 degrees; hours).
 *
 * Dobashi et al. (2003) report 45 min for the cylinder and 4 h for the
 * square prism's 8 directions (finite elements, 4 processors of an SGI
 * Origin 2000), about 1 h in 2-D and 10 h in 3-D (finite differences, a
 * 1.3 GHz Pentium III). The figure to compare is CPU time (all threads
 * of the process), not wall: the machine is shared. Writes
 * bench/results/aero_precompute.csv and prints its rows as a Markdown
 * table (bench/results/aero_precompute.md discusses them). */
#define _POSIX_C_SOURCE 200809L
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

/* The CPU time of the whole process (every thread the generator starts). */
static double process_cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void run(FILE *csv, const shape_case *s, int full)
{
    fg_aero_config c = s->c;
    if (full) {
        c.cells_per_length = 0.0;
        c.seconds = 0.0;
        c.max_transient_s = 0.0;
        c.direction_step_rad = 0.0;
    }
    double wall0 = bench_now_s(), cpu0 = process_cpu_s();
    fg_aero_texture *t;
    fg_result r = fg_aero_generate(&c, NULL, NULL, &t);
    double wall = bench_now_s() - wall0, cpu = process_cpu_s() - cpu0;
    if (r != FG_OK) {
        fprintf(stderr, "aero_bench: %s: %s\n", s->name, fg_result_str(r));
        fprintf(csv, "%s,failed: %s\n", s->name, fg_result_str(r));
        return;
    }
    const fg_aero_texture_desc *d = fg_aero_texture_get(t);
    double st_lo = 1e9, st_hi = 0, frames = 0, simulated = 0;
    for (uint32_t i = 0; i < d->directions; i++) {
        const fg_aero_direction *a = &d->direction[i];
        if (a->frequency_hz > 0) {
            st_lo = fmin(st_lo, a->strouhal);
            st_hi = fmax(st_hi, a->strouhal);
        }
        frames += a->frames;
        simulated += a->transient_s + a->frames / d->sample_rate_hz;
    }
    if (st_hi == 0)
        st_lo = 0;
    /* simulated time in units of reference_m / speed_m_s, all directions */
    double d_v0 = simulated * d->speed_m_s / d->reference_m;
    /* docs/aero-texture-format.md: header, polygon, sources, directions,
     * samples, CRC */
    double bytes = 160 + 16.0 * (d->polygon_vertices + d->sources) + 64.0 * d->directions +
                   4.0 * frames * d->sources * d->components + 4;
    fprintf(csv, "%s,%u,%u,%u,%.0f,%.0f,%.0f,%.1f,%.3f,%.4f,%.4f,%.0f\n", s->name, d->dims,
            d->directions, d->sources, d->cells_per_length, d->reynolds, d_v0, wall, cpu / 60.0,
            st_lo, st_hi, bytes);
    printf("| %s | %u-D | %u | %.0f | %.0f | %.0f | %.2f min | %.2f min | %.3f–%.3f | "
                "%.1f KB | %s |\n",
            s->name, d->dims, d->directions, d->cells_per_length, d->reynolds, d_v0, wall / 60.0,
            cpu / 60.0, st_lo, st_hi, bytes / 1024.0, s->paper);
    fflush(csv);
    fflush(stdout);
    fg_aero_texture_destroy(t);
}

int main(int argc, char **argv)
{
    int full = argc > 1 && strcmp(argv[1], "--full") == 0;
    const double pi = 3.14159265358979323846;
    const shape_case cases[] = {
        {"rod_1cm",
         {.shape = FG_AERO_CIRCLE, .length_m = 0.01, .speed_m_s = 10, .cells_per_length = 12,
          .seconds = 0.05},
         "45 min (FEM, 4 CPUs); ~1 h 2-D (FD, P-III)"},
        {"wire_4mm",
         {.shape = FG_AERO_CIRCLE, .length_m = 0.004, .speed_m_s = 10, .cells_per_length = 12,
          .seconds = 0.03},
         "as above"},
        {"blade",
         {.shape = FG_AERO_RECTANGLE, .length_m = 0.0225, .height_m = 0.005,
          .reference_m = 0.0225, .speed_m_s = 20, .cells_per_length = 12,
          .direction_step_rad = 30 * pi / 180, .seconds = 0.05, .threads = 2},
         "square prism, 8 directions: 4 h (FEM, 4 CPUs)"},
        {"sphere",
         {.shape = FG_AERO_SPHERE, .length_m = 0.1, .speed_m_s = 10, .cells_per_length = 6,
          .max_transient_s = 1.5 * 30 * 0.1 / 10, .seconds = 4 / (0.2 * 10 / 0.1)},
         "~10 h 3-D (FD, P-III)"},
    };
    FILE *csv = bench_open_result("aero_precompute.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    fprintf(csv, "# %s; %s\n", machine,
            full ? "the command's default grids" : "the shipped textures' grids");
    fprintf(csv, "shape,dims,directions,sources,cells_per_d,reynolds,simulated_d_v0,wall_s,"
                 "cpu_min,st_min,st_max,texture_bytes\n");
    printf("| shape | | directions | cells/D | Re | simulated (D/v0) | wall | CPU | St | "
                "texture | paper (Dobashi et al. 2003) |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        run(csv, &cases[i], full);
    fclose(csv);
    return 0;
}
