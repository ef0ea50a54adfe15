/* Typed field reads with path-bearing messages. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "common/text_escape.h"
#include "json_read.h"

void json_path_key(char *out, size_t size, const char *base, const char *key)
{
    snprintf(out, size, "%s%s%s", base, base[0] ? "." : "", key);
}

void json_path_index(char *out, size_t size, const char *base, size_t index)
{
    snprintf(out, size, "%s[%zu]", base, index);
}

int json_fail(char *err, size_t err_size, const char *path, const char *fmt, ...)
{
    /* the path and the values in the message come from the scene: their
     * control and invalid bytes are escaped */
    char text[1024];
    int n = snprintf(text, sizeof text, "%s: ", path[0] ? path : "scene");
    if (n >= 0 && (size_t)n < sizeof text) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(text + n, sizeof text - (size_t)n, fmt, ap);
        va_end(ap);
    }
    if (err_size > 0)
        text_escape(err, err_size, text);
    return -1;
}

static int allowed_index(const char *const *allowed, const char *key)
{
    for (int i = 0; allowed[i]; i++)
        if (strcmp(allowed[i], key) == 0)
            return i;
    return -1;
}

int json_check_keys(const cJSON *obj, const char *path, const char *const *allowed, char *err,
                    size_t err_size)
{
    if (!cJSON_IsObject(obj))
        return json_fail(err, err_size, path, "expected an object");
    char key_path[JSON_PATH_MAX];
    for (const cJSON *item = obj->child; item; item = item->next) {
        json_path_key(key_path, sizeof key_path, path, item->string);
        if (allowed_index(allowed, item->string) < 0) {
            char known[256] = "";
            for (int i = 0; allowed[i]; i++)
                snprintf(known + strlen(known), sizeof known - strlen(known), "%s%s",
                         i ? ", " : "", allowed[i]);
            return json_fail(err, err_size, key_path, "unknown key (known: %s)", known);
        }
        for (const cJSON *prev = obj->child; prev != item; prev = prev->next)
            if (strcmp(prev->string, item->string) == 0)
                return json_fail(err, err_size, key_path, "given twice");
    }
    return 0;
}

int json_number_value(const cJSON *item, const char *path, number_range r, double *out, char *err,
                      size_t err_size)
{
    /* the common case first: the message is formatted only on failure */
    if (cJSON_IsNumber(item) && number_range_holds(r, item->valuedouble)) {
        *out = item->valuedouble;
        return 0;
    }
    char range[96];
    number_range_format(r, range, sizeof range);
    const char *what = r.integer ? "an integer" : "a number";
    if (!cJSON_IsNumber(item))
        return json_fail(err, err_size, path, "expected %s in %s", what, range);
    double v = item->valuedouble;
    if (!isfinite(v))
        return json_fail(err, err_size, path, "expected %s in %s, not infinity", what, range);
    if (r.integer && v != floor(v))
        return json_fail(err, err_size, path, "%.16g is not an integer", v);
    if (!number_range_holds(r, v))
        return json_fail(err, err_size, path, "%.16g is outside %s", v, range);
    *out = v;
    return 0;
}

int json_number(const cJSON *obj, const char *base, const char *key, number_range range,
                double *out, char *err, size_t err_size)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!item)
        return 0;
    char path[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, key);
    return json_number_value(item, path, range, out, err, err_size);
}

int json_vector(const cJSON *obj, const char *base, const char *key, int n, double *out,
                char *err, size_t err_size)
{
    static const char *const forms[] = {"", "", "[x, y]", "[x, y, z]"};
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!item)
        return 0;
    char path[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, key);
    if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != n)
        return json_fail(err, err_size, path, "expected an array %s", forms[n]);
    double v[3];
    int i = 0;
    for (const cJSON *c = item->child; c; c = c->next, i++) {
        if (!cJSON_IsNumber(c) || !isfinite(c->valuedouble))
            return json_fail(err, err_size, path, "element %d is not a finite number", i);
        v[i] = c->valuedouble;
    }
    memcpy(out, v, (size_t)n * sizeof *v);
    return 0;
}

int json_vec3(const cJSON *obj, const char *base, const char *key, double out[3], char *err,
              size_t err_size)
{
    return json_vector(obj, base, key, 3, out, err, err_size);
}

int json_bool(const cJSON *obj, const char *base, const char *key, bool *out, char *err,
              size_t err_size)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!item)
        return 0;
    if (!cJSON_IsBool(item)) {
        char path[JSON_PATH_MAX];
        json_path_key(path, sizeof path, base, key);
        return json_fail(err, err_size, path, "expected true or false");
    }
    *out = cJSON_IsTrue(item);
    return 0;
}

int json_name(const cJSON *obj, const char *base, const char *key, const char *const *names,
              int count, int *out, char *err, size_t err_size)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!item)
        return 0;
    if (cJSON_IsString(item))
        for (int i = 0; i < count; i++)
            if (strcmp(item->valuestring, names[i]) == 0) {
                *out = i;
                return 0;
            }
    char list[256] = "", path[JSON_PATH_MAX];
    for (int i = 0; i < count; i++)
        snprintf(list + strlen(list), sizeof list - strlen(list), "%s\"%s\"", i ? ", " : "",
                 names[i]);
    json_path_key(path, sizeof path, base, key);
    return json_fail(err, err_size, path, "expected one of %s", list);
}

int json_file_name(const cJSON *obj, const char *base, const char *key, const char *dir,
                   const char *what, char *file, size_t file_size, char *err, size_t err_size)
{
    char path[JSON_PATH_MAX];
    json_path_key(path, sizeof path, base, key);
    const cJSON *name = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!cJSON_IsString(name) || !name->valuestring[0])
        return json_fail(err, err_size, path, "required: %s", what);
    if (name->valuestring[0] == '/' || !dir || !dir[0])
        snprintf(file, file_size, "%s", name->valuestring);
    else
        snprintf(file, file_size, "%s/%s", dir, name->valuestring);
    struct stat st;
    if (stat(file, &st) == 0 && !S_ISREG(st.st_mode))
        return json_fail(err, err_size, path, "%s: not a regular file (a device, FIFO or "
                                              "directory)", file);
    return 0;
}
