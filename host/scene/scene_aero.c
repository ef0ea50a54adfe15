/* "aero_objects" and "wind": the scene's aerodynamic objects
 * (docs/scene-format.md), each a texture file, a body and a motion: fixed
 * (wind mode), a swing about a pivot with a smooth angular speed profile,
 * or a throw (a ballistic arc, spinning). The motion is the scene's
 * function of time; scene_render samples it as a frame loop would. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/aero_texture_file.h"
#include "scene_internal.h"
#include "fg_math.h"
#include "fg_vec3.h"

static const char *const object_keys[] = {"texture", "body", "start", "end", "sources", "gain",
                                          "emit_time", "duration", "air_absorption", "motion",
                                          NULL};
static const char *const wind_keys[] = {"velocity", "gust", "gust_period", "seed", NULL};
static const char *const motion_types[] = {"fixed", "swing", "throw"};
static const char *const motion_keys[][10] = {
    {"type", "position", "axis", "normal", NULL},
    {"type", "pivot", "axis", "normal", "turn_axis", "peak_speed", "start", "duration", NULL},
    {"type", "position", "axis", "normal", "turn_axis", "velocity", "spin", "start", "gravity",
     NULL},
};
static const char *const bodies[] = {"stick", "compact"};

#define DEFAULT_GRAVITY_M_S2 9.80665

static fg_vec3 rotate(fg_vec3 v, fg_vec3 k, double angle)
{
    double c = cos(angle), s = sin(angle);
    return fg_v3_add(fg_v3_add(fg_v3_scale(v, c), fg_v3_scale(fg_v3_cross(k, v), s)),
                     fg_v3_scale(k, fg_v3_dot(k, v) * (1.0 - c)));
}

/* The swing's angle at t: the speed peak * sin^2(pi u / T) over its
 * duration T from its start, integrated; 0 before, held after. */
static double swing_angle(const scene_motion *m, double t_s)
{
    double u = fmin(fmax(t_s - m->start_s, 0.0), m->duration_s), T = m->duration_s;
    return m->peak_rad_s * (0.5 * u - T / (4.0 * FG_PI) * sin(2.0 * FG_PI * u / T));
}

/* Its rate, rad/s: the speed peak * sin^2(pi u / T) during the swing. */
static double swing_rate(const scene_motion *m, double t_s)
{
    double u = t_s - m->start_s, s = sin(FG_PI * u / m->duration_s);
    return u > 0.0 && u < m->duration_s ? m->peak_rad_s * s * s : 0.0;
}

void scene_aero_pose_at(const scene_aero *a, double t_s, fg_aero_pose *out)
{
    const scene_motion *m = &a->motion;
    fg_vec3 axis = fg_v3_load(m->axis), normal = fg_v3_load(m->normal);
    fg_vec3 k = fg_v3_load(m->turn_axis);
    *out = (fg_aero_pose){.time_s = t_s, .velocity_given = 1};
    memcpy(out->position, m->position_m, sizeof out->position);
    double angle = 0.0, rate = 0.0;
    if (m->kind == SCENE_MOTION_SWING) {
        angle = swing_angle(m, t_s);
        rate = swing_rate(m, t_s);
    } else if (m->kind == SCENE_MOTION_THROW) {
        double u = fmax(t_s - m->start_s, 0.0);
        angle = m->spin_rad_s * u;
        rate = t_s > m->start_s ? m->spin_rad_s : 0.0;
        for (int c = 0; c < 3; c++) {
            double g = c == 2 ? -m->gravity_m_s2 : 0.0;
            out->position[c] = m->position_m[c] + m->velocity_m_s[c] * u + 0.5 * g * u * u;
            out->velocity[c] = t_s > m->start_s ? m->velocity_m_s[c] + g * u : 0.0;
        }
    }
    fg_v3_store(rotate(axis, k, angle), out->axis);
    fg_v3_store(rotate(normal, k, angle), out->normal);
    fg_v3_store(fg_v3_scale(k, rate), out->angular_velocity);
}

fg_result scene_aero_post_all(const scene *s, fg_engine *e, fg_voice_id *ids, char *err,
                              size_t err_size)
{
    for (size_t i = 0; i < s->aero_count; i++) {
        fg_result r = fg_aero_object_post(e, &s->aeros[i].post, &ids[i]);
        if (r != FG_OK) {
            snprintf(err, err_size, "aero_objects[%zu]: the engine refused it: %s", i,
                     fg_result_str(r));
            return r;
        }
    }
    return FG_OK;
}

fg_result scene_aero_publish_pose(const scene *s, size_t i, fg_engine *e, fg_voice_id id,
                                  double t_s, bool *done, char *err, size_t err_size)
{
    fg_aero_pose pose;
    scene_aero_pose_at(&s->aeros[i], t_s, &pose);
    fg_result r = fg_aero_object_set_pose(e, id, &pose);
    if (r == FG_ERR_NOT_FOUND) {
        *done = true; /* finished and collected */
        return FG_OK;
    }
    if (r != FG_OK)
        snprintf(err, err_size, "aero_objects[%zu]: its pose at %.6f s: %s (faster than %g m/s?)",
                 i, t_s, fg_result_str(r), FG_AERO_MAX_SPEED_M_S);
    return r;
}

static int unit_or_fail(const cJSON *obj, const char *path, const char *key, double v[3],
                        char *err, size_t err_size)
{
    if (json_vec3(obj, path, key, v, err, err_size))
        return -1;
    double len = fg_v3_len(fg_v3_load(v));
    if (!(len > 0.0)) {
        char at[JSON_PATH_MAX];
        json_path_key(at, sizeof at, path, key);
        return json_fail(err, err_size, at, "must have a non-zero length");
    }
    for (int c = 0; c < 3; c++)
        v[c] /= len;
    return 0;
}

static int parse_motion(const cJSON *item, const char *path, scene_motion *m, char *err,
                        size_t err_size)
{
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, path, "required: an object with a \"type\" "
                                              "(fixed, swing or throw)");
    int type = -1;
    if (json_name(item, path, "type", motion_types, 3, &type, err, err_size))
        return -1;
    if (type < 0)
        return json_fail(err, err_size, path, "\"type\" is required (fixed, swing or throw)");
    if (json_check_keys(item, path, motion_keys[type], err, err_size))
        return -1;
    m->kind = (scene_motion_kind)type;
    m->axis[2] = 1.0;
    m->normal[0] = 1.0;
    m->turn_axis[2] = 1.0;
    m->gravity_m_s2 = DEFAULT_GRAVITY_M_S2;
    m->duration_s = 1.0;
    const number_range speed = {.lo = 0, .hi = 1e4}, time = {.lo = 0, .hi = SCENE_MAX_DURATION_S};
    if (json_vec3(item, path, type == SCENE_MOTION_SWING ? "pivot" : "position", m->position_m,
                  err, err_size) ||
        unit_or_fail(item, path, "axis", m->axis, err, err_size) ||
        unit_or_fail(item, path, "normal", m->normal, err, err_size) ||
        unit_or_fail(item, path, "turn_axis", m->turn_axis, err, err_size) ||
        json_number(item, path, "peak_speed", speed, &m->peak_rad_s, err, err_size) ||
        json_number(item, path, "start", time, &m->start_s, err, err_size) ||
        json_number(item, path, "duration", (number_range){0, SCENE_MAX_DURATION_S, .lo_open = true},
                    &m->duration_s, err, err_size) ||
        json_vec3(item, path, "velocity", m->velocity_m_s, err, err_size) ||
        json_number(item, path, "spin", (number_range){.lo = -1e4, .hi = 1e4}, &m->spin_rad_s, err,
                    err_size) ||
        json_number(item, path, "gravity", (number_range){.lo = 0, .hi = 100}, &m->gravity_m_s2, err,
                    err_size))
        return -1;
    if (fg_v3_len(fg_v3_load(m->velocity_m_s)) > FG_AERO_MAX_SPEED_M_S) {
        char at[JSON_PATH_MAX];
        json_path_key(at, sizeof at, path, "velocity");
        return json_fail(err, err_size, at, "faster than %g m/s (the texture's compact, "
                                            "incompressible model)", FG_AERO_MAX_SPEED_M_S);
    }
    if (fabs(fg_v3_dot(fg_v3_load(m->axis), fg_v3_load(m->normal))) > 1.0 - 1e-9) {
        char at[JSON_PATH_MAX];
        json_path_key(at, sizeof at, path, "normal");
        return json_fail(err, err_size, at, "is parallel to axis");
    }
    return 0;
}

/* The texture file named at path, relative to dir unless absolute. */
static int load_texture(const cJSON *obj, const char *path, const char *dir,
                        fg_aero_texture **out, char *err, size_t err_size)
{
    char at[JSON_PATH_MAX], file[4096];
    json_path_key(at, sizeof at, path, "texture");
    if (json_file_name(obj, path, "texture", dir, "the name of a texture file (fulgur aerotex -o FILE)",
                       file, sizeof file, err, err_size))
        return -1;
    char why[512];
    if (aero_texture_load(file, out, why, sizeof why) != 0)
        return json_fail(err, err_size, at, "%s", why);
    return 0;
}

static int parse_object(const cJSON *item, const char *path, const char *dir, scene_aero *a,
                        char *err, size_t err_size)
{
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, path, "expected an object");
    if (json_check_keys(item, path, object_keys, err, err_size))
        return -1;
    int body = 0;
    double sources = 0, gain = 1, emit = 0, duration = 0;
    bool air = false;
    fg_aero_object *o = &a->post;
    if (json_name(item, path, "body", bodies, 2, &body, err, err_size) ||
        json_number(item, path, "start", (number_range){.lo = -1e3, .hi = 1e3}, &o->start_m, err, err_size) ||
        json_number(item, path, "end", (number_range){.lo = -1e3, .hi = 1e3}, &o->end_m, err, err_size) ||
        json_number(item, path, "sources",
                    (number_range){0, FG_AERO_OBJECT_MAX_SOURCES, .integer = true}, &sources, err,
                    err_size) ||
        json_number(item, path, "gain", (number_range){0, 1e9, .lo_open = true}, &gain, err,
                    err_size) ||
        json_number(item, path, "emit_time", (number_range){.lo = 0, .hi = SCENE_MAX_DURATION_S}, &emit, err,
                    err_size) ||
        json_number(item, path, "duration", (number_range){.lo = 0, .hi = SCENE_MAX_DURATION_S}, &duration,
                    err, err_size) ||
        json_bool(item, path, "air_absorption", &air, err, err_size))
        return -1;
    char at[JSON_PATH_MAX];
    json_path_key(at, sizeof at, path, "motion");
    if (parse_motion(cJSON_GetObjectItemCaseSensitive(item, "motion"), at, &a->motion, err,
                     err_size))
        return -1;
    if (body == FG_AERO_STICK && !(o->end_m > o->start_m)) {
        json_path_key(at, sizeof at, path, "end");
        return json_fail(err, err_size, at, "%.16g m must be above start (%.16g m): a stick "
                                            "needs a length", o->end_m, o->start_m);
    }
    if (load_texture(item, path, dir, &a->texture, err, err_size))
        return -1;
    const fg_aero_texture_desc *t = fg_aero_texture_get(a->texture);
    if ((body == FG_AERO_STICK) != (t->dims == 2)) {
        json_path_key(at, sizeof at, path, "texture");
        json_fail(err, err_size, at, "a %u-D texture, but the body is a %s (a stick takes a 2-D "
                                     "cross-section, a compact body a 3-D one)", t->dims,
                  bodies[body]);
        fg_aero_texture_destroy(a->texture);
        a->texture = NULL;
        return -1;
    }
    o->texture = a->texture;
    o->body = (fg_aero_body)body;
    o->sources = (uint32_t)sources;
    o->gain = gain;
    o->emit_time_s = emit;
    o->duration_s = duration;
    o->absorption = air ? FG_ABSORPTION_ISO9613 : FG_ABSORPTION_OFF;
    scene_aero_pose_at(a, emit, &o->pose);
    return 0;
}

int scene_parse_aero(const cJSON *json, const char *dir, scene *s, char *err, size_t err_size)
{
    const cJSON *wind = cJSON_GetObjectItemCaseSensitive(json, "wind");
    fg_aero_wind w = {0};
    if (wind) {
        double seed = 0;
        if (json_check_keys(wind, "wind", wind_keys, err, err_size) ||
            json_vec3(wind, "wind", "velocity", w.velocity, err, err_size) ||
            json_number(wind, "wind", "gust", (number_range){.lo = 0, .hi = 1}, &w.gust, err, err_size) ||
            json_number(wind, "wind", "gust_period", (number_range){.lo = 0.05, .hi = 600}, &w.gust_period_s,
                        err, err_size) ||
            json_number(wind, "wind", "seed", SCENE_SEED_RANGE, &seed, err, err_size))
            return -1;
        if (fg_v3_len(fg_v3_load(w.velocity)) > FG_AERO_MAX_SPEED_M_S)
            return json_fail(err, err_size, "wind.velocity", "faster than %g m/s",
                             FG_AERO_MAX_SPEED_M_S);
        w.seed = (uint64_t)seed;
    }
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(json, "aero_objects");
    if (!list)
        return 0;
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) == 0)
        return json_fail(err, err_size, "aero_objects", "expected a non-empty array");
    size_t n = (size_t)cJSON_GetArraySize(list);
    s->aeros = calloc(n, sizeof *s->aeros);
    if (!s->aeros)
        return json_fail(err, err_size, "aero_objects", "out of memory");
    s->aero_count = n;
    for (size_t i = 0; i < n; i++) {
        char path[JSON_PATH_MAX];
        json_path_index(path, sizeof path, "aero_objects", i);
        s->aeros[i].post.wind = w;
        if (parse_object(cJSON_GetArrayItem(list, (int)i), path, dir, &s->aeros[i], err,
                         err_size))
            return -1;
    }
    return 0;
}

void scene_aero_free(scene *s)
{
    for (size_t i = 0; i < s->aero_count; i++)
        fg_aero_texture_destroy(s->aeros[i].texture);
    free(s->aeros);
    s->aeros = NULL;
    s->aero_count = 0;
}
