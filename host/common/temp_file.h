/* An output file that appears only when complete: it is written under a
 * temporary name in the same directory and renamed over the final path at
 * commit, so a failed run leaves no file behind (and an older file at that
 * path untouched). */
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

/* Creates the temporary file next to path. Returns 0, or -1 with a message
 * naming path in err. */
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
