/* The scene's top level: settings, then the listener and the discharges. */
#define _DEFAULT_SOURCE /* fdopen, fg_big_alloc.h */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scene_internal.h"
#include "scene_override.h"
#include "fg_big_alloc.h"

static const char *const top_keys[] = {
    "sample_rate", "channels", "block", "duration", "seed", "gain", "speed_of_sound",
    "temperature_c", "humidity", "pressure", "propagation", "listener", "discharges",
    "random", "camera", "description", "aero_objects", "wind", "fires", "layout", NULL};

static int syntax_error(const char *text, const char *at, const char *what, char *err,
                        size_t err_size)
{
    int line = 1, column = 1;
    for (const char *c = text; c < at; c++) {
        column++;
        if (*c == '\n') {
            line++;
            column = 1;
        }
    }
    return json_fail(err, err_size, "", "%s at line %d, column %d", what, line, column);
}

static int parse_settings(const cJSON *json, scene *s, char *err, size_t err_size)
{
    double rate = 48000, channels = 2, block = SCENE_BLOCK_FRAMES, seed = 1, speed = 343, temp = 20;
    s->gain = 1;
    s->humidity_pct = 70;
    s->pressure_kpa = 101.325;
    if (json_number(json, "", "sample_rate", (number_range){8000, 384000, .integer = true}, &rate,
                    err, err_size) ||
        json_number(json, "", "channels", (number_range){1, 2, .integer = true}, &channels, err,
                    err_size) ||
        json_number(json, "", "block", (number_range){1, 65536, .integer = true}, &block, err,
                    err_size) ||
        json_number(json, "", "duration", (number_range){0, SCENE_MAX_DURATION_S, .lo_open = true},
                    &s->duration_s, err, err_size) ||
        json_number(json, "", "seed", SCENE_SEED_RANGE, &seed, err, err_size) ||
        json_number(json, "", "gain", (number_range){0, 1e9, .lo_open = true}, &s->gain, err,
                    err_size) ||
        json_number(json, "", "speed_of_sound",
                    (number_range){.lo = FG_SPEED_OF_SOUND_MIN_M_S, .hi = FG_SPEED_OF_SOUND_MAX_M_S},
                    &speed, err, err_size) ||
        json_number(json, "", "temperature_c", (number_range){.lo = -70, .hi = 60}, &temp, err,
                    err_size) ||
        json_number(json, "", "humidity", (number_range){0, 100, .lo_open = true}, &s->humidity_pct,
                    err, err_size) ||
        json_number(json, "", "pressure", (number_range){.lo = 10, .hi = 200}, &s->pressure_kpa,
                    err, err_size))
        return -1;
    const cJSON *prop = cJSON_GetObjectItemCaseSensitive(json, "propagation");
    if (prop && scene_parse_propagation(prop, "propagation", &s->propagation, err, err_size))
        return -1;
    s->temperature_c = temp;
    if (cJSON_GetObjectItemCaseSensitive(json, "temperature_c")) {
        if (cJSON_GetObjectItemCaseSensitive(json, "speed_of_sound"))
            return json_fail(err, err_size, "temperature_c",
                             "give speed_of_sound or temperature_c, not both");
        speed = 331.5 + 0.6 * temp;
    }
    const cJSON *desc = cJSON_GetObjectItemCaseSensitive(json, "description");
    if (desc && !cJSON_IsString(desc))
        return json_fail(err, err_size, "description", "expected a string");
    s->sample_rate_hz = rate;
    s->channels = (uint32_t)channels;
    s->block_frames = (uint32_t)block;
    s->block_given = cJSON_GetObjectItemCaseSensitive(json, "block") != NULL;
    s->seed = (uint64_t)seed;
    s->speed_of_sound_m_s = speed;
    return 0;
}

static int parse_discharges(const cJSON *json, scene *s, char *err, size_t err_size)
{
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(json, "discharges");
    if (!list && (cJSON_GetObjectItemCaseSensitive(json, "random") ||
                  cJSON_GetObjectItemCaseSensitive(json, "aero_objects") ||
                  cJSON_GetObjectItemCaseSensitive(json, "fires")))
        return 0; /* random discharges, aero objects or fires only */
    if (!list)
        return json_fail(err, err_size, "discharges",
                         "required (an array of discharges), unless \"random\", "
                         "\"aero_objects\" or \"fires\" is given");
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) == 0)
        return json_fail(err, err_size, "discharges", "expected a non-empty array");
    size_t n = (size_t)cJSON_GetArraySize(list);
    s->discharges = calloc(n, sizeof *s->discharges);
    if (!s->discharges)
        return json_fail(err, err_size, "discharges", "out of memory");
    char path[JSON_PATH_MAX];
    for (const cJSON *item = list->child; item; item = item->next) {
        size_t i = s->discharge_count;
        json_path_index(path, sizeof path, "discharges", i);
        if (scene_parse_discharge(item, path, i, s, &s->discharges[i], err, err_size))
            return -1;
        s->discharge_count++;
    }
    return 0;
}

/* The scene must end, and nothing may be set to emit after its end. */
static int check_duration(const scene *s, char *err, size_t err_size)
{
    for (size_t i = 0; i < s->aero_count && s->duration_s == 0; i++)
        if (s->aeros[i].post.duration_s == 0)
            return json_fail(err, err_size, "duration",
                             "required, since aero_objects[%zu] has no duration", i);
    char item[JSON_PATH_MAX], path[JSON_PATH_MAX];
    for (size_t i = 0; i < s->discharge_count; i++) {
        const scene_discharge *d = &s->discharges[i];
        if (s->duration_s == 0 && d->post.continuous && d->post.duration_s == 0)
            return json_fail(err, err_size, "duration",
                             "required, since discharges[%zu] is continuous without a duration",
                             i);
        if (s->duration_s > 0 && d->post.emit_time_s >= s->duration_s) {
            json_path_index(item, sizeof item, "discharges", i);
            json_path_key(path, sizeof path, item, "time");
            return json_fail(err, err_size, path, "%.16g s is not before the scene's end (%.16g s)",
                             d->post.emit_time_s, s->duration_s);
        }
    }
    return 0;
}

/* The explicit trees' "nodes" are copied into the discharges once parsed:
 * their part of the document (most of it in a big scene, ~400 bytes of
 * cJSON per node) is freed before anything is built or rendered. What
 * stays is what the generators read again (a run or view regrows them). */
static void drop_parsed_trees(cJSON *json)
{
    cJSON *list = cJSON_GetObjectItemCaseSensitive(json, "discharges");
    for (cJSON *item = list ? list->child : NULL; item; item = item->next)
        cJSON_DeleteItemFromObjectCaseSensitive(item, "tree");
    cJSON_DeleteItemFromObjectCaseSensitive(cJSON_GetObjectItemCaseSensitive(json, "random"),
                                            "tree");
    cJSON_DeleteItemFromObjectCaseSensitive(
        cJSON_GetObjectItemCaseSensitive(json, "random (template)"), "tree");
}

/* The document, with nothing after it but whitespace, into *json. */
static int parse_document(const char *text, size_t size, cJSON **json, char *err,
                          size_t err_size)
{
    const char *end = NULL;
    *json = cJSON_ParseWithLengthOpts(text, size, &end, 0);
    if (!*json)
        return syntax_error(text, end ? end : text, "JSON syntax error", err, err_size);
    while (end < text + size && *end && strchr(" \t\r\n", *end))
        end++;
    if (end < text + size) {
        syntax_error(text, end, "unexpected text after the JSON document", err, err_size);
        cJSON_Delete(*json);
        *json = NULL;
        return -1;
    }
    return 0;
}

/* Whether a --set reaches into "discharges": the streaming reader's lists
 * stand for the trees as the file wrote them, so it is not used then. */
static int sets_reach_discharges(const char *const *sets, size_t set_count)
{
    for (size_t i = 0; i < set_count; i++)
        if (strncmp(sets[i], "discharges", strlen("discharges")) == 0)
            return 1;
    return 0;
}

/* Parses text into *json, the explicit trees read into *lists by the
 * streaming reader where it can (scene_nodes_stream.c). Whatever the rest
 * of the text fails on is parsed again from the whole text, so that every
 * message (its line and column too) is the one the document itself gets. */
static int parse_with_lists(const char *text, size_t size, const char *const *sets,
                            size_t set_count, cJSON **json, scene_node_lists *lists, char *err,
                            size_t err_size)
{
    char *rest = NULL;
    size_t rest_size = 0;
    if (sets_reach_discharges(sets, set_count))
        memset(lists, 0, sizeof *lists);
    else
        rest = scene_nodes_stream(text, size, lists, &rest_size);
    if (rest) {
        int rc = parse_document(rest, rest_size, json, err, err_size);
        free(rest);
        if (rc == 0) {
            scene_node_lists_bind(lists, *json);
            return 0;
        }
        scene_node_lists_free(lists);
    }
    return parse_document(text, size, json, err, err_size);
}

int scene_parse_in(const char *text, size_t size, const char *const *sets, size_t set_count,
                   const char *dir, scene *out, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    cJSON *json;
    scene_node_lists lists;
    if (parse_with_lists(text, size, sets, set_count, &json, &lists, err, err_size))
        return -1;
    int rc = -1;
    for (size_t i = 0; i < set_count; i++)
        if (scene_override(json, sets[i], err, err_size) != 0) {
            scene_node_lists_free(&lists);
            cJSON_Delete(json);
            return -1;
        }
    out->node_lists = &lists;
    if (json_check_keys(json, "", top_keys, err, err_size) == 0 &&
        parse_settings(json, out, err, err_size) == 0 &&
        scene_parse_layout(json, dir, out, err, err_size) == 0 &&
        scene_parse_listener(cJSON_GetObjectItemCaseSensitive(json, "listener"), out, err,
                             err_size) == 0 &&
        parse_discharges(json, out, err, err_size) == 0 &&
        scene_parse_random(json, out, err, err_size) == 0 &&
        scene_parse_camera(cJSON_GetObjectItemCaseSensitive(json, "camera"), out, err,
                           err_size) == 0 &&
        scene_parse_aero(json, dir, out, err, err_size) == 0 &&
        scene_parse_fires(json, dir, out, err, err_size) == 0 &&
        check_duration(out, err, err_size) == 0) {
        drop_parsed_trees(json);
        rc = 0;
    }
    out->node_lists = NULL;
    scene_node_lists_free(&lists);
    out->json = json;
    if (rc != 0)
        scene_deinit(out);
    return rc;
}

int scene_parse_with(const char *text, size_t size, const char *const *sets, size_t set_count,
                     scene *out, char *err, size_t err_size)
{
    return scene_parse_in(text, size, sets, set_count, NULL, out, err, err_size);
}

int scene_parse(const char *text, size_t size, scene *out, char *err, size_t err_size)
{
    return scene_parse_with(text, size, NULL, 0, out, err, err_size);
}

int scene_read_file(const char *path, char **text, size_t *size, char *err, size_t err_size)
{
    *text = NULL;
    *size = 0;
    /* opened without blocking, so that a FIFO cannot stall the check */
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0) {
        snprintf(err, err_size, "%s: cannot open: %s", path, strerror(errno));
        if (fd >= 0)
            close(fd);
        return -1;
    }
    if (!S_ISREG(st.st_mode) || st.st_size > (off_t)SCENE_MAX_FILE_BYTES) {
        if (S_ISREG(st.st_mode))
            snprintf(err, err_size, "%s: %lld bytes, more than a scene file may hold (%u MiB)",
                     path, (long long)st.st_size, SCENE_MAX_FILE_BYTES >> 20);
        else
            snprintf(err, err_size, "%s: not a regular file (a device, FIFO or directory)",
                     path);
        close(fd);
        return -1;
    }
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open: %s", path, strerror(errno));
        close(fd);
        return -1;
    }
    char *buf = NULL;
    size_t n = 0, cap = 0;
    /* the file may grow while it is read: never past the cap */
    for (;;) {
        if (n == cap) {
            /* room for the whole file at once (one byte more to see its end) */
            char *grown = fg_big_grow(buf, &cap, n + 1, 1,
                                      st.st_size > 0 ? (size_t)st.st_size + 1 : 65536);
            if (!grown)
                break;
            buf = grown;
        }
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0 || n > SCENE_MAX_FILE_BYTES)
            break;
    }
    int failed = ferror(f) || n == cap || n > SCENE_MAX_FILE_BYTES;
    fclose(f);
    if (failed) {
        fg_big_free(buf);
        snprintf(err, err_size, "%s: cannot read the file%s", path,
                 n > SCENE_MAX_FILE_BYTES ? ": it grew past the scene file cap" : "");
        return -1;
    }
    *text = buf;
    *size = n;
    return 0;
}

const char *scene_dir_of(const char *path, char *buf, size_t size)
{
    snprintf(buf, size, "%s", path);
    char *slash = strrchr(buf, '/');
    if (!slash)
        return NULL;
    slash[slash == buf ? 1 : 0] = '\0'; /* "/x.json": the root */
    return buf;
}

int scene_load_with(const char *path, const char *const *sets, size_t set_count, scene *out,
                    char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    char *text;
    size_t size;
    if (scene_read_file(path, &text, &size, err, err_size) != 0)
        return -1;
    char dir[4096];
    int rc = scene_parse_in(text, size, sets, set_count, scene_dir_of(path, dir, sizeof dir),
                            out, err, err_size);
    fg_big_free(text);
    return rc;
}

int scene_load(const char *path, scene *out, char *err, size_t err_size)
{
    return scene_load_with(path, NULL, 0, out, err, err_size);
}

void scene_deinit(scene *s)
{
    if (!s)
        return;
    for (size_t i = 0; i < s->discharge_count; i++)
        scene_discharge_free_tree(&s->discharges[i]);
    free(s->discharges);
    scene_aero_free(s);
    scene_fire_free(s);
    free(s->poses);
    free(s->sofa_file);
    cJSON_Delete(s->json);
    memset(s, 0, sizeof *s);
}
