/* Fire sound on one core (Chadwick & James 2011), without a fluid solver:
 * a procedural flame stands in for one (a plume of burn rate, wrinkled by
 * travelling waves that puff at 8-14 Hz, in an updraft with swirl, on a
 * 1 m cube, MAC velocity, iso 0.5).
 *   front: B-spline + marching cubes + flux per step at 32^3 .. 96^3
 *          (subdivision 1 and 2), against the 2.78 ms of a 360 Hz step;
 *   bwe:   10 s of that flame's flux (48^3) through bandwidth extension at
 *          44.1 and 48 kHz, x real time (eq. 13 on the default window and
 *          on table 1's);
 *   texture: the same flux through texture synthesis trained on the
 *          procedural clip, 8 s (the default) and 15 s (|D_1| like the
 *          paper's Dragon and Flame Jet, table 2), x real time.
 * Times are CPU seconds of this thread (the machine is shared); wall times
 * beside them. Writes bench/results/fire.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fg_math.h"
#include "bench_util.h"
#include "fulgur/fire.h"

#define SIM_HZ 360.0
#define FLUX_SECONDS 10.0
#define WAVES 12

typedef struct flame {
    double k[WAVES][3], omega[WAVES], phase[WAVES];
} flame;

static void check(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "fire_bench: %s: %s\n", what, fg_result_str(r));
        exit(1);
    }
}

static flame make_flame(void)
{
    flame f;
    unsigned s = 12345;
    for (int w = 0; w < WAVES; w++) {
        double r[5];
        for (int i = 0; i < 5; i++) {
            s = s * 1103515245u + 12345u;
            r[i] = (double)(s >> 8) / (double)(1u << 24);
        }
        double kk = 12.0 + 28.0 * r[0], th = FG_PI * r[1], ph = 2.0 * FG_PI * r[2];
        f.k[w][0] = kk * sin(th) * cos(ph);
        f.k[w][1] = kk * sin(th) * sin(ph);
        f.k[w][2] = kk * cos(th);
        f.omega[w] = 2.0 * FG_PI * (8.0 + 6.0 * r[3]);
        f.phase[w] = 2.0 * FG_PI * r[4];
    }
    return f;
}

/* The plume's shape at x (m): a cone of burn rate. */
static double plume_at(const double x[3])
{
    double dx = x[0] - 0.5, dy = x[1] - 0.5, z = x[2];
    double radius = 0.22 * (1.0 - 0.8 * z) + 0.02, r2 = dx * dx + dy * dy;
    return z < 0.05 ? 0.0 : 1.4 * exp(-r2 / (radius * radius)) * exp(-z * 1.2);
}

/* The fields on an n^3 grid over the unit cube. The burn rate is
 * plume (1 + 0.12 sum_w sin(k_w . x - omega_w t + phase_w)); each wave is
 * sin(k.x + phase) cos(omega t) - cos(k.x + phase) sin(omega t), so the
 * spatial parts are tabulated once and a step costs no sines. */
typedef struct fields {
    int n;
    double *burn, *u[3];
    double *plume, *wave_s, *wave_c; /* per cell; per cell and wave */
} fields;

static fields fields_alloc(const flame *f, int n)
{
    size_t cells = (size_t)n * n * n;
    fields g = {.n = n, .burn = malloc(sizeof(double) * cells),
                .plume = malloc(sizeof(double) * cells),
                .wave_s = malloc(sizeof(double) * cells * WAVES),
                .wave_c = malloc(sizeof(double) * cells * WAVES)};
    for (int a = 0; a < 3; a++)
        g.u[a] = malloc(sizeof(double) * (size_t)(n + 1) * n * n);
    double h = 1.0 / n;
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                size_t c = (size_t)i + (size_t)n * ((size_t)j + (size_t)n * k);
                double x[3] = {(i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h};
                g.plume[c] = plume_at(x);
                for (int w = 0; w < WAVES; w++) {
                    double arg = f->k[w][0] * x[0] + f->k[w][1] * x[1] + f->k[w][2] * x[2] +
                                 f->phase[w];
                    g.wave_s[c * WAVES + w] = sin(arg);
                    g.wave_c[c * WAVES + w] = cos(arg);
                }
            }
    return g;
}

static void fields_free(fields *g)
{
    free(g->burn);
    free(g->plume);
    free(g->wave_s);
    free(g->wave_c);
    for (int a = 0; a < 3; a++)
        free(g->u[a]);
}

/* An updraft, strongest on the axis, with swirl; travelling waves in z. */
static double velocity_at(const flame *f, int axis, const double x[3], double t)
{
    double dx = x[0] - 0.5, dy = x[1] - 0.5;
    switch (axis) {
    case 0:
        return -0.6 * dy + 0.2 * sin(9.0 * x[2] - f->omega[0] * t);
    case 1:
        return 0.6 * dx + 0.2 * cos(7.0 * x[2] - f->omega[1] * t);
    default:
        return 1.0 + 1.5 * exp(-(dx * dx + dy * dy) / 0.04) +
               0.3 * sin(11.0 * x[2] - f->omega[2] * t);
    }
}

static void fields_at(const flame *f, fields *g, double t)
{
    int n = g->n;
    size_t cells = (size_t)n * n * n;
    double co[WAVES], si[WAVES], h = 1.0 / n;
    for (int w = 0; w < WAVES; w++) {
        co[w] = cos(f->omega[w] * t);
        si[w] = sin(f->omega[w] * t);
    }
    for (size_t c = 0; c < cells; c++) {
        double wrinkle = 0.0;
        for (int w = 0; w < WAVES; w++)
            wrinkle += g->wave_s[c * WAVES + w] * co[w] - g->wave_c[c * WAVES + w] * si[w];
        g->burn[c] = g->plume[c] * (1.0 + 0.12 * wrinkle);
    }
    /* u[a] on the faces normal to a: face coordinates on axis a, centre
     * coordinates on the others */
    for (int a = 0; a < 3; a++) {
        int m[3] = {n, n, n};
        m[a]++;
        size_t at = 0;
        for (int k = 0; k < m[2]; k++)
            for (int j = 0; j < m[1]; j++)
                for (int i = 0; i < m[0]; i++, at++) {
                    double x[3] = {(i + 0.5 * (a != 0)) * h, (j + 0.5 * (a != 1)) * h,
                                   (k + 0.5 * (a != 2)) * h};
                    g->u[a][at] = velocity_at(f, a, x, t);
                }
    }
}

/* The front's cost per step at one grid size; optionally the flux series. */
static void front_rows(FILE *out, const flame *f, int n, int subdivision, int steps, double *flux)
{
    fg_flame_front_config c = {.grid = {{n, n, n}, {0, 0, 0}, 1.0 / n}, .iso_level = 0.5,
                               .subdivision = subdivision};
    fg_flame_front *front;
    check(fg_flame_front_create(&c, &front), "front");
    fields g = fields_alloc(f, n);
    double *cpu = malloc(sizeof(double) * (size_t)steps), *wall = malloc(sizeof(double) * (size_t)steps);
    double tris = 0.0;
    for (int s = 0; s < steps; s++) {
        fields_at(f, &g, s / SIM_HZ);
        fg_flame_velocity v = {FG_VELOCITY_MAC, {g.u[0], g.u[1], g.u[2]}};
        fg_flame_flux fl;
        double c0 = bench_cpu_s(), w0 = bench_now_s();
        check(fg_flame_front_flux(front, g.burn, &v, &fl), "flux");
        cpu[s] = bench_cpu_s() - c0;
        wall[s] = bench_now_s() - w0;
        tris += (double)fl.triangles / steps;
        if (flux)
            flux[s] = fl.flux_m3_s;
    }
    double mc = bench_median(cpu, (size_t)steps) * 1e3, mw = bench_median(wall, (size_t)steps) * 1e3;
    double budget = 1e3 / SIM_HZ;
    fprintf(out, "front,%d^3 sub %d,%d,%.0f,%.3f,%.3f,%.2f,of a %.2f ms step at %.0f Hz\n", n,
            subdivision, steps, tris, mc, mw, mc / budget, budget, SIM_HZ);
    printf("front %3d^3 sub %d: %7.0f triangles, %8.3f ms CPU (%.3f wall) per step = %5.2f x a "
           "360 Hz step\n",
           n, subdivision, tris, mc, mw, mc / budget);
    fflush(stdout);
    free(cpu);
    free(wall);
    fields_free(&g);
    fg_flame_front_destroy(front);
}

/* One stream over the flux series: CPU and wall seconds, frames. */
static void run_stream(const fg_fire_sound_config *c, const double *flux, size_t steps,
                       double *cpu_s, double *wall_s, size_t *frames)
{
    fg_fire_sound *s;
    check(fg_fire_sound_create(c, &s), "sound");
    size_t block = 6; /* a 60 Hz game frame's steps at 360 Hz */
    size_t cap = fg_fire_sound_max_frames(s, block);
    float *out = malloc(sizeof(float) * cap);
    size_t made = 0, n;
    double c0 = bench_cpu_s(), w0 = bench_now_s();
    for (size_t i = 0; i < steps; i += block) {
        size_t k = steps - i < block ? steps - i : block;
        check(fg_fire_sound_process(s, flux + i, k, out, cap, &n), "process");
        made += n;
    }
    *cpu_s = bench_cpu_s() - c0;
    *wall_s = bench_now_s() - w0;
    *frames = made;
    free(out);
    fg_fire_sound_destroy(s);
}

static void stream_rows(FILE *out, const char *what, const fg_fire_sound_config *c,
                        const double *flux, size_t steps, int repeats, const char *note)
{
    double cpu[8], wall[8];
    size_t frames = 0;
    for (int r = 0; r < repeats; r++)
        run_stream(c, flux, steps, &cpu[r], &wall[r], &frames);
    double mc = bench_median(cpu, (size_t)repeats), mw = bench_median(wall, (size_t)repeats);
    double audio = (double)frames / c->sample_rate_hz;
    fprintf(out, "%s,%.0f Hz,%d,%.2f,%.3f,%.3f,%.1f,%s\n", what, c->sample_rate_hz, repeats, audio,
            mc, mw, audio / mc, note);
    printf("%-8s %6.0f Hz: %.2f s of sound in %.3f s CPU (%.3f wall) = %.1f x real time%s%s\n",
           what, c->sample_rate_hz, audio, mc, mw, audio / mc, *note ? "; " : "", note);
    fflush(stdout);
}

int main(void)
{
    FILE *out = bench_open_result("fire.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    fprintf(out, "# fulgur fire_bench, one thread; %s\n", machine);
    fprintf(out, "# front rows: kind,grid,steps,mean triangles,median CPU ms,median wall ms,"
                 "CPU / 360 Hz step,note\n");
    fprintf(out, "# stream rows: kind,rate,repeats,audio s,median CPU s,median wall s,"
                 "x real time (CPU),note\n");
    flame f = make_flame();
    size_t steps = (size_t)(FLUX_SECONDS * SIM_HZ);
    double *flux = malloc(sizeof(double) * steps);
    front_rows(out, &f, 32, 1, 360, NULL);
    front_rows(out, &f, 32, 2, 180, NULL);
    front_rows(out, &f, 48, 1, (int)steps, flux); /* the series the extensions hear */
    front_rows(out, &f, 64, 1, 120, NULL);
    front_rows(out, &f, 64, 2, 40, NULL);
    front_rows(out, &f, 96, 1, 40, NULL);

    fg_fire_sound_config bwe = {.sample_rate_hz = 44100.0};
    stream_rows(out, "bwe", &bwe, flux, steps, 5, "eq. 13 on A = fs / sigma_cut (the default)");
    bwe.sample_rate_hz = 48000.0;
    stream_rows(out, "bwe", &bwe, flux, steps, 5, "eq. 13 on A = fs / sigma_cut (the default)");
    fg_fire_sound_config literal = {.sample_rate_hz = 44100.0,
                                    .bwe = {.beta_half_window_frames = 500}};
    stream_rows(out, "bwe", &literal, flux, steps, 5, "eq. 13 on A = w_H (table 1's window)");
    fg_fire_sound_config low = {.sample_rate_hz = 48000.0, .extension = FG_FIRE_LOW_ONLY};
    stream_rows(out, "low", &low, flux, steps, 5, "Mitchell-Netravali + high-pass only");

    for (int long_clip = 0; long_clip < 2; long_clip++) {
        double fs = 44100.0, seconds = long_clip ? 15.0 : FG_FIRE_DEFAULT_TRAINING_S;
        size_t frames = (size_t)(seconds * fs);
        float *clip = malloc(sizeof(float) * frames);
        check(fg_fire_training_clip(fs, 1, clip, frames), "clip");
        fg_fire_texture_config tc = {.samples = clip, .frames = frames, .sample_rate_hz = fs};
        fg_fire_texture *t;
        double c0 = bench_cpu_s();
        check(fg_fire_texture_create(&tc, &t), "texture");
        double train = bench_cpu_s() - c0;
        fg_fire_texture_info info;
        fg_fire_texture_get_info(t, &info);
        char note[160];
        snprintf(note, sizeof note, "training %.0f s clip; |D_1| %zu; %.2f s CPU to train; %.0f MB",
                 seconds, info.dictionary[0], train, (double)info.bytes / 1e6);
        fg_fire_sound_config tex = {.sample_rate_hz = fs, .extension = FG_FIRE_TEXTURE,
                                    .texture = t};
        stream_rows(out, "texture", &tex, flux, steps, 1, note);
        fg_fire_texture_destroy(t);
        free(clip);
    }
    free(flux);
    fclose(out);
    return 0;
}
