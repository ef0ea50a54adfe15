/* libFuzzer target for the fire API (fulgur/fire.h): any bytes become a
 * stream configuration and a flux series, or a burn field and a velocity
 * on a small grid. Whatever the values (NaN, infinities, huge, denormal),
 * each call either succeeds with finite output within its stated bounds or
 * refuses with an error and changes nothing. Corpus:
 * corpus/fulgur_fuzz_fire/ (byte 0 picks the part, byte 1 the settings,
 * then little-endian doubles). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fulgur/fire.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_STEPS 512
#define GRID 6

static fg_fire_texture *texture_8k(void)
{
    static fg_fire_texture *t;
    if (!t) {
        static float clip[12000];
        if (fg_fire_training_clip(8000.0, 1, clip, 12000) != FG_OK)
            abort();
        fg_fire_texture_config c = {.samples = clip, .frames = 12000, .sample_rate_hz = 8000.0};
        if (fg_fire_texture_create(&c, &t) != FG_OK)
            abort();
    }
    return t;
}

static size_t doubles(const uint8_t *data, size_t size, double *out, size_t max)
{
    size_t n = size / 8 < max ? size / 8 : max;
    memcpy(out, data, n * 8);
    return n;
}

static void fuzz_stream(uint8_t settings, const uint8_t *data, size_t size)
{
    static const double rates[] = {8000.0, 44100.0, 48000.0};
    fg_fire_sound_config c = {
        .sample_rate_hz = rates[settings % 3],
        .sim_rate_hz = (settings & 8) ? 240.0 : 360.0,
        .extension = (fg_fire_extension)((settings >> 4) % 3),
        .bwe = {.alpha = 1.0 + (settings >> 6), .seed = settings},
    };
    if (c.extension == FG_FIRE_TEXTURE) {
        c.sample_rate_hz = 8000.0;
        c.texture = texture_8k();
    }
    fg_fire_sound *s;
    if (fg_fire_sound_create(&c, &s) != FG_OK)
        abort();
    static double flux[MAX_STEPS];
    size_t steps = doubles(data, size, flux, MAX_STEPS);
    size_t cap = fg_fire_sound_max_frames(s, steps) + fg_fire_sound_drain_frames(s);
    float *out = malloc(sizeof(float) * cap);
    size_t total = 0, frames;
    /* in blocks of 1 .. 8 steps */
    for (size_t i = 0; i < steps;) {
        size_t k = 1 + (size_t)(data[i % size] & 7);
        if (k > steps - i)
            k = steps - i;
        fg_fire_sound_stats before, after;
        fg_fire_sound_get_stats(s, &before);
        fg_result r = fg_fire_sound_process(s, flux + i, k, out + total, cap - total, &frames);
        fg_fire_sound_get_stats(s, &after);
        if (r != FG_OK) {
            if ((r != FG_ERR_NOT_FINITE && r != FG_ERR_ARGUMENT) || frames != 0 ||
                after.flux_steps != before.flux_steps)
                abort();
        } else if (frames > fg_fire_sound_max_frames(s, k)) {
            abort();
        }
        total += frames;
        i += k;
    }
    if (fg_fire_sound_drain(s, out + total, cap - total, &frames) != FG_OK)
        abort();
    total += frames;
    for (size_t i = 0; i < total; i++)
        if (!isfinite(out[i]))
            abort();
    free(out);
    fg_fire_sound_destroy(s);
}

static void fuzz_front(uint8_t settings, const uint8_t *data, size_t size)
{
    fg_flame_front_config c = {.grid = {{GRID, GRID, GRID}, {0, 0, 0}, 0.1},
                               .iso_level = 0.5, .subdivision = 1 + settings % 3};
    fg_flame_front *f;
    if (fg_flame_front_create(&c, &f) != FG_OK)
        abort();
    enum { CELLS = GRID * GRID * GRID, FACES = (GRID + 1) * GRID * GRID };
    static double burn[CELLS], u[3][FACES], values[CELLS + 3 * FACES];
    size_t n = doubles(data, size, values, CELLS + 3 * FACES);
    if (n == 0) {
        fg_flame_front_destroy(f);
        return;
    }
    for (size_t i = 0; i < CELLS; i++)
        burn[i] = values[i % n];
    for (int a = 0; a < 3; a++)
        for (size_t i = 0; i < FACES; i++)
            u[a][i] = values[(CELLS + a * FACES + i) % n];
    fg_flame_velocity v = {(settings & 4) ? FG_VELOCITY_COLLOCATED : FG_VELOCITY_MAC,
                           {u[0], u[1], u[2]}};
    fg_flame_flux out = {.flux_m3_s = 7.0};
    fg_result r = fg_flame_front_flux(f, burn, &v, &out);
    const double *xyz;
    size_t tris;
    if (fg_flame_front_triangles(f, &xyz, &tris) != FG_OK)
        abort();
    if (r == FG_OK) {
        if (!isfinite(out.flux_m3_s) || !isfinite(out.area_m2) || out.area_m2 < 0 ||
            tris != out.triangles)
            abort();
        for (size_t i = 0; i < 9 * tris; i++)
            if (!isfinite(xyz[i]) || xyz[i] < -0.2 || xyz[i] > 0.8)
                abort();
    } else if ((r != FG_ERR_NOT_FINITE && r != FG_ERR_ARGUMENT) || out.flux_m3_s != 7.0 ||
               tris != 0) {
        abort();
    }
    fg_flame_front_destroy(f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    if (data[0] & 1)
        fuzz_front(data[1], data + 2, size - 2);
    else
        fuzz_stream(data[1], data + 2, size - 2);
    return 0;
}
