/* Generators that grow a tree in an electric field: "spark_gap" and
 * "plasma_ball" (the engine's presets) and "field" (grid, shapes and growth
 * from the scene). The JSON is described in docs/generators-field.md. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "fg_math.h"
#include "fulgur/fulgur.h"
#include "generator.h"
#ifdef FULGUR_HOST_GPU
#include "generator_field_gpu.h"
#endif

typedef struct ctx {
    const char *path;
    char *err;
    size_t err_size;
} ctx;

static int fail(const ctx *c, const char *field, const char *fmt, ...)
{
    int n = snprintf(c->err, c->err_size, "%s%s%s: ", c->path, field[0] ? "." : "", field);
    if (n >= 0 && (size_t)n < c->err_size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(c->err + n, c->err_size - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* An optional number: absent leaves *out alone. */
static int number(const ctx *c, const cJSON *obj, const char *key, const char *field,
                  double *out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v)
        return 0;
    if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble))
        return fail(c, field, "must be a finite number");
    *out = v->valuedouble;
    return 0;
}

static int integer(const ctx *c, const cJSON *obj, const char *key, const char *field, int lo,
                   int hi, int *out)
{
    double d = *out;
    if (!cJSON_GetObjectItemCaseSensitive(obj, key))
        return 0;
    if (number(c, obj, key, field, &d) != 0)
        return -1;
    if (d != floor(d) || d < lo || d > hi)
        return fail(c, field, "must be an integer in %d..%d", lo, hi);
    *out = (int)d;
    return 0;
}

static int boolean(const ctx *c, const cJSON *obj, const char *key, const char *field, int *out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v)
        return 0;
    if (!cJSON_IsBool(v))
        return fail(c, field, "must be true or false");
    *out = cJSON_IsTrue(v);
    return 0;
}

static int vec3(const ctx *c, const cJSON *obj, const char *key, const char *field, double out[3])
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v)
        return fail(c, field, "is required: [x, y, z] in metres");
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != 3)
        return fail(c, field, "must be [x, y, z]");
    for (int a = 0; a < 3; a++) {
        const cJSON *e = cJSON_GetArrayItem(v, a);
        if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble))
            return fail(c, field, "must hold three finite numbers");
        out[a] = e->valuedouble;
    }
    return 0;
}

static int pick_name(const ctx *c, const cJSON *obj, const char *key, const char *field,
                     const char *const *names, int count, int *out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!v)
        return 0;
    if (cJSON_IsString(v))
        for (int i = 0; i < count; i++)
            if (strcmp(v->valuestring, names[i]) == 0) {
                *out = i;
                return 0;
            }
    char list[128] = "";
    for (int i = 0; i < count; i++)
        snprintf(list + strlen(list), sizeof list - strlen(list), "%s\"%s\"", i ? ", " : "",
                 names[i]);
    return fail(c, field, "must be one of %s", list);
}

static int parse_grid(const ctx *c, const cJSON *spec, fg_grid_config *g)
{
    const cJSON *grid = cJSON_GetObjectItemCaseSensitive(spec, "grid");
    if (!cJSON_IsObject(grid))
        return fail(c, "grid", "is required: {\"size\", \"min\", \"max\"}");
    int size = FG_FIELD_DEFAULT_SIZE;
    if (integer(c, grid, "size", "grid.size", FG_FIELD_MIN_SIZE, FG_FIELD_MAX_SIZE, &size) ||
        vec3(c, grid, "min", "grid.min", g->min_m) ||
        vec3(c, grid, "max", "grid.max", g->max_m))
        return -1;
    for (int a = 0; a < 3; a++) {
        g->size[a] = size;
        if (!(g->max_m[a] > g->min_m[a]))
            return fail(c, "grid.max", "must exceed grid.min on every axis");
    }
    size_t need = fg_field_memory_bytes(g);
    if (need > FG_FIELD_DEFAULT_MAX_BYTES)
        return fail(c, "grid.size", "needs %zu MiB, more than the limit of %zu MiB", need >> 20,
                    (size_t)FG_FIELD_DEFAULT_MAX_BYTES >> 20);
    return 0;
}

/* "field.name" in buf, for messages. */
static const char *sub(char *buf, size_t size, const char *field, const char *name)
{
    snprintf(buf, size, "%s.%s", field, name);
    return buf;
}

static int parse_shape(const ctx *c0, const cJSON *j, const char *field, fg_shape *s)
{
    static const char *const kinds[] = {"sphere", "box", "plane", "point", "ground"};
    static const char *const roles[] = {"fixed", "origin", "target"};
    char f[160];
    int kind = -1, role = 0;
    ctx c = *c0;
    memset(s, 0, sizeof *s);
    if (!cJSON_IsObject(j))
        return fail(&c, field, "must be an object");
    if (pick_name(&c, j, "kind", sub(f, sizeof f, field, "kind"), kinds, 5, &kind) ||
        pick_name(&c, j, "role", sub(f, sizeof f, field, "role"), roles, 3, &role))
        return -1;
    if (kind < 0)
        return fail(&c, sub(f, sizeof f, field, "kind"), "is required");
    s->kind = (fg_shape_kind)kind;
    s->role = (fg_shape_role)role;
    if (number(&c, j, "potential", sub(f, sizeof f, field, "potential"), &s->potential) ||
        boolean(&c, j, "outside", sub(f, sizeof f, field, "outside"), &s->outside))
        return -1;
    switch (s->kind) {
    case FG_SHAPE_SPHERE:
        if (vec3(&c, j, "center", sub(f, sizeof f, field, "center"), s->centre_m) ||
            number(&c, j, "radius", sub(f, sizeof f, field, "radius"), &s->radius_m))
            return -1;
        if (!(s->radius_m > 0.0))
            return fail(&c, sub(f, sizeof f, field, "radius"), "is required and must be > 0 (metres)");
        break;
    case FG_SHAPE_BOX:
        if (vec3(&c, j, "min", sub(f, sizeof f, field, "min"), s->box_min_m) ||
            vec3(&c, j, "max", sub(f, sizeof f, field, "max"), s->box_max_m))
            return -1;
        break;
    case FG_SHAPE_PLANE:
        if (vec3(&c, j, "center", sub(f, sizeof f, field, "center"), s->centre_m) ||
            vec3(&c, j, "normal", sub(f, sizeof f, field, "normal"), s->normal))
            return -1;
        break;
    case FG_SHAPE_POINT:
        if (vec3(&c, j, "center", sub(f, sizeof f, field, "center"), s->centre_m))
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
    const cJSON *j = cJSON_GetObjectItemCaseSensitive(spec, "growth");
    if (!j)
        return 0;
    if (!cJSON_IsObject(j))
        return fail(c, "growth", "must be an object");
    if (pick_name(c, j, "model", "growth.model", models, 2, dbm) ||
        number(c, j, "step", "growth.step", &g->step_m) ||
        number(c, j, "gamma", "growth.gamma", &g->gamma) ||
        number(c, j, "eta", "growth.eta", &g->eta) ||
        number(c, j, "cone", "growth.cone", &g->cone_rad) ||
        number(c, j, "branch_probability", "growth.branch_probability",
               &g->branch_probability) ||
        number(c, j, "branch_length", "growth.branch_length", &g->branch_length_m) ||
        integer(c, j, "candidates", "growth.candidates", 1, FG_GROWTH_MAX_CANDIDATES,
                &g->candidates) ||
        integer(c, j, "max_tips", "growth.max_tips", 1, 4096, &g->max_tips) ||
        integer(c, j, "max_steps", "growth.max_steps", 1, 1 << 24, &g->max_steps) ||
        boolean(c, j, "all_tips_connect", "growth.all_tips_connect", &g->all_tips_connect))
        return -1;
    if (!(g->step_m > 0.0))
        return fail(c, "growth.step", "must be > 0 (metres)");
    if (g->gamma < 0.0 || g->eta < 0.0)
        return fail(c, g->gamma < 0.0 ? "growth.gamma" : "growth.eta", "must be >= 0");
    if (g->cone_rad < 0.0 || g->cone_rad > FG_PI)
        return fail(c, "growth.cone", "must be an angle in 0..pi radians");
    if (g->branch_probability < 0.0 || g->branch_probability > 1.0)
        return fail(c, "growth.branch_probability", "must be in 0..1");
    if (g->branch_length_m < 0.0)
        return fail(c, "growth.branch_length", "must be >= 0 (metres)");
    return 0;
}

enum { SOLVER_CPU = 0, SOLVER_GPU = 1 };

/* "solver": "cpu" (the default) or "gpu". */
static int parse_solver(const ctx *c, const cJSON *spec, int dbm, int *solver)
{
    static const char *const names[] = {"cpu", "gpu"};
    if (pick_name(c, spec, "solver", "solver", names, 2, solver))
        return -1;
#ifndef FULGUR_HOST_GPU
    if (*solver == SOLVER_GPU)
        return fail(c, "solver", "\"gpu\" needs a fulgur built with gpu/ (FULGUR_GPU=ON)");
#endif
    if (*solver == SOLVER_GPU && dbm)
        return fail(c, "solver", "\"gpu\" grows Matsuyama leaders only: DBM changes the "
                                 "field at every step, use \"cpu\"");
    return 0;
}

/* Sets the shapes, solves (on the CPU, or the GPU) and grows. */
static int run(const ctx *c, const fg_grid_config *grid, const fg_shape *shapes, size_t count,
               const fg_growth_config *growth, int dbm, int solver, fg_tree *out)
{
    fg_field *f = NULL;
    fg_result r = fg_field_create(grid, &f);
    if (r != FG_OK)
        return fail(c, "grid", "%s", fg_result_str(r));
    size_t bad = count;
    r = fg_field_set_shapes(f, shapes, count, &bad);
    if (r != FG_OK) {
        fg_field_destroy(f);
        if (bad < count) {
            char field[32];
            snprintf(field, sizeof field, "shapes[%zu]", bad);
            return fail(c, field,
                        r == FG_ERR_ARGUMENT
                            ? "covers no node of the grid (outside it?), or its size, normal "
                              "or potential is invalid"
                            : "%s",
                        fg_result_str(r));
        }
        return fail(c, "shapes",
                    "needs at least one \"origin\" and one \"target\" shape, all origins at one "
                    "potential and all targets at another");
    }
    fg_solve_report rep = {0};
#ifdef FULGUR_HOST_GPU
    if (solver == SOLVER_GPU) {
        char msg[256] = "";
        r = gen_field_gpu_grow(f, growth, out, &rep.residual, msg, sizeof msg);
        fg_field_destroy(f);
        if (r == FG_ERR_UNREACHABLE)
            return fail(c, "shapes", "the target cannot be reached from the origin");
        if (r != FG_OK)
            return fail(c, "solver", "the GPU solve or growth failed: %s (%s)",
                        fg_result_str(r), msg);
        return 0;
    }
#else
    (void)solver;
#endif
    r = fg_field_solve(f, NULL, &rep);
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
        return fail(c, "grid", "the field solve did not converge (residual %.1e)", rep.residual);
    if (r == FG_ERR_UNREACHABLE)
        return fail(c, "shapes", "the target cannot be reached from the origin");
    if (r != FG_OK)
        return fail(c, "growth", "%s", fg_result_str(r));
    return 0;
}

/* The preset's field scene on the grid "size" asks for. */
static int preset_scene(const ctx *c, fg_preset preset, const cJSON *spec, fg_field_scene *s)
{
    int size = FG_FIELD_DEFAULT_SIZE;
    if (integer(c, spec, "size", "size", FG_FIELD_MIN_SIZE, FG_FIELD_MAX_SIZE, &size))
        return -1;
    if (fg_field_scene_preset(preset, size, s) != FG_OK)
        return fail(c, "size", "must be %d..%d", FG_FIELD_MIN_SIZE, FG_FIELD_MAX_SIZE);
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
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(spec, "shapes");
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) < 2)
        return fail(c, "shapes", "is required: an array with an origin and a target shape");
    int n = cJSON_GetArraySize(list);
    if (n > FG_FIELD_MAX_SHAPES)
        return fail(c, "shapes", "at most %d shapes", FG_FIELD_MAX_SHAPES);
    for (int i = 0; i < n; i++) {
        char field[32];
        snprintf(field, sizeof field, "shapes[%d]", i);
        if (parse_shape(c, cJSON_GetArrayItem(list, i), field, &shapes[i]))
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
    fg_grid_config grid = {0};
    fg_shape shapes[FG_FIELD_MAX_SHAPES];
    size_t count;
    if (parse_field(&c, spec, &grid, shapes, &count))
        return -1;
    const cJSON *growth = cJSON_GetObjectItemCaseSensitive(spec, "growth");
    if (!cJSON_IsObject(growth) || !cJSON_GetObjectItemCaseSensitive(growth, "step"))
        return fail(&c, "growth.step", "is required: the segment length in metres");
    fg_growth_config g = {.seed = gc->seed};
    int dbm = 0, solver = SOLVER_CPU;
    if (parse_growth(&c, spec, &g, &dbm) || parse_solver(&c, spec, dbm, &solver))
        return -1;
    return run(&c, &grid, shapes, count, &g, dbm, solver, out);
}
