/* Write-then-rename output files. */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen, fchmod */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "temp_file.h"

int temp_file_open(temp_file *t, const char *path, char *err, size_t err_size)
{
    memset(t, 0, sizeof *t);
    t->fd = -1;
    size_t n = strlen(path);
    t->path = malloc(n + 1);
    t->temp_path = malloc(n + sizeof ".tmp-XXXXXX");
    if (t->path && t->temp_path) {
        memcpy(t->path, path, n + 1);
        snprintf(t->temp_path, n + sizeof ".tmp-XXXXXX", "%s.tmp-XXXXXX", path);
        t->fd = mkstemp(t->temp_path);
    }
    if (t->fd < 0) {
        snprintf(err, err_size, "%s: cannot create: %s", path,
                 t->temp_path ? strerror(errno) : "out of memory");
        free(t->path);
        free(t->temp_path);
        memset(t, 0, sizeof *t);
        return -1;
    }
    /* mkstemp makes the file private; give it the mode a new file gets */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(t->fd, 0666 & ~mask) != 0) {
        snprintf(err, err_size, "%s: cannot set the mode: %s", path, strerror(errno));
        temp_file_abort(t);
        return -1;
    }
    return 0;
}

FILE *temp_file_stream(temp_file *t)
{
    if (!t->stream)
        t->stream = fdopen(t->fd, "w");
    return t->stream;
}

static int close_file(temp_file *t)
{
    int rc = t->stream ? fclose(t->stream) : close(t->fd);
    t->stream = NULL;
    t->fd = -1;
    return rc;
}

int temp_file_commit(temp_file *t, char *err, size_t err_size)
{
    if (close_file(t) != 0 || rename(t->temp_path, t->path) != 0) {
        snprintf(err, err_size, "%s: cannot write: %s", t->path, strerror(errno));
        temp_file_abort(t);
        return -1;
    }
    free(t->path);
    free(t->temp_path);
    memset(t, 0, sizeof *t);
    return 0;
}

void temp_file_abort(temp_file *t)
{
    if (t->stream || t->fd >= 0)
        close_file(t);
    if (t->temp_path)
        unlink(t->temp_path);
    free(t->path);
    free(t->temp_path);
    memset(t, 0, sizeof *t);
    t->fd = -1;
}
