/* Typed reads of the fields of a JSON object, for scene files.
 *
 * Every function that can fail writes a message starting with the JSON path
 * of the offending field ("discharges[2].T0: -1 is outside (0, 0.1]") into
 * err (always NUL-terminated) and returns -1; success returns 0. Paths are
 * built by the caller with json_path_key/json_path_index; the root's path is
 * the empty string. */
#ifndef HOST_SCENE_JSON_READ_H
#define HOST_SCENE_JSON_READ_H

#include <stdbool.h>
#include <stddef.h>

#include <cjson/cJSON.h>

#include "common/number_range.h"

/* Room for any path a scene produces. */
#define JSON_PATH_MAX 256

/* out = base + "." + key (just key when base is ""), and base + "[index]". */
void json_path_key(char *out, size_t size, const char *base, const char *key);
void json_path_index(char *out, size_t size, const char *base, size_t index);

/* Formats "path: message" into err; returns -1 so callers can return it. */
int json_fail(char *err, size_t err_size, const char *path, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Requires obj to be an object whose keys are all in the NULL-terminated
 * list allowed, each at most once (typos and duplicates are errors). */
int json_check_keys(const cJSON *obj, const char *path, const char *const *allowed, char *err,
                    size_t err_size);

/* Checks that item (at path) is a number inside range; *out gets it. */
int json_number_value(const cJSON *item, const char *path, number_range range, double *out,
                      char *err, size_t err_size);

/* Reads obj[key] as a number inside range into *out; *out keeps its value
 * (the default) when the key is absent. */
int json_number(const cJSON *obj, const char *base, const char *key, number_range range,
                double *out, char *err, size_t err_size);

/* Reads obj[key], when present, as an array of n (2 or 3) finite numbers. */
int json_vector(const cJSON *obj, const char *base, const char *key, int n, double *out,
                char *err, size_t err_size);

/* Reads obj[key], when present, as an array of three finite numbers. */
int json_vec3(const cJSON *obj, const char *base, const char *key, double out[3], char *err,
              size_t err_size);

/* Reads obj[key], when present, as true or false. */
int json_bool(const cJSON *obj, const char *base, const char *key, bool *out, char *err,
              size_t err_size);

/* Reads obj[key], when present, as one of the count strings in names;
 * *out gets its index. */
int json_name(const cJSON *obj, const char *base, const char *key, const char *const *names,
              int count, int *out, char *err, size_t err_size);

/* Reads obj[key], required, as the name of a file, relative to dir unless
 * absolute or dir is NULL or "": file (file_size bytes) gets the name
 * resolved. Refuses a missing or empty string (what describes the file it
 * must name) and a name of something that exists but is not a regular
 * file (a FIFO would stall the parse); a missing file is the caller's to
 * report as it opens it. */
int json_file_name(const cJSON *obj, const char *base, const char *key, const char *dir,
                   const char *what, char *file, size_t file_size, char *err, size_t err_size);

#endif
