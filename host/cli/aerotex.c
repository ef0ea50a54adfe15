/* fulgur aerotex: computes an aerodynamic sound texture by CFD and writes
 * it to a file; --info prints a texture file's contents. */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno, clock_gettime */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "common/aero_texture_file.h"
#include "common/commands.h"
#include "fg_math.h"

#define MAX_LIST 4096

static const char usage[] =
    "usage: fulgur aerotex --shape SHAPE SIZE --speed M/S -o FILE.aerotex [OPTIONS]\n"
    "       fulgur aerotex --info FILE.aerotex\n"
    "Computes the aerodynamic sound texture of a shape (Dobashi et al. 2003): the\n"
    "flow past it by CFD at the base speed, the force on it, g = dF/dt as a seamless\n"
    "loop per flow direction (2-D) or per source along it (3-D).\n"
    "Shapes and their sizes (metres):\n"
    "  --shape circle    --diameter D          a circular cylinder (2-D)\n"
    "  --shape square    --side S              a square prism (2-D)\n"
    "  --shape rectangle --width W --height H  W along the flow at 0 degrees (2-D)\n"
    "  --shape polygon   --polygon x,y,x,y,... any simple polygon, e.g. a blade (2-D)\n"
    "  --shape sphere    --diameter D          (3-D)\n"
    "  --shape club      --length L --diameters DH,DT  tapered, round ends (3-D)\n"
    "Options:\n"
    "  --speed M/S          base speed v0 (required)\n"
    "  --tone aeolian|cavity  the level law it is played with (aeolian: (v/v0)^3)\n"
    "  --reference M        the D of Re and St (default: the diameter, or the width\n"
    "                       across the flow at 0 degrees, or the club's largest diameter)\n"
    "  --grid N             cells across the reference length (32 in 2-D, 12 in 3-D)\n"
    "  --rate HZ            texture sample rate (16 samples per D/v0: 16 kHz at 1 cm, 10 m/s)\n"
    "  --seconds S          loop length at v0 (default 24 shedding periods)\n"
    "  --transient S        least start-up to discard (60 D/v0 in 2-D, 30 in 3-D)\n"
    "  --max-transient S    give up without settled shedding by then (5x --transient)\n"
    "  --directions A,B,... flow angles to sample, degrees (default: every --step over\n"
    "                       the range the shape's symmetry leaves)\n"
    "  --step DEG           direction step (5)\n"
    "  --sources N          club: sources along it (one per 3 mean diameters)\n"
    "  --domain U,D,S       box upstream, downstream, half-width in reference lengths\n"
    "                       (10,15,6 in 2-D; 4,8,3 in 3-D)\n"
    "  --cfl C              free-stream Courant number of the flow steps (0.5)\n"
    "  --viscosity M2/S     kinematic viscosity (air: 1.5e-5)\n"
    "  --density KG/M3      (air: 1.204)\n"
    "  --threads N          directions computed at once (the number of CPUs)\n"
    "  --quiet              no progress line on a terminal\n"
    "Progress goes to stderr when it is a terminal; a summary to stdout.\n"
    "A direction in which the body does not shed is quiet (frequency 0 in the summary).\n"
    "Exit: 0 done, 1 the flow blew up or an I/O error, 2 bad arguments.\n";

typedef struct options {
    fg_aero_config c;
    const char *out, *info;
    int quiet;
    double side, width, diameter, length, step_deg;
    int have[32];
    double polygon[2 * MAX_LIST];
    double directions[MAX_LIST];
} options;

static int bad(const char *fmt, const char *arg)
{
    fprintf(stderr, "fulgur aerotex: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n(fulgur aerotex --help lists the options)\n");
    return CLI_USAGE;
}

/* A finite number in (lo, hi] (lo_open) or [lo, hi]. */
static int number(const char *name, const char *text, double lo, double hi, int lo_open,
                  double *out)
{
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end || !isfinite(v) || (lo_open ? !(v > lo) : !(v >= lo)) || v > hi) {
        fprintf(stderr, "fulgur aerotex: %s %s: expected a number in %s%g, %g]\n", name, text,
                lo_open ? "(" : "[", lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

static int whole(const char *name, const char *text, unsigned lo, unsigned hi, uint32_t *out)
{
    char *end;
    long v = strtol(text, &end, 10);
    if (end == text || *end || v < (long)lo || v > (long)hi) {
        fprintf(stderr, "fulgur aerotex: %s %s: expected a whole number in %u..%u\n", name, text,
                lo, hi);
        return -1;
    }
    *out = (uint32_t)v;
    return 0;
}

/* Comma-separated finite numbers; returns the count, or -1. */
static int list(const char *name, const char *text, double *out, int most)
{
    int n = 0;
    const char *p = text;
    for (;;) {
        char *end;
        double v = strtod(p, &end);
        if (end == p || !isfinite(v) || n == most || (*end && *end != ',')) {
            fprintf(stderr, "fulgur aerotex: %s %s: expected up to %d numbers separated by "
                            "commas\n", name, text, most);
            return -1;
        }
        out[n++] = v;
        if (!*end)
            return n;
        p = end + 1;
    }
}

enum { O_SHAPE, O_DIAMETER, O_SIDE, O_WIDTH, O_HEIGHT, O_POLYGON, O_LENGTH, O_DIAMETERS };

static int parse(int argc, char **argv, options *o)
{
    fg_aero_config *c = &o->c;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(usage, stdout);
            return -2;
        }
        if (strcmp(a, "--quiet") == 0) {
            o->quiet = 1;
            continue;
        }
        if (a[0] != '-')
            return bad("unexpected argument \"%s\"", a);
        if (!v)
            return bad("%s needs a value", a);
        i++;
        int rc = 0;
        if (strcmp(a, "--shape") == 0) {
            static const struct {
                const char *name;
                fg_aero_shape shape;
            } shapes[] = {{"circle", FG_AERO_CIRCLE},     {"square", FG_AERO_RECTANGLE},
                          {"rectangle", FG_AERO_RECTANGLE}, {"polygon", FG_AERO_POLYGON},
                          {"sphere", FG_AERO_SPHERE},     {"club", FG_AERO_CLUB}};
            c->shape = 0;
            for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++)
                if (strcmp(v, shapes[k].name) == 0)
                    c->shape = shapes[k].shape;
            if (!c->shape)
                return bad("--shape %s: expected circle, square, rectangle, polygon, sphere or "
                           "club", v);
            o->have[O_SHAPE] = strcmp(v, "square") == 0 ? 2 : 1;
        } else if (strcmp(a, "--diameter") == 0) {
            rc = number(a, v, 0, 100, 1, &o->diameter);
            o->have[O_DIAMETER] = 1;
        } else if (strcmp(a, "--side") == 0) {
            rc = number(a, v, 0, 100, 1, &o->side);
            o->have[O_SIDE] = 1;
        } else if (strcmp(a, "--width") == 0) {
            rc = number(a, v, 0, 100, 1, &o->width);
            o->have[O_WIDTH] = 1;
        } else if (strcmp(a, "--height") == 0) {
            rc = number(a, v, 0, 100, 1, &c->height_m);
            o->have[O_HEIGHT] = 1;
        } else if (strcmp(a, "--length") == 0) {
            rc = number(a, v, 0, 100, 1, &o->length);
            o->have[O_LENGTH] = 1;
        } else if (strcmp(a, "--diameters") == 0) {
            int n = list(a, v, c->diameter_m, 2);
            if (n != 2 || !(c->diameter_m[0] > 0) || !(c->diameter_m[1] > 0))
                return bad("--diameters %s: expected two positive diameters, handle,tip", v);
            o->have[O_DIAMETERS] = 1;
        } else if (strcmp(a, "--polygon") == 0) {
            int n = list(a, v, o->polygon, 2 * MAX_LIST);
            if (n < 0)
                return CLI_USAGE;
            if (n % 2 || n < 6)
                return bad("--polygon %s: expected x,y pairs of at least 3 vertices", v);
            c->polygon_xy = o->polygon;
            c->polygon_vertices = (uint32_t)(n / 2);
            o->have[O_POLYGON] = 1;
        } else if (strcmp(a, "--speed") == 0) {
            rc = number(a, v, 0, 340, 1, &c->speed_m_s);
        } else if (strcmp(a, "--tone") == 0) {
            if (strcmp(v, "aeolian") == 0)
                c->tone = FG_AERO_AEOLIAN;
            else if (strcmp(v, "cavity") == 0)
                c->tone = FG_AERO_CAVITY;
            else
                return bad("--tone %s: expected aeolian or cavity", v);
        } else if (strcmp(a, "--reference") == 0) {
            rc = number(a, v, 0, 100, 1, &c->reference_m);
        } else if (strcmp(a, "--grid") == 0) {
            rc = number(a, v, 4, 1024, 0, &c->cells_per_length);
        } else if (strcmp(a, "--rate") == 0) {
            rc = number(a, v, 0, 1e7, 1, &c->sample_rate_hz);
        } else if (strcmp(a, "--seconds") == 0) {
            rc = number(a, v, 0, 3600, 1, &c->seconds);
        } else if (strcmp(a, "--transient") == 0) {
            rc = number(a, v, 0, 3600, 1, &c->transient_s);
        } else if (strcmp(a, "--max-transient") == 0) {
            rc = number(a, v, 0, 36000, 1, &c->max_transient_s);
        } else if (strcmp(a, "--directions") == 0) {
            int n = list(a, v, o->directions, FG_AERO_MAX_DIRECTIONS);
            if (n < 0)
                return CLI_USAGE;
            for (int k = 0; k < n; k++)
                o->directions[k] *= FG_PI / 180.0;
            c->directions_rad = o->directions;
            c->direction_count = (uint32_t)n;
        } else if (strcmp(a, "--step") == 0) {
            rc = number(a, v, 0.1, 180, 0, &o->step_deg);
            c->direction_step_rad = o->step_deg * FG_PI / 180.0;
        } else if (strcmp(a, "--sources") == 0) {
            rc = whole(a, v, 1, FG_AERO_MAX_SOURCES, &c->sources);
        } else if (strcmp(a, "--domain") == 0) {
            int n = list(a, v, c->domain, 3);
            if (n != 3 || !(c->domain[0] > 0) || !(c->domain[1] > 0) || !(c->domain[2] > 0))
                return bad("--domain %s: expected three positive lengths, upstream,downstream,"
                           "half-width", v);
        } else if (strcmp(a, "--cfl") == 0) {
            rc = number(a, v, 0, 4, 1, &c->cfl);
        } else if (strcmp(a, "--viscosity") == 0) {
            rc = number(a, v, 0, 1, 1, &c->viscosity_m2_s);
        } else if (strcmp(a, "--density") == 0) {
            rc = number(a, v, 0, 1e4, 1, &c->density_kg_m3);
        } else if (strcmp(a, "--threads") == 0) {
            rc = whole(a, v, 1, 64, &c->threads);
        } else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            o->out = v;
        } else if (strcmp(a, "--info") == 0) {
            o->info = v;
        } else {
            return bad("unknown option \"%s\"", a);
        }
        if (rc != 0)
            return CLI_USAGE;
    }
    return 0;
}

/* Which size options each shape takes; the others are refused. */
static int sizes(options *o)
{
    fg_aero_config *c = &o->c;
    static const char *names[] = {"", "--diameter", "--side", "--width", "--height",
                                  "--polygon", "--length", "--diameters"};
    int wants[8] = {0};
    switch (c->shape) {
    case FG_AERO_CIRCLE:
    case FG_AERO_SPHERE:
        wants[O_DIAMETER] = 1;
        c->length_m = o->diameter;
        break;
    case FG_AERO_RECTANGLE:
        if (o->have[O_SHAPE] == 2) {
            wants[O_SIDE] = 1;
            c->length_m = c->height_m = o->side;
        } else {
            wants[O_WIDTH] = wants[O_HEIGHT] = 1;
            c->length_m = o->width;
        }
        break;
    case FG_AERO_POLYGON:
        wants[O_POLYGON] = 1;
        break;
    case FG_AERO_CLUB:
        wants[O_LENGTH] = wants[O_DIAMETERS] = 1;
        c->length_m = o->length;
        if (o->have[O_LENGTH] && o->have[O_DIAMETERS] &&
            !(o->length > fmax(c->diameter_m[0], c->diameter_m[1])))
            return bad("%s", "--length must be greater than both --diameters");
        break;
    default:
        return bad("%s", "--shape is required");
    }
    for (int k = O_DIAMETER; k <= O_DIAMETERS; k++) {
        if (wants[k] && !o->have[k])
            return bad("%s is required for this --shape", names[k]);
        if (!wants[k] && o->have[k])
            return bad("%s does not apply to this --shape", names[k]);
    }
    if (c->sources > 0 && c->shape != FG_AERO_CLUB)
        return bad("%s", "--sources applies to --shape club only");
    if ((c->directions_rad || c->direction_step_rad > 0) &&
        (c->shape == FG_AERO_CIRCLE || c->shape == FG_AERO_SPHERE || c->shape == FG_AERO_CLUB))
        return bad("%s", "--directions and --step apply to 2-D shapes without full symmetry "
                         "(square, rectangle, polygon)");
    if (c->directions_rad && c->direction_step_rad > 0)
        return bad("%s", "give --directions or --step, not both");
    if (c->max_transient_s > 0 && c->transient_s > c->max_transient_s)
        return bad("%s", "--max-transient must be at least --transient");
    return 0;
}

/* What fg_aero_config_check found, in the options' words. */
static int explain(const fg_aero_check *w)
{
    char m[256];
    static const char *names[] = {
        [FG_AERO_FIELD_SHAPE] = "--shape",         [FG_AERO_FIELD_TONE] = "--tone",
        [FG_AERO_FIELD_REFERENCE] = "--reference", [FG_AERO_FIELD_SPEED] = "--speed",
        [FG_AERO_FIELD_VISCOSITY] = "--viscosity", [FG_AERO_FIELD_DENSITY] = "--density",
        [FG_AERO_FIELD_CELLS] = "--grid",          [FG_AERO_FIELD_SECONDS] = "--seconds",
        [FG_AERO_FIELD_TRANSIENT] = "--transient", [FG_AERO_FIELD_DIRECTIONS] = "--directions",
        [FG_AERO_FIELD_STEP] = "--step",           [FG_AERO_FIELD_SOURCES] = "--sources",
        [FG_AERO_FIELD_THREADS] = "--threads",     [FG_AERO_FIELD_DOMAIN] = "--domain",
        [FG_AERO_FIELD_CFL] = "--cfl"};
    switch (w->field) {
    case FG_AERO_FIELD_SIZE:
        snprintf(m, sizeof m, "the shape's size is out of range");
        break;
    case FG_AERO_FIELD_POLYGON:
        switch (w->polygon) {
        case FG_AERO_POLYGON_COUNT:
            snprintf(m, sizeof m, "--polygon: %u vertices (3..%u)", w->index, FG_AERO_MAX_POLYGON);
            break;
        case FG_AERO_POLYGON_NOT_FINITE:
            snprintf(m, sizeof m, "--polygon: vertex %u is not a finite number", w->index);
            break;
        case FG_AERO_POLYGON_REPEATED:
            snprintf(m, sizeof m, "--polygon: vertex %u repeats the one before it", w->index);
            break;
        case FG_AERO_POLYGON_CROSSING:
            snprintf(m, sizeof m, "--polygon: edges %u and %u cross or touch (edge i runs from "
                                  "vertex i to vertex i + 1, counting from 0)", w->index, w->other);
            break;
        default:
            snprintf(m, sizeof m, "--polygon: the vertices enclose no area");
        }
        break;
    case FG_AERO_FIELD_RATE:
        snprintf(m, sizeof m, "--rate: at least %.4g Hz for this size and speed (8 samples a "
                              "shedding period at St 0.2), at most 1e7", w->limit);
        break;
    case FG_AERO_FIELD_MAX_TRANSIENT:
        snprintf(m, sizeof m, "--max-transient must be at least --transient");
        break;
    case FG_AERO_FIELD_GRID:
        snprintf(m, sizeof m, "the flow's box would have %.3g cells, more than 2^27: lower "
                              "--grid or --domain", w->limit);
        break;
    default: {
        const char *name = w->field < sizeof names / sizeof names[0] ? names[w->field] : NULL;
        snprintf(m, sizeof m, "%s is out of range", name ? name : "a value");
    }
    }
    return bad("%s", m);
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct progress_state {
    double start;
    int shown;
} progress_state;

static void show_progress(const fg_aero_progress *p, void *user)
{
    progress_state *s = user;
    static const char *phase[] = {"starting the flow", "recording", "done"};
    double elapsed = now_s() - s->start;
    char eta[32] = "";
    if (p->fraction > 0.02 && p->fraction < 1.0) {
        double left = elapsed * (1.0 - p->fraction) / p->fraction;
        snprintf(eta, sizeof eta, ", about %.0f min left", ceil(left / 60.0));
    }
    fprintf(stderr, "\raerotex: %u/%u directions done, direction %u %s (t = %.4g s), %.0f %%%s, "
                    "%.0f cells   ",
            p->directions_done, p->directions, p->direction + 1, phase[p->phase], p->simulated_s,
            100.0 * p->fraction, eta, p->cells);
    fflush(stderr);
    s->shown = 1;
}

static const char *shape_name(fg_aero_shape s)
{
    static const char *names[] = {"?", "circle", "rectangle", "polygon", "sphere", "club"};
    return (unsigned)s <= FG_AERO_CLUB ? names[s] : "?";
}

static void print_texture(FILE *to, const fg_aero_texture *t)
{
    const fg_aero_texture_desc *d = fg_aero_texture_get(t);
    fprintf(to, "%s (%u-D), %s tone: reference %.4g m, v0 %.4g m/s, Re %.0f, %.0f Hz, "
                "%.4g cells per reference, %u source%s, %u direction%s\n",
            shape_name(d->shape), d->dims, d->tone == FG_AERO_CAVITY ? "cavity" : "aeolian",
            d->reference_m, d->speed_m_s, d->reynolds, d->sample_rate_hz, d->cells_per_length,
            d->sources, d->sources == 1 ? "" : "s", d->directions, d->directions == 1 ? "" : "s");
    fprintf(to, "  angle_deg  frequency_hz  strouhal  lift_amplitude  drag_mean  periods  frames"
                "  transient_s\n");
    for (uint32_t i = 0; i < d->directions; i++) {
        const fg_aero_direction *r = &d->direction[i];
        fprintf(to, "  %9.3f  %12.4f  %8.4f  %14.4f  %9.4f  %7u  %6u  %11.4g\n",
                r->angle_rad * 180.0 / FG_PI, r->frequency_hz, r->strouhal, r->lift_amplitude,
                r->drag_mean, r->periods, r->frames, r->transient_s);
    }
}

int aerotex_main(int argc, char **argv)
{
    static options o; /* large lists: off the stack */
    memset(&o, 0, sizeof o);
    int rc = parse(argc, argv, &o);
    if (rc == -2)
        return CLI_OK;
    if (rc != 0)
        return rc;
    char err[512];
    if (o.info) {
        if (argc != 3)
            return bad("%s", "--info takes a file and no other option");
        fg_aero_texture *t;
        if (aero_texture_load(o.info, &t, err, sizeof err) != 0) {
            fprintf(stderr, "fulgur aerotex: %s\n", err);
            return CLI_USAGE;
        }
        print_texture(stdout, t);
        fg_aero_texture_destroy(t);
        return CLI_OK;
    }
    if ((rc = sizes(&o)) != 0)
        return rc;
    if (!(o.c.speed_m_s > 0))
        return bad("%s", "--speed is required");
    if (!o.out)
        return bad("%s", "-o FILE is required");
    fg_aero_check why;
    if (fg_aero_config_check(&o.c, &why) != FG_OK)
        return explain(&why);
    if (!o.c.threads) {
        long cpus = sysconf(_SC_NPROCESSORS_ONLN);
        o.c.threads = cpus > 0 && cpus < 64 ? (uint32_t)cpus : 1;
    }
    progress_state ps = {.start = now_s()};
    int show = !o.quiet && isatty(fileno(stderr));
    clock_t cpu0 = clock();
    fg_aero_texture *t;
    fg_result r = fg_aero_generate(&o.c, show ? show_progress : NULL, &ps, &t);
    if (ps.shown)
        fputc('\n', stderr);
    if (r != FG_OK) {
        const char *reason = r == FG_ERR_NOT_CONVERGED
                                 ? "the flow blew up; try a smaller --cfl or a finer --grid"
                                 : fg_result_str(r);
        fprintf(stderr, "fulgur aerotex: %s\n", reason);
        return r == FG_ERR_NOT_CONVERGED || r == FG_ERR_NO_MEMORY ? CLI_RUNTIME : CLI_USAGE;
    }
    double cpu = (double)(clock() - cpu0) / CLOCKS_PER_SEC, wall = now_s() - ps.start;
    if (aero_texture_save(t, o.out, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur aerotex: %s\n", err);
        fg_aero_texture_destroy(t);
        return CLI_RUNTIME;
    }
    fprintf(stdout, "%s: ", o.out);
    print_texture(stdout, t);
    fprintf(stdout, "  computed in %.1f s, %.1f s of CPU\n", wall, cpu);
    fg_aero_texture_destroy(t);
    return CLI_OK;
}
