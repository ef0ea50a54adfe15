/* The listener: one fixed pose, or a path of timed poses interpolated in
 * time (linear positions, normalised-lerp directions, held at the ends). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene_internal.h"
#include "fg_math.h"
#include "fg_vec3.h"

static const char *const pose_keys[] = {"position", "forward", "up", NULL};
static const char *const only_path[] = {"path", NULL};
static const char *const path_pose_keys[] = {"time", "position", "forward", "up", NULL};

static double dot(const double a[3], const double b[3])
{
    return fg_v3_dot(fg_v3_load(a), fg_v3_load(b));
}

static void normalise(const double v[3], double out[3])
{
    fg_vec3 a = fg_v3_load(v);
    fg_v3_store(fg_v3_div(a, fg_v3_len(a)), out);
}

/* Cosine of the angle between two non-zero vectors. */
static double cosine(const double a[3], const double b[3])
{
    double ua[3], ub[3];
    normalise(a, ua);
    normalise(b, ub);
    return dot(ua, ub);
}

/* The least sine of the angle between forward and up a pose may have:
 * twice the engine's (fg_engine_set_listener refuses below 1e-3, about
 * 0.06 degrees), so that every pose the render publishes is accepted. */
#define MIN_UP_SINE 2e-3

/* Sine of the angle between two non-zero vectors. */
static double sine(const double a[3], const double b[3])
{
    fg_vec3 ua = fg_v3_load(a), ub = fg_v3_load(b);
    ua = fg_v3_div(ua, fg_v3_len(ua));
    ub = fg_v3_div(ub, fg_v3_len(ub));
    return fg_v3_len(fg_v3_cross(ua, ub));
}

/* Reads position/forward/up of one pose and checks the directions. */
static int parse_pose(const cJSON *obj, const char *path, scene_pose *p, char *err,
                      size_t err_size)
{
    char key[JSON_PATH_MAX];
    if (json_vec3(obj, path, "position", p->position_m, err, err_size) ||
        json_vec3(obj, path, "forward", p->forward, err, err_size) ||
        json_vec3(obj, path, "up", p->up, err, err_size))
        return -1;
    if (dot(p->forward, p->forward) == 0 || !isfinite(dot(p->forward, p->forward))) {
        json_path_key(key, sizeof key, path, "forward");
        return json_fail(err, err_size, key, "must have a finite, non-zero length");
    }
    if (dot(p->up, p->up) == 0 || !isfinite(dot(p->up, p->up))) {
        json_path_key(key, sizeof key, path, "up");
        return json_fail(err, err_size, key, "must have a finite, non-zero length");
    }
    if (sine(p->forward, p->up) < MIN_UP_SINE) {
        json_path_key(key, sizeof key, path, "up");
        return json_fail(err, err_size, key, "is parallel to forward");
    }
    return 0;
}

static const scene_pose default_pose = {
    .position_m = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};

/* A direction may not reverse between two poses: its lerp would pass
 * through zero. */
static int check_turn(const double prev[3], const double next[3], const char *path,
                      const char *key, char *err, size_t err_size)
{
    if (cosine(prev, next) > -1 + 1e-9)
        return 0;
    char full[JSON_PATH_MAX];
    json_path_key(full, sizeof full, path, key);
    return json_fail(err, err_size, full,
                     "opposite to the previous pose's; add a pose in between");
}

static void lerp(const double a[3], const double b[3], double u, double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] + u * (b[k] - a[k]);
}

/* Forward and up (not normalised) at fraction u of the way from pose a to
 * pose b: the lerp of the unit directions. */
static void directions_between(const scene_pose *a, const scene_pose *b, double u,
                               double forward[3], double up[3])
{
    double fa[3], fb[3], ua[3], ub[3];
    normalise(a->forward, fa);
    normalise(b->forward, fb);
    normalise(a->up, ua);
    normalise(b->up, ub);
    lerp(fa, fb, u, forward);
    lerp(ua, ub, u, up);
}

/* The sine between forward and up at fraction u of the way from a to b. */
static double sine_between(const scene_pose *a, const scene_pose *b, double u)
{
    double f[3], up[3];
    directions_between(a, b, u, f, up);
    return sine(f, up);
}

/* Forward and up may not come near parallel anywhere between two poses
 * (each pose alone is checked): the render publishes poses at times that
 * depend on its block size, and one that fell where they are parallel was
 * refused mid-render (block 256 failed at 0.5 s, block 24000 did not). The
 * sine is smooth in u: the least of 256 samples, refined by a ternary
 * search between its neighbours, finds its minimum. */
#define TURN_SAMPLES 256

static int check_between(const scene_pose *a, const scene_pose *b, const char *path, char *err,
                         size_t err_size)
{
    int best = 0;
    double least = INFINITY;
    for (int i = 0; i <= TURN_SAMPLES; i++) {
        double v = sine_between(a, b, (double)i / TURN_SAMPLES);
        if (v < least) {
            least = v;
            best = i;
        }
    }
    double lo = fmax(0, (best - 1.0) / TURN_SAMPLES), hi = fmin(1, (best + 1.0) / TURN_SAMPLES);
    for (int k = 0; k < 60; k++) {
        double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (sine_between(a, b, m1) < sine_between(a, b, m2))
            hi = m2;
        else
            lo = m1;
    }
    double u = 0.5 * (lo + hi);
    least = fmin(least, sine_between(a, b, u));
    if (least >= MIN_UP_SINE)
        return 0;
    char key[JSON_PATH_MAX];
    json_path_key(key, sizeof key, path, "up");
    return json_fail(err, err_size, key,
                     "forward and up come within %.2f degrees of parallel at %.6g s, between "
                     "the previous pose and this one; add a pose in between",
                     asin(fmin(least, 1.0)) * 180 / FG_PI,
                     a->time_s + u * (b->time_s - a->time_s));
}

static int parse_path(const cJSON *list, scene *s, char *err, size_t err_size)
{
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) == 0)
        return json_fail(err, err_size, "listener.path", "expected a non-empty array of poses");
    size_t n = (size_t)cJSON_GetArraySize(list);
    scene_pose *poses = calloc(n, sizeof *poses);
    if (!poses)
        return json_fail(err, err_size, "listener.path", "out of memory");
    char path[JSON_PATH_MAX], key[JSON_PATH_MAX];
    size_t i = 0;
    for (const cJSON *item = list->child; item; item = item->next, i++) {
        json_path_index(path, sizeof path, "listener.path", i);
        poses[i] = default_pose;
        poses[i].time_s = -1;
        if (json_check_keys(item, path, path_pose_keys, err, err_size) ||
            json_number(item, path, "time", (number_range){.lo = 0, .hi = SCENE_MAX_DURATION_S},
                        &poses[i].time_s, err, err_size) ||
            parse_pose(item, path, &poses[i], err, err_size))
            goto fail;
        json_path_key(key, sizeof key, path, "time");
        if (poses[i].time_s < 0) {
            json_fail(err, err_size, key, "required (seconds)");
            goto fail;
        }
        if (!cJSON_GetObjectItemCaseSensitive(item, "position")) {
            json_path_key(key, sizeof key, path, "position");
            json_fail(err, err_size, key, "required ([x, y, z] in metres)");
            goto fail;
        }
        if (i == 0)
            continue;
        if (poses[i].time_s <= poses[i - 1].time_s) {
            json_fail(err, err_size, key, "%.16g s is not after the previous pose's %.16g s",
                      poses[i].time_s, poses[i - 1].time_s);
            goto fail;
        }
        if (check_turn(poses[i - 1].forward, poses[i].forward, path, "forward", err, err_size) ||
            check_turn(poses[i - 1].up, poses[i].up, path, "up", err, err_size) ||
            check_between(&poses[i - 1], &poses[i], path, err, err_size))
            goto fail;
    }
    s->poses = poses;
    s->pose_count = n;
    return 0;
fail:
    free(poses);
    return -1;
}

int scene_parse_listener(const cJSON *item, scene *s, char *err, size_t err_size)
{
    if (item && cJSON_IsObject(item) && cJSON_GetObjectItemCaseSensitive(item, "path")) {
        for (int k = 0; pose_keys[k]; k++)
            if (cJSON_GetObjectItemCaseSensitive(item, pose_keys[k]))
                return json_fail(err, err_size, "listener",
                                 "give either \"path\" or position/forward/up, not both");
        if (json_check_keys(item, "listener", only_path, err, err_size))
            return -1;
        return parse_path(cJSON_GetObjectItemCaseSensitive(item, "path"), s, err, err_size);
    }
    scene_pose pose = default_pose;
    if (item && (json_check_keys(item, "listener", pose_keys, err, err_size) ||
                 parse_pose(item, "listener", &pose, err, err_size)))
        return -1;
    s->poses = malloc(sizeof *s->poses);
    if (!s->poses)
        return json_fail(err, err_size, "listener", "out of memory");
    *s->poses = pose;
    s->pose_count = 1;
    return 0;
}

void scene_listener_at(const scene *s, double t_s, fg_listener *out)
{
    const scene_pose *p = s->poses;
    memset(out, 0, sizeof *out);
    /* the last pose at or before t (the first when t is earlier) */
    size_t lo = 0, hi = s->pose_count;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (p[mid].time_s <= t_s)
            lo = mid;
        else
            hi = mid;
    }
    if (lo + 1 == s->pose_count || t_s <= p[lo].time_s) {
        memcpy(out->position, p[lo].position_m, sizeof out->position);
        normalise(p[lo].forward, out->forward);
        normalise(p[lo].up, out->up);
        return;
    }
    const scene_pose *a = &p[lo], *b = &p[lo + 1];
    double span = b->time_s - a->time_s, u = (t_s - a->time_s) / span;
    double f[3], up[3];
    directions_between(a, b, u, f, up);
    lerp(a->position_m, b->position_m, u, out->position);
    normalise(f, out->forward);
    normalise(up, out->up);
    for (int k = 0; k < 3; k++)
        out->velocity[k] = (b->position_m[k] - a->position_m[k]) / span;
}
