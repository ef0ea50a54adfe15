/* "fires": the scene's fires (docs/scene-format.md), each a position or a
 * path of timed points, and a flux series file (the flame front's flux I,
 * m^3/s, at sim_rate) or a flame simulation to run for it (scene_fire_sim.c),
 * whose sound the render computes with fg_fire_feed:
 * p = dI/dt, the 30 Hz high-pass, then bandwidth extension, texture
 * synthesis (on the project's procedural training clip) or neither. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fg_vec3.h"
#include "scene_internal.h"

static const char *const fire_keys[] = {"position", "path", "flux", "sim_rate", "extension",
                                        "alpha", "seed", "gain", "start", "air_absorption",
                                        "ring", "simulation", NULL};
static const char *const point_keys[] = {"time", "position", NULL};
static const char *const extensions[] = {"bwe", "texture", "low"};

/* Flux samples per file at most: an hour at 360 Hz. */
#define MAX_FLUX_SAMPLES (3600u * 360u)

void scene_fire_pose_at(const scene_fire *f, double t_s, fg_fire_pose *out)
{
    *out = (fg_fire_pose){.time_s = t_s};
    const scene_fire_point *p = f->path;
    size_t n = f->path_count, k = 0;
    while (k + 1 < n && p[k + 1].time_s <= t_s)
        k++;
    if (k + 1 == n || t_s < p[0].time_s) {
        memcpy(out->position, p[t_s < p[0].time_s ? 0 : k].position_m, sizeof out->position);
        return;
    }
    double dt = p[k + 1].time_s - p[k].time_s, u = (t_s - p[k].time_s) / dt;
    for (int c = 0; c < 3; c++) {
        double d = p[k + 1].position_m[c] - p[k].position_m[c];
        out->position[c] = p[k].position_m[c] + u * d;
        out->velocity[c] = d / dt;
    }
}

static int parse_path(const cJSON *item, const char *path, scene_fire *f, char *err,
                      size_t err_size)
{
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(item, "path");
    char at[JSON_PATH_MAX];
    json_path_key(at, sizeof at, path, "path");
    if (cJSON_GetObjectItemCaseSensitive(item, "position") && list)
        return json_fail(err, err_size, at, "give a position or a path, not both");
    if (!list) {
        f->path = calloc(1, sizeof *f->path);
        if (!f->path)
            return json_fail(err, err_size, path, "out of memory");
        f->path_count = 1;
        return json_vec3(item, path, "position", f->path[0].position_m, err, err_size);
    }
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) < 2)
        return json_fail(err, err_size, at, "expected an array of at least two points "
                                            "{\"time\": s, \"position\": [x, y, z]}");
    size_t n = (size_t)cJSON_GetArraySize(list);
    f->path = calloc(n, sizeof *f->path);
    if (!f->path)
        return json_fail(err, err_size, at, "out of memory");
    for (size_t i = 0; i < n; i++) {
        char pt[JSON_PATH_MAX];
        json_path_index(pt, sizeof pt, at, i);
        const cJSON *p = cJSON_GetArrayItem(list, (int)i);
        scene_fire_point *q = &f->path[i];
        q->time_s = -1.0;
        if (!cJSON_IsObject(p))
            return json_fail(err, err_size, pt, "expected {\"time\": s, \"position\": [x, y, z]}");
        if (json_check_keys(p, pt, point_keys, err, err_size) ||
            json_number(p, pt, "time", (number_range){.lo = 0, .hi = SCENE_MAX_DURATION_S}, &q->time_s, err,
                        err_size) ||
            json_vec3(p, pt, "position", q->position_m, err, err_size))
            return -1;
        if (q->time_s < 0.0)
            return json_fail(err, err_size, pt, "\"time\" is required");
        f->path_count = i + 1;
        if (i == 0)
            continue;
        double dt = q->time_s - q[-1].time_s;
        if (!(dt > 0.0))
            return json_fail(err, err_size, pt, "time %.16g s must be after the point before's "
                                                "(%.16g s)", q->time_s, q[-1].time_s);
        double speed = fg_v3_len(fg_v3_sub(fg_v3_load(q->position_m), fg_v3_load(q[-1].position_m))) / dt;
        if (speed > FG_FIRE_MAX_SPEED_M_S)
            return json_fail(err, err_size, pt, "reached at %.6g m/s, faster than %g m/s",
                             speed, FG_FIRE_MAX_SPEED_M_S);
    }
    return 0;
}

/* Reads the flux file: numbers separated by white space or commas, '#'
 * to the end of a line a comment (lines up to 4095 bytes). */
static int load_flux(const cJSON *item, const char *path, const char *dir, scene_fire *f,
                     char *err, size_t err_size)
{
    char at[JSON_PATH_MAX], file[4096];
    json_path_key(at, sizeof at, path, "flux");
    if (json_file_name(item, path, "flux", dir, "the name of a flux series file (I in m^3/s, "
                                                "one number per simulation step)",
                       file, sizeof file, err, err_size))
        return -1;
    FILE *in = fopen(file, "r");
    if (!in)
        return json_fail(err, err_size, at, "%s: cannot read it (missing or unreadable)", file);
    size_t cap = 0, line = 0;
    int rc = 0;
    char buf[4096];
    while (rc == 0 && fgets(buf, sizeof buf, in)) {
        line++;
        char *hash = strchr(buf, '#');
        if (hash)
            *hash = '\0';
        for (char *c = buf; *c && rc == 0;) {
            if (*c == ' ' || *c == '\t' || *c == '\r' || *c == '\n' || *c == ',') {
                c++;
                continue;
            }
            char *end;
            double v = strtod(c, &end);
            if (end == c || !isfinite(v) || fabs(v) > FG_FIRE_MAX_FLUX_M3_S) {
                rc = json_fail(err, err_size, at, "%s line %zu: %s", file, line,
                               end == c ? "not a number"
                                        : "a flux beyond +-1e12 m^3/s, or not finite");
                break;
            }
            if (f->flux_count == MAX_FLUX_SAMPLES) {
                rc = json_fail(err, err_size, at, "%s: more than %u samples", file,
                               MAX_FLUX_SAMPLES);
                break;
            }
            if (f->flux_count == cap) {
                cap = cap ? 2 * cap : 1024;
                double *grown = realloc(f->flux_m3_s, cap * sizeof *grown);
                if (!grown) {
                    rc = json_fail(err, err_size, at, "out of memory");
                    break;
                }
                f->flux_m3_s = grown;
            }
            f->flux_m3_s[f->flux_count++] = v;
            c = end;
        }
    }
    if (rc == 0 && ferror(in))
        rc = json_fail(err, err_size, at, "%s: read error", file);
    fclose(in);
    if (rc == 0 && f->flux_count < 4)
        rc = json_fail(err, err_size, at, "%s: %zu samples; at least 4 are needed", file,
                       f->flux_count);
    return rc;
}

static int parse_fire(const cJSON *item, const char *path, const char *dir, const scene *s,
                      scene_fire *f, char *err, size_t err_size)
{
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, path, "expected an object");
    if (json_check_keys(item, path, fire_keys, err, err_size) ||
        parse_path(item, path, f, err, err_size))
        return -1;
    int ext = 0;
    double sim = 360.0, alpha = 3.0, seed = 0, gain = 1.0, start = 0.0, ring = 0.0;
    bool air = false;
    if (json_name(item, path, "extension", extensions, 3, &ext, err, err_size) ||
        json_number(item, path, "sim_rate", (number_range){.lo = 10, .hi = s->sample_rate_hz / 4}, &sim, err,
                    err_size) ||
        json_number(item, path, "alpha", (number_range){.lo = 0.5, .hi = 6}, &alpha, err, err_size) ||
        json_number(item, path, "seed", SCENE_SEED_RANGE, &seed, err, err_size) ||
        json_number(item, path, "gain", (number_range){.lo = 0, .hi = 1e9, .lo_open = true}, &gain, err,
                    err_size) ||
        json_number(item, path, "start", (number_range){.lo = 0, .hi = SCENE_MAX_DURATION_S}, &start, err,
                    err_size) ||
        json_number(item, path, "ring", (number_range){.lo = FG_FIRE_RING_MIN_S, .hi = FG_FIRE_RING_MAX_S},
                    &ring, err, err_size) ||
        json_bool(item, path, "air_absorption", &air, err, err_size))
        return -1;
    bool simulated = cJSON_GetObjectItemCaseSensitive(item, "simulation") != NULL;
    if (simulated && cJSON_GetObjectItemCaseSensitive(item, "flux"))
        return json_fail(err, err_size, path, "give a \"flux\" file or a \"simulation\", not both");
    if (simulated ? scene_fire_simulate(item, path, sim, f, err, err_size)
                  : load_flux(item, path, dir, f, err, err_size))
        return -1;
    f->sound = (fg_fire_sound_config){
        .sample_rate_hz = s->sample_rate_hz,
        .sim_rate_hz = sim,
        .extension = ext == 0 ? FG_FIRE_BANDWIDTH_EXTENSION : ext == 1 ? FG_FIRE_TEXTURE
                                                                       : FG_FIRE_LOW_ONLY,
        .bwe = {.alpha = alpha, .seed = (uint64_t)seed},
    };
    f->post = (fg_fire_voice){.gain = gain, .emit_time_s = start, .ring_s = ring,
                              .absorption = air ? FG_ABSORPTION_ISO9613 : FG_ABSORPTION_OFF};
    scene_fire_pose_at(f, start, &f->post.pose);
    if (f->post.pose.time_s == 0.0)
        f->post.pose.time_s = 1e-9; /* 0 would mean "now" to the engine */
    return 0;
}

int scene_parse_fires(const cJSON *json, const char *dir, scene *s, char *err, size_t err_size)
{
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(json, "fires");
    if (!list)
        return 0;
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) == 0)
        return json_fail(err, err_size, "fires", "expected a non-empty array");
    size_t n = (size_t)cJSON_GetArraySize(list);
    if (n > FG_FIRE_VOICE_MAX)
        return json_fail(err, err_size, "fires", "%zu fires; at most %u", n, FG_FIRE_VOICE_MAX);
    s->fires = calloc(n, sizeof *s->fires);
    if (!s->fires)
        return json_fail(err, err_size, "fires", "out of memory");
    s->fire_count = n;
    for (size_t i = 0; i < n; i++) {
        char path[JSON_PATH_MAX];
        json_path_index(path, sizeof path, "fires", i);
        if (parse_fire(cJSON_GetArrayItem(list, (int)i), path, dir, s, &s->fires[i], err,
                       err_size))
            return -1;
    }
    return 0;
}

void scene_fire_free(scene *s)
{
    for (size_t i = 0; i < s->fire_count; i++) {
        free(s->fires[i].path);
        free(s->fires[i].flux_m3_s);
    }
    free(s->fires);
    s->fires = NULL;
    s->fire_count = 0;
}
