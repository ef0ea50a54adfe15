/* "propagation": the air between a discharge and the ear, switched effect
 * by effect. Each key takes false (off), true (on, with its defaults) or an
 * object of its parameters (on):
 *   "refraction": {"radius": m}          default 55 km, 20-200 km
 *   "turbulence": {"amplitude": s, "length": m}   default 2 ms, 50 m
 *   "absorption": "off" | "iso9613" | "abe_fir", or {"model": "abe_fir",
 *                 "distance": m}         Abe's filter beyond 1 km by default
 *   "ground":     {"reflection": 0..1}   default 0.9
 *   "head_shadow": true | false */
#include <string.h>

#include "scene_internal.h"

static const char *const propagation_keys[] = {"refraction", "turbulence", "absorption", "ground",
                                               "head_shadow", NULL};

/* item is false, true or an object; *on says which; an object is checked
 * against keys. */
static int switch_or_object(const cJSON *item, const char *path, const char *const *keys,
                            bool *on, char *err, size_t err_size)
{
    if (cJSON_IsBool(item)) {
        *on = cJSON_IsTrue(item);
        return 0;
    }
    if (!cJSON_IsObject(item))
        return json_fail(err, err_size, path, "expected true, false or an object");
    *on = true;
    return json_check_keys(item, path, keys, err, err_size);
}

static int parse_refraction(const cJSON *obj, const char *base, fg_propagation_config *p, char *err,
                            size_t err_size)
{
    static const char *const keys[] = {"radius", NULL};
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "refraction");
    char path[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, "refraction");
    bool on = false;
    if (!item || switch_or_object(item, path, keys, &on, err, err_size))
        return item ? -1 : 0;
    p->refraction_radius_m = on ? FG_REFRACTION_STORM_M : 0;
    return on && cJSON_IsObject(item)
               ? json_number(item, path, "radius",
                             (number_range){.lo = FG_REFRACTION_MIN_M, .hi = FG_REFRACTION_MAX_M},
                             &p->refraction_radius_m, err, err_size)
               : 0;
}

static int parse_turbulence(const cJSON *obj, const char *base, fg_propagation_config *p, char *err,
                            size_t err_size)
{
    static const char *const keys[] = {"amplitude", "length", NULL};
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "turbulence");
    char path[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, "turbulence");
    bool on = false;
    if (!item || switch_or_object(item, path, keys, &on, err, err_size))
        return item ? -1 : 0;
    p->turbulence_s = on ? FG_TURBULENCE_DEFAULT_S : 0;
    p->turbulence_length_m = on ? FG_TURBULENCE_DEFAULT_LENGTH_M : 0;
    return on && cJSON_IsObject(item)
               ? json_number(item, path, "amplitude",
                             (number_range){0, 1, .lo_open = true, .hi_open = true},
                             &p->turbulence_s, err, err_size) ||
                         json_number(item, path, "length",
                                     (number_range){.lo = FG_TURBULENCE_MIN_LENGTH_M, .hi = 1e5},
                                     &p->turbulence_length_m, err, err_size)
                     ? -1
                     : 0
               : 0;
}

static int absorption_name(const cJSON *item, const char *path, fg_absorption *out, char *err,
                           size_t err_size)
{
    static const char *const names[] = {"off", "iso9613", "abe_fir"};
    if (cJSON_IsString(item))
        for (int i = 0; i < 3; i++)
            if (strcmp(item->valuestring, names[i]) == 0) {
                *out = (fg_absorption)i;
                return 0;
            }
    return json_fail(err, err_size, path, "expected \"off\", \"iso9613\" or \"abe_fir\"");
}

static int parse_absorption(const cJSON *obj, const char *base, fg_propagation_config *p, char *err,
                            size_t err_size)
{
    static const char *const keys[] = {"model", "distance", NULL};
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "absorption");
    char path[JSON_PATH_MAX], key[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, "absorption");
    if (!item)
        return 0;
    if (!cJSON_IsObject(item))
        return absorption_name(item, path, &p->absorption, err, err_size);
    json_path_key(key, sizeof key, path, "model");
    const cJSON *model = cJSON_GetObjectItemCaseSensitive(item, "model");
    if (json_check_keys(item, path, keys, err, err_size))
        return -1;
    if (!model)
        return json_fail(err, err_size, key, "required (\"off\", \"iso9613\" or \"abe_fir\")");
    return absorption_name(model, key, &p->absorption, err, err_size) ||
                   json_number(item, path, "distance", (number_range){0, 1e6, .lo_open = true},
                               &p->abe_fir_distance_m, err, err_size)
               ? -1
               : 0;
}

static int parse_ground(const cJSON *obj, const char *base, fg_propagation_config *p, char *err,
                        size_t err_size)
{
    static const char *const keys[] = {"reflection", NULL};
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "ground");
    char path[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, "ground");
    bool on = false;
    if (!item || switch_or_object(item, path, keys, &on, err, err_size))
        return item ? -1 : 0;
    p->ground_reflection = on ? FG_GROUND_DEFAULT_REFLECTION : 0;
    return on && cJSON_IsObject(item)
               ? json_number(item, path, "reflection", (number_range){0, 1, .lo_open = true},
                             &p->ground_reflection, err, err_size)
               : 0;
}

int scene_parse_propagation(const cJSON *item, const char *path, fg_propagation_config *p, char *err,
                            size_t err_size)
{
    char key[JSON_PATH_MAX];
    if (json_check_keys(item, path, propagation_keys, err, err_size) ||
        parse_refraction(item, path, p, err, err_size) ||
        parse_turbulence(item, path, p, err, err_size) ||
        parse_absorption(item, path, p, err, err_size) || parse_ground(item, path, p, err, err_size))
        return -1;
    const cJSON *head = cJSON_GetObjectItemCaseSensitive(item, "head_shadow");
    json_path_key(key, sizeof key, path, "head_shadow");
    if (head && !cJSON_IsBool(head))
        return json_fail(err, err_size, key, "expected true or false");
    if (head)
        p->head_shadow = cJSON_IsTrue(head);
    return 0;
}
