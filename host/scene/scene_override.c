/* KEY=VALUE into a scene document. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json_read.h"
#include "scene_override.h"

/* Components of a key at most (a scene's paths are a few deep). */
#define MAX_DEPTH 16

typedef struct component {
    bool is_index;
    size_t index;
    char name[64];
} component;

/* Splits key[0..len) into parts; returns their count, or 0 with a message. */
static size_t split_key(const char *key, size_t len, component *parts, char *err, size_t err_size)
{
    size_t n = 0, i = 0;
    while (i < len) {
        if (n == MAX_DEPTH) {
            snprintf(err, err_size, "%.*s: deeper than %d keys", (int)len, key, MAX_DEPTH);
            return 0;
        }
        component *c = &parts[n];
        *c = (component){0};
        if (key[i] == '[') {
            size_t start = ++i;
            while (i < len && key[i] >= '0' && key[i] <= '9' && i - start < 9)
                c->index = c->index * 10 + (size_t)(key[i++] - '0');
            if (i == start || i == len || key[i] != ']') {
                snprintf(err, err_size, "%.*s: expected an index (digits) and ']' at character %zu",
                         (int)len, key, start + 1);
                return 0;
            }
            i++;
            c->is_index = true;
        } else {
            if (n > 0 && key[i++] != '.') {
                snprintf(err, err_size, "%.*s: expected '.' or '[' at character %zu", (int)len,
                         key, i);
                return 0;
            }
            size_t start = i;
            while (i < len && key[i] != '.' && key[i] != '[' && key[i] != ']')
                i++;
            if (i == start || i - start >= sizeof c->name) {
                snprintf(err, err_size, "%.*s: expected a key of 1 to %zu characters at character %zu",
                         (int)len, key, sizeof c->name - 1, start + 1);
                return 0;
            }
            memcpy(c->name, key + start, i - start);
        }
        n++;
    }
    if (n == 0)
        snprintf(err, err_size, "expected KEY=VALUE, KEY a JSON path such as discharges[0].time");
    return n;
}

/* VALUE as JSON, else as a string. */
static cJSON *parse_value(const char *text)
{
    const char *end = NULL;
    cJSON *v = cJSON_ParseWithOpts(text, &end, 1);
    return v ? v : cJSON_CreateString(text);
}

static int fail(char *err, size_t err_size, const char *path, const char *key, size_t key_len,
                const char *what)
{
    json_fail(err, err_size, path[0] ? path : "(the scene)", "%s, setting %.*s", what,
              (int)key_len, key);
    return -1;
}

/* Where place() created the first missing object, to take it out again. */
typedef struct created {
    cJSON *parent;
    const char *name;
} created;

/* Puts value at parts[0..n) below doc; value is consumed only on success.
 * *made receives the first object created on the way. */
static int place(cJSON *doc, const component *parts, size_t n, cJSON *value, const char *key,
                 size_t key_len, created *made, char *err, size_t err_size)
{
    char path[JSON_PATH_MAX] = "", next[JSON_PATH_MAX], what[JSON_PATH_MAX + 128];
    cJSON *node = doc;
    for (size_t i = 0; i < n; i++) {
        const component *c = &parts[i];
        bool last = i + 1 == n;
        if (c->is_index) {
            json_path_index(next, sizeof next, path, c->index);
            if (!cJSON_IsArray(node)) {
                snprintf(what, sizeof what, "is not an array, so it has no element [%zu]", c->index);
                return fail(err, err_size, path, key, key_len, what);
            }
            size_t size = (size_t)cJSON_GetArraySize(node);
            if (last && c->index < size)
                return cJSON_ReplaceItemInArray(node, (int)c->index, value) ? 0 : -1;
            if (last && c->index == size)
                return cJSON_AddItemToArray(node, value) ? 0 : -1;
            if (c->index >= size) {
                snprintf(what, sizeof what, "past the end of %s (%zu elements)",
                         path[0] ? path : "the array", size);
                return fail(err, err_size, next, key, key_len, what);
            }
            node = cJSON_GetArrayItem(node, (int)c->index);
        } else {
            json_path_key(next, sizeof next, path, c->name);
            if (!cJSON_IsObject(node)) {
                snprintf(what, sizeof what, "is not an object, so it has no key \"%s\"", c->name);
                return fail(err, err_size, path, key, key_len, what);
            }
            cJSON *child = cJSON_GetObjectItemCaseSensitive(node, c->name);
            if (last && child)
                return cJSON_ReplaceItemInObjectCaseSensitive(node, c->name, value) ? 0 : -1;
            if (last)
                return cJSON_AddItemToObject(node, c->name, value) ? 0 : -1;
            if (!child && parts[i + 1].is_index) {
                snprintf(what, sizeof what, "no such key, so no element [%zu] (set %s whole)",
                         parts[i + 1].index, next);
                return fail(err, err_size, next, key, key_len, what);
            }
            if (!child) {
                if (!(child = cJSON_AddObjectToObject(node, c->name)))
                    return fail(err, err_size, next, key, key_len, "out of memory");
                if (!made->parent)
                    *made = (created){node, c->name};
            }
            node = child;
        }
        memcpy(path, next, sizeof path);
    }
    return -1;
}

int scene_override(cJSON *doc, const char *assignment, char *err, size_t err_size)
{
    const char *eq = strchr(assignment, '=');
    if (!eq) {
        snprintf(err, err_size, "%s: expected KEY=VALUE, KEY a JSON path such as discharges[0].time",
                 assignment);
        return -1;
    }
    size_t key_len = (size_t)(eq - assignment);
    component parts[MAX_DEPTH];
    size_t n = split_key(assignment, key_len, parts, err, err_size);
    if (n == 0)
        return -1;
    if (parts[0].is_index)
        return fail(err, err_size, "", assignment, key_len,
                    "is an object: the path starts with a key");
    cJSON *value = parse_value(eq + 1);
    if (!value) {
        snprintf(err, err_size, "%.*s: out of memory", (int)key_len, assignment);
        return -1;
    }
    err[0] = '\0';
    created made = {0};
    if (place(doc, parts, n, value, assignment, key_len, &made, err, err_size) == 0)
        return 0;
    cJSON_Delete(value);
    if (made.parent)
        cJSON_DeleteItemFromObjectCaseSensitive(made.parent, made.name);
    if (!err[0])
        snprintf(err, err_size, "%.*s: out of memory", (int)key_len, assignment);
    return -1;
}
