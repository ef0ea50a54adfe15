/* The frame as a PNG file: written under a temporary name beside the
 * target and renamed over it, so that no error leaves a partial file. No
 * time chunk is written: the same frame gives the same bytes. */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "picture_internal.h"

/* libpng reports through longjmp; the message is kept for ours. */
static void png_error_fn(png_structp png, png_const_charp message)
{
    char *keep = png_get_error_ptr(png);
    snprintf(keep, 256, "%s", message);
    png_longjmp(png, 1);
}

static void png_warning_fn(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

/* Writes the rows to f; 0, or -1 with why in reason (256 bytes). */
static int write_rows(FILE *f, const uint8_t *rgba, int w, int h, char *reason)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, reason, png_error_fn,
                                              png_warning_fn);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info) {
        png_destroy_write_struct(&png, NULL);
        snprintf(reason, 256, "libpng could not start");
        return -1;
    }
    png_bytep *rows = malloc((size_t)h * sizeof *rows);
    if (!rows) {
        png_destroy_write_struct(&png, &info);
        snprintf(reason, 256, "no memory");
        return -1;
    }
    for (int y = 0; y < h; y++)
        rows[y] = (png_bytep)(rgba + (size_t)y * 4 * (size_t)w);
    int rc = -1;
    if (setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, f);
        png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGBA,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
        png_set_rows(png, info, rows);
        png_write_png(png, info, PNG_TRANSFORM_IDENTITY, NULL);
        rc = 0;
    }
    png_destroy_write_struct(&png, &info);
    free(rows);
    return rc;
}

static mode_t current_umask(void)
{
    mode_t mask = umask(0);
    umask(mask);
    return mask;
}

fg_result fgg_picture_write_png(fgg_picture *p, const char *path)
{
    if (!p || !path)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_write_png: %s is NULL",
                        !p ? "picture" : "path");
    size_t bytes = 4 * (size_t)p->width * (size_t)p->height;
    uint8_t *rgba = malloc(bytes);
    size_t tlen = strlen(path) + sizeof ".tmp-XXXXXX";
    char *temp = malloc(tlen);
    if (!rgba || !temp) {
        free(rgba);
        free(temp);
        return fgg_fail(FG_ERR_NO_MEMORY, "fgg_picture_write_png: no memory");
    }
    fg_result r = fgg_picture_read_rgba8(p, rgba);
    if (r != FG_OK) {
        free(rgba);
        free(temp);
        return r;
    }
    snprintf(temp, tlen, "%s.tmp-XXXXXX", path);
    char reason[256] = "";
    int fd = mkstemp(temp);
    FILE *f = NULL;
    if (fd < 0) {
        snprintf(reason, sizeof reason, "cannot create a file there: %s", strerror(errno));
    } else if (fchmod(fd, 0666 & ~current_umask()) != 0) {
        /* mkstemp makes it private: a PNG gets the mode any new file gets */
        snprintf(reason, sizeof reason, "cannot set its mode: %s", strerror(errno));
        close(fd);
        fd = -1;
        remove(temp);
    } else if (!(f = fdopen(fd, "wb"))) {
        snprintf(reason, sizeof reason, "cannot open it: %s", strerror(errno));
        close(fd);
    }
    int ok = f && write_rows(f, rgba, p->width, p->height, reason) == 0;
    if (f && fflush(f) != 0 && ok) {
        snprintf(reason, sizeof reason, "cannot write: %s", strerror(errno));
        ok = 0;
    }
    if (f && fclose(f) != 0 && ok) {
        snprintf(reason, sizeof reason, "cannot write: %s", strerror(errno));
        ok = 0;
    }
    if (ok && rename(temp, path) != 0) {
        snprintf(reason, sizeof reason, "cannot rename the temporary file into place: %s",
                 strerror(errno));
        ok = 0;
    }
    if (!ok && fd >= 0)
        remove(temp);
    free(rgba);
    free(temp);
    if (!ok)
        return fgg_fail(FG_ERR_ARGUMENT, "%s: %s", path, reason);
    return FG_OK;
}
