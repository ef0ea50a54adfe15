/* Scene generators "lightning" and "charges": JSON to the engine's
 * fg_lightning_config / fg_charges_config, every error naming its path. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fulgur/charges.h"
#include "fulgur/lightning.h"
#include "generator.h"
#include "json_read.h"
#include "fg_math.h"

static const number_range positive = {0, 1e7, true, false, false};
static const number_range non_negative = {0, 1e7, false, false, false};
static const number_range fraction = {0, 1, false, false, false};
static const double deg = FG_PI / 180.0;

static int count_range(const cJSON *obj, const char *base, const char *key, double lo, double hi,
                       uint32_t *out, char *err, size_t err_size)
{
    double v = *out;
    if (json_number(obj, base, key, (number_range){lo, hi, false, false, true}, &v, err, err_size))
        return -1;
    *out = (uint32_t)v;
    return 0;
}

/* "skeleton": [[x, y, z], ...], root first; *out is malloc'd (caller frees). */
static int parse_skeleton(const cJSON *item, const char *path, double **out, size_t *count,
                          char *err, size_t err_size)
{
    int n = cJSON_GetArraySize(item);
    if (!cJSON_IsArray(item) || n < 2 || n > FG_LIGHTNING_MAX_SKELETON)
        return json_fail(err, err_size, path, "expected an array of 2 to %d points [x, y, z]",
                         FG_LIGHTNING_MAX_SKELETON);
    double *k = malloc((size_t)n * 3 * sizeof *k);
    if (!k)
        return json_fail(err, err_size, path, "out of memory");
    char at[JSON_PATH_MAX];
    int i = 0;
    for (const cJSON *c = item->child; c; c = c->next, i++) {
        json_path_index(at, sizeof at, path, (size_t)i);
        int bad = !cJSON_IsArray(c) || cJSON_GetArraySize(c) != 3;
        for (int j = 0; j < 3 && !bad; j++) {
            const cJSON *v = cJSON_GetArrayItem(c, j);
            bad = !cJSON_IsNumber(v) || !isfinite(v->valuedouble);
            if (!bad)
                k[3 * i + j] = v->valuedouble;
        }
        const char *why = bad                                 ? "expected [x, y, z], finite"
                          : k[3 * i + 2] < 0                  ? "below the ground (z < 0)"
                          : i == 0 && k[2] == 0               ? "the root must be above the ground"
                          : i > 0 && !memcmp(&k[3 * i], &k[3 * i - 3], 3 * sizeof *k)
                              ? "repeats the point before it"
                              : NULL;
        if (why) {
            free(k);
            return json_fail(err, err_size, at, "%s", why);
        }
    }
    *out = k;
    *count = (size_t)n;
    return 0;
}

static int parse_feature(const cJSON *item, const char *path, fg_thunder_feature *b, char *err,
                       size_t err_size)
{
    static const char *const keys[] = {"feature", "start", "end", "amplitude", NULL};
    static const char *const names[] = {"clap", "rumble", "roar"};
    if (json_check_keys(item, path, keys, err, err_size))
        return -1;
    char key[JSON_PATH_MAX];
    json_path_key(key, sizeof key, path, "feature");
    const cJSON *f = cJSON_GetObjectItemCaseSensitive(item, "feature");
    b->kind = 0;
    for (int i = 0; i < 3 && cJSON_IsString(f); i++)
        if (strcmp(f->valuestring, names[i]) == 0)
            b->kind = (fg_thunder_kind)(FG_THUNDER_CLAP + i);
    if (!b->kind)
        return json_fail(err, err_size, key, "required: \"clap\", \"rumble\" or \"roar\"");
    b->start = NAN, b->end = NAN, b->amplitude = 1;
    if (json_number(item, path, "start", fraction, &b->start, err, err_size) ||
        json_number(item, path, "end", fraction, &b->end, err, err_size) ||
        json_number(item, path, "amplitude", (number_range){0, 1, true, false, false},
                    &b->amplitude, err, err_size))
        return -1;
    if (isnan(b->start) || isnan(b->end))
        return json_fail(err, err_size, path, "\"start\" and \"end\" are required");
    if (b->start >= b->end)
        return json_fail(err, err_size, path, "start %g is not before end %g", b->start, b->end);
    if (b->kind != FG_THUNDER_ROAR && b->end == 1)
        return json_fail(err, err_size, path,
                         "a %s must end before 1: the channel needs a stretch to reach the ground",
                         names[b->kind - 1]);
    return 0;
}

static int parse_design(const cJSON *item, const char *path, fg_thunder_feature *features,
                        size_t *count, char *err, size_t err_size)
{
    int n = cJSON_GetArraySize(item);
    if (!cJSON_IsArray(item) || n > FG_THUNDER_MAX_FEATURES)
        return json_fail(err, err_size, path, "expected an array of at most %d features",
                         FG_THUNDER_MAX_FEATURES);
    char at[JSON_PATH_MAX];
    size_t i = 0;
    for (const cJSON *c = item->child; c; c = c->next, i++) {
        json_path_index(at, sizeof at, path, i);
        if (parse_feature(c, at, &features[i], err, err_size))
            return -1;
        for (size_t j = 0; j < i; j++)
            if (features[i].start < features[j].end && features[j].start < features[i].end)
                return json_fail(err, err_size, at, "overlaps %s[%zu]", path, j);
    }
    *count = i;
    return 0;
}

/* The horizontal point "distance" metres from the listener toward
 * "azimuth_deg" (counter-clockwise from +x). */
static int placement(const cJSON *spec, const char *path, const gen_context *ctx,
                     double strike[2], int *placed, char *err, size_t err_size)
{
    double distance = -1, azimuth = 0;
    if (json_number(spec, path, "distance", non_negative, &distance, err, err_size) ||
        json_number(spec, path, "azimuth_deg", (number_range){-360, 360, false, false, false},
                    &azimuth, err, err_size))
        return -1;
    *placed = distance >= 0;
    if (*placed) {
        strike[0] = ctx->listener_m[0] + distance * cos(azimuth * deg);
        strike[1] = ctx->listener_m[1] + distance * sin(azimuth * deg);
    }
    return 0;
}

static int engine_fail(fg_result r, const char *path, char *err, size_t err_size)
{
    const char *why = r == FG_ERR_ARGUMENT
                          ? "the design cannot be built above the ground (a clap arc longer "
                            "than half its circle, or a shape below z = 0)"
                          : r == FG_ERR_UNREACHABLE ? "the walk did not reach the ground"
                          : r == FG_ERR_CAPACITY    ? "more nodes than max_nodes"
                                                    : fg_result_str(r);
    return json_fail(err, err_size, path, "%s", why);
}

int gen_lightning(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
                  char *err, size_t err_size)
{
    static const char *const keys[] = {
        "type",     "skeleton",      "strike",          "distance",          "azimuth_deg",
        "height",   "segment",       "turn_mean_deg",   "max_deviation_deg", "lookahead",
        "branch_probability",        "branch_length",   "branch_depth",      "design",
        "max_nodes", "in_cloud",     "in_cloud_azimuth_deg",                 NULL};
    if (json_check_keys(spec, path, keys, err, err_size))
        return -1;
    fg_lightning_config p = {.seed = ctx->seed};
    memcpy(p.listener_m, ctx->listener_m, sizeof p.listener_m);
    double branch_p = -2;
    int placed;
    if (json_vector(spec, path, "strike", 2, p.strike_m, err, err_size) ||
        placement(spec, path, ctx, p.strike_m, &placed, err, err_size) ||
        json_number(spec, path, "height", positive, &p.height_m, err, err_size) ||
        json_number(spec, path, "in_cloud", (number_range){0, 20000, false, false, false},
                    &p.in_cloud_m, err, err_size) ||
        json_number(spec, path, "in_cloud_azimuth_deg",
                    (number_range){-360, 360, false, false, false}, &p.in_cloud_azimuth_deg, err,
                    err_size) ||
        json_number(spec, path, "segment", positive, &p.segment_m, err, err_size) ||
        json_number(spec, path, "turn_mean_deg", (number_range){0, 90, true, true, false},
                    &p.turn_mean_deg, err, err_size) ||
        json_number(spec, path, "max_deviation_deg", (number_range){0, 180, true, true, false},
                    &p.max_deviation_deg, err, err_size) ||
        json_number(spec, path, "lookahead", positive, &p.lookahead_m, err, err_size) ||
        json_number(spec, path, "branch_probability", fraction, &branch_p, err, err_size) ||
        json_number(spec, path, "branch_length", positive, &p.branch_length_m, err, err_size) ||
        count_range(spec, path, "branch_depth", 1, 8, &p.branch_depth, err, err_size) ||
        count_range(spec, path, "max_nodes", 2, 1e8, &p.max_nodes, err, err_size))
        return -1;
    if (branch_p != -2) /* JSON 0 is "no branches"; the engine's 0 is "default" */
        p.branch_probability = branch_p > 0 ? branch_p : -1;
    if (placed && cJSON_GetObjectItemCaseSensitive(spec, "strike")) {
        char key[JSON_PATH_MAX];
        json_path_key(key, sizeof key, path, "strike");
        return json_fail(err, err_size, key, "give \"strike\" or \"distance\", not both");
    }
    char key[JSON_PATH_MAX];
    fg_thunder_feature features[FG_THUNDER_MAX_FEATURES];
    const cJSON *design = cJSON_GetObjectItemCaseSensitive(spec, "design");
    json_path_key(key, sizeof key, path, "design");
    if (design && parse_design(design, key, features, &p.feature_count, err, err_size))
        return -1;
    p.features = features;
    double *skeleton = NULL;
    const cJSON *sk = cJSON_GetObjectItemCaseSensitive(spec, "skeleton");
    json_path_key(key, sizeof key, path, "skeleton");
    if (sk && parse_skeleton(sk, key, &skeleton, &p.skeleton_points, err, err_size))
        return -1;
    if (skeleton && placed) { /* move the skeleton so that it strikes at the placement */
        double dx = p.strike_m[0] - skeleton[3 * p.skeleton_points - 3];
        double dy = p.strike_m[1] - skeleton[3 * p.skeleton_points - 2];
        for (size_t i = 0; i < p.skeleton_points; i++)
            skeleton[3 * i] += dx, skeleton[3 * i + 1] += dy;
    }
    p.skeleton_m = skeleton;
    fg_result r = fg_lightning_generate(&p, out, NULL);
    free(skeleton);
    json_path_key(key, sizeof key, path, design ? "design" : "skeleton");
    return r == FG_OK ? 0 : engine_fail(r, r == FG_ERR_ARGUMENT ? key : path, err, err_size);
}

static int parse_charges(const cJSON *item, const char *path, fg_point_charge **out,
                         size_t *count, char *err, size_t err_size)
{
    static const char *const keys[] = {"position", "charge", NULL};
    int n = cJSON_GetArraySize(item);
    if (!cJSON_IsArray(item) || n < 1 || n > 4096)
        return json_fail(err, err_size, path, "expected an array of 1 to 4096 charges");
    fg_point_charge *q = calloc((size_t)n, sizeof *q);
    if (!q)
        return json_fail(err, err_size, path, "out of memory");
    char at[JSON_PATH_MAX];
    size_t i = 0;
    for (const cJSON *c = item->child; c; c = c->next, i++) {
        json_path_index(at, sizeof at, path, i);
        q[i].charge_c = NAN;
        q[i].position_m[2] = NAN;
        if (json_check_keys(c, at, keys, err, err_size) ||
            json_vec3(c, at, "position", q[i].position_m, err, err_size) ||
            json_number(c, at, "charge", (number_range){-1e6, 1e6, false, false, false},
                        &q[i].charge_c, err, err_size) ||
            ((isnan(q[i].charge_c) || isnan(q[i].position_m[2])) &&
             json_fail(err, err_size, at, "\"position\" and \"charge\" are required"))) {
            free(q);
            return -1;
        }
    }
    *out = q;
    *count = i;
    return 0;
}

static int parse_target(const cJSON *item, const char *path, fg_charges_config *p, char *err,
                        size_t err_size)
{
    static const char *const keys[] = {"position", "radius", NULL};
    p->target_m[2] = NAN;
    if (json_check_keys(item, path, keys, err, err_size) ||
        json_vec3(item, path, "position", p->target_m, err, err_size) ||
        json_number(item, path, "radius", positive, &p->target_radius_m, err, err_size))
        return -1;
    if (isnan(p->target_m[2]) || p->target_radius_m == 0)
        return json_fail(err, err_size, path, "\"position\" and \"radius\" are required");
    return 0;
}

/* Runs the growth, naming the field at fault when the engine refuses the
 * combination of values (the JSON ranges have checked each alone). */
static int grow_charges(const fg_charges_config *p, const char *path, fg_tree *out, char *err,
                        size_t err_size)
{
    char key[JSON_PATH_MAX];
    json_path_key(key, sizeof key, path, "start");
    double dx = p->start_m[0] - p->target_m[0], dy = p->start_m[1] - p->target_m[1],
           dz = p->start_m[2] - p->target_m[2];
    if (p->target_radius_m == 0 && p->start_m[2] <= 0)
        return json_fail(err, err_size, key, "must be above the ground (z > 0)");
    if (p->target_radius_m > 0 && sqrt(dx * dx + dy * dy + dz * dz) <= p->target_radius_m)
        return json_fail(err, err_size, key, "lies inside the target");
    fg_charges_config used, one = *p;
    one.chosen = 1;
    if (fg_charges_config_resolve(p, &used) != FG_OK) {
        int chosen_at_fault = fg_charges_config_resolve(&one, &used) == FG_OK;
        json_path_key(key, sizeof key, path, chosen_at_fault ? "chosen" : "exclusion");
        return json_fail(err, err_size, key, "%s",
                         chosen_at_fault ? "more than the candidates (default 8)"
                                         : "must be less than twice the step (default 3 m)");
    }
    fg_result r = fg_charges_grow(&used, out);
    if (r == FG_ERR_UNREACHABLE)
        return json_fail(err, err_size, path,
                         "the leader did not reach its target within %u nodes (max_nodes)",
                         (unsigned)used.max_nodes);
    return r == FG_OK ? 0 : json_fail(err, err_size, path, "%s", fg_result_str(r));
}

int gen_charges(const cJSON *spec, const char *path, const gen_context *ctx, fg_tree *out,
                char *err, size_t err_size)
{
    static const char *const keys[] = {"type",     "charges",   "start",  "step",
                                       "candidates", "chosen",  "exclusion", "max_tips",
                                       "target",   "max_nodes", NULL};
    if (json_check_keys(spec, path, keys, err, err_size))
        return -1;
    fg_charges_config p = {.seed = ctx->seed, .start_m = {NAN, NAN, NAN}};
    char key[JSON_PATH_MAX];
    const cJSON *target = cJSON_GetObjectItemCaseSensitive(spec, "target");
    json_path_key(key, sizeof key, path, "target");
    if (json_vec3(spec, path, "start", p.start_m, err, err_size) ||
        json_number(spec, path, "step", positive, &p.step_m, err, err_size) ||
        count_range(spec, path, "candidates", 1, 4096, &p.candidates, err, err_size) ||
        count_range(spec, path, "chosen", 1, 4096, &p.chosen, err, err_size) ||
        json_number(spec, path, "exclusion", positive, &p.exclusion_m, err, err_size) ||
        count_range(spec, path, "max_tips", 1, 4096, &p.max_tips, err, err_size) ||
        count_range(spec, path, "max_nodes", 2, 1e8, &p.max_nodes, err, err_size) ||
        (target && parse_target(target, key, &p, err, err_size)))
        return -1;
    if (isnan(p.start_m[0]))
        return json_fail(err, err_size, path, "\"start\" is required");
    const cJSON *charges = cJSON_GetObjectItemCaseSensitive(spec, "charges");
    json_path_key(key, sizeof key, path, "charges");
    fg_point_charge *q = NULL;
    if (parse_charges(charges, key, &q, &p.charge_count, err, err_size))
        return -1;
    p.charges = q;
    int r = grow_charges(&p, path, out, err, err_size);
    free(q);
    return r;
}
