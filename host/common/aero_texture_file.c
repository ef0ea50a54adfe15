/* Encoding and decoding of aerodynamic sound texture files. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "aero_texture_file.h"
#include "fg_array.h"
#include "temp_file.h"

#define HEADER_BYTES 160u
#define DIRECTION_BYTES 64u
#define SOURCE_BYTES 16u
#define CRC_BYTES 4u
#define MAX_FILE_BYTES ((uint64_t)1 << 36)

/* --- little-endian fields ------------------------------------------------ */

static void put_u32(uint8_t *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (uint8_t)(v >> (8 * i));
}

static void put_u64(uint8_t *p, uint64_t v)
{
    for (int i = 0; i < 8; i++)
        p[i] = (uint8_t)(v >> (8 * i));
}

static void put_f64(uint8_t *p, double v)
{
    uint64_t u;
    memcpy(&u, &v, sizeof u);
    put_u64(p, u);
}

static void put_f32(uint8_t *p, float v)
{
    uint32_t u;
    memcpy(&u, &v, sizeof u);
    put_u32(p, u);
}

static uint32_t get_u32(const uint8_t *p)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++)
        v |= (uint32_t)p[i] << (8 * i);
    return v;
}

static uint64_t get_u64(const uint8_t *p)
{
    uint64_t v = 0;
    for (int i = 0; i < 8; i++)
        v |= (uint64_t)p[i] << (8 * i);
    return v;
}

static double get_f64(const uint8_t *p)
{
    uint64_t u = get_u64(p);
    double v;
    memcpy(&v, &u, sizeof v);
    return v;
}

static float get_f32(const uint8_t *p)
{
    uint32_t u = get_u32(p);
    float v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* The header's fields, in file order. */
enum {
    OFF_MAGIC = 0, OFF_VERSION = 8, OFF_HEADER = 12, OFF_SHAPE = 16, OFF_TONE = 20,
    OFF_DIMS = 24, OFF_COMPONENTS = 28, OFF_SOURCES = 32, OFF_DIRECTIONS = 36,
    OFF_VERTICES = 40, OFF_ROTATION = 44, OFF_MIRROR = 48, OFF_RESERVED = 52,
    OFF_LENGTH = 56, OFF_HEIGHT = 64, OFF_DIAMETER0 = 72, OFF_DIAMETER1 = 80,
    OFF_REFERENCE = 88, OFF_SPEED = 96, OFF_VISCOSITY = 104, OFF_DENSITY = 112,
    OFF_REYNOLDS = 120, OFF_RATE = 128, OFF_CELLS = 136, OFF_MIRROR_ANGLE = 144,
    OFF_FILE_BYTES = 152
};

/* The file size the counts imply; 0 when it overflows the limit. */
static uint64_t expected_bytes(uint32_t vertices, uint32_t sources, uint32_t directions,
                               const uint64_t *floats)
{
    uint64_t n = HEADER_BYTES + 16ull * vertices + (uint64_t)SOURCE_BYTES * sources +
                 (uint64_t)DIRECTION_BYTES * directions + CRC_BYTES;
    if (*floats > MAX_FILE_BYTES / 4)
        return 0;
    n += 4 * *floats;
    return n <= MAX_FILE_BYTES ? n : 0;
}

int aero_texture_encode(const fg_aero_texture *t, uint8_t **bytes, size_t *size)
{
    const fg_aero_texture_desc *d = fg_aero_texture_get(t);
    uint64_t floats = 0;
    for (uint32_t i = 0; i < d->directions; i++)
        floats += (uint64_t)d->direction[i].frames * d->sources * d->components;
    uint64_t n = expected_bytes(d->polygon_vertices, d->sources, d->directions, &floats);
    uint8_t *b = n ? calloc(1, (size_t)n) : NULL;
    if (!b)
        return -1;
    memcpy(b + OFF_MAGIC, AERO_TEXTURE_MAGIC, 8);
    put_u32(b + OFF_VERSION, AERO_TEXTURE_VERSION);
    put_u32(b + OFF_HEADER, HEADER_BYTES);
    put_u32(b + OFF_SHAPE, (uint32_t)d->shape);
    put_u32(b + OFF_TONE, (uint32_t)d->tone);
    put_u32(b + OFF_DIMS, d->dims);
    put_u32(b + OFF_COMPONENTS, d->components);
    put_u32(b + OFF_SOURCES, d->sources);
    put_u32(b + OFF_DIRECTIONS, d->directions);
    put_u32(b + OFF_VERTICES, d->polygon_vertices);
    put_u32(b + OFF_ROTATION, d->rotation_order);
    put_u32(b + OFF_MIRROR, d->mirror);
    put_f64(b + OFF_LENGTH, d->length_m);
    put_f64(b + OFF_HEIGHT, d->height_m);
    put_f64(b + OFF_DIAMETER0, d->diameter_m[0]);
    put_f64(b + OFF_DIAMETER1, d->diameter_m[1]);
    put_f64(b + OFF_REFERENCE, d->reference_m);
    put_f64(b + OFF_SPEED, d->speed_m_s);
    put_f64(b + OFF_VISCOSITY, d->viscosity_m2_s);
    put_f64(b + OFF_DENSITY, d->density_kg_m3);
    put_f64(b + OFF_REYNOLDS, d->reynolds);
    put_f64(b + OFF_RATE, d->sample_rate_hz);
    put_f64(b + OFF_CELLS, d->cells_per_length);
    put_f64(b + OFF_MIRROR_ANGLE, d->mirror_angle_rad);
    put_u64(b + OFF_FILE_BYTES, n);
    uint8_t *p = b + HEADER_BYTES;
    for (uint32_t i = 0; i < 2 * d->polygon_vertices; i++, p += 8)
        put_f64(p, d->polygon_xy[i]);
    for (uint32_t s = 0; s < d->sources; s++, p += SOURCE_BYTES) {
        put_f64(p, d->source[s].position_m);
        put_f64(p + 8, d->source[s].span_m);
    }
    for (uint32_t i = 0; i < d->directions; i++, p += DIRECTION_BYTES) {
        const fg_aero_direction *r = &d->direction[i];
        double v[7] = {r->angle_rad, r->frontal_m, r->frequency_hz, r->strouhal,
                       r->lift_amplitude, r->drag_mean, r->transient_s};
        for (int k = 0; k < 7; k++)
            put_f64(p + 8 * k, v[k]);
        put_u32(p + 56, r->periods);
        put_u32(p + 60, r->frames);
    }
    for (uint32_t i = 0; i < d->directions; i++) {
        size_t m = (size_t)d->direction[i].frames * d->sources * d->components;
        for (size_t k = 0; k < m; k++, p += 4)
            put_f32(p, d->direction[i].samples[k]);
    }
    put_u32(p, (uint32_t)crc32_z(0L, b, (z_size_t)(p - b)));
    *bytes = b;
    *size = (size_t)n;
    return 0;
}

static int fail(char *err, size_t size, const char *name, const char *fmt, ...)
{
    char what[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(err, size, "%s: %s", name, what);
    return -1;
}

/* A count in [lo, hi], or a message naming it. */
static int count_in(uint32_t v, uint32_t lo, uint32_t hi, const char *what, const char *name,
                    char *err, size_t size)
{
    if (v >= lo && v <= hi)
        return 0;
    return fail(err, size, name, "%s is %u (must be %u..%u)", what, v, lo, hi);
}

int aero_texture_decode(const uint8_t *b, size_t size, const char *name, fg_aero_texture **out,
                        char *err, size_t err_size)
{
    if (size < HEADER_BYTES + CRC_BYTES)
        return fail(err, err_size, name, "truncated: %zu bytes, less than a header (%u)", size,
                    HEADER_BYTES + CRC_BYTES);
    if (memcmp(b + OFF_MAGIC, AERO_TEXTURE_MAGIC, 8) != 0)
        return fail(err, err_size, name, "not a fulgur aero texture (no \"%s\" magic)",
                    AERO_TEXTURE_MAGIC);
    uint32_t version = get_u32(b + OFF_VERSION);
    if (version != AERO_TEXTURE_VERSION)
        return fail(err, err_size, name, "format version %u; this fulgur reads version %u",
                    version, AERO_TEXTURE_VERSION);
    if (get_u32(b + OFF_HEADER) != HEADER_BYTES)
        return fail(err, err_size, name, "header size %u, expected %u", get_u32(b + OFF_HEADER),
                    HEADER_BYTES);
    uint64_t stated = get_u64(b + OFF_FILE_BYTES);
    if (stated != size)
        return fail(err, err_size, name, "%s: the header says %llu bytes, the file has %zu",
                    stated > size ? "truncated" : "wrong size", (unsigned long long)stated, size);
    uint32_t crc = (uint32_t)crc32_z(0L, b, (z_size_t)(size - CRC_BYTES));
    if (crc != get_u32(b + size - CRC_BYTES))
        return fail(err, err_size, name, "checksum mismatch (CRC-32 %08x, stored %08x): corrupt",
                    crc, get_u32(b + size - CRC_BYTES));
    fg_aero_texture_desc d = {0};
    d.shape = (fg_aero_shape)get_u32(b + OFF_SHAPE);
    d.tone = (fg_aero_tone)get_u32(b + OFF_TONE);
    d.dims = get_u32(b + OFF_DIMS);
    d.components = get_u32(b + OFF_COMPONENTS);
    d.sources = get_u32(b + OFF_SOURCES);
    d.directions = get_u32(b + OFF_DIRECTIONS);
    d.polygon_vertices = get_u32(b + OFF_VERTICES);
    d.rotation_order = get_u32(b + OFF_ROTATION);
    d.mirror = get_u32(b + OFF_MIRROR);
    if (count_in((uint32_t)d.shape, FG_AERO_CIRCLE, FG_AERO_CLUB, "shape", name, err, err_size) ||
        count_in((uint32_t)d.tone, FG_AERO_AEOLIAN, FG_AERO_CAVITY, "tone", name, err, err_size) ||
        count_in(d.dims, 2, 3, "dims", name, err, err_size) ||
        count_in(d.components, d.dims, d.dims, "components", name, err, err_size) ||
        count_in(d.sources, 1, FG_AERO_MAX_SOURCES, "sources", name, err, err_size) ||
        count_in(d.directions, 1, FG_AERO_MAX_DIRECTIONS, "directions", name, err, err_size) ||
        count_in(d.polygon_vertices, 0, FG_AERO_MAX_POLYGON, "polygon vertices", name, err,
                 err_size) ||
        count_in(d.rotation_order, 0, 12, "rotation order", name, err, err_size) ||
        count_in(d.mirror, 0, 1, "mirror", name, err, err_size) ||
        count_in(get_u32(b + OFF_RESERVED), 0, 0, "the reserved word", name, err, err_size))
        return -1;
    static const struct {
        int offset;
        const char *what;
    } scalars[] = {{OFF_LENGTH, "length"},     {OFF_HEIGHT, "height"},
                   {OFF_DIAMETER0, "diameter"}, {OFF_DIAMETER1, "tip diameter"},
                   {OFF_REFERENCE, "reference"}, {OFF_SPEED, "speed"},
                   {OFF_VISCOSITY, "viscosity"}, {OFF_DENSITY, "density"},
                   {OFF_REYNOLDS, "Reynolds number"}, {OFF_RATE, "sample rate"},
                   {OFF_CELLS, "grid resolution"}, {OFF_MIRROR_ANGLE, "mirror angle"}};
    for (size_t i = 0; i < sizeof scalars / sizeof scalars[0]; i++)
        if (!isfinite(get_f64(b + scalars[i].offset)))
            return fail(err, err_size, name, "the %s is not a finite number", scalars[i].what);
    d.length_m = get_f64(b + OFF_LENGTH);
    d.height_m = get_f64(b + OFF_HEIGHT);
    d.diameter_m[0] = get_f64(b + OFF_DIAMETER0);
    d.diameter_m[1] = get_f64(b + OFF_DIAMETER1);
    d.reference_m = get_f64(b + OFF_REFERENCE);
    d.speed_m_s = get_f64(b + OFF_SPEED);
    d.viscosity_m2_s = get_f64(b + OFF_VISCOSITY);
    d.density_kg_m3 = get_f64(b + OFF_DENSITY);
    d.reynolds = get_f64(b + OFF_REYNOLDS);
    d.sample_rate_hz = get_f64(b + OFF_RATE);
    d.cells_per_length = get_f64(b + OFF_CELLS);
    d.mirror_angle_rad = get_f64(b + OFF_MIRROR_ANGLE);
    /* the sections' sizes before reading them */
    const uint8_t *dirs = b + HEADER_BYTES + 16ull * d.polygon_vertices +
                          (uint64_t)SOURCE_BYTES * d.sources;
    if ((uint64_t)(dirs - b) + (uint64_t)DIRECTION_BYTES * d.directions + CRC_BYTES > size)
        return fail(err, err_size, name, "truncated: %u directions do not fit in %zu bytes",
                    d.directions, size);
    uint64_t floats = 0;
    for (uint32_t i = 0; i < d.directions; i++) {
        uint32_t frames = get_u32(dirs + (size_t)i * DIRECTION_BYTES + 60);
        if (frames < 1 || frames > FG_AERO_MAX_FRAMES)
            return fail(err, err_size, name, "direction %u has %u frames (must be 1..%u)", i,
                        frames, FG_AERO_MAX_FRAMES);
        floats += (uint64_t)frames * d.sources * d.components;
    }
    uint64_t want = expected_bytes(d.polygon_vertices, d.sources, d.directions, &floats);
    if (want != size)
        return fail(err, err_size, name, "the counts make %llu bytes, the file has %zu",
                    (unsigned long long)want, size);
    double *poly = malloc((2 * (size_t)d.polygon_vertices + 1) * sizeof(double));
    fg_aero_source *src = malloc(d.sources * sizeof *src);
    fg_aero_direction *dir = malloc(d.directions * sizeof *dir);
    float *samples = malloc((size_t)(floats ? floats : 1) * sizeof(float));
    int rc = 0;
    if (!poly || !src || !dir || !samples) {
        rc = fail(err, err_size, name, "out of memory for %llu samples",
                  (unsigned long long)floats);
        goto done;
    }
    const uint8_t *p = b + HEADER_BYTES;
    for (uint32_t i = 0; i < 2 * d.polygon_vertices; i++, p += 8)
        poly[i] = get_f64(p);
    for (uint32_t s = 0; s < d.sources; s++, p += SOURCE_BYTES) {
        src[s].position_m = get_f64(p);
        src[s].span_m = get_f64(p + 8);
    }
    float *next = samples;
    const uint8_t *data = dirs + (size_t)DIRECTION_BYTES * d.directions;
    for (uint32_t i = 0; i < d.directions; i++, p += DIRECTION_BYTES) {
        fg_aero_direction *r = &dir[i];
        r->angle_rad = get_f64(p);
        r->frontal_m = get_f64(p + 8);
        r->frequency_hz = get_f64(p + 16);
        r->strouhal = get_f64(p + 24);
        r->lift_amplitude = get_f64(p + 32);
        r->drag_mean = get_f64(p + 40);
        r->transient_s = get_f64(p + 48);
        r->periods = get_u32(p + 56);
        r->frames = get_u32(p + 60);
        size_t m = (size_t)r->frames * d.sources * d.components;
        for (size_t k = 0; k < m; k++, data += 4) {
            next[k] = get_f32(data);
            if (!isfinite(next[k])) {
                rc = fail(err, err_size, name, "sample %zu of direction %u is not finite", k, i);
                goto done;
            }
        }
        r->samples = next;
        next += m;
    }
    d.polygon_xy = poly;
    d.source = src;
    d.direction = dir;
    fg_aero_texture *t;
    fg_result r = fg_aero_texture_create(&d, &t);
    if (r != FG_OK)
        rc = fail(err, err_size, name, "not a valid texture: %s (shape %u, %u directions, "
                  "%u sources, speed %g m/s, Re %g)", fg_result_str(r), (unsigned)d.shape,
                  d.directions, d.sources, d.speed_m_s, d.reynolds);
    else
        *out = t;
done:
    free(poly);
    free(src);
    free(dir);
    free(samples);
    return rc;
}

int aero_texture_save(const fg_aero_texture *t, const char *path, char *err, size_t err_size)
{
    uint8_t *bytes;
    size_t size;
    if (aero_texture_encode(t, &bytes, &size) != 0)
        return fail(err, err_size, path, "out of memory");
    temp_file tf;
    if (temp_file_open(&tf, path, err, err_size) != 0) {
        free(bytes);
        return -1;
    }
    FILE *f = temp_file_stream(&tf);
    int ok = f && fwrite(bytes, 1, size, f) == size;
    free(bytes);
    if (!ok) {
        temp_file_abort(&tf);
        return fail(err, err_size, path, "cannot write: %s", strerror(errno));
    }
    return temp_file_commit(&tf, err, err_size);
}

int aero_texture_load(const char *path, fg_aero_texture **out, char *err, size_t err_size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return fail(err, err_size, path, "cannot open: %s", strerror(errno));
    uint8_t *bytes = NULL;
    size_t size = 0, cap = 0;
    for (;;) {
        if (size == cap) {
            uint8_t *grown =
                size < MAX_FILE_BYTES ? fg_array_grow(bytes, &cap, size + 1, 1, 1 << 16) : NULL;
            if (!grown) {
                free(bytes);
                fclose(f);
                return fail(err, err_size, path, "too large, or out of memory");
            }
            bytes = grown;
        }
        size_t got = fread(bytes + size, 1, cap - size, f);
        size += got;
        if (got == 0)
            break;
    }
    int bad = ferror(f);
    fclose(f);
    int rc = bad ? fail(err, err_size, path, "cannot read: %s", strerror(errno))
                 : aero_texture_decode(bytes, size, path, out, err, err_size);
    free(bytes);
    return rc;
}
