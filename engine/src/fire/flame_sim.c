/* The flame simulation: the combustion model of fulgur/flame.h on the fluid
 * core, through its two hooks — `forces` (after advection: emitters, the
 * burn, heat, cooling, buoyancy) and `divergence` (phi = expansion * B
 * before the projection) — and the flame front's flux at each step's end.
 *
 * The burn of a substep integrates dF/dt = -r F exactly over dt, so no
 * rate makes F negative, and B is the fuel that substep removed per
 * second: the projection's phi and the front's field are the same B, and
 * the integral of phi is expansion times the mixture burnt per second. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "flame_sim_internal.h"

#define DEFAULT_CELLS 32
#define DEFAULT_CELL_M 0.02
#define DEFAULT_STEP_RATE_HZ 360.0
#define DEFAULT_AMBIENT_K 293.15
#define DEFAULT_IGNITION_K 700.0
#define DEFAULT_BURN_RATE 20.0
#define DEFAULT_HEAT_K 1900.0
#define DEFAULT_COOLING 3.0
#define GRAVITY_M_S2 9.81
#define MIN_STEP_RATE_HZ 10.0
#define MAX_STEP_RATE_HZ 10000.0
/* the substeps keep |u| dt / h at or below this */
#define MAX_CFL 1.0

struct fg_flame_sim {
    fg_flame_sim_config config;
    fg_fluid *fluid;
    fg_flame_front *front;
    double *burn; /* B of the last substep, 1/s per cell */
    double lo[3], hi[3];
    double dt;    /* the step */
    fg_flame_sim_stats stats;
    int broken;
};

static double def(double v, double d)
{
    return v == 0.0 ? d : v;
}

static void fill_defaults(fg_flame_sim_config *c)
{
    for (int a = 0; a < 3; a++)
        if (c->cells[a] == 0)
            c->cells[a] = DEFAULT_CELLS;
    c->cell_m = def(c->cell_m, DEFAULT_CELL_M);
    c->step_rate_hz = def(c->step_rate_hz, DEFAULT_STEP_RATE_HZ);
    c->ambient_k = def(c->ambient_k, DEFAULT_AMBIENT_K);
    c->ignition_k = def(c->ignition_k, DEFAULT_IGNITION_K);
    c->burn_rate_1_s = def(c->burn_rate_1_s, DEFAULT_BURN_RATE);
    c->heat_k = def(c->heat_k, DEFAULT_HEAT_K);
    c->expansion = def(c->expansion, c->heat_k / c->ambient_k);
    c->cooling_1_s = def(c->cooling_1_s, DEFAULT_COOLING);
    c->buoyancy = def(c->buoyancy, 1.0);
    c->iso_level = def(c->iso_level, c->burn_rate_1_s / 1000.0);
    if (c->front_subdivision == 0)
        c->front_subdivision = 1;
    if (c->max_bytes == 0)
        c->max_bytes = FG_FLAME_SIM_DEFAULT_MAX_BYTES;
}

static fg_result check_config(const fg_flame_sim_config *c)
{
    const double v[] = {c->cell_m,        c->origin_m[0], c->origin_m[1], c->origin_m[2],
                        c->step_rate_hz,  c->ambient_k,   c->ignition_k,  c->burn_rate_1_s,
                        c->heat_k,        c->expansion,   c->cooling_1_s, c->buoyancy,
                        c->iso_level};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i]))
            return FG_ERR_NOT_FINITE;
    for (int a = 0; a < 3; a++)
        if (c->cells[a] < FG_FLAME_SIM_MIN_CELLS || c->cells[a] > FG_FLAME_SIM_MAX_CELLS)
            return FG_ERR_ARGUMENT;
    for (size_t i = 4; i < sizeof v / sizeof v[0]; i++)
        if (v[i] < 0.0)
            return FG_ERR_ARGUMENT;
    if (!(c->cell_m > 0.0) || c->step_rate_hz < MIN_STEP_RATE_HZ ||
        c->step_rate_hz > MAX_STEP_RATE_HZ || !(c->ignition_k > c->ambient_k) ||
        c->front_subdivision < 1 || c->front_subdivision > FG_FLAME_MAX_SUBDIVISION ||
        c->emitters < 0 || c->emitters > FG_FLAME_MAX_EMITTERS)
        return FG_ERR_ARGUMENT;
    return FG_OK;
}

static void fluid_config(const fg_flame_sim_config *c, fg_fluid_config *out)
{
    memset(out, 0, sizeof *out);
    out->dims = 3;
    for (int a = 0; a < 3; a++) {
        out->cells[a] = c->cells[a];
        out->origin_m[a] = c->origin_m[a];
        out->boundary[a][0] = out->boundary[a][1] = FG_FLUID_OPEN;
    }
    if (!c->open_floor)
        out->boundary[2][0] = FG_FLUID_WALL;
    out->cell_m = c->cell_m;
    out->viscosity_m2_s = -1.0; /* air's 1.5e-5 m^2/s is far below the grid's own */
    out->scalars = FG_FLAME_SCALARS;
}

static void front_config(const fg_flame_sim_config *c, size_t max_bytes, fg_flame_front_config *out)
{
    memset(out, 0, sizeof *out);
    for (int a = 0; a < 3; a++) {
        out->grid.size[a] = c->cells[a];
        out->grid.origin_m[a] = c->origin_m[a];
    }
    out->grid.cell_m = c->cell_m;
    out->iso_level = c->iso_level;
    out->subdivision = c->front_subdivision;
    out->max_bytes = max_bytes;
}

static size_t cell_count(const fg_flame_sim_config *c)
{
    return (size_t)c->cells[0] * (size_t)c->cells[1] * (size_t)c->cells[2];
}

/* The memory of a checked configuration with its defaults; 0 if a part is
 * refused by its own limits. */
static size_t memory_bytes(const fg_flame_sim_config *c)
{
    fg_fluid_config fc;
    fluid_config(c, &fc);
    fg_flame_front_config front;
    front_config(c, SIZE_MAX, &front);
    size_t fluid = fg_fluid_memory_bytes(&fc), edge = fg_flame_front_memory_bytes(&front);
    if (fluid == 0 || edge == 0)
        return 0;
    return sizeof(fg_flame_sim) + fluid + edge + cell_count(c) * sizeof(double);
}

size_t fg_flame_sim_memory_bytes(const fg_flame_sim_config *config)
{
    if (!config)
        return 0;
    fg_flame_sim_config c = *config;
    fill_defaults(&c);
    if (check_config(&c) != FG_OK)
        return 0;
    return memory_bytes(&c);
}

fg_result fg_flame_sim_create(const fg_flame_sim_config *config, fg_flame_sim **out)
{
    if (!config || !out)
        return FG_ERR_NULL;
    fg_flame_sim_config c = *config;
    fill_defaults(&c);
    fg_result r = check_config(&c);
    if (r != FG_OK)
        return r;
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = c.origin_m[a];
        hi[a] = c.origin_m[a] + c.cells[a] * c.cell_m;
    }
    for (int e = 0; e < c.emitters; e++)
        if ((r = fg_flame_emitter_prepare(&config->emitter[e], lo, hi, c.cell_m, &c.emitter[e])) !=
            FG_OK)
            return r;
    memset(&c.emitter[c.emitters], 0,
           (FG_FLAME_MAX_EMITTERS - (size_t)c.emitters) * sizeof c.emitter[0]);
    size_t bytes = memory_bytes(&c);
    if (bytes == 0)
        return FG_ERR_ARGUMENT;
    if (bytes > c.max_bytes)
        return FG_ERR_CAPACITY;
    fg_flame_sim *s = calloc(1, sizeof *s);
    if (!s)
        return FG_ERR_NO_MEMORY;
    s->config = c;
    memcpy(s->lo, lo, sizeof lo);
    memcpy(s->hi, hi, sizeof hi);
    s->dt = 1.0 / c.step_rate_hz;
    fg_fluid_config fc;
    fluid_config(&c, &fc);
    fg_flame_front_config front;
    front_config(&c, SIZE_MAX, &front);
    s->burn = calloc(cell_count(&c), sizeof(double));
    if (!s->burn || (r = fg_fluid_create(&fc, &s->fluid)) != FG_OK ||
        (r = fg_flame_front_create(&front, &s->front)) != FG_OK) {
        fg_flame_sim_destroy(s);
        return r == FG_OK ? FG_ERR_NO_MEMORY : r;
    }
    fg_fluid_array t = fg_fluid_scalar(s->fluid, FG_FLAME_TEMPERATURE);
    for (size_t i = 0; i < cell_count(&c); i++)
        t.data[i] = c.ambient_k;
    s->stats.max_temperature_k = c.ambient_k;
    *out = s;
    return FG_OK;
}

void fg_flame_sim_destroy(fg_flame_sim *sim)
{
    if (!sim)
        return;
    fg_flame_front_destroy(sim->front);
    fg_fluid_destroy(sim->fluid);
    free(sim->burn);
    free(sim);
}

void fg_flame_sim_get_config(const fg_flame_sim *sim, fg_flame_sim_config *out)
{
    *out = sim->config;
}

/* The forces hook: emitters, then the burn, heat and cooling of each cell,
 * then buoyancy on the vertical faces from the temperature of the cells on
 * either side. */
static void react(fg_fluid *f, double dt, void *user)
{
    fg_flame_sim *s = user;
    const fg_flame_sim_config *c = &s->config;
    fg_fluid_array fuel = fg_fluid_scalar(f, FG_FLAME_FUEL);
    fg_fluid_array temp = fg_fluid_scalar(f, FG_FLAME_TEMPERATURE);
    size_t cells = cell_count(c);
    /* F is a volume fraction, so it obeys dF/dt + u . grad F = -F div u:
     * the advection moved it along u, this dilutes it by the divergence of
     * the flow that carried it (the last substep's phi) */
    for (size_t i = 0; i < cells; i++)
        if (s->burn[i] > 0.0)
            fuel.data[i] *= exp(-c->expansion * s->burn[i] * dt);
    for (int e = 0; e < c->emitters; e++)
        s->stats.fuel_emitted_m3 += fg_flame_emitter_release(&c->emitter[e], f, dt);
    double burnt_share = -expm1(-c->burn_rate_1_s * dt), keep_heat = exp(-c->cooling_1_s * dt);
    double burnt = 0.0, hottest = c->ambient_k;
    for (size_t i = 0; i < cells; i++) {
        double F = fuel.data[i], T = temp.data[i], b = 0.0;
        if (T > c->ignition_k && F > 0.0) {
            b = F * burnt_share;
            fuel.data[i] = F - b;
            T += c->heat_k * b;
        }
        s->burn[i] = b / dt;
        burnt += b;
        T = c->ambient_k + (T - c->ambient_k) * keep_heat;
        temp.data[i] = T;
        hottest = T > hottest ? T : hottest;
    }
    double cell_volume = c->cell_m * c->cell_m * c->cell_m;
    s->stats.fuel_burnt_m3 += burnt * cell_volume;
    s->stats.burning_m3_s = burnt * cell_volume / dt;
    s->stats.expansion_m3_s = c->expansion * s->stats.burning_m3_s;
    s->stats.max_temperature_k = hottest;
    fg_fluid_array w = fg_fluid_velocity(f, 2);
    double g = c->buoyancy * GRAVITY_M_S2 * dt;
    size_t layer = temp.stride[2];
    for (int k = 1; k < w.size[2] - 1; k++)
        for (int j = 0; j < w.size[1]; j++)
            for (int i = 0; i < w.size[0]; i++) {
                size_t below = (size_t)i + (size_t)j * temp.stride[1] + (size_t)(k - 1) * layer;
                double tb = temp.data[below], ta = temp.data[below + layer];
                double lift = 0.5 * ((tb - c->ambient_k) / tb + (ta - c->ambient_k) / ta);
                w.data[i * w.stride[0] + j * w.stride[1] + k * w.stride[2]] += g * lift;
            }
}

static void expand(fg_fluid *f, double dt, double *phi, void *user)
{
    (void)f;
    (void)dt;
    const fg_flame_sim *s = user;
    size_t cells = cell_count(&s->config);
    for (size_t i = 0; i < cells; i++)
        phi[i] = s->config.expansion * s->burn[i];
}

static double fuel_present(const fg_flame_sim *s)
{
    fg_fluid_array fuel = fg_fluid_scalar(s->fluid, FG_FLAME_FUEL);
    size_t cells = cell_count(&s->config);
    double sum = 0.0;
    for (size_t i = 0; i < cells; i++)
        sum += fuel.data[i];
    return sum * s->config.cell_m * s->config.cell_m * s->config.cell_m;
}

/* The fastest the flow may be in the coming step: now, or what a jet sets. */
static double speed_bound(const fg_flame_sim *s)
{
    double v = fg_fluid_max_speed(s->fluid);
    for (int e = 0; e < s->config.emitters; e++)
        if (s->config.emitter[e].kind == FG_FLAME_EMITTER_JET)
            for (int a = 0; a < 3; a++) {
                double j = fabs(s->config.emitter[e].jet_velocity_m_s[a]);
                v = j > v ? j : v;
            }
    return v;
}

fg_result fg_flame_sim_step(fg_flame_sim *sim, fg_flame_flux *out)
{
    if (!sim)
        return FG_ERR_NULL;
    if (sim->broken)
        return FG_ERR_NOT_FINITE;
    double cfl = speed_bound(sim) * sim->dt / sim->config.cell_m;
    int substeps = cfl <= MAX_CFL ? 1 : (int)ceil(cfl / MAX_CFL);
    if (!(cfl <= MAX_CFL * FG_FLAME_MAX_SUBSTEPS)) {
        sim->broken = 1;
        return FG_ERR_NOT_FINITE;
    }
    fg_fluid_hooks hooks = {.forces = react, .divergence = expand, .user = sim};
    double dt = sim->dt / substeps;
    for (int n = 0; n < substeps; n++) {
        fg_result r = fg_fluid_step(sim->fluid, dt, &hooks);
        sim->stats.substeps++;
        if (r == FG_ERR_NOT_CONVERGED) {
            sim->stats.not_converged++;
        } else if (r != FG_OK) {
            sim->broken = 1;
            return FG_ERR_NOT_FINITE;
        }
    }
    sim->stats.steps++;
    sim->stats.time_s = fg_fluid_time_s(sim->fluid);
    sim->stats.fuel_present_m3 = fuel_present(sim);
    sim->stats.max_speed_m_s = fg_fluid_max_speed(sim->fluid);
    const fg_fluid_report *rep = fg_fluid_last_report(sim->fluid);
    sim->stats.projection_residual = rep->residual;
    sim->stats.projection_iterations = rep->iterations;
    fg_flame_velocity v;
    fg_result r = fg_flame_sim_velocity(sim, &v);
    if (r != FG_OK)
        return r;
    fg_flame_flux flux;
    r = fg_flame_front_flux(sim->front, sim->burn, &v, &flux);
    if (r != FG_OK)
        return r;
    sim->stats.flux = flux;
    if (out)
        *out = flux;
    return FG_OK;
}

fg_result fg_flame_sim_set_emitter(fg_flame_sim *sim, int index, const fg_flame_emitter *emitter)
{
    if (!sim || !emitter)
        return FG_ERR_NULL;
    if (index < 0 || index >= sim->config.emitters)
        return FG_ERR_ARGUMENT;
    return fg_flame_emitter_prepare(emitter, sim->lo, sim->hi, sim->config.cell_m,
                                    &sim->config.emitter[index]);
}

void fg_flame_sim_get_stats(const fg_flame_sim *sim, fg_flame_sim_stats *out)
{
    *out = sim->stats;
}

fg_result fg_flame_sim_field(const fg_flame_sim *sim, fg_flame_field field,
                             fg_flame_field_view *out)
{
    if (!sim || !out)
        return FG_ERR_NULL;
    const double *data;
    switch (field) {
    case FG_FLAME_FIELD_BURN:
        data = sim->burn;
        break;
    case FG_FLAME_FIELD_TEMPERATURE:
        data = fg_fluid_scalar(sim->fluid, FG_FLAME_TEMPERATURE).data;
        break;
    case FG_FLAME_FIELD_FUEL:
        data = fg_fluid_scalar(sim->fluid, FG_FLAME_FUEL).data;
        break;
    default:
        return FG_ERR_ARGUMENT;
    }
    out->data = data;
    for (int a = 0; a < 3; a++) {
        out->grid.size[a] = sim->config.cells[a];
        out->grid.origin_m[a] = sim->config.origin_m[a];
    }
    out->grid.cell_m = sim->config.cell_m;
    return FG_OK;
}

fg_result fg_flame_sim_velocity(const fg_flame_sim *sim, fg_flame_velocity *out)
{
    if (!sim || !out)
        return FG_ERR_NULL;
    out->layout = FG_VELOCITY_MAC;
    for (int a = 0; a < 3; a++)
        out->u_m_s[a] = fg_fluid_velocity(sim->fluid, a).data;
    return FG_OK;
}

fg_result fg_flame_sim_triangles(const fg_flame_sim *sim, const double **xyz_m, size_t *triangles)
{
    if (!sim)
        return FG_ERR_NULL;
    return fg_flame_front_triangles(sim->front, xyz_m, triangles);
}
