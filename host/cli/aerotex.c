/* fulgur aerotex: computes an aerodynamic sound texture by CFD and writes
 * it to a file; --info prints a texture file's contents. */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno, sysconf */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "common/aero_texture_file.h"
#include "common/clock.h"
#include "common/commands.h"
#include "common/options.h"
#include "fg_math.h"

#define MAX_LIST 4096

static const char about[] =
    "Computes the aerodynamic sound texture of a shape (Dobashi et al. 2003): the\n"
    "flow past it by CFD at the base speed, the force on it, g = dF/dt as a seamless\n"
    "loop per flow direction (2-D) or per source along it (3-D). With --info FILE,\n"
    "prints what a texture file holds.\n"
    "Shapes and their sizes (metres):\n"
    "  --shape circle    --diameter D          a circular cylinder (2-D)\n"
    "  --shape square    --side S              a square prism (2-D)\n"
    "  --shape rectangle --width W --height H  W along the flow at 0 degrees (2-D)\n"
    "  --shape polygon   --polygon x,y,x,y,... any simple polygon, e.g. a blade (2-D)\n"
    "  --shape sphere    --diameter D          (3-D)\n"
    "  --shape club      --length L --diameters DH,DT  tapered, round ends (3-D)\n";

static const char notes[] =
    "Progress goes to stderr when it is a terminal; a summary to stdout.\n"
    "A direction in which the body does not shed is quiet (frequency 0 in the summary).\n"
    "Exit: 0 done, 1 the flow blew up or an I/O error, 2 bad arguments.\n";

/* The shape as named on the command line: square is a rectangle given by
 * --side. */
typedef enum shape_choice { SHAPE_NONE, SHAPE_CIRCLE, SHAPE_SQUARE, SHAPE_RECTANGLE, SHAPE_POLYGON,
                          SHAPE_SPHERE, SHAPE_CLUB } shape_choice;

typedef struct number_list {
    double v[2 * MAX_LIST];
    int n;
} number_list;

typedef struct options {
    fg_aero_config c;
    const char *out, *info;
    bool quiet;
    shape_choice shape;
    double side, width, diameter, length, step_deg;
    number_list polygon, directions, diameters, domain;
} options;

/* Comma-separated finite numbers, at most `most`, into list. */
static int read_list(const char *text, number_list *list, int most, char *why, size_t why_size)
{
    list->n = 0;
    const char *p = text;
    for (;;) {
        char *end;
        double v = strtod(p, &end);
        if (end == p || !isfinite(v) || list->n == most || (*end && *end != ',')) {
            snprintf(why, why_size, "expected up to %d numbers separated by commas", most);
            return -1;
        }
        list->v[list->n++] = v;
        if (!*end)
            return 0;
        p = end + 1;
    }
}

static int parse_shape(const char *text, void *value, char *why, size_t why_size)
{
    static const char *names[] = {[SHAPE_CIRCLE] = "circle",   [SHAPE_SQUARE] = "square",
                                  [SHAPE_RECTANGLE] = "rectangle", [SHAPE_POLYGON] = "polygon",
                                  [SHAPE_SPHERE] = "sphere",   [SHAPE_CLUB] = "club"};
    for (int k = SHAPE_CIRCLE; k <= SHAPE_CLUB; k++)
        if (strcmp(text, names[k]) == 0) {
            *(shape_choice *)value = (shape_choice)k;
            return 0;
        }
    snprintf(why, why_size, "expected circle, square, rectangle, polygon, sphere or club");
    return -1;
}

static int parse_tone(const char *text, void *value, char *why, size_t why_size)
{
    if (strcmp(text, "aeolian") == 0 || strcmp(text, "cavity") == 0) {
        *(fg_aero_tone *)value = text[0] == 'a' ? FG_AERO_AEOLIAN : FG_AERO_CAVITY;
        return 0;
    }
    snprintf(why, why_size, "expected aeolian or cavity");
    return -1;
}

static int parse_polygon(const char *text, void *value, char *why, size_t why_size)
{
    number_list *l = value;
    if (read_list(text, l, 2 * MAX_LIST, why, why_size) != 0)
        return -1;
    if (l->n % 2 || l->n < 6) {
        snprintf(why, why_size, "expected x,y pairs of at least 3 vertices");
        return -1;
    }
    return 0;
}

static int parse_directions(const char *text, void *value, char *why, size_t why_size)
{
    return read_list(text, value, FG_AERO_MAX_DIRECTIONS, why, why_size);
}

/* Exactly `count` positive numbers. */
static int positive_list(const char *text, number_list *l, int count, const char *what, char *why,
                         size_t why_size)
{
    int ok = read_list(text, l, count, why, why_size) == 0 && l->n == count;
    for (int k = 0; ok && k < count; k++)
        ok = l->v[k] > 0;
    if (!ok) {
        snprintf(why, why_size, "expected %s", what);
        l->n = 0;
    }
    return ok ? 0 : -1;
}

static int parse_diameters(const char *text, void *value, char *why, size_t why_size)
{
    return positive_list(text, value, 2, "two positive diameters, handle,tip", why, why_size);
}

static int parse_domain(const char *text, void *value, char *why, size_t why_size)
{
    return positive_list(text, value, 3,
                         "three positive lengths, upstream,downstream,half-width", why, why_size);
}

#define POSITIVE(hi_) {.lo = 0, .hi = (hi_), .lo_open = true}

static options opts; /* large lists: off the stack */

static const option table[] = {
    {"--shape", OPTION_PARSED, &opts.shape, "SHAPE",
     "circle, square, rectangle, polygon, sphere or club", .parse = parse_shape},
    {"--diameter", OPTION_NUMBER, &opts.diameter, "M", "circle, sphere", .range = POSITIVE(100)},
    {"--side", OPTION_NUMBER, &opts.side, "M", "square", .range = POSITIVE(100)},
    {"--width", OPTION_NUMBER, &opts.width, "M", "rectangle: along the flow at 0 degrees",
     .range = POSITIVE(100)},
    {"--height", OPTION_NUMBER, &opts.c.height_m, "M", "rectangle: across it",
     .range = POSITIVE(100)},
    {"--polygon", OPTION_PARSED, &opts.polygon, "X,Y,...", "polygon: its vertices in order",
     .parse = parse_polygon},
    {"--length", OPTION_NUMBER, &opts.length, "M", "club: overall", .range = POSITIVE(100)},
    {"--diameters", OPTION_PARSED, &opts.diameters, "DH,DT", "club: at the handle and the tip",
     .parse = parse_diameters},
    {"--speed", OPTION_NUMBER, &opts.c.speed_m_s, "M/S", "base speed v0 (required)",
     .range = POSITIVE(340)},
    {"--tone", OPTION_PARSED, &opts.c.tone, "aeolian|cavity",
     "the level law it is played with (aeolian: (v/v0)^3)", .parse = parse_tone},
    {"--reference", OPTION_NUMBER, &opts.c.reference_m, "M",
     "the D of Re and St (default: the diameter, or the width\nacross the flow at 0 "
     "degrees, or the club's largest diameter)", .range = POSITIVE(100)},
    {"--grid", OPTION_NUMBER, &opts.c.cells_per_length, "N",
     "cells across the reference length (32 in 2-D, 12 in 3-D)",
     .range = {.lo = 4, .hi = 1024}},
    {"--rate", OPTION_NUMBER, &opts.c.sample_rate_hz, "HZ",
     "texture sample rate (16 samples per D/v0: 16 kHz at 1 cm, 10 m/s)",
     .range = POSITIVE(1e7)},
    {"--seconds", OPTION_NUMBER, &opts.c.seconds, "S",
     "loop length at v0 (default 24 shedding periods)", .range = POSITIVE(3600)},
    {"--transient", OPTION_NUMBER, &opts.c.transient_s, "S",
     "least start-up to discard (60 D/v0 in 2-D, 30 in 3-D)", .range = POSITIVE(3600)},
    {"--max-transient", OPTION_NUMBER, &opts.c.max_transient_s, "S",
     "give up without settled shedding by then (5x --transient)",
     .range = POSITIVE(36000)},
    {"--directions", OPTION_PARSED, &opts.directions, "A,B,...",
     "flow angles to sample, degrees (default: every --step over\nthe range the shape's "
     "symmetry leaves)", .parse = parse_directions},
    {"--step", OPTION_NUMBER, &opts.step_deg, "DEG", "direction step (5)",
     .range = {.lo = 0.1, .hi = 180}},
    {"--sources", OPTION_INTEGER, &opts.c.sources, "N",
     "club: sources along it (one per 3 mean diameters)",
     .range = {.lo = 1, .hi = FG_AERO_MAX_SOURCES}},
    {"--domain", OPTION_PARSED, &opts.domain, "U,D,S",
     "box upstream, downstream, half-width in reference lengths\n(10,15,6 in 2-D; 4,8,3 "
     "in 3-D)", .parse = parse_domain},
    {"--cfl", OPTION_NUMBER, &opts.c.cfl, "C",
     "free-stream Courant number of the flow steps (0.5)", .range = POSITIVE(4)},
    {"--viscosity", OPTION_NUMBER, &opts.c.viscosity_m2_s, "M2/S",
     "kinematic viscosity (air: 1.5e-5)", .range = POSITIVE(1)},
    {"--density", OPTION_NUMBER, &opts.c.density_kg_m3, "KG/M3", "(air: 1.204)",
     .range = POSITIVE(1e4)},
    {"--threads", OPTION_INTEGER, &opts.c.threads, "N",
     "directions computed at once (the number of CPUs)", .range = {.lo = 1, .hi = 64}},
    {"--quiet", OPTION_FLAG, &opts.quiet, NULL, .help = "no progress line on a terminal"},
    {"-o", OPTION_TEXT, &opts.out, "FILE.aerotex", .help = "the texture to write"},
    {"--info", OPTION_TEXT, &opts.info, "FILE.aerotex",
     .help = "print what a texture file holds (alone)"},
    {0},
};

static const command_line cl = {"fulgur aerotex", "", 0, 0, about, notes, table};

/* Which size options each shape takes; the others are refused. */
static options_result sizes(options *o)
{
    fg_aero_config *c = &o->c;
    enum { DIAMETER, SIDE, WIDTH, HEIGHT, POLYGON, LENGTH, DIAMETERS, SIZES };
    static const char *names[SIZES] = {"--diameter", "--side", "--width", "--height",
                                       "--polygon", "--length", "--diameters"};
    bool have[SIZES] = {o->diameter > 0, o->side > 0, o->width > 0, c->height_m > 0,
                        o->polygon.n > 0, o->length > 0, o->diameters.n > 0};
    bool wants[SIZES] = {false};
    switch (o->shape) {
    case SHAPE_CIRCLE:
    case SHAPE_SPHERE:
        c->shape = o->shape == SHAPE_CIRCLE ? FG_AERO_CIRCLE : FG_AERO_SPHERE;
        wants[DIAMETER] = true;
        c->length_m = o->diameter;
        break;
    case SHAPE_SQUARE:
        c->shape = FG_AERO_RECTANGLE;
        wants[SIDE] = true;
        c->length_m = o->side;
        break;
    case SHAPE_RECTANGLE:
        c->shape = FG_AERO_RECTANGLE;
        wants[WIDTH] = wants[HEIGHT] = true;
        c->length_m = o->width;
        break;
    case SHAPE_POLYGON:
        c->shape = FG_AERO_POLYGON;
        wants[POLYGON] = true;
        c->polygon_xy = o->polygon.v;
        c->polygon_vertices = (uint32_t)(o->polygon.n / 2);
        break;
    case SHAPE_CLUB:
        c->shape = FG_AERO_CLUB;
        wants[LENGTH] = wants[DIAMETERS] = true;
        c->length_m = o->length;
        c->diameter_m[0] = o->diameters.v[0];
        c->diameter_m[1] = o->diameters.v[1];
        if (have[LENGTH] && have[DIAMETERS] &&
            !(o->length > fmax(c->diameter_m[0], c->diameter_m[1])))
            return options_fail(&cl, "--length must be greater than both --diameters");
        break;
    default:
        return options_fail(&cl, "--shape is required");
    }
    for (int k = 0; k < SIZES; k++) {
        if (wants[k] && !have[k])
            return options_fail(&cl, "%s is required for this --shape", names[k]);
        if (!wants[k] && have[k])
            return options_fail(&cl, "%s does not apply to this --shape", names[k]);
    }
    if (o->shape == SHAPE_SQUARE)
        c->height_m = o->side;
    if (o->directions.n > 0) {
        for (int k = 0; k < o->directions.n; k++)
            o->directions.v[k] *= FG_PI / 180.0;
        c->directions_rad = o->directions.v;
        c->direction_count = (uint32_t)o->directions.n;
    }
    c->direction_step_rad = o->step_deg * FG_PI / 180.0;
    for (int k = 0; k < o->domain.n; k++)
        c->domain[k] = o->domain.v[k];
    if (c->sources > 0 && c->shape != FG_AERO_CLUB)
        return options_fail(&cl, "--sources applies to --shape club only");
    if ((c->directions_rad || c->direction_step_rad > 0) &&
        (c->shape == FG_AERO_CIRCLE || c->shape == FG_AERO_SPHERE || c->shape == FG_AERO_CLUB))
        return options_fail(&cl, "--directions and --step apply to 2-D shapes without full "
                                 "symmetry (square, rectangle, polygon)");
    if (c->directions_rad && c->direction_step_rad > 0)
        return options_fail(&cl, "give --directions or --step, not both");
    if (c->max_transient_s > 0 && c->transient_s > c->max_transient_s)
        return options_fail(&cl, "--max-transient must be at least --transient");
    return OPTIONS_OK;
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
    options_fail(&cl, "%s", m);
    return CLI_USAGE;
}

static double now_s(void)
{
    return 1e-9 * (double)monotonic_now_ns();
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
    options *o = &opts;
    memset(o, 0, sizeof *o);
    size_t operands;
    options_result parsed = options_parse(&cl, argc, argv, NULL, &operands);
    if (parsed != OPTIONS_OK)
        return parsed == OPTIONS_HELP ? CLI_OK : CLI_USAGE;
    char err[512];
    if (o->info) {
        if (argc != 3) {
            options_fail(&cl, "--info takes a file and no other option");
            return CLI_USAGE;
        }
        fg_aero_texture *t;
        if (aero_texture_load(o->info, &t, err, sizeof err) != 0) {
            fprintf(stderr, "fulgur aerotex: %s\n", err);
            return CLI_USAGE;
        }
        print_texture(stdout, t);
        fg_aero_texture_destroy(t);
        return CLI_OK;
    }
    if (sizes(o) != OPTIONS_OK)
        return CLI_USAGE;
    if (!(o->c.speed_m_s > 0)) {
        options_fail(&cl, "--speed is required");
        return CLI_USAGE;
    }
    if (!o->out) {
        options_fail(&cl, "-o FILE.aerotex is required");
        return CLI_USAGE;
    }
    fg_aero_check why;
    if (fg_aero_config_check(&o->c, &why) != FG_OK)
        return explain(&why);
    if (!o->c.threads) {
        long cpus = sysconf(_SC_NPROCESSORS_ONLN);
        o->c.threads = cpus > 0 && cpus < 64 ? (uint32_t)cpus : 1;
    }
    progress_state ps = {.start = now_s()};
    int show = !o->quiet && isatty(fileno(stderr));
    clock_t cpu0 = clock();
    fg_aero_texture *t;
    fg_result r = fg_aero_generate(&o->c, show ? show_progress : NULL, &ps, &t);
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
    if (aero_texture_save(t, o->out, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur aerotex: %s\n", err);
        fg_aero_texture_destroy(t);
        return CLI_RUNTIME;
    }
    fprintf(stdout, "%s: ", o->out);
    print_texture(stdout, t);
    fprintf(stdout, "  computed in %.1f s, %.1f s of CPU\n", wall, cpu);
    fg_aero_texture_destroy(t);
    return CLI_OK;
}
