/* The binaural layout with the measured MIT KEMAR set that Debian's
 * libmysofa1 installs, read by the host's SOFA reader
 * (host/common/sofa_hrir) at 48 kHz, diffuse-field equalized with a flat
 * low end (host/common/hrir_equalize.h). The outside references are the
 * SOFA data itself and the head's transparency at low frequencies:
 *  - for a spark 1 m away at azimuths 0 to 330 degrees (30 degree steps)
 *    and elevations -30, 0 and +30 degrees, the rendered interaural time
 *    difference (cross-correlation below 1.5 kHz) lies within 50 us of the
 *    measured pair's for that direction, taken the same way (the same
 *    spark, heard at the head's centre, through the pair), and the
 *    interaural level difference in each octave from 500 Hz to 8 kHz
 *    within 1.5 dB of the pair's;
 *  - every response, both ears, within 1.5 dB of unity in the 63 and 125
 *    Hz octaves (a head is small against those wavelengths: free-field
 *    pressure, Kuhn 1977), and the set's diffuse-field average within 0.75
 *    dB of unity in each octave from 250 Hz to 8 kHz (the file's is -11
 *    dB at 250-500 Hz and +6 dB at 2 kHz: its measurement chain).
 *
 * Bad input: the engine refuses a binaural layout without HRIRs, HRIRs for
 * another layout, an ambisonic order, channels other than 2, too few
 * directions, a NULL array, another rate, a non-finite tap; the reader refuses a missing file, a directory, a
 * file that is not SOFA, a truncated SOFA file and one whose convention is
 * not SimpleFreeFieldHRIR, each with a message naming the file. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "common/sofa_hrir.h"
#include "ear_measure.h"
#include "engine_fixture.h"
#include "fulgur/fulgur.h"
#include "core/engine_internal.h"
#include "dsp/fft_internal.h"
#include "spatial/binaural_internal.h"

#define FS 48000.0
#define FRAMES 2048
#define PI 3.14159265358979323846

static sofa_hrirs kemar;

static int load_kemar(void **state)
{
    (void)state;
    char err[512];
    if (sofa_hrirs_read(SOFA_DEFAULT_FILE, FS, &kemar, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    return 0;
}

static int free_kemar(void **state)
{
    (void)state;
    sofa_hrirs_free(&kemar);
    return 0;
}

static void kemar_as_read(void **state)
{
    (void)state;
    assert_int_equal(kemar.set.count, 710);
    assert_true(kemar.file_rate_hz == 44100.0);
    /* 512 taps at 44.1 kHz, converted: ceil(512 * 48 / 44.1) */
    assert_int_equal(kemar.set.length, 558);
    assert_true(kemar.set.sample_rate_hz == FS);
}

/* The energy of a response in [lo, hi) Hz, from its n-point spectrum
 * x[0 .. n + 2) (fg_fft_forward's), over a unit impulse's. */
static double band_db(const double *x, size_t n, double lo, double hi)
{
    double e = 0.0;
    size_t bins = 0;
    for (size_t k = 0; k <= n / 2; k++) {
        double f = (double)k * FS / (double)n;
        if (f >= lo && f < hi) {
            e += x[2 * k] * x[2 * k] + x[2 * k + 1] * x[2 * k + 1];
            bins++;
        }
    }
    return 10.0 * log10(e / (double)bins);
}

/* The set as equalized: each response within 1.5 dB of unity in the 63
 * and 125 Hz octaves, the diffuse-field average within 0.75 dB of unity
 * in each octave from 250 Hz to 8 kHz (measured: 0.64 dB and -0.49 dB at
 * 500 Hz, the crossover's neighbourhood, at most). */
static void kemar_equalized(void **state)
{
    (void)state;
    enum { N = 8192 };
    static const double low[] = {63.0, 125.0}, mid[] = {250, 500, 1000, 2000, 4000, 8000};
    static double x[N + 2];
    double df[6] = {0}, worst_low = 0.0, worst_mid = 0.0;
    fg_fft fft;
    assert_true(fg_fft_init(&fft, N));
    const size_t len = kemar.set.length, count = kemar.set.count;
    for (size_t s = 0; s < 2 * count; s++) {
        const float *ir = (s < count ? kemar.set.left : kemar.set.right) + (s % count) * len;
        memset(x, 0, sizeof x);
        for (size_t k = 0; k < len; k++)
            x[k] = ir[k];
        fg_fft_forward(&fft, x, x);
        for (size_t b = 0; b < 2; b++)
            worst_low = fmax(worst_low, fabs(band_db(x, N, low[b] / sqrt(2.0), low[b] * sqrt(2.0))));
        for (size_t b = 0; b < 6; b++)
            df[b] += pow(10.0, band_db(x, N, mid[b] / sqrt(2.0), mid[b] * sqrt(2.0)) / 10.0) /
                     (double)(2 * count);
    }
    fg_fft_deinit(&fft);
    char line[256];
    int at = snprintf(line, sizeof line, "diffuse-field average (dB) at 250 Hz .. 8 kHz:");
    for (size_t b = 0; b < 6; b++) {
        double db = 10.0 * log10(df[b]);
        worst_mid = fmax(worst_mid, fabs(db));
        at += snprintf(line + at, sizeof line - (size_t)at, " %+.2f", db);
    }
    print_message("%s; every response at 63 and 125 Hz within %.2f dB of unity\n", line,
                  worst_low);
    assert_true(worst_low < 1.5);
    assert_true(worst_mid < 0.75);
}

/* The measurement nearest the head-frame direction u, and how far. */
static size_t nearest(const double u[3], double *angle_deg)
{
    size_t s = fg_hrir_nearest(&kemar.set, u);
    const double *d = kemar.set.direction + 3 * s;
    double c = (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) /
               sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    *angle_deg = acos(fmin(1.0, c)) * 180.0 / PI;
    return s;
}

/* A spark 1 m from the head in the head-frame direction u (x ahead, y
 * left, z up), rendered by an engine of cfg's layout into planes. The head
 * stands at (0, 0, 1.7) looking along +y (world x is to its right). */
static void render_at(const double u[3], fg_engine_config cfg, float *const *planes)
{
    cfg.sample_rate_hz = FS;
    cfg.max_block_frames = 256;
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    fg_node nodes[2];
    fx_segment(nodes, (double[]){-u[1], u[0], 1.7 + u[2]}, (double[]){0, 0, 1}, 1e-3);
    fg_discharge d = {.nodes = nodes, .node_count = 2, .strokes = 1, .seed = 3};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    d.sound.t0_jitter = 0;
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    fx_render(e, planes, cfg.layout == FG_LAYOUT_BINAURAL ? 2 : cfg.channels, FRAMES, 256);
    fg_engine_destroy(e);
}

/* The spark heard binaurally. */
static void render_spark(const double u[3], float *left, float *right)
{
    render_at(u, (fg_engine_config){.layout = FG_LAYOUT_BINAURAL, .hrirs = &kemar.set},
              (float *[]){left, right});
}

/* The same spark heard by one ear at the head's centre (the stereo layout
 * of one channel): what the binaural layout pans to its loudspeakers. */
static void render_centre(const double u[3], float *mono)
{
    render_at(u, (fg_engine_config){.channels = 1}, (float *[]){mono});
}

/* out[0..FRAMES) = x * h, h of n taps. */
static void convolve(const float *x, const float *h, size_t n, float *out)
{
    for (size_t t = 0; t < FRAMES; t++) {
        double acc = 0.0;
        for (size_t k = 0; k < n && k <= t; k++)
            acc += (double)h[k] * x[t - k];
        out[t] = (float)acc;
    }
}

static double ild_db(const float *l, const float *r, double centre_hz)
{
    double lo = centre_hz / sqrt(2.0), hi = centre_hz * sqrt(2.0);
    return 10.0 * log10(em_band_energy(l, FRAMES, FS, lo, hi) /
                        em_band_energy(r, FRAMES, FS, lo, hi));
}

static void kemar_itd_and_ild(void **state)
{
    (void)state;
    static const double octaves[] = {500.0, 1000.0, 2000.0, 4000.0, 8000.0};
    static float l[FRAMES], r[FRAMES], hl[FRAMES], hr[FRAMES], mono[FRAMES];
    double worst_itd = 0.0, worst_ild = 0.0;
    int failures = 0;
    for (int el = -30; el <= 30; el += 30) {
        for (int az = 0; az < 360; az += 30) {
            double a = az * PI / 180.0, e = el * PI / 180.0;
            double u[3] = {cos(e) * cos(a), cos(e) * sin(a), sin(e)};
            double off;
            size_t s = nearest(u, &off);
            assert_true(off < 0.5); /* the grid holds the direction */
            /* the pair's: the spark at the head's centre through it */
            render_centre(u, mono);
            convolve(mono, kemar.set.left + s * kemar.set.length, kemar.set.length, hl);
            convolve(mono, kemar.set.right + s * kemar.set.length, kemar.set.length, hr);
            render_spark(u, l, r);
            double itd = em_itd_s(l, r, FRAMES, FS, 1500.0, 1.5e-3);
            double want = em_itd_s(hl, hr, FRAMES, FS, 1500.0, 1.5e-3);
            worst_itd = fmax(worst_itd, fabs(itd - want));
            bool bad = fabs(itd - want) > 50e-6;
            char line[256];
            int len = snprintf(line, sizeof line, "az %3d el %+3d: ITD %+7.1f us (SOFA %+7.1f)",
                               az, el, itd * 1e6, want * 1e6);
            for (size_t o = 0; o < 5; o++) {
                double got = ild_db(l, r, octaves[o]), ref = ild_db(hl, hr, octaves[o]);
                worst_ild = fmax(worst_ild, fabs(got - ref));
                bad = bad || fabs(got - ref) > 1.5;
                len += snprintf(line + len, sizeof line - (size_t)len, " %+5.1f/%+5.1f", got,
                                ref);
            }
            print_message("%s%s\n", line, bad ? "  <-- outside" : "");
            failures += bad;
        }
    }
    print_message("ILD dB (rendered/SOFA) at 0.5 1 2 4 8 kHz; worst ITD error %.1f us (limit "
                  "50), worst ILD error %.2f dB (limit 1.5)\n",
                  worst_itd * 1e6, worst_ild);
    assert_int_equal(failures, 0);
}

/* The output's delay: through a set whose every response is a unit
 * impulse (each loudspeaker heard as it is), both ears are the spark at the
 * head's centre FG_BINAURAL_LATENCY_FRAMES later, to float rounding, and
 * silent before; a frame more or less is off by the wave's size. */
static void output_is_latency_late(void **state)
{
    (void)state;
    enum { TAPS = 8 };
    const uint32_t count = kemar.set.count;
    float *ir = calloc((size_t)count * TAPS, sizeof *ir);
    assert_non_null(ir);
    for (uint32_t s = 0; s < count; s++)
        ir[(size_t)s * TAPS] = 1.0f;
    fg_hrir_set unit = {.sample_rate_hz = FS, .count = count, .length = TAPS,
                        .direction = kemar.set.direction, .left = ir, .right = ir};
    static float l[FRAMES], r[FRAMES], mono[FRAMES];
    const double u[3] = {0.6, 0.64, 0.48}; /* between loudspeakers: four of them */
    render_at(u, (fg_engine_config){.layout = FG_LAYOUT_BINAURAL, .hrirs = &unit},
              (float *[]){l, r});
    render_centre(u, mono);
    free(ir);
    const size_t late = FG_BINAURAL_LATENCY_FRAMES;
    double peak = 0.0, early = 0.0, off[3] = {0.0, 0.0, 0.0};
    for (size_t t = 0; t < FRAMES; t++) {
        peak = fmax(peak, fabs(mono[t]));
        if (t < late)
            early = fmax(early, fmax(fabs(l[t]), fabs(r[t])));
        for (int d = -1; d <= 1; d++)
            if (t + late + 1 < FRAMES && t >= 1)
                off[d + 1] = fmax(off[d + 1], fmax(fabs(l[t + late + d] - mono[t]),
                                                   fabs(r[t + late + d] - mono[t])));
    }
    print_message("peak %.3g Pa; before %zu frames %.3g; late by %zu - 1, %zu, %zu + 1: off by "
                  "%.2e, %.2e, %.2e of the peak\n",
                  peak, late, early, late, late, late, off[0] / peak, off[1] / peak, off[2] / peak);
    assert_true(peak > 0.0);
    assert_true(early == 0.0);
    assert_true(off[1] < 1e-5 * peak);
    assert_true(off[0] > 1e-2 * peak && off[2] > 1e-2 * peak);
}

/* The panning: a loudspeaker's own direction goes to it alone; any
 * direction to at most four loudspeakers with gains summing to 1; the
 * poles and a direction that is not a number stay inside the array. */
static void panning_gains(void **state)
{
    (void)state;
    double g[FG_BINAURAL_SPEAKERS];
    for (unsigned k = 0; k < FG_BINAURAL_SPEAKERS; k++) {
        double u[3];
        fg_binaural_speaker(k, u);
        fg_binaural_gains(u, g);
        for (unsigned i = 0; i < FG_BINAURAL_SPEAKERS; i++)
            if (fabs(g[i] - (i == k ? 1.0 : 0.0)) > 1e-9)
                fail_msg("loudspeaker %u: gain %g on %u", k, g[i], i);
    }
    for (int n = 0; n < 2000; n++) {
        double z = 1.0 - (2.0 * n + 1.0) / 2000.0, r = sqrt(1.0 - z * z), a = 2.39996 * n;
        fg_binaural_gains((const double[]){r * cos(a), r * sin(a), z}, g);
        double sum = 0.0;
        unsigned used = 0;
        for (unsigned i = 0; i < FG_BINAURAL_SPEAKERS; i++) {
            assert_true(g[i] >= 0.0);
            sum += g[i];
            used += g[i] != 0.0;
        }
        assert_true(fabs(sum - 1.0) < 1e-12);
        assert_true(used <= 4);
    }
    fg_binaural_gains((const double[]){0, 0, -1}, g);
    assert_true(g[0] == 1.0);
    fg_binaural_gains((const double[]){0, 0, 1}, g);
    assert_true(g[FG_BINAURAL_SPEAKERS - 1] == 1.0);
    fg_binaural_gains((const double[]){NAN, 0, 0}, g);
    double sum = 0.0;
    for (unsigned i = 0; i < FG_BINAURAL_SPEAKERS; i++)
        sum += g[i];
    assert_true(sum == 1.0);
}

static void engine_refuses_bad_hrirs(void **state)
{
    (void)state;
    fg_engine *e = (fg_engine *)&e;
    fg_engine_config cfg = {.layout = FG_LAYOUT_BINAURAL};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_ARGUMENT); /* no HRIRs */
    assert_null(e);
    cfg = (fg_engine_config){.layout = FG_LAYOUT_STEREO, .hrirs = &kemar.set};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_ARGUMENT);
    cfg = (fg_engine_config){.layout = FG_LAYOUT_BINAURAL, .hrirs = &kemar.set,
                             .ambisonic_order = 3}; /* binaural takes no order */
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_ARGUMENT);
    cfg = (fg_engine_config){.layout = FG_LAYOUT_BINAURAL, .hrirs = &kemar.set, .channels = 4};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_ARGUMENT);
    cfg = (fg_engine_config){.layout = FG_LAYOUT_BINAURAL, .hrirs = &kemar.set,
                             .sample_rate_hz = 44100.0};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_SAMPLE_RATE);
    fg_hrir_set few = kemar.set;
    few.count = 15;
    cfg = (fg_engine_config){.layout = FG_LAYOUT_BINAURAL, .hrirs = &few};
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_ARGUMENT);
    few = kemar.set;
    few.left = NULL;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_NULL);
    /* a non-finite tap */
    float saved = kemar.left[1000];
    kemar.left[1000] = NAN;
    cfg.hrirs = &kemar.set;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_ERR_NOT_FINITE);
    kemar.left[1000] = saved;
    /* and the good set: the configuration in use no longer points at it */
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_engine_config used;
    fg_engine_get_config(e, &used);
    assert_null(used.hrirs);
    assert_int_equal(used.channels, 2);
    assert_int_equal(used.ambisonic_order, 0);
    fg_engine_destroy(e);
}

/* A 10 m segment 30 m from the head, ahead and to the left, rendered
 * binaurally in calls of `call` frames by an engine for max_block frames
 * (its waves last about 30 ms: they span many blocks). */
static void render_long_segment(uint32_t max_block, uint32_t call, float *left, float *right,
                                size_t frames)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = max_block,
                            .layout = FG_LAYOUT_BINAURAL, .hrirs = &kemar.set};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_node nodes[2];
    fx_segment(nodes, (double[]){-20, 20, 3}, (double[]){1, 0, 0.3}, 5.0);
    fg_discharge d = {.nodes = nodes, .node_count = 2, .strokes = 1, .seed = 5};
    assert_int_equal(fg_preset_sound(FG_PRESET_SPARK_BALLS, &d.sound), FG_OK);
    d.sound.t0_jitter = 0;
    assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
    fx_render(e, (float *[]){left, right}, 2, frames, call);
    fg_engine_destroy(e);
}

/* Memory bounded whatever max_block_frames: a binaural engine for 4096
 * frames keeps bus planes of 512 frames (FG_BUS_PLANE_BYTES), and a call
 * of 4096 frames is rendered as eight blocks of 512, the same samples as
 * eight calls; the sound does not depend on the block: a segment whose
 * waves span many blocks has the same energy in blocks of 64 and 512
 * frames; and a wave is heard to its end (its status once came from
 * loudspeaker 0, which mostly has gain 0: a wave was dropped after the
 * first block it reached, a segment's second pulse lost). */
static void long_calls_are_blocks(void **state)
{
    (void)state;
    enum { N = 4 * 4096 };
    static float l1[N], r1[N], l8[N], r8[N], l64[N], r64[N];
    fg_engine_config cfg = {.sample_rate_hz = FS, .max_block_frames = 4096,
                            .layout = FG_LAYOUT_BINAURAL, .hrirs = &kemar.set};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    assert_int_equal(e->buses.max_frames, 512);
    assert_int_equal(e->buses.count, FG_BUS_PLAIN); /* no head, no twins */
    fg_engine_destroy(e);
    cfg.layout = FG_LAYOUT_STEREO;
    cfg.hrirs = NULL;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    assert_int_equal(e->buses.max_frames, 4096);
    fg_engine_destroy(e);

    render_long_segment(4096, 4096, l1, r1, N);
    render_long_segment(4096, 512, l8, r8, N);
    assert_memory_equal(l1, l8, sizeof l1);
    assert_memory_equal(r1, r8, sizeof r1);
    render_long_segment(64, 64, l64, r64, N);
    double e512 = fx_energy(l8, 0, N) + fx_energy(r8, 0, N);
    double e64 = fx_energy(l64, 0, N) + fx_energy(r64, 0, N);
    print_message("energy in blocks of 512: %.6g, of 64: %.6g (ratio %.6f)\n", e512, e64,
                  e64 / e512);
    assert_true(e512 > 0.0);
    assert_true(fabs(e64 / e512 - 1.0) < 1e-4);
    /* both ends of the segment are heard: a WM-wave's two pulses, as far
     * apart as the ends' distances from the head (it is at the origin) */
    double ends[2];
    for (int k = 0; k < 2; k++) {
        double sgn = k ? 1.0 : -1.0, u = 5.0 / sqrt(1.09);
        double p[3] = {-20 + sgn * u, 20, 3 + sgn * 0.3 * u};
        ends[k] = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    }
    double want = fabs(ends[0] - ends[1]) / 343.0 * FS;
    size_t at[4];
    size_t found = fx_onsets(l64, N, 0.05f * fx_peak(l64, N), 240, at, 4);
    print_message("pulses: %zu, %zu frames apart (the ends: %.0f)\n", found,
                  found == 2 ? at[1] - at[0] : 0, want);
    assert_int_equal(found, 2);
    assert_true(fabs((double)(at[1] - at[0]) - want) < 48.0);
}

/* Writes n bytes of data to dir/name; returns the path (static). */
static const char *write_file(const char *dir, const char *name, const void *data, size_t n)
{
    static char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
    return path;
}

static void expect_refused(const char *path, const char *says)
{
    sofa_hrirs h;
    char err[512] = "";
    assert_int_equal(sofa_hrirs_read(path, FS, &h, err, sizeof err), -1);
    print_message("%s\n", err);
    assert_non_null(strstr(err, path));
    assert_non_null(strstr(err, says));
    assert_null(h.left);
    assert_int_equal(h.set.count, 0);
}

static void reader_refuses_bad_files(void **state)
{
    (void)state;
    char dir[] = "/tmp/fulgur_sofa_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char missing[4200];
    snprintf(missing, sizeof missing, "%s/none.sofa", dir);
    expect_refused(missing, "cannot open");
    expect_refused(dir, "not a SOFA file");
    static const char text[] = "{\"not\": \"a SOFA file\"}\n";
    char path[4200];
    snprintf(path, sizeof path, "%s", write_file(dir, "text.sofa", text, sizeof text - 1));
    expect_refused(path, "not a SOFA file");
    /* the KEMAR file cut in half, and with its convention renamed */
    FILE *f = fopen(SOFA_DEFAULT_FILE, "rb");
    assert_non_null(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    size_t n = (size_t)ftell(f);
    rewind(f);
    char *bytes = malloc(n);
    assert_non_null(bytes);
    assert_int_equal(fread(bytes, 1, n, f), n);
    fclose(f);
    snprintf(path, sizeof path, "%s", write_file(dir, "half.sofa", bytes, n / 2));
    expect_refused(path, "not a SOFA file");
    char *at = NULL;
    static const char convention[] = "SimpleFreeFieldHRIR";
    for (size_t k = 0; k + sizeof convention - 1 <= n && !at; k++)
        if (memcmp(bytes + k, convention, sizeof convention - 1) == 0)
            at = bytes + k;
    assert_non_null(at);
    memcpy(at, "SimpleFreeFieldHRTF", sizeof convention - 1);
    snprintf(path, sizeof path, "%s", write_file(dir, "hrtf.sofa", bytes, n));
    expect_refused(path, "SimpleFreeFieldHRIR");
    free(bytes);
    static const char *const made[] = {"text.sofa", "half.sofa", "hrtf.sofa"};
    for (size_t k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, made[k]);
        assert_int_equal(unlink(path), 0);
    }
    assert_int_equal(rmdir(dir), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(kemar_as_read),
        cmocka_unit_test(kemar_equalized),
        cmocka_unit_test(kemar_itd_and_ild),
        cmocka_unit_test(output_is_latency_late),
        cmocka_unit_test(panning_gains),
        cmocka_unit_test(engine_refuses_bad_hrirs),
        cmocka_unit_test(long_calls_are_blocks),
        cmocka_unit_test(reader_refuses_bad_files),
    };
    return cmocka_run_group_tests(tests, load_kemar, free_kemar);
}
