/* Output names: a file, a directory or a pattern. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "render_output.h"

/* The scene file's name without its folder and extension. */
static void scene_name(const char *scene, char *out, size_t size)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    const char *dot = strrchr(base, '.');
    size_t n = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    snprintf(out, size, "%.*s", (int)n, base);
}

/* target with {name} and {index} replaced; NULL when out of memory. */
static char *expand(const char *target, const char *name, size_t index)
{
    char number[24];
    snprintf(number, sizeof number, "%zu", index);
    size_t cap = strlen(target) + 1;
    for (const char *at = target; (at = strchr(at, '{')); at++)
        cap += strlen(name) + strlen(number);
    char *out = malloc(cap), *w = out;
    if (!out)
        return NULL;
    for (const char *r = target; *r;) {
        const char *piece = NULL;
        size_t skip = 0;
        if (strncmp(r, "{name}", 6) == 0)
            piece = name, skip = 6;
        else if (strncmp(r, "{index}", 7) == 0)
            piece = number, skip = 7;
        if (piece) {
            w += sprintf(w, "%s", piece);
            r += skip;
        } else {
            *w++ = *r++;
        }
    }
    *w = '\0';
    return out;
}

static bool is_directory(const char *target)
{
    struct stat st;
    size_t n = strlen(target);
    return (n > 0 && target[n - 1] == '/') || (stat(target, &st) == 0 && S_ISDIR(st.st_mode));
}

int render_output_paths(const char *option, const char *target, const char *const *scenes,
                        size_t count, const char *extension, char **paths, char *err,
                        size_t err_size)
{
    bool pattern = strstr(target, "{name}") || strstr(target, "{index}");
    bool directory = !pattern && is_directory(target);
    if (!pattern && !directory && count > 1) {
        snprintf(err, err_size,
                 "%s %s: %zu scenes need a directory or a pattern with {name} or {index}",
                 option, target, count);
        return -1;
    }
    memset(paths, 0, count * sizeof *paths);
    for (size_t i = 0; i < count; i++) {
        char name[256];
        scene_name(scenes[i], name, sizeof name);
        if (pattern) {
            paths[i] = expand(target, name, i + 1);
        } else if (directory) {
            size_t n = strlen(target) + strlen(name) + strlen(extension) + 2;
            if ((paths[i] = malloc(n)))
                snprintf(paths[i], n, "%s%s%s%s", target,
                         target[strlen(target) - 1] == '/' ? "" : "/", name, extension);
        } else {
            paths[i] = strdup(target);
        }
        if (!paths[i]) {
            render_output_free(paths, count);
            snprintf(err, err_size, "out of memory");
            return -1;
        }
        for (size_t k = 0; k < i; k++)
            if (strcmp(paths[k], paths[i]) == 0) {
                snprintf(err, err_size, "%s and %s would both write %s (%s: use {index})",
                         scenes[k], scenes[i], paths[i], option);
                render_output_free(paths, count);
                return -1;
            }
    }
    return 0;
}

int render_output_make_directory(const char *option, const char *target, char *err,
                                 size_t err_size)
{
    size_t n = strlen(target);
    if (n == 0 || target[n - 1] != '/' || strstr(target, "{name}") || strstr(target, "{index}") ||
        mkdir(target, 0777) == 0 || errno == EEXIST)
        return 0;
    snprintf(err, err_size, "%s %s: cannot make the directory: %s", option, target,
             strerror(errno));
    return -1;
}

void render_output_free(char **paths, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        free(paths[i]);
        paths[i] = NULL;
    }
}
