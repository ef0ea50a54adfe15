/* A WAV opened through a header of our own (wav_file.h). */
#define _POSIX_C_SOURCE 200809L /* fseeko, ftello */
#define _FILE_OFFSET_BITS 64    /* and a 64-bit off_t where long is 32 bits */
#include "wav_file.h"

#include <stdarg.h>
#include <stdbool.h>
#include <string.h>
#include <sys/types.h>

#include "text_escape.h"

/* "not known": the size a streaming writer leaves, or RF64's pointer to ds64 */
#define SIZE_NOT_KNOWN UINT32_MAX

typedef enum { KIND_RIFF, KIND_RIFX, KIND_RF64 } wav_kind;

/* What the walk found in the file. */
typedef struct found {
    wav_kind kind;
    uint64_t file_bytes;
    bool fmt, data, ds64, comment;
    uint64_t fmt_at; /* its contents */
    uint32_t fmt_bytes;
    uint64_t data_at;   /* the samples */
    uint32_t data_size; /* as data's header says */
    uint64_t ds64_data_bytes;
    uint32_t riff_size;
    char text[WAV_FILE_MAX_COMMENT + 1];
} found;

/* Writes "name: " and what into err; returns -1. */
static int fail(char *err, size_t err_size, const char *name, const char *what, ...)
    __attribute__((format(printf, 4, 5)));

static int fail(char *err, size_t err_size, const char *name, const char *what, ...)
{
    int n = snprintf(err, err_size, "%s: ", name);
    va_list ap;
    va_start(ap, what);
    if (n >= 0 && (size_t)n < err_size)
        vsnprintf(err + n, err_size - (size_t)n, what, ap);
    va_end(ap);
    return -1;
}

static uint32_t get32(const unsigned char *b, bool big_endian)
{
    return big_endian ? (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3]
                      : (uint32_t)b[3] << 24 | (uint32_t)b[2] << 16 | (uint32_t)b[1] << 8 | b[0];
}

static uint64_t get64(const unsigned char *b)
{
    return (uint64_t)get32(b + 4, false) << 32 | get32(b, false);
}

static void put32(unsigned char *b, uint32_t v, bool big_endian)
{
    for (int k = 0; k < 4; k++)
        b[big_endian ? 3 - k : k] = (unsigned char)(v >> (8 * k));
}

static void put64(unsigned char *b, uint64_t v)
{
    put32(b, (uint32_t)v, false);
    put32(b + 4, (uint32_t)(v >> 32), false);
}

/* Reads bytes at byte at of in; false when the file does not hold them. */
static bool read_at(FILE *in, uint64_t at, void *out, size_t bytes)
{
    return at <= INT64_MAX && fseeko(in, (off_t)at, SEEK_SET) == 0 &&
           fread(out, 1, bytes, in) == bytes;
}

/* The comment (ICMT) of the LIST/INFO chunk whose contents lie at
 * [at, end), if it holds one within it: each step moves on by at least 8
 * bytes, and a sub-chunk claiming past the list ends the walk. */
static void read_comment(FILE *in, uint64_t at, uint64_t end, bool big_endian, found *f)
{
    unsigned char head[8];
    if (!read_at(in, at, head, 4) || memcmp(head, "INFO", 4) != 0)
        return;
    for (at += 4; at + 8 <= end;) {
        if (!read_at(in, at, head, 8))
            return;
        uint32_t size = get32(head + 4, big_endian);
        if (size > end - at - 8)
            return;
        if (memcmp(head, "ICMT", 4) == 0) {
            size_t n = size < WAV_FILE_MAX_COMMENT ? size : WAV_FILE_MAX_COMMENT;
            if (!read_at(in, at + 8, f->text, n))
                return;
            f->text[n] = '\0';
            f->comment = true;
            return;
        }
        at += 8 + (uint64_t)size + (size & 1u);
    }
}

/* The chunk id at b, escaped for a message. */
static void chunk_id(const unsigned char *b, char *id, size_t id_size)
{
    char raw[5] = {0};
    memcpy(raw, b, 4);
    text_escape(id, id_size, raw);
}

/* The sample bytes data's header (or ds64) declares; those the file holds
 * where it says "not known", as does a size of 0 in a RIFF whose own size
 * is 8 (a writer that never closed the file, as libsndfile reads it). */
static uint64_t declared(const found *f, uint64_t rest)
{
    if (f->kind == KIND_RF64 && f->data_size == SIZE_NOT_KNOWN)
        return f->ds64 ? f->ds64_data_bytes : rest;
    if (f->data_size == SIZE_NOT_KNOWN || (f->data_size == 0 && f->riff_size == 8))
        return rest;
    return f->data_size;
}

/* Walks the file's chunks into f (wav_file.h says what is refused). */
static int walk(FILE *in, const char *name, found *f, char *err, size_t err_size)
{
    unsigned char head[12];
    if (fseeko(in, 0, SEEK_END) != 0 || ftello(in) < 0)
        return fail(err, err_size, name, "cannot seek in it: fulgur reads WAV files, not streams");
    f->file_bytes = (uint64_t)ftello(in);
    if (!read_at(in, 0, head, 12) || memcmp(head + 8, "WAVE", 4) != 0 ||
        (memcmp(head, "RIFF", 4) != 0 && memcmp(head, "RIFX", 4) != 0 &&
         memcmp(head, "RF64", 4) != 0))
        return fail(err, err_size, name,
                    "not a WAV file: it does not start with RIFF, RIFX or RF64 and WAVE");
    f->kind = head[1] == 'F' ? KIND_RF64 : head[3] == 'F' ? KIND_RIFF : KIND_RIFX;
    const bool big_endian = f->kind == KIND_RIFX;
    f->riff_size = get32(head + 4, big_endian);
    /* each step moves on by at least 8 bytes: the walk ends */
    for (uint64_t at = 12; at + 8 <= f->file_bytes;) {
        if (!read_at(in, at, head, 8))
            break;
        const uint32_t size = get32(head + 4, big_endian);
        const uint64_t room = f->file_bytes - at - 8;
        uint64_t bytes = size;
        if (memcmp(head, "data", 4) == 0 && !f->data) {
            f->data = true;
            f->data_at = at + 8;
            f->data_size = size;
            bytes = declared(f, room);
            if (bytes >= room)
                break; /* the samples run to the file's end */
        } else if (size > room) {
            if (f->fmt && f->data)
                break; /* what follows the samples is not needed */
            char id[4 * 4 + 1];
            chunk_id(head, id, sizeof id);
            return fail(err, err_size, name,
                        "its '%s' chunk at byte %llu claims %u bytes, past the file's end "
                        "(%llu bytes)",
                        id, (unsigned long long)at, size, (unsigned long long)f->file_bytes);
        } else if (memcmp(head, "fmt ", 4) == 0 && !f->fmt) {
            if (size < 16 || size > WAV_FILE_MAX_FMT_BYTES)
                return fail(err, err_size, name, "its 'fmt ' chunk holds %u bytes, outside 16..%u",
                            size, WAV_FILE_MAX_FMT_BYTES);
            f->fmt = true;
            f->fmt_at = at + 8;
            f->fmt_bytes = size;
        } else if (memcmp(head, "ds64", 4) == 0 && f->kind == KIND_RF64 && size >= 28 && !f->ds64) {
            unsigned char sizes[16];
            if (!read_at(in, at + 8, sizes, sizeof sizes))
                break;
            f->ds64 = true;
            f->ds64_data_bytes = get64(sizes + 8);
        } else if (memcmp(head, "LIST", 4) == 0 && !f->comment) {
            read_comment(in, at + 8, at + 8 + size, big_endian, f);
        }
        at += 8 + bytes + (bytes & 1u);
    }
    if (!f->fmt)
        return fail(err, err_size, name, "it has no 'fmt ' chunk");
    if (!f->data)
        return fail(err, err_size, name, "it has no 'data' chunk");
    return 0;
}

/* Appends a chunk header to w's header. */
static void put_chunk(wav_file *w, const char *id, uint32_t size, bool big_endian)
{
    memcpy(w->header + w->header_bytes, id, 4);
    put32(w->header + w->header_bytes + 4, size, big_endian);
    w->header_bytes += 8;
}

/* w's header for what f found: the file's kind, ds64 (RF64), the fmt
 * chunk's bytes, the comment, data's header. */
static int write_header(wav_file *w, const found *f)
{
    const bool big_endian = f->kind == KIND_RIFX, rf64 = f->kind == KIND_RF64;
    size_t comment = f->comment ? strlen(f->text) + 1 : 0;
    comment += comment & 1u;
    size_t bytes = 12 + (rf64 ? 36 : 0) + 8 + f->fmt_bytes + (f->fmt_bytes & 1u) +
                   (comment ? 20 + comment : 0) + 8;
    /* a RIFF's 32-bit sizes hold its samples */
    if (!rf64 && w->held_bytes > UINT32_MAX - bytes)
        w->held_bytes = w->declared_bytes = UINT32_MAX - bytes;
    uint64_t riff = bytes - 8 + w->held_bytes;
    w->header_bytes = 0;
    static const char *const ids[] = {
        [KIND_RIFF] = "RIFF", [KIND_RIFX] = "RIFX", [KIND_RF64] = "RF64"};
    put_chunk(w, ids[f->kind], rf64 ? SIZE_NOT_KNOWN : (uint32_t)riff, big_endian);
    memcpy(w->header + w->header_bytes, "WAVE", 4);
    w->header_bytes += 4;
    if (rf64) {
        put_chunk(w, "ds64", 28, false);
        unsigned char *d = w->header + w->header_bytes;
        memset(d, 0, 28);
        put64(d, riff);
        put64(d + 8, w->held_bytes);
        w->header_bytes += 28;
    }
    put_chunk(w, "fmt ", f->fmt_bytes, big_endian);
    if (!read_at(w->in, f->fmt_at, w->header + w->header_bytes, f->fmt_bytes))
        return -1;
    w->header_bytes += f->fmt_bytes;
    if (f->fmt_bytes & 1u)
        w->header[w->header_bytes++] = 0;
    if (comment) {
        put_chunk(w, "LIST", (uint32_t)(12 + comment), big_endian);
        memcpy(w->header + w->header_bytes, "INFO", 4);
        w->header_bytes += 4;
        put_chunk(w, "ICMT", (uint32_t)comment, big_endian);
        memset(w->header + w->header_bytes, 0, comment);
        memcpy(w->header + w->header_bytes, f->text, strlen(f->text));
        w->header_bytes += comment;
    }
    put_chunk(w, "data", rf64 ? SIZE_NOT_KNOWN : (uint32_t)w->held_bytes, big_endian);
    return 0;
}

static sf_count_t view_length(void *user)
{
    const wav_file *w = user;
    return (sf_count_t)(w->header_bytes + w->held_bytes);
}

/* As a file's: any position from 0 on, past the end as well (libsndfile
 * seeks over an odd data chunk's pad byte, and then sees the end). */
static sf_count_t view_seek(sf_count_t offset, int whence, void *user)
{
    wav_file *w = user;
    const sf_count_t base = whence == SEEK_SET   ? 0
                            : whence == SEEK_CUR ? (sf_count_t)w->at
                                                 : view_length(w);
    /* 0 <= base + offset <= INT64_MAX, tested without a sum that can overflow */
    if (offset < -base || offset > INT64_MAX - base)
        return -1;
    w->at = (uint64_t)(base + offset);
    return (sf_count_t)w->at;
}

static sf_count_t view_read(void *out, sf_count_t count, void *user)
{
    wav_file *w = user;
    const uint64_t end = w->header_bytes + w->held_bytes;
    uint64_t want = count < 0 || w->at >= end ? 0 : (uint64_t)count, done = 0;
    if (want > end - w->at)
        want = end - w->at;
    if (w->at < w->header_bytes) {
        done = w->header_bytes - w->at < want ? w->header_bytes - w->at : want;
        memcpy(out, w->header + w->at, (size_t)done);
    }
    if (done < want) {
        const uint64_t from = w->data_at + (w->at + done - w->header_bytes);
        if (from <= INT64_MAX && fseeko(w->in, (off_t)from, SEEK_SET) == 0)
            done += fread((unsigned char *)out + done, 1, (size_t)(want - done), w->in);
    }
    w->at += done;
    return (sf_count_t)done;
}

static sf_count_t view_write(const void *in, sf_count_t count, void *user)
{
    (void)in, (void)count, (void)user;
    return 0;
}

static sf_count_t view_tell(void *user)
{
    return (sf_count_t)((const wav_file *)user)->at;
}

int wav_open(wav_file *w, FILE *in, const char *name, char *err, size_t err_size)
{
    memset(w, 0, sizeof *w);
    found f = {0};
    if (walk(in, name, &f, err, err_size) != 0)
        return -1;
    const uint64_t rest = f.file_bytes - f.data_at;
    w->in = in;
    w->data_at = f.data_at;
    w->declared_bytes = declared(&f, rest);
    w->held_bytes = w->declared_bytes < rest ? w->declared_bytes : rest;
    if (write_header(w, &f) != 0)
        return fail(err, err_size, name, "cannot read its 'fmt ' chunk");
    SF_VIRTUAL_IO io = {view_length, view_seek, view_read, view_write, view_tell};
    w->sndfile = sf_open_virtual(&io, SFM_READ, &w->info, w);
    if (!w->sndfile)
        return fail(err, err_size, name, "libsndfile cannot read it: %s", sf_strerror(NULL));
    return 0;
}

void wav_close(wav_file *w)
{
    if (w->sndfile)
        sf_close(w->sndfile);
    w->sndfile = NULL;
}
