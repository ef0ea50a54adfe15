/* Write-then-rename output files.
 *
 * The temporary file is "<dir>/.fulgur-XXXXXX" next to the final path: a
 * name of its own, so that any final name the file system takes (up to
 * 255 bytes) works. Live temporaries are listed in a fixed table that a
 * SIGINT/SIGTERM handler walks with unlink (async-signal-safe) before the
 * signal's default action ends the process. */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen, fchmod, sigaction */
#include <errno.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "temp_file.h"

#define TEMP_NAME "/.fulgur-XXXXXX"
/* More outputs than any one command writes at once (WAV, PNG, report). */
#define TEMP_LIVE_MAX 8

static _Atomic(char *) live[TEMP_LIVE_MAX];
static atomic_flag handlers_installed = ATOMIC_FLAG_INIT;

static void remove_live(int sig)
{
    for (int i = 0; i < TEMP_LIVE_MAX; i++) {
        char *p = atomic_load(&live[i]);
        if (p)
            unlink(p);
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_handlers(void)
{
    if (atomic_flag_test_and_set(&handlers_installed))
        return;
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        struct sigaction old;
        /* a signal the caller ignores stays ignored */
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        struct sigaction sa = {.sa_handler = remove_live};
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[i], &sa, NULL);
    }
}

/* Lists t's temporary path for the handler; false when the table is full. */
static bool track(char *temp_path)
{
    for (int i = 0; i < TEMP_LIVE_MAX; i++) {
        char *none = NULL;
        if (atomic_compare_exchange_strong(&live[i], &none, temp_path))
            return true;
    }
    return false;
}

static void untrack(const char *temp_path)
{
    for (int i = 0; i < TEMP_LIVE_MAX; i++)
        if (atomic_load(&live[i]) == temp_path)
            atomic_store(&live[i], NULL);
}

static int check_path(const char *path, char *err, size_t err_size)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return 0; /* a new file, or a directory error that open reports */
    if (S_ISREG(st.st_mode))
        return 0;
    snprintf(err, err_size, "%s: is %s, not a regular file: refusing to replace it", path,
             S_ISDIR(st.st_mode)                         ? "a directory"
             : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
             : S_ISFIFO(st.st_mode)                       ? "a FIFO"
                                                          : "a special file");
    return -1;
}

int temp_file_check_output(const char *output, const char *input, char *err, size_t err_size)
{
    if (check_path(output, err, err_size) != 0)
        return -1;
    struct stat out, in;
    if (!input || stat(output, &out) != 0 || stat(input, &in) != 0)
        return 0; /* a new output, or an input that its reader reports */
    if (out.st_dev != in.st_dev || out.st_ino != in.st_ino)
        return 0;
    snprintf(err, err_size, "%s: is the input %s: refusing to overwrite it", output, input);
    return -1;
}

int temp_file_open(temp_file *t, const char *path, char *err, size_t err_size)
{
    memset(t, 0, sizeof *t);
    t->fd = -1;
    if (check_path(path, err, err_size) != 0)
        return -1;
    size_t n = strlen(path);
    const char *slash = strrchr(path, '/');
    size_t dir = slash ? (size_t)(slash - path) : 1; /* "." for a bare name */
    t->path = malloc(n + 1);
    t->temp_path = malloc(dir + sizeof TEMP_NAME);
    if (t->path && t->temp_path) {
        memcpy(t->path, path, n + 1);
        if (slash)
            memcpy(t->temp_path, path, dir);
        else
            t->temp_path[0] = '.';
        memcpy(t->temp_path + dir, TEMP_NAME, sizeof TEMP_NAME);
        install_handlers();
        /* listed before it exists, so that no signal can leave it behind */
        if (track(t->temp_path)) {
            t->fd = mkstemp(t->temp_path);
            if (t->fd < 0)
                untrack(t->temp_path);
        } else {
            errno = EMFILE;
        }
    }
    if (t->fd < 0) {
        snprintf(err, err_size, "%s: cannot create: %s", path,
                 t->temp_path ? strerror(errno) : "out of memory");
        free(t->path);
        free(t->temp_path);
        memset(t, 0, sizeof *t);
        t->fd = -1;
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

static void release(temp_file *t)
{
    untrack(t->temp_path);
    free(t->path);
    free(t->temp_path);
    memset(t, 0, sizeof *t);
    t->fd = -1;
}

int temp_file_commit(temp_file *t, char *err, size_t err_size)
{
    /* checked again: the path may have become a device meanwhile */
    if (check_path(t->path, err, err_size) != 0) {
        temp_file_abort(t);
        return -1;
    }
    if (close_file(t) != 0 || rename(t->temp_path, t->path) != 0) {
        snprintf(err, err_size, "%s: cannot write: %s", t->path, strerror(errno));
        temp_file_abort(t);
        return -1;
    }
    release(t);
    return 0;
}

void temp_file_abort(temp_file *t)
{
    if (t->stream || t->fd >= 0)
        close_file(t);
    if (t->temp_path)
        unlink(t->temp_path);
    release(t);
}
