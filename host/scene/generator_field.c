/* Generators that grow a tree in an electric field: "spark_gap" and
 * "plasma_ball" (the engine's presets) and "field" (grid, shapes and growth
 * from the scene). The JSON is described in docs/generators-field.md. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "fg_math.h"
#include "fulgur/fulgur.h"
#include "generator.h"
#include "generator_field_gpu.h"
#include "json_read.h"

/* "solver": "gpu": set by the program that has one (generator_field_gpu.h). */
static gen_field_gpu_grower gpu_grower;

void gen_field_set_gpu_grower(gen_field_gpu_grower grow)
{
    gpu_grower = grow;
}

/* Where messages point: the generator's JSON path and the caller's buffer. */
typedef struct ctx {
    const char *path;
    char *err;
    size_t err_size;
} ctx;

/* Any finite number; the checks that need more say so after the read. */
static const number_range any_number = {.lo = -INFINITY, .hi = INFINITY};

/* The path of field (relative, "grid.size") below the generator, in buf. */
static const char *at(const ctx *c, char buf[JSON_PATH_MAX], const char *field)
{
    json_path_key(buf, JSON_PATH_MAX, c->path, field);
    return buf;
}

/* obj[key] at base as an integer in lo..hi; absent leaves *out alone. */
static int integer(const ctx *c, const cJSON *obj, const char *base, const char *key, int lo,
                   int hi, int *out)
{
    double d = *out;
    if (json_number(obj, base, key, (number_range){.lo = lo, .hi = hi, .integer = true}, &d, c->err,
                    c->err_size))
        return -1;
    *out = (int)d;
    return 0;
}

static int boolean(const ctx *c, const cJSON *obj, const char *base, const char *key, int *out)
{
    bool b = *out != 0;
    if (json_bool(obj, base, key, &b, c->err, c->err_size))
        return -1;
    *out = b;
    return 0;
}

/* A required [x, y, z]. */
static int point(const ctx *c, const cJSON *obj, const char *base, const char *key, double out[3])
{
    char p[JSON_PATH_MAX];
    if (!cJSON_GetObjectItemCaseSensitive(obj, key)) {
        json_path_key(p, sizeof p, base, key);
        return json_fail(c->err, c->err_size, p, "is required: [x, y, z] in metres");
    }
    return json_vec3(obj, base, key, out, c->err, c->err_size);
}

static int parse_grid(const ctx *c, const cJSON *spec, fg_grid_config *g)
{
    char base[JSON_PATH_MAX], p[JSON_PATH_MAX];
    const cJSON *grid = cJSON_GetObjectItemCaseSensitive(spec, "grid");
    if (!cJSON_IsObject(grid))
        return json_fail(c->err, c->err_size, at(c, p, "grid"),
                         "is required: {\"size\", \"min\", \"max\"}");
    at(c, base, "grid");
    int size = FG_FIELD_DEFAULT_SIZE;
    if (integer(c, grid, base, "size", FG_FIELD_MIN_SIZE, FG_FIELD_MAX_SIZE, &size) ||
        point(c, grid, base, "min", g->min_m) || point(c, grid, base, "max", g->max_m))
        return -1;
    for (int a = 0; a < 3; a++) {
        g->size[a] = size;
        if (!(g->max_m[a] > g->min_m[a]))
            return json_fail(c->err, c->err_size, at(c, p, "grid.max"),
                             "must exceed grid.min on every axis");
    }
    size_t need = fg_field_memory_bytes(g);
    if (need > FG_FIELD_DEFAULT_MAX_BYTES)
        return json_fail(c->err, c->err_size, at(c, p, "grid.size"),
                         "needs %zu MiB, more than the limit of %zu MiB", need >> 20,
                         (size_t)FG_FIELD_DEFAULT_MAX_BYTES >> 20);
    return 0;
}

/* shapes[i], whose path is base. */
static int parse_shape(const ctx *c, const cJSON *j, const char *base, fg_shape *s)
{
    static const char *const kinds[] = {"sphere", "box", "plane", "point", "ground"};
    static const char *const roles[] = {"fixed", "origin", "target"};
    char p[JSON_PATH_MAX];
    int kind = -1, role = 0;
    memset(s, 0, sizeof *s);
    if (!cJSON_IsObject(j))
        return json_fail(c->err, c->err_size, base, "must be an object");
    if (json_name(j, base, "kind", kinds, 5, &kind, c->err, c->err_size) ||
        json_name(j, base, "role", roles, 3, &role, c->err, c->err_size))
        return -1;
    json_path_key(p, sizeof p, base, "kind");
    if (kind < 0)
        return json_fail(c->err, c->err_size, p, "is required");
    s->kind = (fg_shape_kind)kind;
    s->role = (fg_shape_role)role;
    if (json_number(j, base, "potential", any_number, &s->potential, c->err, c->err_size) ||
        boolean(c, j, base, "outside", &s->outside))
        return -1;
    switch (s->kind) {
    case FG_SHAPE_SPHERE:
        if (point(c, j, base, "center", s->centre_m) ||
            json_number(j, base, "radius", any_number, &s->radius_m, c->err, c->err_size))
            return -1;
        json_path_key(p, sizeof p, base, "radius");
        if (!(s->radius_m > 0.0))
            return json_fail(c->err, c->err_size, p, "is required and must be > 0 (metres)");
        break;
    case FG_SHAPE_BOX:
        if (point(c, j, base, "min", s->box_min_m) || point(c, j, base, "max", s->box_max_m))
            return -1;
        break;
    case FG_SHAPE_PLANE:
        if (point(c, j, base, "center", s->centre_m) || point(c, j, base, "normal", s->normal))
            return -1;
        break;
    case FG_SHAPE_POINT:
        if (point(c, j, base, "center", s->centre_m))
            return -1;
        break;
    case FG_SHAPE_GROUND:
        break;
    }
    return 0;
}

static int parse_growth(const ctx *c, const cJSON *spec, fg_growth_config *g, int *dbm)
{
    static const char *const models[] = {"matsuyama", "dbm"};
    char base[JSON_PATH_MAX], p[JSON_PATH_MAX];
    const cJSON *j = cJSON_GetObjectItemCaseSensitive(spec, "growth");
    if (!j)
        return 0;
    at(c, base, "growth");
    if (!cJSON_IsObject(j))
        return json_fail(c->err, c->err_size, base, "must be an object");
    char *err = c->err;
    size_t size = c->err_size;
    if (json_name(j, base, "model", models, 2, dbm, err, size) ||
        json_number(j, base, "step", any_number, &g->step_m, err, size) ||
        json_number(j, base, "gamma", any_number, &g->gamma, err, size) ||
        json_number(j, base, "eta", any_number, &g->eta, err, size) ||
        json_number(j, base, "cone", any_number, &g->cone_rad, err, size) ||
        json_number(j, base, "branch_probability", any_number, &g->branch_probability, err, size) ||
        json_number(j, base, "branch_length", any_number, &g->branch_length_m, err, size) ||
        integer(c, j, base, "candidates", 1, FG_GROWTH_MAX_CANDIDATES, &g->candidates) ||
        integer(c, j, base, "max_tips", 1, 4096, &g->max_tips) ||
        integer(c, j, base, "max_steps", 1, 1 << 24, &g->max_steps) ||
        boolean(c, j, base, "all_tips_connect", &g->all_tips_connect))
        return -1;
    if (!(g->step_m > 0.0))
        return json_fail(err, size, at(c, p, "growth.step"), "must be > 0 (metres)");
    if (g->gamma < 0.0 || g->eta < 0.0)
        return json_fail(err, size, at(c, p, g->gamma < 0.0 ? "growth.gamma" : "growth.eta"),
                         "must be >= 0");
    if (g->cone_rad < 0.0 || g->cone_rad > FG_PI)
        return json_fail(err, size, at(c, p, "growth.cone"), "must be an angle in 0..pi radians");
    if (g->branch_probability < 0.0 || g->branch_probability > 1.0)
        return json_fail(err, size, at(c, p, "growth.branch_probability"), "must be in 0..1");
    if (g->branch_length_m < 0.0)
        return json_fail(err, size, at(c, p, "growth.branch_length"), "must be >= 0 (metres)");
    return 0;
}

enum { SOLVER_CPU = 0, SOLVER_GPU = 1 };

/* "solver": "cpu" (the default) or "gpu". */
static int parse_solver(const ctx *c, const cJSON *spec, int dbm, int *solver)
{
    static const char *const names[] = {"cpu", "gpu"};
    char p[JSON_PATH_MAX];
    if (json_name(spec, c->path, "solver", names, 2, solver, c->err, c->err_size))
        return -1;
    if (*solver == SOLVER_GPU && !gpu_grower)
        return json_fail(c->err, c->err_size, at(c, p, "solver"),
                         "\"gpu\" needs a fulgur built with gpu/ (FULGUR_GPU=ON)");
    if (*solver == SOLVER_GPU && dbm)
        return json_fail(c->err, c->err_size, at(c, p, "solver"),
                         "\"gpu\" grows Matsuyama leaders only: DBM changes the field at "
                         "every step, use \"cpu\"");
    return 0;
}

/* Sets the shapes, solves (on the CPU, or the GPU) and grows. */
static int run(const ctx *c, const fg_grid_config *grid, const fg_shape *shapes, size_t count,
               const fg_growth_config *growth, int dbm, int solver, fg_tree *out)
{
    char p[JSON_PATH_MAX];
    fg_field *f = NULL;
    fg_result r = fg_field_create(grid, &f);
    if (r != FG_OK)
        return json_fail(c->err, c->err_size, at(c, p, "grid"), "%s", fg_result_str(r));
    size_t bad = count;
    r = fg_field_set_shapes(f, shapes, count, &bad);
    if (r != FG_OK) {
        fg_field_destroy(f);
        if (bad < count) {
            char field[32];
            snprintf(field, sizeof field, "shapes[%zu]", bad);
            return json_fail(c->err, c->err_size, at(c, p, field),
                             r == FG_ERR_ARGUMENT
                                 ? "covers no node of the grid (outside it?), or its size, normal "
                                   "or potential is invalid"
                                 : "%s",
                             fg_result_str(r));
        }
        return json_fail(
            c->err, c->err_size, at(c, p, "shapes"),
            "needs at least one \"origin\" and one \"target\" shape, all origins at one "
            "potential and all targets at another");
    }
    fg_solve_report rep = {0};
    if (solver == SOLVER_GPU && gpu_grower) {
        char msg[256] = "";
        r = gpu_grower(f, growth, out, &rep.residual, msg, sizeof msg);
        fg_field_destroy(f);
        if (r == FG_ERR_UNREACHABLE)
            return json_fail(c->err, c->err_size, at(c, p, "shapes"),
                             "the target cannot be reached from the origin");
        if (r != FG_OK)
            return json_fail(c->err, c->err_size, at(c, p, "solver"),
                             "the GPU solve or growth failed: %s (%s)", fg_result_str(r), msg);
        return 0;
    }
    /* DBM solves again as it grows, to the solver's default. */
    fg_solve_config sc = {.tolerance = dbm ? 0.0 : FG_GROWTH_FIELD_TOLERANCE};
    r = fg_field_solve(f, &sc, &rep);
    if (r == FG_OK) {
        if (dbm) {
            r = fg_grow_dbm(f, growth, out, NULL);
        } else {
            fg_field_source src;
            fg_field_source_init(f, &src);
            r = fg_grow_matsuyama(&src, growth, out, NULL);
        }
    }
    fg_field_destroy(f);
    if (r == FG_ERR_NOT_CONVERGED)
        return json_fail(c->err, c->err_size, at(c, p, "grid"),
                         "the field solve did not converge (residual %.1e)", rep.residual);
    if (r == FG_ERR_UNREACHABLE)
        return json_fail(c->err, c->err_size, at(c, p, "shapes"),
                         "the target cannot be reached from the origin");
    if (r != FG_OK)
        return json_fail(c->err, c->err_size, at(c, p, "growth"), "%s", fg_result_str(r));
    return 0;
}

/* The preset's field scene on the grid "size" asks for. */
static int preset_scene(const ctx *c, fg_preset preset, const cJSON *spec, fg_field_scene *s)
{
    int size = FG_FIELD_DEFAULT_SIZE;
    char p[JSON_PATH_MAX];
    if (integer(c, spec, c->path, "size", FG_FIELD_MIN_SIZE, FG_FIELD_MAX_SIZE, &size))
        return -1;
    if (fg_field_scene_preset(preset, size, s) != FG_OK)
        return json_fail(c->err, c->err_size, at(c, p, "size"), "must be %d..%d",
                         FG_FIELD_MIN_SIZE, FG_FIELD_MAX_SIZE);
    return 0;
}

static int generate_preset(fg_preset preset, const cJSON *spec, const char *path,
                           const gen_context *gc, fg_tree *out, char *err, size_t err_size)
{
    ctx c = {path, err, err_size};
    int dbm = 0, solver = SOLVER_CPU;
    fg_field_scene s;
    if (preset_scene(&c, preset, spec, &s))
        return -1;
    s.growth.seed = gc->seed;
    if (parse_growth(&c, spec, &s.growth, &dbm) || parse_solver(&c, spec, dbm, &solver))
        return -1;
    return run(&c, &s.grid, s.shapes, s.shape_count, &s.growth, dbm, solver, out);
}

static int preset_shapes(fg_preset preset, const cJSON *spec, const char *path, fg_shape *shapes,
                         size_t *count, double box_min_m[3], double box_max_m[3], char *err,
                         size_t err_size)
{
    ctx c = {path, err, err_size};
    fg_field_scene s;
    if (preset_scene(&c, preset, spec, &s))
        return -1;
    memcpy(shapes, s.shapes, s.shape_count * sizeof *shapes);
    *count = s.shape_count;
    memcpy(box_min_m, s.grid.min_m, 3 * sizeof *box_min_m);
    memcpy(box_max_m, s.grid.max_m, 3 * sizeof *box_max_m);
    return 0;
}

int gen_spark_gap_shapes(const cJSON *spec, const char *path, fg_shape *shapes, size_t *count,
                         double box_min_m[3], double box_max_m[3], char *err, size_t err_size)
{
    return preset_shapes(FG_PRESET_SPARK_BALLS, spec, path, shapes, count, box_min_m, box_max_m,
                         err, err_size);
}

int gen_plasma_ball_shapes(const cJSON *spec, const char *path, fg_shape *shapes, size_t *count,
                           double box_min_m[3], double box_max_m[3], char *err, size_t err_size)
{
    return preset_shapes(FG_PRESET_PLASMA_BALL, spec, path, shapes, count, box_min_m, box_max_m,
                         err, err_size);
}

int gen_spark_gap(const cJSON *spec, const char *path, const gen_context *gc, fg_tree *out,
                  char *err, size_t err_size)
{
    return generate_preset(FG_PRESET_SPARK_BALLS, spec, path, gc, out, err, err_size);
}

int gen_plasma_ball(const cJSON *spec, const char *path, const gen_context *gc, fg_tree *out,
                    char *err, size_t err_size)
{
    return generate_preset(FG_PRESET_PLASMA_BALL, spec, path, gc, out, err, err_size);
}

/* "grid" and "shapes" of a field generator. */
static int parse_field(const ctx *c, const cJSON *spec, fg_grid_config *grid, fg_shape *shapes,
                       size_t *count)
{
    if (parse_grid(c, spec, grid))
        return -1;
    char p[JSON_PATH_MAX], item[JSON_PATH_MAX];
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(spec, "shapes");
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) < 2)
        return json_fail(c->err, c->err_size, at(c, p, "shapes"),
                         "is required: an array with an origin and a target shape");
    int n = cJSON_GetArraySize(list);
    if (n > FG_FIELD_MAX_SHAPES)
        return json_fail(c->err, c->err_size, at(c, p, "shapes"), "at most %d shapes",
                         FG_FIELD_MAX_SHAPES);
    at(c, p, "shapes");
    for (int i = 0; i < n; i++) {
        json_path_index(item, sizeof item, p, (size_t)i);
        if (parse_shape(c, cJSON_GetArrayItem(list, i), item, &shapes[i]))
            return -1;
    }
    *count = (size_t)n;
    return 0;
}

int gen_field_shapes(const cJSON *spec, const char *path, fg_shape *shapes, size_t *count,
                     double box_min_m[3], double box_max_m[3], char *err, size_t err_size)
{
    ctx c = {path, err, err_size};
    fg_grid_config grid = {0};
    if (parse_field(&c, spec, &grid, shapes, count))
        return -1;
    memcpy(box_min_m, grid.min_m, 3 * sizeof *box_min_m);
    memcpy(box_max_m, grid.max_m, 3 * sizeof *box_max_m);
    return 0;
}

int gen_field(const cJSON *spec, const char *path, const gen_context *gc, fg_tree *out,
              char *err, size_t err_size)
{
    ctx c = {path, err, err_size};
    char p[JSON_PATH_MAX];
    fg_grid_config grid = {0};
    fg_shape shapes[FG_FIELD_MAX_SHAPES];
    size_t count;
    if (parse_field(&c, spec, &grid, shapes, &count))
        return -1;
    const cJSON *growth = cJSON_GetObjectItemCaseSensitive(spec, "growth");
    if (!cJSON_IsObject(growth) || !cJSON_GetObjectItemCaseSensitive(growth, "step"))
        return json_fail(c.err, c.err_size, at(&c, p, "growth.step"),
                         "is required: the segment length in metres");
    fg_growth_config g = {.seed = gc->seed};
    int dbm = 0, solver = SOLVER_CPU;
    if (parse_growth(&c, spec, &g, &dbm) || parse_solver(&c, spec, dbm, &solver))
        return -1;
    return run(&c, &grid, shapes, count, &g, dbm, solver, out);
}
