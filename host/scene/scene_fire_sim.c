/* A fire's "simulation" (docs/scene-format.md, fires): instead of a flux
 * file, the scene names an emitter preset, a grid and a seed, and the
 * flame simulation (fulgur/flame.h) makes the flux series the rest of the
 * chain (fg_fire_feed) plays, at the fire's sim_rate for its duration.
 * By default the scene's load runs it offline, because grids of 16^3 and
 * up are slower than real time at 360 Hz (bench/results/flame.md: 16^3
 * runs at 0.80x, 24^3 at 0.21x on one core): the render waits for it
 * before the first block. With "live" the configuration is only checked
 * here, and the render's or run's sim thread steps it as the fire sounds
 * (scene_fire_render.c), which small grids keep up with (8^3 4.2x, 12^3
 * 1.3x real time). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fg_rng.h"
#include "fulgur/flame.h"
#include "scene_internal.h"

static const char *const sim_keys[] = {"emitter", "cells", "seconds", "seed", "live", NULL};
static const char *const presets[] = {"campfire", "torch", "jet", "object"};

/* The simulation's box is 0.64 m on each side whatever the cell count
 * (the size bench_flame and `fulgur flame` use). */
#define SIM_BOX_M 0.64
#define SIM_MAX_CELLS 32
#define SIM_MAX_SECONDS 60.0

/* The preset's emitter, centred in the box's floor plan. */
static fg_flame_emitter preset(int which, double side)
{
    double c = 0.5 * side;
    switch (which) {
    case 0: /* a campfire: a flat 24 x 24 x 8 cm box of fuel on the ground, ~9 kW */
        return (fg_flame_emitter){.kind = FG_FLAME_EMITTER_SOURCE, .shape = FG_FLAME_BOX,
                                  .centre_m = {c, c, 0.06}, .half_size_m = {0.12, 0.12, 0.04},
                                  .fuel_m3_s = 1.5e-3};
    case 1: /* a torch's head: a 4 cm sphere, 1 L/s, ~2.3 kW */
        return (fg_flame_emitter){.kind = FG_FLAME_EMITTER_SOURCE, .shape = FG_FLAME_SPHERE,
                                  .centre_m = {c, c, 0.12}, .radius_m = 0.04, .fuel_m3_s = 1e-3};
    case 2: /* a jet: a 4 cm nozzle blowing fuel up at 3 m/s */
        return (fg_flame_emitter){.kind = FG_FLAME_EMITTER_JET, .shape = FG_FLAME_SPHERE,
                                  .centre_m = {c, c, 0.1}, .radius_m = 0.04, .fuel_m3_s = 4e-3,
                                  .jet_velocity_m_s = {0, 0, 3}};
    default: /* a burning object: fuel from the skin of a 10 cm sphere */
        return (fg_flame_emitter){.kind = FG_FLAME_EMITTER_OBJECT, .shape = FG_FLAME_SPHERE,
                                  .centre_m = {c, c, 0.18}, .radius_m = 0.1, .fuel_m3_s = 3e-3};
    }
}

int scene_fire_simulate(const cJSON *item, const char *path, double sim_rate_hz,
                        scene_fire *f, char *err, size_t err_size)
{
    const cJSON *sim = cJSON_GetObjectItemCaseSensitive(item, "simulation");
    char at[JSON_PATH_MAX];
    json_path_key(at, sizeof at, path, "simulation");
    if (!cJSON_IsObject(sim))
        return json_fail(err, err_size, at, "expected {\"emitter\": \"campfire\"|\"torch\"|"
                                            "\"jet\"|\"object\", \"cells\": N, \"seconds\": S, "
                                            "\"seed\": K}");
    int which = -1;
    double cells = 16, seconds = 4, seed = 0;
    bool live = false;
    if (json_check_keys(sim, at, sim_keys, err, err_size) ||
        json_bool(sim, at, "live", &live, err, err_size) ||
        json_name(sim, at, "emitter", presets, 4, &which, err, err_size) ||
        json_number(sim, at, "cells", (number_range){.lo = FG_FLAME_SIM_MIN_CELLS,
                                                     .hi = SIM_MAX_CELLS, .integer = true},
                    &cells, err, err_size) ||
        json_number(sim, at, "seconds", (number_range){.lo = 0, .hi = SIM_MAX_SECONDS,
                                                       .lo_open = true},
                    &seconds, err, err_size) ||
        json_number(sim, at, "seed", SCENE_SEED_RANGE, &seed, err, err_size))
        return -1;
    if (which < 0) {
        char e[JSON_PATH_MAX];
        json_path_key(e, sizeof e, at, "emitter");
        return json_fail(err, err_size, e, "required: campfire, torch, jet or object");
    }
    int n = (int)cells;
    fg_flame_sim_config c = {.cells = {n, n, n}, .cell_m = SIM_BOX_M / n,
                             .step_rate_hz = sim_rate_hz, .emitters = 1,
                             .open_floor = which == 1 || which == 2};
    c.emitter[0] = preset(which, SIM_BOX_M);
    /* The simulation has no randomness of its own: the seed moves the
     * emitter by up to half a cell across the floor plan, which changes
     * how its fuel falls on the grid and so the flow's details. 0 keeps
     * it centred. */
    uint64_t state = (uint64_t)seed;
    for (int a = 0; seed != 0 && a < 2; a++)
        c.emitter[0].centre_m[a] += (fg_splitmix64_uniform(&state) - 0.5) * c.cell_m;
    size_t steps = (size_t)ceil(seconds * sim_rate_hz);
    if (steps < 4)
        return json_fail(err, err_size, at, "%zu steps; at least 4 are needed", steps);
    fg_flame_sim *fs;
    fg_result r = fg_flame_sim_create(&c, &fs);
    if (r != FG_OK)
        return json_fail(err, err_size, at, "the flame simulation refused it: %s",
                         fg_result_str(r));
    f->flux_count = steps;
    if (live) { /* checked; run as the fire sounds */
        fg_flame_sim_destroy(fs);
        f->live = true;
        f->sim = c;
        return 0;
    }
    f->flux_m3_s = malloc(steps * sizeof *f->flux_m3_s);
    if (!f->flux_m3_s) {
        fg_flame_sim_destroy(fs);
        return json_fail(err, err_size, at, "out of memory");
    }
    for (size_t k = 0; k < steps; k++) {
        fg_flame_flux flux;
        if ((r = fg_flame_sim_step(fs, &flux)) != FG_OK) {
            fg_flame_sim_destroy(fs);
            return json_fail(err, err_size, at, "the flame simulation failed at step %zu: %s",
                             k, fg_result_str(r));
        }
        f->flux_m3_s[k] = flux.flux_m3_s;
    }
    fg_flame_sim_destroy(fs);
    return 0;
}
