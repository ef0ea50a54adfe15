/* Opening the GL module (gl_module.h). */
#define _GNU_SOURCE /* readlink of /proc/self/exe */
#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "common/commands.h"
#include "gl_module.h"

#define GL_MODULE_FILE "fulgur-gl.so"

static pthread_once_t once = PTHREAD_ONCE_INIT;
static const gl_module *opened;
static char why[1024]; /* the reason opened is NULL */

/* Appends "path: reason" to why (cut at its end). */
static void note(const char *path, const char *reason)
{
    size_t used = strlen(why);
    if (snprintf(why + used, sizeof why - used, "%s%s: %s", used ? "; " : "", path, reason) < 0)
        why[used] = '\0';
}

/* Opens dir/rel; the table, or NULL with dlopen's reason appended to why. */
static const gl_module *try_open(const char *dir, const char *rel)
{
    char path[PATH_MAX + 64];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    if (access(path, F_OK) != 0) {
        note(path, "absent");
        return NULL;
    }
    void *lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    const gl_module *m = lib ? dlsym(lib, GL_MODULE_SYMBOL) : NULL;
    if (m && m->version == GL_MODULE_VERSION)
        return m; /* stays open for the process */
    note(path, !lib || !m ? dlerror() : "a module of another fulgur version (its table differs)");
    if (lib)
        dlclose(lib);
    return NULL;
}

static void open_module(void)
{
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) {
        snprintf(why, sizeof why, "cannot find the program's own path (/proc/self/exe)");
        return;
    }
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (slash)
        *slash = '\0';
    opened = try_open(exe, GL_MODULE_FILE);
    if (!opened)
        opened = try_open(exe, FULGUR_GL_MODULE_FROM_BIN);
}

const gl_module *gl_module_get(char *err, size_t err_size)
{
    pthread_once(&once, open_module);
    if (!opened)
        snprintf(err, err_size, "cannot open fulgur's GL module (view, --png, \"solver\": "
                                "\"gpu\"): %s", why);
    return opened;
}

int gl_view_main(int argc, char **argv)
{
    char err[1200];
    const gl_module *m = gl_module_get(err, sizeof err);
    if (!m) {
        fprintf(stderr, "fulgur view: %s\n", err);
        return CLI_RUNTIME;
    }
    return m->view_main(argc, argv);
}

fg_result gl_field_gpu_grow(fg_field *description, const fg_growth_config *growth, fg_tree *out,
                            double *residual, char *msg, size_t msg_size)
{
    const gl_module *m = gl_module_get(msg, msg_size);
    *residual = 0;
    return m ? m->field_gpu_grow(description, growth, out, residual, msg, msg_size)
             : FG_ERR_UNSUPPORTED;
}
