/* fulgur flame: runs the flame simulation (fulgur/flame.h) offline with one
 * emitter and writes its flux series as CSV and, optionally, its sound
 * through fg_fire_sound as a WAV. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/audio_file.h"
#include "common/commands.h"
#include "common/options.h"
#include "common/temp_file.h"
#include "fulgur/fire.h"
#include "fulgur/flame.h"

#define BOX_M 0.64

static const char about[] =
    "Runs the flame simulation (Chadwick & James 2011, section 2.1: fuel burning above\n"
    "its ignition temperature, expansion as the projection's divergence source,\n"
    "buoyancy) with one emitter in a box of --cells^3 cells, and writes the flame\n"
    "front's flux I at each step as CSV (t_s, flux_m3_s, expansion_m3_s,\n"
    "burning_m3_s, triangles) and, with --wav, the sound p = dI/dt extended to the\n"
    "audio band (bandwidth extension, section 4), peak-normalised to 0.5.\n"
    "Coordinates in metres from the box's low corner; +z is up, z = 0 the ground.\n";

static const char notes[] =
    "The simulation is slower than real time (docs/fire-sound.md: 13 ms a step at\n"
    "24^3 on one core); a summary goes to stdout.\n"
    "Exit: 0 done, 1 the simulation failed or an I/O error, 2 bad arguments.\n";

typedef struct triple {
    double v[3];
    bool given;
} triple;

typedef struct options {
    double cells, cell_m, seconds, rate_hz, sample_rate_hz, alpha;
    double radius_m, fuel_m3_s, temperature_k;
    fg_flame_emitter_kind kind;
    fg_flame_shape shape;
    triple at, size, jet;
    const char *csv, *wav;
} options;

static options opts;

static int parse_triple(const char *text, void *value, char *why, size_t why_size)
{
    triple *t = value;
    char *end;
    const char *p = text;
    for (int a = 0; a < 3; a++) {
        t->v[a] = strtod(p, &end);
        if (end == p || !isfinite(t->v[a]) || (a < 2 ? *end != ',' : *end != '\0')) {
            snprintf(why, why_size, "expected X,Y,Z (three finite numbers)");
            return -1;
        }
        p = end + 1;
    }
    t->given = true;
    return 0;
}

static int parse_kind(const char *text, void *value, char *why, size_t why_size)
{
    static const char *names[] = {"source", "jet", "object"};
    for (int k = 0; k < 3; k++)
        if (strcmp(text, names[k]) == 0) {
            *(fg_flame_emitter_kind *)value = (fg_flame_emitter_kind)(FG_FLAME_EMITTER_SOURCE + k);
            return 0;
        }
    snprintf(why, why_size, "expected source, jet or object");
    return -1;
}

static int parse_shape(const char *text, void *value, char *why, size_t why_size)
{
    if (strcmp(text, "sphere") == 0 || strcmp(text, "box") == 0) {
        *(fg_flame_shape *)value = text[0] == 's' ? FG_FLAME_SPHERE : FG_FLAME_BOX;
        return 0;
    }
    snprintf(why, why_size, "expected sphere or box");
    return -1;
}

#define POSITIVE(hi_) {.lo = 0, .hi = (hi_), .lo_open = true}

static const option table[] = {
    {"-o", OPTION_TEXT, &opts.csv, "FLUX.csv", .help = "the flux series to write (required)",
     .required = true},
    {"--wav", OPTION_TEXT, &opts.wav, "SOUND.wav", .help = "also the sound, 32-bit float mono"},
    {"--cells", OPTION_NUMBER, &opts.cells, "N", "cells per axis (24)",
     .range = {.lo = FG_FLAME_SIM_MIN_CELLS, .hi = FG_FLAME_SIM_MAX_CELLS, .integer = true}},
    {"--cell", OPTION_NUMBER, &opts.cell_m, "M", "cell size (0.64 m / --cells)",
     .range = POSITIVE(10)},
    {"--seconds", OPTION_NUMBER, &opts.seconds, "S", "simulated time (2)",
     .range = POSITIVE(600)},
    {"--rate", OPTION_NUMBER, &opts.rate_hz, "HZ", "simulation steps per second (360)",
     .range = {.lo = 40, .hi = 10000}},
    {"--sample-rate", OPTION_NUMBER, &opts.sample_rate_hz, "HZ", "the WAV's rate (48000)",
     .range = {.lo = 8000, .hi = 384000}},
    {"--alpha", OPTION_NUMBER, &opts.alpha, "A", "bandwidth extension's power law f^-A (3)",
     .range = {.lo = 0.5, .hi = 6}},
    {"--emitter", OPTION_PARSED, &opts.kind, "source|jet|object",
     "a fuel source, a jet, a burning object (source)", .parse = parse_kind},
    {"--shape", OPTION_PARSED, &opts.shape, "sphere|box", "the emitter's shape (sphere)",
     .parse = parse_shape},
    {"--at", OPTION_PARSED, &opts.at, "X,Y,Z",
     "the emitter's centre (the box's middle, 0.08 m up)", .parse = parse_triple},
    {"--radius", OPTION_NUMBER, &opts.radius_m, "M", "sphere: radius (0.04)",
     .range = POSITIVE(100)},
    {"--size", OPTION_PARSED, &opts.size, "HX,HY,HZ", "box: half sizes", .parse = parse_triple},
    {"--fuel", OPTION_NUMBER, &opts.fuel_m3_s, "M3/S",
     "mixture released per second (0.001: about 2.3 kW)", .range = POSITIVE(1e3)},
    {"--temperature", OPTION_NUMBER, &opts.temperature_k, "K",
     "the released gas's temperature (1200: lit)", .range = POSITIVE(1e4)},
    {"--jet", OPTION_PARSED, &opts.jet, "VX,VY,VZ", "jet: the gas velocity (m/s)",
     .parse = parse_triple},
    {0},
};

static const command_line cl = {"fulgur flame", "", 0, 0, about, notes, table};

/* The configuration from the options; OPTIONS_BAD after the message. */
static options_result configure(const options *o, fg_flame_sim_config *c)
{
    int n = o->cells > 0 ? (int)o->cells : 24;
    memset(c, 0, sizeof *c);
    c->cells[0] = c->cells[1] = c->cells[2] = n;
    c->cell_m = o->cell_m > 0 ? o->cell_m : BOX_M / n;
    c->step_rate_hz = o->rate_hz;
    c->emitters = 1;
    fg_flame_emitter *e = &c->emitter[0];
    double side = n * c->cell_m;
    e->kind = o->kind ? o->kind : FG_FLAME_EMITTER_SOURCE;
    e->shape = o->shape;
    for (int a = 0; a < 3; a++) {
        e->centre_m[a] = o->at.given ? o->at.v[a] : a < 2 ? 0.5 * side : 0.08;
        e->half_size_m[a] = o->size.v[a];
        e->jet_velocity_m_s[a] = o->jet.v[a];
    }
    e->radius_m = o->shape == FG_FLAME_SPHERE ? (o->radius_m > 0 ? o->radius_m : 0.04) : 0.0;
    e->fuel_m3_s = o->fuel_m3_s > 0 ? o->fuel_m3_s : 1e-3;
    e->temperature_k = o->temperature_k;
    if (o->shape == FG_FLAME_BOX && !o->size.given)
        return options_fail(&cl, "--size is required for --shape box");
    if (o->shape == FG_FLAME_SPHERE && o->size.given)
        return options_fail(&cl, "--size applies to --shape box only");
    if (o->shape == FG_FLAME_BOX && o->radius_m > 0)
        return options_fail(&cl, "--radius applies to --shape sphere only");
    if (o->size.given && (o->size.v[0] < 0 || o->size.v[1] < 0 || o->size.v[2] < 0))
        return options_fail(&cl, "--size: the half sizes must not be negative");
    if (e->kind == FG_FLAME_EMITTER_JET && !o->jet.given)
        return options_fail(&cl, "--jet is required for --emitter jet");
    if (e->kind != FG_FLAME_EMITTER_JET && o->jet.given)
        return options_fail(&cl, "--jet applies to --emitter jet only");
    if (e->kind == FG_FLAME_EMITTER_JET && e->jet_velocity_m_s[0] == 0 &&
        e->jet_velocity_m_s[1] == 0 && e->jet_velocity_m_s[2] == 0)
        return options_fail(&cl, "--jet must not be 0,0,0");
    if (o->sample_rate_hz > 0 && o->wav == NULL)
        return options_fail(&cl, "--sample-rate applies with --wav only");
    return OPTIONS_OK;
}

/* Why create refused c, in the options' words. */
static void explain(fg_result r, const fg_flame_sim_config *c)
{
    double side = c->cells[0] * c->cell_m;
    if (r == FG_ERR_CAPACITY)
        fprintf(stderr, "fulgur flame: %d^3 cells would need %.1f MiB, more than the %.0f MiB "
                        "allowed: lower --cells\n",
                c->cells[0], fg_flame_sim_memory_bytes(c) / 1048576.0,
                FG_FLAME_SIM_DEFAULT_MAX_BYTES / 1048576.0);
    else
        fprintf(stderr, "fulgur flame: %s: the emitter (with an object's one-cell layer) must "
                        "lie inside the box, 0 .. %.4g m on each axis\n",
                fg_result_str(r), side);
}

static int write_sound(temp_file *t, const float *audio, size_t frames, double rate,
                       char *err, size_t err_size)
{
    audio_wav *wav = audio_wav_open(t->fd, t->path, rate, 1, frames, err, err_size);
    if (!wav)
        return -1;
    char why[256];
    int ok = audio_wav_write(wav, audio, frames, why, sizeof why) == 0;
    ok &= audio_wav_close(wav) == 0;
    if (!ok)
        snprintf(err, err_size, "%s: could not write the sound", t->path);
    return ok ? 0 : -1;
}

int flame_main(int argc, char **argv)
{
    options *o = &opts;
    memset(o, 0, sizeof *o);
    size_t operands;
    options_result parsed = options_parse(&cl, argc, argv, NULL, &operands);
    if (parsed != OPTIONS_OK)
        return parsed == OPTIONS_HELP ? CLI_OK : CLI_USAGE;
    fg_flame_sim_config c;
    if (configure(o, &c) != OPTIONS_OK)
        return CLI_USAGE;
    char err[512];
    if (temp_file_check_output(o->csv, NULL, err, sizeof err) != 0 ||
        (o->wav && temp_file_check_output(o->wav, o->csv, err, sizeof err) != 0)) {
        fprintf(stderr, "fulgur flame: %s\n", err);
        return CLI_USAGE;
    }
    fg_flame_sim *sim;
    fg_result r = fg_flame_sim_create(&c, &sim);
    if (r != FG_OK) {
        explain(r, &c);
        return r == FG_ERR_NO_MEMORY ? CLI_RUNTIME : CLI_USAGE;
    }
    fg_flame_sim_get_config(sim, &c);
    size_t steps = (size_t)ceil((o->seconds > 0 ? o->seconds : 2.0) * c.step_rate_hz);
    double *flux = malloc(sizeof(double) * steps);
    temp_file csv;
    int code = CLI_RUNTIME;
    if (!flux || temp_file_open(&csv, o->csv, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur flame: %s\n", flux ? err : "out of memory");
        free(flux);
        fg_flame_sim_destroy(sim);
        return CLI_RUNTIME;
    }
    FILE *out = temp_file_stream(&csv);
    if (out)
        fprintf(out, "t_s,flux_m3_s,expansion_m3_s,burning_m3_s,triangles\n");
    for (size_t n = 0; out && n < steps; n++) {
        fg_flame_flux f;
        if ((r = fg_flame_sim_step(sim, &f)) != FG_OK) {
            fprintf(stderr, "fulgur flame: step %zu: %s\n", n, fg_result_str(r));
            break;
        }
        fg_flame_sim_stats st;
        fg_flame_sim_get_stats(sim, &st);
        flux[n] = f.flux_m3_s;
        fprintf(out, "%.6f,%.9g,%.9g,%.9g,%zu\n", st.time_s, f.flux_m3_s, st.expansion_m3_s,
                st.burning_m3_s, f.triangles);
    }
    fg_flame_sim_stats st;
    fg_flame_sim_get_stats(sim, &st);
    fg_flame_sim_destroy(sim);
    if (!out || r != FG_OK || ferror(out)) {
        if (!out || ferror(out))
            fprintf(stderr, "fulgur flame: %s: could not write\n", o->csv);
        temp_file_abort(&csv);
        free(flux);
        return CLI_RUNTIME;
    }
    temp_file wav_file;
    float *audio = NULL;
    size_t frames = 0;
    double peak = 0.0;
    if (o->wav) {
        fg_fire_sound_config sc = {.sample_rate_hz = o->sample_rate_hz,
                                   .sim_rate_hz = c.step_rate_hz,
                                   .bwe = {.alpha = o->alpha, .seed = 1}};
        fg_fire_sound *sound;
        if ((r = fg_fire_sound_create(&sc, &sound)) != FG_OK) {
            fprintf(stderr, "fulgur flame: the sound: %s\n", fg_result_str(r));
            temp_file_abort(&csv);
            free(flux);
            return CLI_USAGE;
        }
        size_t room = fg_fire_sound_max_frames(sound, steps) + fg_fire_sound_drain_frames(sound);
        audio = malloc(sizeof(float) * (room ? room : 1));
        size_t got = 0, more = 0;
        r = audio ? fg_fire_sound_process(sound, flux, steps, audio, room, &got) : FG_ERR_NO_MEMORY;
        if (r == FG_OK)
            r = fg_fire_sound_drain(sound, audio + got, room - got, &more);
        fg_fire_sound_destroy(sound);
        frames = got + more;
        for (size_t i = 0; r == FG_OK && i < frames; i++)
            peak = fabs(audio[i]) > peak ? fabs(audio[i]) : peak;
        for (size_t i = 0; r == FG_OK && peak > 0 && i < frames; i++)
            audio[i] = (float)(0.5 * audio[i] / peak);
        if (r != FG_OK || temp_file_open(&wav_file, o->wav, err, sizeof err) != 0) {
            fprintf(stderr, "fulgur flame: %s\n", r != FG_OK ? fg_result_str(r) : err);
            temp_file_abort(&csv);
            free(audio);
            free(flux);
            return CLI_RUNTIME;
        }
        if (write_sound(&wav_file, audio, frames, sc.sample_rate_hz ? sc.sample_rate_hz : 48000,
                        err, sizeof err) != 0) {
            fprintf(stderr, "fulgur flame: %s\n", err);
            temp_file_abort(&wav_file);
            temp_file_abort(&csv);
            free(audio);
            free(flux);
            return CLI_RUNTIME;
        }
    }
    code = CLI_OK;
    if (temp_file_commit(&csv, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur flame: %s\n", err);
        code = CLI_RUNTIME;
        if (o->wav)
            temp_file_abort(&wav_file);
    } else if (o->wav && temp_file_commit(&wav_file, err, sizeof err) != 0) {
        fprintf(stderr, "fulgur flame: %s\n", err);
        code = CLI_RUNTIME;
    }
    double mean = 0.0;
    for (size_t n = steps / 3; n < steps; n++)
        mean += flux[n] / (double)(steps - steps / 3);
    printf("%zu steps at %.0f Hz on %d^3 cells of %.4g m: mean flux %.4g m^3/s over the last "
           "two thirds; fuel emitted %.4g m^3, burnt %.4g m^3",
           steps, c.step_rate_hz, c.cells[0], c.cell_m, mean, st.fuel_emitted_m3,
           st.fuel_burnt_m3);
    if (o->wav)
        printf("; %zu frames of sound, scaled by %.4g (peak p %.4g m^3/s^2)", frames,
               peak > 0 ? 0.5 / peak : 0.0, peak);
    printf("\n");
    free(audio);
    free(flux);
    return code;
}
