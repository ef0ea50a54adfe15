/* An output file that appears only when complete: it is written under a
 * temporary name in the same directory and renamed over the final path at
 * commit, so a failed run leaves no file behind (and an older file at that
 * path untouched). A path that names anything but a regular file (a device,
 * FIFO or directory) is refused, never replaced; a SIGINT, SIGTERM or
 * SIGHUP removes the temporaries still open before the process ends. */
#ifndef HOST_COMMON_TEMP_FILE_H
#define HOST_COMMON_TEMP_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct temp_file {
    char *path;        /* the final name */
    char *temp_path;   /* where it is written meanwhile */
    int fd;            /* open for writing */
    FILE *stream;      /* NULL until temp_file_stream */
} temp_file;

/* Refuses (-1 with a message naming output in err) an output path that
 * exists and is not a regular file (a device, FIFO or directory), or that
 * names the same file as input (the same device and inode, through any name
 * or link; input may be NULL). 0 otherwise, also for a path that does not
 * exist yet. Commands call it for every output before they start work. */
int temp_file_check_output(const char *output, const char *input, char *err, size_t err_size);

/* Creates the temporary file next to path; a path that is not a regular
 * file is refused here too (and again at commit). Returns 0, or -1 with a
 * message naming path in err. */
int temp_file_open(temp_file *t, const char *path, char *err, size_t err_size);

/* A stdio stream on the file, owned by t (closed by commit or abort); NULL
 * when it cannot be made. */
FILE *temp_file_stream(temp_file *t);

/* Closes the file and renames it to its final name. Returns 0, or -1 with a
 * message (the temporary file is then removed). Either way t is released. */
int temp_file_commit(temp_file *t, char *err, size_t err_size);

/* Closes and removes the temporary file; t is released. */
void temp_file_abort(temp_file *t);

#endif
