/* One discharge: when, which preset with which overrides, strokes or a
 * continuous repeat, its seed, and where its tree comes from. */
#define _DEFAULT_SOURCE /* fg_big_alloc.h */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fg_big_alloc.h"
#include "generator.h"
#include "scene_internal.h"
#include "fg_rng.h"

static const char *const discharge_keys[] = {
    "time", "preset", "T0", "r0", "ps0", "sigma0", "t0_jitter", "return_stroke_speed", "ref_half_len",
    "strokes", "continuous", "seed", "offset", "propagation", "model", "tree", "generator",
    "description", NULL};
static const char *const continuous_keys[] = {"min_interval", "max_interval", "duration", NULL};

static int parse_preset(const cJSON *obj, const char *base, scene_discharge *d, char *err,
                        size_t err_size)
{
    char path[JSON_PATH_MAX], names[96] = "";
    json_path_key(path, sizeof path, base, "preset");
    for (int p = 0; p < FG_PRESET_COUNT; p++)
        snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", p ? ", " : "",
                 fg_preset_name((fg_preset)p));
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "preset");
    if (!item)
        return json_fail(err, err_size, path, "required (%s)", names);
    if (!cJSON_IsString(item))
        return json_fail(err, err_size, path, "expected a string (%s)", names);
    if (fg_preset_from_name(item->valuestring, &d->preset) != FG_OK)
        return json_fail(err, err_size, path, "unknown preset \"%s\" (%s)", item->valuestring,
                         names);
    if (fg_preset_sound(d->preset, &d->post.sound) != FG_OK)
        return json_fail(err, err_size, path, "preset has no sound parameters");
    return 0;
}

/* The overrides of the preset's sound parameters, each in its unit. */
static int parse_sound(const cJSON *obj, const char *base, fg_sound_config *p, char *err,
                       size_t err_size)
{
    return json_number(obj, base, "T0",
                       (number_range){.lo = FG_SOUND_MIN_T0_S, .hi = FG_SOUND_MAX_T0_S}, &p->t0_s,
                       err, err_size) ||
           json_number(obj, base, "r0", (number_range){0, FG_SOUND_MAX_R0_M, .lo_open = true},
                       &p->r0_m, err, err_size) ||
           json_number(obj, base, "ps0", (number_range){0, FG_SOUND_MAX_PS0_PA, .lo_open = true},
                       &p->ps0_pa, err, err_size) ||
           json_number(obj, base, "sigma0", (number_range){.lo = 0, .hi = FG_SOUND_MAX_SIGMA0},
                       &p->sigma0, err, err_size) ||
           json_number(obj, base, "t0_jitter", (number_range){0, 1, .hi_open = true},
                       &p->t0_jitter, err, err_size) ||
           json_number(obj, base, "return_stroke_speed",
                       (number_range){.lo = FG_SOUND_MIN_RETURN_STROKE_M_S,
                                      .hi = FG_SOUND_MAX_RETURN_STROKE_M_S},
                       &p->return_stroke_speed_m_s, err, err_size) ||
           json_number(obj, base, "ref_half_len", (number_range){.lo = 0, .hi = 1000},
                       &p->ref_half_len_m, err, err_size)
               ? -1
               : 0;
}

static int parse_continuous(const cJSON *obj, const char *base, scene_discharge *d, char *err,
                            size_t err_size)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "continuous");
    if (!item)
        return 0;
    char path[JSON_PATH_MAX], key[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, "continuous");
    d->post.continuous = 1;
    d->post.repeat_min_s = 0.010;
    d->post.repeat_max_s = 0.050;
    number_range interval = {.lo = FG_REPEAT_MIN_S, .hi = FG_REPEAT_MAX_S};
    if (json_check_keys(item, path, continuous_keys, err, err_size) ||
        json_number(item, path, "min_interval", interval, &d->post.repeat_min_s, err, err_size) ||
        json_number(item, path, "max_interval", interval, &d->post.repeat_max_s, err, err_size) ||
        json_number(item, path, "duration",
                    (number_range){0, SCENE_MAX_DURATION_S, .lo_open = true}, &d->post.duration_s,
                    err, err_size))
        return -1;
    if (d->post.repeat_min_s > d->post.repeat_max_s) {
        json_path_key(key, sizeof key, path, "min_interval");
        return json_fail(err, err_size, key, "%.16g s is above max_interval (%.16g s)",
                         d->post.repeat_min_s, d->post.repeat_max_s);
    }
    if (d->post.strokes > 1) {
        json_path_key(key, sizeof key, base, "strokes");
        return json_fail(err, err_size, key, "a continuous discharge has one stroke, not %u",
                         (unsigned)d->post.strokes);
    }
    return 0;
}

static int parse_generator(const cJSON *item, const char *path, scene_discharge *d, char *err,
                           size_t err_size)
{
    char key[JSON_PATH_MAX];
    json_path_key(key, sizeof key, path, "type");
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, path, "expected an object with a \"type\"");
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(item, "type");
    if (!cJSON_IsString(type))
        return json_fail(err, err_size, key, "required, a string (known: %s)", gen_type_list());
    if (!gen_find(type->valuestring))
        return json_fail(err, err_size, key, "unknown generator \"%s\" (known: %s)",
                         type->valuestring, gen_type_list());
    d->generator = item;
    return 0;
}

static int parse_source(const cJSON *obj, const char *base, scene_node_lists *lists,
                        scene_discharge *d, char *err, size_t err_size)
{
    const cJSON *tree = cJSON_GetObjectItemCaseSensitive(obj, "tree");
    const cJSON *gen = cJSON_GetObjectItemCaseSensitive(obj, "generator");
    if (!tree == !gen)
        return json_fail(err, err_size, base, "give exactly one of \"tree\" and \"generator\"");
    char path[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, tree ? "tree" : "generator");
    if (tree)
        return scene_parse_tree(tree, path, d->offset_m, lists, &d->post.nodes,
                                &d->post.node_count, err, err_size);
    return parse_generator(gen, path, d, err, err_size);
}

void scene_discharge_free_tree(scene_discharge *d)
{
    fg_big_free((fg_node *)d->post.nodes);
    d->post.nodes = NULL;
    d->post.node_count = 0;
}

uint64_t scene_discharge_seed(uint64_t scene_seed, size_t index)
{
    /* splitmix64's finaliser over the seed, then over the index mixed in:
     * neighbouring indices and seeds give unrelated values. */
    uint64_t z = scene_seed + FG_SPLITMIX64_GAMMA * ((uint64_t)index + 1);
    return fg_splitmix64_mix(fg_splitmix64_mix(z));
}

int scene_parse_discharge(const cJSON *item, const char *path, size_t index, const scene *s,
                          scene_discharge *d, char *err, size_t err_size)
{
    double strokes = 0, seed = -1;
    if (json_check_keys(item, path, discharge_keys, err, err_size))
        return -1;
    char key[JSON_PATH_MAX];
    json_path_key(key, sizeof key, path, "time");
    if (!cJSON_GetObjectItemCaseSensitive(item, "time"))
        return json_fail(err, err_size, key, "required (emit time, seconds)");
    const cJSON *desc = cJSON_GetObjectItemCaseSensitive(item, "description");
    json_path_key(key, sizeof key, path, "description");
    if (desc && !cJSON_IsString(desc))
        return json_fail(err, err_size, key, "expected a string");
    if (json_number(item, path, "time", (number_range){.lo = 0, .hi = SCENE_MAX_DURATION_S},
                    &d->post.emit_time_s, err, err_size) ||
        parse_preset(item, path, d, err, err_size) ||
        parse_sound(item, path, &d->post.sound, err, err_size) ||
        json_number(item, path, "strokes", (number_range){0, FG_MAX_STROKES, .integer = true},
                    &strokes, err, err_size) ||
        json_number(item, path, "seed", SCENE_SEED_RANGE, &seed, err, err_size) ||
        json_vec3(item, path, "offset", d->offset_m, err, err_size))
        return -1;
    d->post.strokes = (uint32_t)strokes;
    d->post.seed = seed >= 0 ? (uint64_t)seed : scene_discharge_seed(s->seed, index);
    d->post.propagation = s->propagation;
    const cJSON *prop = cJSON_GetObjectItemCaseSensitive(item, "propagation");
    json_path_key(key, sizeof key, path, "propagation");
    if (prop && scene_parse_propagation(prop, key, &d->post.propagation, err, err_size))
        return -1;
    const cJSON *model = cJSON_GetObjectItemCaseSensitive(item, "model");
    json_path_key(key, sizeof key, path, "model");
    if (model && !(cJSON_IsString(model) && (strcmp(model->valuestring, "wm") == 0 ||
                                             strcmp(model->valuestring, "abe") == 0)))
        return json_fail(err, err_size, key, "expected \"wm\" (Matsuyama) or \"abe\" (Abe et al.)");
    d->post.model = model && strcmp(model->valuestring, "abe") == 0 ? FG_MODEL_ABE : FG_MODEL_WM;
    return parse_continuous(item, path, d, err, err_size) ||
                   parse_source(item, path, s->node_lists, d, err, err_size)
               ? -1
               : 0;
}
