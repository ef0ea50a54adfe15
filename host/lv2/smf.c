/* Standard MIDI File reading: chunks, variable-length numbers, running
 * status, the tempo map (meta 0x51) and SMPTE divisions. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "smf.h"
#include "fg_array.h"

#define MAX_FILE_BYTES (64u << 20)
#define DEFAULT_TEMPO_US 500000.0   /* 120 bpm until a tempo event */

typedef struct raw_event {
    uint64_t tick;
    size_t order;     /* position in the file: ties stay in file order */
    int tempo;        /* 1: a tempo change of tempo_us per quarter note */
    double tempo_us;
    uint8_t status, data1, data2;
} raw_event;

typedef struct reader {
    const uint8_t *p, *end;
    raw_event *events;
    size_t count, capacity;
    char *err;
    size_t err_size;
    const char *name;   /* the file, for messages */
} reader;

static int fail(reader *r, const char *what, size_t track)
{
    snprintf(r->err, r->err_size, "%s: %s (track %zu)", r->name, what, track);
    return -1;
}

static int varlen(const uint8_t **p, const uint8_t *end, uint32_t *out)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++) {
        if (*p >= end)
            return -1;
        uint8_t b = *(*p)++;
        v = v << 7 | (b & 0x7f);
        if (!(b & 0x80)) {
            *out = v;
            return 0;
        }
    }
    return -1;   /* more than four bytes */
}

static int push(reader *r, raw_event e)
{
    raw_event *grown = fg_array_grow(r->events, &r->capacity, r->count + 1, sizeof *grown, 256);
    if (!grown)
        return -1;
    r->events = grown;
    e.order = r->count;
    r->events[r->count++] = e;
    return 0;
}

static int read_track(reader *r, const uint8_t *p, const uint8_t *end, size_t track)
{
    uint64_t tick = 0;
    uint8_t running = 0;
    while (p < end) {
        uint32_t delta;
        if (varlen(&p, end, &delta) != 0 || p >= end)
            return fail(r, "truncated event", track);
        tick += delta;
        uint8_t status = *p;
        if (status == 0xff || status == 0xf0 || status == 0xf7) {
            uint8_t type = 0;
            p++;
            if (status == 0xff) {
                if (p >= end)
                    return fail(r, "truncated meta event", track);
                type = *p++;
            }
            uint32_t len;
            if (varlen(&p, end, &len) != 0 || (size_t)(end - p) < len)
                return fail(r, "truncated meta or sysex event", track);
            if (status == 0xff && type == 0x2f)
                return 0;   /* end of track */
            if (status == 0xff && type == 0x51) {
                if (len != 3)
                    return fail(r, "tempo event not 3 bytes", track);
                double us = (double)(p[0] << 16 | p[1] << 8 | p[2]);
                if (us <= 0 || push(r, (raw_event){.tick = tick, .tempo = 1, .tempo_us = us}))
                    return fail(r, us <= 0 ? "tempo of zero" : "out of memory", track);
            }
            p += len;
            running = 0;   /* meta and sysex cancel running status */
            continue;
        }
        if (status & 0x80)
            running = *p++;
        else if (!running)
            return fail(r, "running status with no status before it", track);
        if (running >= 0xf0)
            return fail(r, "system message inside a track", track);
        int bytes = (running & 0xf0) == 0xc0 || (running & 0xf0) == 0xd0 ? 1 : 2;
        if (end - p < bytes)
            return fail(r, "truncated channel message", track);
        uint8_t d1 = p[0], d2 = bytes == 2 ? p[1] : 0;
        p += bytes;
        if ((d1 | d2) & 0x80)
            return fail(r, "data byte above 127", track);
        if (bytes == 2 &&
            push(r, (raw_event){.tick = tick, .status = running, .data1 = d1, .data2 = d2}))
            return fail(r, "out of memory", track);
    }
    return fail(r, "track ends without an end-of-track event", track);
}

static int by_tick(const void *a, const void *b)
{
    const raw_event *x = a, *y = b;
    if (x->tick != y->tick)
        return x->tick < y->tick ? -1 : 1;
    return x->order < y->order ? -1 : x->order > y->order;
}

static uint8_t *slurp(const char *path, size_t *size, char *err, size_t err_size)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open", path);
        return NULL;
    }
    uint8_t *data = malloc(MAX_FILE_BYTES);
    size_t n = data ? fread(data, 1, MAX_FILE_BYTES, f) : 0;
    int too_big = data && n == MAX_FILE_BYTES && fgetc(f) != EOF;
    fclose(f);
    if (!data || too_big) {
        snprintf(err, err_size, "%s: %s", path, data ? "larger than 64 MiB" : "out of memory");
        free(data);
        return NULL;
    }
    *size = n;
    return data;
}

static uint32_t be32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

int smf_read(const char *path, smf_event **events, size_t *count, char *err, size_t err_size)
{
    size_t size;
    uint8_t *data = slurp(path, &size, err, err_size);
    if (!data)
        return -1;
    int result = smf_parse(data, size, path, events, count, err, err_size);
    free(data);
    return result;
}

int smf_parse(const uint8_t *data, size_t size, const char *name, smf_event **events,
              size_t *count, char *err, size_t err_size)
{
    reader r = {.p = data, .end = data + size, .err = err, .err_size = err_size, .name = name};
    int ok = size >= 14 && !memcmp(data, "MThd", 4) && be32(data + 4) >= 6 &&
             be32(data + 4) <= size - 8;
    if (!ok) {
        snprintf(err, err_size, "%s: not a Standard MIDI File (no MThd header)", name);
        return -1;
    }
    unsigned format = (unsigned)(data[8] << 8 | data[9]);
    unsigned division = (unsigned)(data[12] << 8 | data[13]);
    double tick_s = 0, ticks_per_quarter = division;
    if (division & 0x8000) {   /* SMPTE: frames per second and ticks per frame */
        int fps = -(int8_t)(division >> 8), per_frame = division & 0xff;
        tick_s = fps > 0 && per_frame > 0 ? 1.0 / (fps * per_frame) : 0;
    }
    if (format > 1 || (!(division & 0x8000) && division == 0) || ((division & 0x8000) && !tick_s)) {
        snprintf(err, err_size, "%s: format %u or division %u not supported (formats 0 and 1)",
                 name, format, division);
        return -1;
    }
    const uint8_t *p = data + 8 + be32(data + 4);
    size_t track = 0;
    while (ok && r.end - p >= 8) {
        uint32_t len = be32(p + 4);
        if ((size_t)(r.end - p - 8) < len) {
            ok = fail(&r, "chunk runs past the end of the file", track) == 0;
            break;
        }
        if (!memcmp(p, "MTrk", 4))
            ok = read_track(&r, p + 8, p + 8 + len, track++) == 0;
        p += 8 + len;   /* chunks of other types are skipped, as the standard says */
    }
    smf_event *out = ok ? malloc((r.count ? r.count : 1) * sizeof *out) : NULL;
    if (!out) {
        if (ok)
            snprintf(err, err_size, "%s: out of memory", name);
        free(r.events);
        return -1;
    }
    if (r.count)   /* no track, or empty ones: events is NULL, which qsort may not take */
        qsort(r.events, r.count, sizeof *r.events, by_tick);
    double tempo_us = DEFAULT_TEMPO_US, t_s = 0;
    uint64_t last_tick = 0;
    size_t n = 0;
    for (size_t i = 0; i < r.count; i++) {
        const raw_event *e = &r.events[i];
        double per_tick = division & 0x8000 ? tick_s : tempo_us * 1e-6 / ticks_per_quarter;
        t_s += (double)(e->tick - last_tick) * per_tick;
        last_tick = e->tick;
        if (e->tempo)
            tempo_us = e->tempo_us;
        else
            out[n++] = (smf_event){t_s, e->status, e->data1, e->data2};
    }
    free(r.events);
    *events = out;
    *count = n;
    return 0;
}
