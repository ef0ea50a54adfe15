/* The aerodynamic sound texture file: a round trip bit for bit, and every
 * way a file can be wrong — each refused with a message naming the file
 * and the fault, and nothing made; a failed save leaves no file. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include <cmocka.h>

#include "common/aero_texture_file.h"
#include "fg_math.h"


/* A small texture by hand: a polygon with 3 directions (or a 3-D club
 * with 3 sources), samples a known function. */
static fg_aero_texture *make(int club)
{
    static double poly[8] = {-0.01, -0.002, 0.01, -0.002, 0.01, 0.002, -0.01, 0.002};
    static float samples[3][3 * 50 * 3];
    fg_aero_source src[3] = {{0.05, 0.1}, {0.15, 0.1}, {0.25, 0.1}};
    fg_aero_direction dir[3];
    uint32_t sources = club ? 3 : 1, comps = club ? 3 : 2, directions = club ? 1 : 3;
    for (uint32_t i = 0; i < directions; i++) {
        uint32_t frames = 40 + 5 * i;
        for (uint32_t k = 0; k < frames * sources * comps; k++)
            samples[i][k] = (float)(sin(0.37 * k + i) * 1e-3 * (k % 7));
        dir[i] = (fg_aero_direction){.angle_rad = i * 5.0 * FG_PI / 180.0, .frontal_m = 0.004,
                                     .frequency_hz = 500 + i, .strouhal = 0.2 + 0.001 * i,
                                     .lift_amplitude = 0.7, .drag_mean = 1.9,
                                     .transient_s = 0.06, .periods = 4, .frames = frames,
                                     .samples = samples[i]};
    }
    fg_aero_texture_desc d = {
        .shape = club ? FG_AERO_CLUB : FG_AERO_POLYGON, .tone = FG_AERO_AEOLIAN,
        .dims = club ? 3 : 2, .components = comps,
        .length_m = club ? 0.3 : 0.0, .diameter_m = {club ? 0.02 : 0, club ? 0.05 : 0},
        .polygon_vertices = club ? 0 : 4, .polygon_xy = club ? NULL : poly,
        .reference_m = club ? 0.05 : 0.004, .speed_m_s = 10.0, .viscosity_m2_s = 1.5e-5,
        .density_kg_m3 = 1.204, .sample_rate_hz = 16000, .cells_per_length = 24,
        .rotation_order = club ? 0 : 2, .mirror = 1, .sources = sources, .source = src,
        .directions = directions, .direction = dir};
    d.reynolds = d.reference_m * d.speed_m_s / d.viscosity_m2_s;
    fg_aero_texture *t = NULL;
    assert_int_equal(fg_aero_texture_create(&d, &t), FG_OK);
    return t;
}

static void same(const fg_aero_texture *a, const fg_aero_texture *b)
{
    const fg_aero_texture_desc *x = fg_aero_texture_get(a), *y = fg_aero_texture_get(b);
    assert_int_equal(x->shape, y->shape);
    assert_int_equal(x->directions, y->directions);
    assert_int_equal(x->sources, y->sources);
    assert_true(x->reynolds == y->reynolds && x->speed_m_s == y->speed_m_s &&
                x->sample_rate_hz == y->sample_rate_hz && x->mirror_angle_rad == y->mirror_angle_rad);
    for (uint32_t i = 0; i < 2 * x->polygon_vertices; i++)
        assert_true(x->polygon_xy[i] == y->polygon_xy[i]);
    for (uint32_t s = 0; s < x->sources; s++)
        assert_true(x->source[s].position_m == y->source[s].position_m &&
                    x->source[s].span_m == y->source[s].span_m);
    for (uint32_t i = 0; i < x->directions; i++) {
        const fg_aero_direction *p = &x->direction[i], *q = &y->direction[i];
        assert_true(p->angle_rad == q->angle_rad && p->strouhal == q->strouhal &&
                    p->frames == q->frames && p->periods == q->periods);
        assert_memory_equal(p->samples, q->samples,
                            (size_t)p->frames * x->sources * x->components * sizeof(float));
    }
}

/* Encoded, decoded, encoded again: the same bytes; saved and loaded. */
static void round_trip(void **state)
{
    (void)state;
    for (int club = 0; club < 2; club++) {
        fg_aero_texture *t = make(club), *u = NULL;
        uint8_t *bytes, *again;
        size_t size, size2;
        char err[512];
        assert_int_equal(aero_texture_encode(t, &bytes, &size), 0);
        assert_memory_equal(bytes, AERO_TEXTURE_MAGIC, 8);
        assert_int_equal(aero_texture_decode(bytes, size, "mem", &u, err, sizeof err), 0);
        same(t, u);
        assert_int_equal(aero_texture_encode(u, &again, &size2), 0);
        assert_int_equal(size, size2);
        assert_memory_equal(bytes, again, size);
        char path[] = "/tmp/fulgur-aerotex-XXXXXX";
        int fd = mkstemp(path);
        assert_true(fd >= 0);
        close(fd);
        fg_aero_texture *v = NULL;
        assert_int_equal(aero_texture_save(t, path, err, sizeof err), 0);
        assert_int_equal(aero_texture_load(path, &v, err, sizeof err), 0);
        same(t, v);
        unlink(path);
        free(bytes);
        free(again);
        fg_aero_texture_destroy(t);
        fg_aero_texture_destroy(u);
        fg_aero_texture_destroy(v);
    }
}

/* Re-seals a modified file with a correct checksum, so that the check
 * behind the checksum is the one that answers. */
static void reseal(uint8_t *b, size_t size)
{
    uint32_t crc = (uint32_t)crc32_z(0L, b, size - 4);
    for (int i = 0; i < 4; i++)
        b[size - 4 + i] = (uint8_t)(crc >> (8 * i));
}

static void put32(uint8_t *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (uint8_t)(v >> (8 * i));
}

static void put64f(uint8_t *p, double v)
{
    uint64_t u;
    memcpy(&u, &v, 8);
    for (int i = 0; i < 8; i++)
        p[i] = (uint8_t)(u >> (8 * i));
}

static void refused(const uint8_t *b, size_t size, const char *needle)
{
    fg_aero_texture *t = (fg_aero_texture *)&needle; /* must stay untouched */
    char err[512] = "";
    assert_int_equal(aero_texture_decode(b, size, "bad.aerotex", &t, err, sizeof err), -1);
    assert_ptr_equal(t, (fg_aero_texture *)&needle);
    if (strncmp(err, "bad.aerotex: ", 13) != 0 || !strstr(err, needle))
        fail_msg("expected \"%s\" in \"%s\"", needle, err);
}

/* Header offsets (docs/aero-texture-format.md). */
enum { VERSION = 8, HEADER = 12, SHAPE = 16, TONE = 20, DIMS = 24, SOURCES = 32,
       DIRECTIONS = 36, VERTICES = 40, ROTATION = 44, RESERVED = 52, SPEED = 96, REYNOLDS = 120,
       RATE = 128, FIRST_DIRECTION = 160 + 64 + 16 };

static void corrupt(void **state)
{
    (void)state;
    fg_aero_texture *t = make(0);
    uint8_t *good, *b;
    size_t size;
    assert_int_equal(aero_texture_encode(t, &good, &size), 0);
    b = malloc(size);
    /* every truncation */
    for (size_t n = 0; n < size; n++) {
        fg_aero_texture *u = NULL;
        char err[512];
        assert_int_equal(aero_texture_decode(good, n, "bad.aerotex", &u, err, sizeof err), -1);
        assert_null(u);
        assert_true(strstr(err, "truncated") || strstr(err, "magic") || strstr(err, "size"));
    }
    refused(good, 100, "truncated");
    refused(good, size - 1, "truncated: the header says");
    /* one flipped bit anywhere: the checksum */
    for (size_t at = 0; at < size; at += 7) {
        memcpy(b, good, size);
        b[at] ^= 0x10;
        fg_aero_texture *u = NULL;
        char err[512];
        assert_int_equal(aero_texture_decode(b, size, "bad.aerotex", &u, err, sizeof err), -1);
        assert_null(u);
    }
    memcpy(b, good, size);
    b[size / 2] ^= 1;
    refused(b, size, "checksum mismatch");
    /* behind the checksum */
    static const struct {
        int offset;
        uint32_t value;
        const char *needle;
    } words[] = {
        {0, 0x45544147, "magic"},
        {VERSION, 2, "format version 2; this fulgur reads version 1"},
        {HEADER, 128, "header size 128"},
        {SHAPE, 9, "shape is 9"},
        {TONE, 3, "tone is 3"},
        {DIMS, 3, "components is 2"},
        {SOURCES, 0, "sources is 0"},
        {DIRECTIONS, 0, "directions is 0"},
        {DIRECTIONS, 100000, "directions is 100000"},
        {DIRECTIONS, 2, "counts make"},
        {VERTICES, 5000, "polygon vertices is 5000"},
        {ROTATION, 13, "rotation order is 13"},
        {RESERVED, 32, "the reserved word is 32"},
        {SHAPE, FG_AERO_CIRCLE, "not a valid texture"},          /* a polygon called a circle */
        {FIRST_DIRECTION + 60, 0, "direction 0 has 0 frames"},
        {FIRST_DIRECTION + 60, 41, "counts make"},
        {FIRST_DIRECTION + 56, 0, "not a valid texture"},        /* no whole period */
    };
    for (size_t k = 0; k < sizeof words / sizeof words[0]; k++) {
        memcpy(b, good, size);
        put32(b + words[k].offset, words[k].value);
        if (words[k].offset != 0)
            reseal(b, size);
        refused(b, size, words[k].needle);
    }
    static const struct {
        int offset;
        double value;
        const char *needle;
    } reals[] = {
        {SPEED, NAN, "speed is not a finite number"},
        {RATE, INFINITY, "sample rate is not a finite number"},
        {SPEED, -10.0, "not a valid texture"},
        {REYNOLDS, 1234.0, "not a valid texture"},               /* Re != D v0 / nu */
        {FIRST_DIRECTION, 3.0, "not a valid texture"},           /* angle outside 0..90 deg */
        {FIRST_DIRECTION + 64, 0.0, "not a valid texture"},      /* angles not increasing */
        {FIRST_DIRECTION + 16, NAN, "not a valid texture"},      /* frequency */
    };
    for (size_t k = 0; k < sizeof reals / sizeof reals[0]; k++) {
        memcpy(b, good, size);
        put64f(b + reals[k].offset, reals[k].value);
        reseal(b, size);
        refused(b, size, reals[k].needle);
    }
    /* a NaN sample, re-sealed */
    memcpy(b, good, size);
    size_t first_sample = FIRST_DIRECTION + 3 * 64;
    float nan = NAN;
    uint32_t bits;
    memcpy(&bits, &nan, 4);
    put32(b + first_sample + 4 * 17, bits);
    reseal(b, size);
    refused(b, size, "sample 17 of direction 0 is not finite");
    free(b);
    free(good);
    fg_aero_texture_destroy(t);
}

/* Files: a missing file, a directory that is not there (no temporary
 * left, nothing written), an older file kept when the new one fails. */
static void files(void **state)
{
    (void)state;
    fg_aero_texture *t = make(1), *u = NULL;
    char err[512];
    assert_int_equal(aero_texture_load("/nonexistent/x.aerotex", &u, err, sizeof err), -1);
    assert_non_null(strstr(err, "/nonexistent/x.aerotex: cannot open"));
    assert_null(u);
    assert_int_equal(aero_texture_save(t, "/nonexistent/dir/x.aerotex", err, sizeof err), -1);
    assert_non_null(strstr(err, "/nonexistent/dir/x.aerotex"));
    /* an older file survives a failed load of garbage written elsewhere */
    char path[] = "/tmp/fulgur-aerotex-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, "hello", 5), 5);
    close(fd);
    assert_int_equal(aero_texture_load(path, &u, err, sizeof err), -1);
    assert_non_null(strstr(err, "truncated"));
    assert_int_equal(aero_texture_save(t, path, err, sizeof err), 0);
    assert_int_equal(aero_texture_load(path, &u, err, sizeof err), 0);
    same(t, u);
    unlink(path);
    fg_aero_texture_destroy(t);
    fg_aero_texture_destroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(round_trip),
        cmocka_unit_test(corrupt),
        cmocka_unit_test(files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
