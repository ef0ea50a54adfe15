/* Validation against real thunder (DESIGN §5): renders reference scenes
 * through the engine with the whole atmosphere on and writes
 * bench/results/validation.md, its CSVs and plots' data:
 *   1. spectra of a 5 km bolt heard at 1 km and at 8 km;
 *   2. the duration of a 5 km bolt heard from 3 km: how long its A-weighted
 *      F level stays above a rural background, and its 90 % energy span;
 *      then the same with 0-10 km of the generator's in-cloud channel;
 *   3. the shadow zone at D = 3 km, R = 55 km, measured segment by segment
 *      against the tangent ray and the creeping wave's decay;
 *   4. the lightning preset's mean segments and sound against table 2;
 *   5. spark-scale peak pressures and spectra at 1 m;
 *   6. peak pressure and A-weighted level of the bolt at 3, 15 and 25 km.
 * Sections 1 and 6 cover both lightning presets: "lightning" (calibrated to
 * measured thunder) and "lightning_table1" (Matsuyama's table 1).
 * With --check it exits non-zero when a deterministic figure leaves its
 * tolerance (the CTest "validation"); the judgements stay in the report. */
#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "fg_array.h"
#include "fg_math.h"
#include "fulgur/fulgur.h"

#define FS 48000.0
#define C 343.0
#define WINDOW 16384
#define TABLE2_SEEDS 8
/* The background a thunder roll must rise above to be heard, dB(A): the
 * daytime level of ANSI/ASA S12.9-2013/Part 3 (annex C, table C.1), category 6,
 * "very quiet suburban and rural residential" (34 dB(A) at night). */
#define BACKGROUND_DBA 40.0
/* IEC 61672-1 time weighting F (fast), s. */
#define FAST_S 0.125

typedef struct signal {
    float *x;
    size_t n;
} signal;

static void must(fg_result r, const char *what)
{
    if (r != FG_OK) {
        fprintf(stderr, "validate: %s: %s\n", what, fg_result_str(r));
        exit(2);
    }
}

/* The full atmosphere of a storm. */
static fg_propagation_config storm(void)
{
    return (fg_propagation_config){.refraction_radius_m = FG_REFRACTION_STORM_M,
                            .turbulence_s = FG_TURBULENCE_DEFAULT_S,
                            .absorption = FG_ABSORPTION_ISO9613,
                            .ground_reflection = FG_GROUND_DEFAULT_REFLECTION};
}

/* One discharge heard by one ear at the origin, 1.7 m up, until it ends. */
static signal render(const fg_node *nodes, size_t count, const fg_sound_config *sound,
                     const fg_propagation_config *prop, uint32_t strokes)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .channels = 1, .speed_of_sound_m_s = C,
                            .max_block_frames = 1024, .segment_capacity = (uint32_t)(2 * count)};
    fg_engine *e;
    must(fg_engine_create(&cfg, &e), "create");
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    must(fg_engine_set_listener(e, &head), "listener");
    fg_discharge d = {.nodes = nodes, .node_count = count, .sound = *sound, .strokes = strokes,
                      .seed = 1, .propagation = *prop};
    must(fg_engine_post(e, &d, NULL), "post");
    signal s = {0};
    size_t cap = 0;
    fg_engine_report st = {0};
    while (st.finished == 0) {
        float *grown = fg_array_grow(s.x, &cap, s.n + 1024, sizeof *s.x, 1 << 20);
        if (!grown) {
            fprintf(stderr, "validate: out of memory\n");
            exit(1);
        }
        s.x = grown;
        float *plane = s.x + s.n;
        must(fg_engine_render(e, &plane, 1024), "render");
        s.n += 1024;
        fg_engine_get_report(e, &st);
    }
    fg_engine_destroy(e);
    return s;
}

/* A 5 km cloud-to-ground bolt striking at (x, y). */
static fg_tree *bolt(double x, double y, uint64_t seed)
{
    fg_tree *t;
    must(fg_tree_create(16384, &t), "tree");
    fg_lightning_config p = {.strike_m = {x, y}, .seed = seed};
    must(fg_lightning_generate(&p, t, NULL), "lightning");
    return t;
}

/* A 5 km bolt striking at (0, 3000) down a given skeleton: eight jittered
 * pieces from (400, 3300, 5000) to the strike, with the generator's
 * in-cloud channel cloud_m long from its root toward +x, across the line of
 * sight of an ear at the origin (none for 0). */
static fg_tree *cloud_bolt(double cloud_m)
{
    double k[3 * 9];
    for (int j = 0; j <= 8; j++) {
        double w = j / 8.0, wobble = j > 0 && j < 8 ? 150 : 0;
        k[3 * j] = 400 * (1 - w) + wobble * sin(3 * j);
        k[3 * j + 1] = 3000 + 300 * (1 - w) + wobble * cos(2 * j);
        k[3 * j + 2] = 5000 * (1 - w);
    }
    fg_tree *t;
    must(fg_tree_create(16384, &t), "tree");
    fg_lightning_config p = {.skeleton_m = k, .skeleton_points = 9, .in_cloud_m = cloud_m,
                             .seed = 7};
    must(fg_lightning_generate(&p, t, NULL), "lightning");
    return t;
}

/* Welch power spectrum (Hann, half overlap) into psd[WINDOW/2 + 1]. */
static void spectrum(const signal *s, double *psd)
{
    double *in = fftw_malloc(WINDOW * sizeof *in);
    fftw_complex *out = fftw_malloc((WINDOW / 2 + 1) * sizeof *out);
    fftw_plan plan = fftw_plan_dft_r2c_1d(WINDOW, in, out, FFTW_ESTIMATE);
    memset(psd, 0, (WINDOW / 2 + 1) * sizeof *psd);
    size_t frames = 0;
    for (size_t at = 0; at + WINDOW <= s->n; at += WINDOW / 2, frames++) {
        for (int k = 0; k < WINDOW; k++)
            in[k] = s->x[at + k] * (0.5 - 0.5 * cos(2 * FG_PI * k / WINDOW));
        fftw_execute(plan);
        for (int k = 0; k <= WINDOW / 2; k++)
            psd[k] += creal(out[k]) * creal(out[k]) + cimag(out[k]) * cimag(out[k]);
    }
    for (int k = 0; k <= WINDOW / 2; k++)
        psd[k] /= frames ? (double)frames : 1.0;
    fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
}

/* The 1/3-octave band (centres 10 Hz .. 16 kHz) holding the most energy. */
static double peak_band_hz(const double *psd)
{
    double best = -1, best_hz = 0;
    for (int i = 0; i <= 32; i++) {
        double fc = 10.0 * pow(2.0, i / 3.0), lo = fc * pow(2.0, -1 / 6.0), hi = fc * pow(2.0, 1 / 6.0);
        double e = 0;
        for (int k = (int)ceil(lo * WINDOW / FS); k <= (int)(hi * WINDOW / FS) && k <= WINDOW / 2; k++)
            e += psd[k];
        if (e > best) {
            best = e;
            best_hz = fc;
        }
    }
    return best_hz;
}

/* The frequency below which half the energy between 20 Hz and 5 kHz lies:
 * a steadier measure of where a broad spectrum sits than its peak. */
static double median_hz(const double *psd)
{
    int lo = (int)ceil(20.0 * WINDOW / FS), hi = (int)(5000.0 * WINDOW / FS);
    double total = 0, run = 0;
    for (int k = lo; k <= hi; k++)
        total += psd[k];
    for (int k = lo; k <= hi; k++) {
        run += psd[k];
        if (run >= 0.5 * total)
            return k * FS / WINDOW;
    }
    return hi * FS / WINDOW;
}

/* The span holding the middle 90 % of the energy, seconds. */
static double duration_90(const signal *s)
{
    double total = 0, run = 0;
    for (size_t k = 0; k < s->n; k++)
        total += (double)s->x[k] * s->x[k];
    size_t a = 0, b = 0;
    for (size_t k = 0; k < s->n; k++) {
        run += (double)s->x[k] * s->x[k];
        if (run < 0.05 * total)
            a = k;
        if (run < 0.95 * total)
            b = k;
    }
    return (double)(b - a) / FS;
}

/* IEC 61672-1 A-weighting, as a power ratio, at f_hz (0 dB at 1 kHz). */
static double a_weight_power(double f_hz)
{
    double f2 = f_hz * f_hz;
    double ra = 12194.0 * 12194.0 * f2 * f2 /
                ((f2 + 20.6 * 20.6) * sqrt((f2 + 107.7 * 107.7) * (f2 + 737.9 * 737.9)) *
                 (f2 + 12194.0 * 12194.0));
    return ra * ra * pow(10.0, 2.0 / 10.0);
}

/* The A-weighted (IEC 61672-1) pressure of s: its spectrum (one FFT of the
 * whole render, zero-padded) times the weighting's magnitude, zero phase.
 * Pressures in double, s->n of them. */
static double *a_weighted(const signal *s)
{
    size_t n = 1;
    while (n < s->n)
        n *= 2;
    double *in = fftw_malloc(n * sizeof *in);
    fftw_complex *out = fftw_malloc((n / 2 + 1) * sizeof *out);
    fftw_plan fwd = fftw_plan_dft_r2c_1d((int)n, in, out, FFTW_ESTIMATE);
    fftw_plan back = fftw_plan_dft_c2r_1d((int)n, out, in, FFTW_ESTIMATE);
    for (size_t k = 0; k < n; k++)
        in[k] = k < s->n ? s->x[k] : 0.0;
    fftw_execute(fwd);
    out[0] = 0.0;
    for (size_t k = 1; k <= n / 2; k++)
        out[k] *= sqrt(a_weight_power(k * FS / n)) / (double)n;
    fftw_execute(back);
    double *xa = malloc(s->n * sizeof *xa);
    if (!xa) {
        fprintf(stderr, "validate: out of memory\n");
        exit(1);
    }
    memcpy(xa, in, s->n * sizeof *xa);
    fftw_destroy_plan(fwd);
    fftw_destroy_plan(back);
    fftw_free(in);
    fftw_free(out);
    return xa;
}

/* The A-weighted equivalent level over the span holding the middle 90 % of
 * the energy, dB re 20 uPa: 90 % of the A-weighted energy over that span.
 * -inf for silence. */
static double laeq_90(const signal *s)
{
    double *xa = a_weighted(s);
    double energy = 0.0;
    for (size_t k = 0; k < s->n; k++)
        energy += xa[k] * xa[k];
    free(xa);
    double span = duration_90(s);
    return 10.0 * log10(0.9 * energy / (FS * fmax(span, 1.0 / FS)) / (20e-6 * 20e-6));
}

/* What a listener would time as the thunder's duration: how long the
 * A-weighted, time-weighted 'F' level (IEC 61672-1: exponential mean of
 * the squared pressure, 125 ms) stays above the background, from the first
 * sample above it to the last, counting the decay into the silence after
 * the render. *max_dba receives the highest L_AF. */
static double audible_span(const signal *s, double *max_dba)
{
    double *xa = a_weighted(s);
    const double p_ref2 = 20e-6 * 20e-6, floor2 = p_ref2 * pow(10.0, BACKGROUND_DBA / 10.0);
    const double step = 1.0 - exp(-1.0 / (FS * FAST_S));
    double mean = 0.0, top = 0.0;
    size_t first = 0, last = 0;
    int heard = 0;
    for (size_t k = 0; k < s->n; k++) {
        mean += (xa[k] * xa[k] - mean) * step;
        top = fmax(top, mean);
        if (mean > floor2) {
            if (!heard)
                first = k;
            heard = 1;
            last = k;
        }
    }
    free(xa);
    *max_dba = 10.0 * log10(fmax(top, 1e-30) / p_ref2);
    if (!heard)
        return 0.0;
    /* the render stops when the last wave has ended: silence follows, in
     * which the mean decays as exp(-t / FAST_S) until it meets the floor */
    double tail = mean > floor2 ? FAST_S * log(mean / floor2) : 0.0;
    return (double)(last - first + 1) / FS + tail;
}

static double peak_pa(const signal *s)
{
    double p = 0;
    for (size_t k = 0; k < s->n; k++)
        p = fmax(p, fabs(s->x[k]));
    return p;
}

static void write_spectrum(const char *name, const double *a, const double *b)
{
    FILE *f = bench_open_result(name);
    fprintf(f, "hz,first_db,second_db\n");
    for (int k = 1; k <= WINDOW / 2; k++) {
        double hz = k * FS / WINDOW;
        if (hz > 20000)
            break;
        fprintf(f, "%.3f,%.2f,%.2f\n", hz, 10 * log10(a[k] + 1e-30), 10 * log10(b[k] + 1e-30));
    }
    fclose(f);
}

typedef struct checks {
    int failed;
    FILE *md;
} checks;

static void check(checks *c, int ok, const char *what)
{
    fprintf(c->md, "- %s: **%s**\n", what, ok ? "pass" : "FAIL");
    if (!ok) {
        fprintf(stderr, "validate: failed: %s\n", what);
        c->failed = 1;
    }
}

int main(int argc, char **argv)
{
    int enforce = argc > 1 && strcmp(argv[1], "--check") == 0;
    checks c = {0, bench_open_result("validation.md")};
    char cpu[256];
    bench_machine(cpu, sizeof cpu);
    /* table 1's bolt first, the calibrated one last (the checks read it) */
    static const fg_preset bolts[] = {FG_PRESET_LIGHTNING_TABLE1, FG_PRESET_LIGHTNING};
    fg_sound_config lightning;
    must(fg_preset_sound(FG_PRESET_LIGHTNING, &lightning), "preset");
    fg_propagation_config air = storm();
    static double near_psd[WINDOW / 2 + 1], far_psd[WINDOW / 2 + 1];
    fprintf(c.md, "# Validation against real thunder\n\n"
                  "Written by `bench_validate` (bench/validate.c, run by `scripts/bench.sh`); "
                  "%s. Every render "
                  "goes through `fg_engine_render` to one ear 1.7 m up; those of the bolts "
                  "(sections 1, 2, 4 and 6) with refraction (R = 55 km), turbulence (2 ms), "
                  "ISO 9613-1 absorption (20 °C, 70 %%) and a ground image (0.9), sections 3 "
                  "and 5 with what they say. Checks marked pass/FAIL are also run by CTest "
                  "(`bench_validate --check`).\n\n",
            cpu);

    /* 1. spectra at 1 km and 8 km, both lightning presets */
    fprintf(c.md, "## 1. Spectrum peak\n\nThe same 5 km bolt (seed 7) heard at 1 km and at "
                  "8 km. Peak: the 1/3-octave band with the most energy; median: the frequency "
                  "halving the energy between 20 Hz and 5 kHz. Published: cloud-to-ground "
                  "thunder peaks near 50 Hz (4-125 Hz, Holmes et al. 1971), close strikes higher "
                  "(80-160 Hz), distant ones lower (20-40 Hz); Matsuyama's near/far spectra peak "
                  "at 100-200 Hz.\n\n"
                  "| preset | T0 | listener | peak band | median | peak pressure |\n"
                  "|---|---|---|---|---|---|\n");
    double near_median = 0, far_median = 0, near_hz = 0, far_hz = 0;
    double table1_near_hz = 0, table1_far_hz = 0;
    for (int i = 0; i < 2; i++) {
        fg_sound_config p;
        must(fg_preset_sound(bolts[i], &p), "preset");
        signal s[2];
        for (int j = 0; j < 2; j++) {
            fg_tree *b = bolt(0, j == 0 ? 1000 : 8000, 7);
            s[j] = render(fg_tree_nodes(b), fg_tree_count(b), &p, &air, 1);
            fg_tree_destroy(b);
        }
        spectrum(&s[0], near_psd);
        spectrum(&s[1], far_psd);
        for (int j = 0; j < 2; j++) {
            const double *psd = j == 0 ? near_psd : far_psd;
            fprintf(c.md, "| %s | %.1f ms | %s | %.0f Hz | %.0f Hz | %.2f Pa |\n",
                    fg_preset_name(bolts[i]), 1e3 * p.t0_s, j == 0 ? "1 km" : "8 km",
                    peak_band_hz(psd), median_hz(psd), peak_pa(&s[j]));
        }
        if (i == 0) {
            table1_near_hz = peak_band_hz(near_psd);
            table1_far_hz = peak_band_hz(far_psd);
        } else {
            near_median = median_hz(near_psd);
            far_median = median_hz(far_psd);
            near_hz = peak_band_hz(near_psd);
            far_hz = peak_band_hz(far_psd);
            write_spectrum("validation_spectra.csv", near_psd, far_psd);
        }
        free(s[0].x);
        free(s[1].x);
    }
    fprintf(c.md, "\n![spectra](validation_spectra.png)\n\n");
    check(&c, far_median < near_median,
          "lightning: the distant bolt sits lower than the near one (median)");
    /* one bolt's loudest band moves between 50 and 100 Hz with the tree
     * (gcc's and clang's builds grow different trees from the same seed):
     * a judgement, not a check; the median above is */
    fprintf(c.md, "- judgement, lightning: the loudest band %.0f Hz at 1 km, %.0f Hz at 8 km "
                  "against 80-160 and 20-40 Hz: %s\n",
            near_hz, far_hz,
            near_hz >= 80.0 && near_hz <= 160.0 && far_hz >= 20.0 && far_hz <= 40.0
                ? "inside"
                : "outside (one bolt; the median is checked)");
    fprintf(c.md, "- judgement, lightning_table1: peaks at %.0f Hz (1 km, %s) and %.0f Hz "
                  "(8 km, %s) against roughly 20-200 Hz (see the note below)\n\n",
            table1_near_hz, table1_near_hz <= 200 ? "inside" : "above it", table1_far_hz,
            table1_far_hz <= 200 ? "inside" : "above it");

    /* 2. duration at 3 km, both lightning presets */
    fprintf(c.md,
            "## 2. Duration\n\nA 5 km bolt heard from 3 km: Glassner's geometry gives "
            "(sqrt(3^2 + 5^2) - 3) km / c = 8.3 s between the nearest and farthest point; "
            "recorded rolls last from 5 to 30-40 s, timed by ear from the first to the last "
            "audible sound. Heard: how long the A-weighted level with IEC 61672-1's F time "
            "weighting (125 ms) stays above a %.0f dB(A) background (ANSI/ASA "
            "S12.9-2013/Part 3, annex C, table C.1: daytime, \"very quiet suburban and rural "
            "residential\"; 34 dB(A) at night), first to last sample above it; this is the duration compared with the "
            "published rolls. Also given: the span holding the middle 90 %% of the energy, "
            "which leaves out the quiet start and end that a listener still hears.\n\n"
            "| preset | heard (L_AF > %.0f dB(A)) | max L_AF | 90 %% energy span |\n"
            "|---|---|---|---|\n",
            BACKGROUND_DBA, BACKGROUND_DBA);
    double durs[2], heard[2];
    fg_tree *b = bolt(0, 3000, 7);
    for (int i = 0; i < 2; i++) {
        fg_sound_config p;
        must(fg_preset_sound(bolts[i], &p), "preset");
        signal mid = render(fg_tree_nodes(b), fg_tree_count(b), &p, &air, 1);
        double top;
        durs[i] = duration_90(&mid);
        heard[i] = audible_span(&mid, &top);
        free(mid.x);
        fprintf(c.md, "| %s | %.2f s | %.1f dB(A) | %.2f s |\n", fg_preset_name(bolts[i]),
                heard[i], top, durs[i]);
    }
    fg_tree_destroy(b);
    double dur = heard[1];
    fputc('\n', c.md);
    check(&c, dur >= 5.0 && dur <= 40.0,
          "lightning: heard at 3 km for 5-40 s, the published rolls");
    check(&c, durs[0] > 5.0 && durs[0] < 11.0, "lightning_table1: the 90 % span lies within 5-11 s");
    fprintf(c.md, "- judgement, lightning_table1: heard for %.2f s against the published 5 to "
                  "30-40 s: %s\n\n",
            heard[0], heard[0] >= 5.0 && heard[0] <= 40.0 ? "inside" : "outside");
    /* the in-cloud channel the random skeleton lacks */
    fprintf(c.md, "The random skeleton is a cloud-to-ground channel only. Real flashes also "
                  "run for kilometres horizontally inside the cloud (Rakov & Uman, *Lightning: "
                  "Physics and Effects*, 2003, not retrieved; see docs/generators-lightning.md "
                  "for the sources that were), and that channel's sound arrives later. The "
                  "same kind of 5 km bolt down a given skeleton, with the generator's "
                  "in-cloud channel (`in_cloud`) grown from its root at the cloud's height "
                  "across the line of sight (lightning preset):"
                  "\n\n| in-cloud channel | segments | heard | 90 %% energy span |\n"
                  "|---|---|---|---|\n");
    static const double cloud_km[] = {0.0, 2.0, 5.0, 10.0};
    size_t cloud_segs[4];
    for (int i = 0; i < 4; i++) {
        fg_tree *t = cloud_bolt(1000.0 * cloud_km[i]);
        signal s = render(fg_tree_nodes(t), fg_tree_count(t), &lightning, &air, 1);
        double loudest, heard_s = audible_span(&s, &loudest);
        cloud_segs[i] = fg_tree_count(t) - 1;
        fprintf(c.md, "| %.0f km | %zu | %.2f s | %.2f s |\n", cloud_km[i],
                fg_tree_count(t) - 1, heard_s, duration_90(&s));
        fg_tree_destroy(t);
        free(s.x);
    }
    fprintf(c.md, "\nThe generator's default stays without it (`in_cloud` 0): its segment "
                  "count is matched "
                  "to Matsuyama's table 2 (section 4), which 2 to 10 km of in-cloud channel "
                  "multiply by %.1f to %.1f here.\n\n",
            (double)cloud_segs[1] / (double)cloud_segs[0],
            (double)cloud_segs[3] / (double)cloud_segs[0]);

    /* 3. the shadow zone, one horizontal segment per height, D = 3 km */
    FILE *zone = bench_open_result("validation_shadow.csv");
    fprintf(zone, "height_m,level_ratio\n");
    double ratio_20 = 0, ratio_120 = 0;
    fg_propagation_config bent = {.refraction_radius_m = FG_REFRACTION_STORM_M};
    fg_propagation_config straight = {0};
    for (int h = 5; h <= 150; h += 5) {
        fg_node seg[2] = {{-1.5, 3000, h, -1, 0}, {1.5, 3000, h, 0, 0}};
        signal a = render(seg, 2, &lightning, &straight, 1), r = render(seg, 2, &lightning, &bent, 1);
        double ea = 0, er = 0;
        for (size_t k = 0; k < a.n; k++)
            ea += (double)a.x[k] * a.x[k];
        for (size_t k = 0; k < r.n; k++)
            er += (double)r.x[k] * r.x[k];
        double ratio = sqrt(er / ea);
        fprintf(zone, "%d,%.5f\n", h, ratio);
        if (h == 20)
            ratio_20 = ratio;
        if (h == 120)
            ratio_120 = ratio;
        free(a.x);
        free(r.x);
    }
    fclose(zone);
    /* the model's prediction, from the geometry and Pierce's first mode */
    const double radius = FG_REFRACTION_STORM_M, ear_z = 1.7;
    double reach_ear = sqrt(2.0 * radius * ear_z);
    double top = (3000.0 - reach_ear) * (3000.0 - reach_ear) / (2.0 * radius);
    double k50 = 2.0 * FG_PI * 50.0 / 343.0;
    double beta = 20.0 * log10(exp(1.0)) * 1.018793 * sqrt(3.0) / 2.0 *
                  cbrt(k50 / (2.0 * radius * radius));
    double depth_20 = 3000.0 - reach_ear - sqrt(2.0 * radius * 20.0);
    double want_20 = pow(10.0, -beta * depth_20 / 20.0);
    fprintf(c.md,
            "## 3. Shadow zone\n\nD = 3 km, R = 55 km, ear 1.7 m up: the tangent ray over the ear "
            "stands h = (D - sqrt(2 R z_ear))²/2R = %.1f m high (81.8 m for an ear on the "
            "ground). Below it the sound is the creeping wave of the shadow, weaker by "
            "8.686 |a1'| sin 60° (k/2R²)^(1/3) = %.2f dB/km of shadow at 50 Hz (first Airy mode "
            "over rigid ground, a1' = -1.01879 the first zero of Ai' (NIST DLMF table "
            "9.9.1); Fock's creeping wave, for refracted sound Pierce, Acoustics, 1981, "
            "ch. 9), applied at 50 Hz to every frequency: its growth as f^(1/3) is not "
            "modelled, and no published dB/km figure was at hand to check 4.1 dB/km "
            "against (docs/sound-model.md, \"The air\"). Level of a segment with "
            "refraction against straight rays, by height: 20 m (%.0f m into the shadow) → "
            "%.3f (model %.3f), 120 m → %.3f.\n\n![shadow](validation_shadow.png)\n\n",
            top, 1000.0 * beta, depth_20, ratio_20, want_20, ratio_120);
    check(&c, fabs(ratio_20 - want_20) < 2e-3 && fabs(ratio_120 - 1) < 1e-3,
          "the creeping-wave decay below the tangent ray (20 m), untouched above");
    fputc('\n', c.md);

    /* 4. table 2: the lightning preset's mean figures */
    double segs = 0, sound = 0, heard_mean = 0, heard_min = INFINITY, heard_max = 0;
    for (int seed = 0; seed < TABLE2_SEEDS; seed++) {
        b = bolt(0, 3000, 100 + (uint64_t)seed);
        signal s = render(fg_tree_nodes(b), fg_tree_count(b), &lightning, &air, 1);
        double loudest;
        segs += (double)(fg_tree_count(b) - 1) / TABLE2_SEEDS;
        sound += (double)s.n / FS / TABLE2_SEEDS;
        double heard_s = audible_span(&s, &loudest);
        heard_mean += heard_s / TABLE2_SEEDS;
        heard_min = fmin(heard_min, heard_s);
        heard_max = fmax(heard_max, heard_s);
        fg_tree_destroy(b);
        free(s.x);
    }
    fprintf(c.md, "## 4. Table 2\n\n| | segments | sound | heard |\n|---|---|---|---|\n"
                  "| Matsuyama table 2 (mean) | 9438 | 13.6 s | |\n"
                  "| fulgur lightning preset, %d seeds, heard from 3 km | %.0f | %.1f s | "
                  "%.1f s |\n\n"
                  "Sound: from the flash to the end of the last segment's wave, the travel "
                  "to the nearest point of the channel included (Matsuyama does not say how "
                  "his figure is timed, nor from where). Heard: as in section 2, the mean; "
                  "%.1f to %.1f s over the seeds.\n\n",
            TABLE2_SEEDS, segs, sound, heard_mean, heard_min, heard_max);
    check(&c, fabs(segs / 9438 - 1) < 0.25, "mean segment count within 25 % of 9438");
    check(&c, heard_min >= 5.0 && heard_max <= 40.0,
          "every seed heard at 3 km for 5-40 s, the published rolls");
    fputc('\n', c.md);

    /* 5. spark scale at 1 m */
    fprintf(c.md, "## 5. Spark scale\n\nA 2 cm spark and a 20 cm plasma-ball filament "
                  "as straight chains of their preset's segments, 1 m in front of the ear, "
                  "free air.\n\n| preset | peak at 1 m | peak band |\n|---|---|---|\n");
    static const fg_preset small[] = {FG_PRESET_SPARK_BALLS, FG_PRESET_PLASMA_BALL};
    static double spark_psd[2][WINDOW / 2 + 1];
    for (int i = 0; i < 2; i++) {
        fg_sound_config p;
        fg_preset_scale scale;
        must(fg_preset_sound(small[i], &p), "preset");
        must(fg_preset_get_scale(small[i], &scale), "scale");
        size_t n = (size_t)(scale.path_m / (2 * scale.half_step_m)) + 1;
        fg_node *chain = calloc(n, sizeof *chain);
        for (size_t k = 0; k < n; k++)
            chain[k] = (fg_node){0.002 * sin(1.7 * k) * scale.path_m, 1.0,
                                 1.7 + scale.path_m / 2 - 2 * scale.half_step_m * k, (int32_t)k - 1, 0};
        signal s = render(chain, n, &p, &straight, 1);
        signal padded = {calloc(WINDOW, sizeof(float)), WINDOW};
        memcpy(padded.x, s.x, (s.n < WINDOW ? s.n : WINDOW) * sizeof(float));
        spectrum(&padded, spark_psd[i]);
        fprintf(c.md, "| %s | %.1f Pa (%.0f dB SPL) | %.0f Hz |\n", fg_preset_name(small[i]),
                peak_pa(&s), 20 * log10(peak_pa(&s) / 20e-6), peak_band_hz(spark_psd[i]));
        free(chain);
        free(s.x);
        free(padded.x);
    }
    write_spectrum("validation_sparks.csv", spark_psd[0], spark_psd[1]);
    fprintf(c.md, "\n![sparks](validation_sparks.png)\n\n");

    /* 6. level and audibility against distance, both lightning presets */
    fprintf(c.md, "## 6. Level against distance\n\nThe 5 km bolt (seed 7) heard at 3, 15 and "
                  "25 km. LAeq: the A-weighted (IEC 61672-1) equivalent level over the span "
                  "holding 90 %% of the energy; max L_AF and heard as in section 2 (above the "
                  "%.0f dB(A) background). Published: \"a few tens of Pa\" a few km away; "
                  "thunder is rarely heard beyond 20-25 km.\n\n"
                  "| preset | T0 | listener | peak band | peak pressure | LAeq | max L_AF | heard |\n"
                  "|---|---|---|---|---|---|---|---|\n",
            BACKGROUND_DBA);
    static const double ranges_km[] = {3.0, 15.0, 25.0};
    double band_hz[3], peak[3], laeq[3], laf_max[3], span[3], table1_3km_hz = 0;
    for (int i = 0; i < 2; i++) {
        fg_sound_config p;
        must(fg_preset_sound(bolts[i], &p), "preset");
        for (int j = 0; j < 3; j++) {
            fg_tree *t = bolt(0, 1000.0 * ranges_km[j], 7);
            signal s = render(fg_tree_nodes(t), fg_tree_count(t), &p, &air, 1);
            fg_tree_destroy(t);
            static double psd[WINDOW / 2 + 1];
            spectrum(&s, psd);
            band_hz[j] = peak_band_hz(psd);
            peak[j] = peak_pa(&s);
            laeq[j] = laeq_90(&s);
            span[j] = audible_span(&s, &laf_max[j]);
            if (i == 0 && j == 0)
                table1_3km_hz = band_hz[0];
            fprintf(c.md,
                    "| %s | %.1f ms | %.0f km | %.0f Hz | %.2f Pa | %.1f dBA | %.1f dBA | "
                    "%.2f s |\n",
                    fg_preset_name(bolts[i]), 1e3 * p.t0_s, ranges_km[j], band_hz[j], peak[j],
                    laeq[j], laf_max[j], span[j]);
            free(s.x);
        }
    }
    /* the figures of the last (calibrated) rows against the published ones */
    fputc('\n', c.md);
    check(&c, band_hz[0] >= 20.0 && band_hz[0] < 100.0,
          "lightning, 3 km: the loudest third-octave band within 20-100 Hz");
    check(&c, peak[0] >= 10.0 && peak[0] <= 100.0,
          "lightning, 3 km: peak of tens of pascals (10-100 Pa)");
    check(&c, laeq[1] <= laeq[0] - 10.0, "lightning: 15 km at least 10 dB below 3 km");
    check(&c, laeq[2] < 40.0, "lightning: 25 km below 40 dBA");
    fprintf(c.md, "- judgement, lightning: at 25 km L_AF peaks at %.1f dB(A) and stays above "
                  "the %.0f dB(A) background for %.2f s (%.2f s at 3 km): %s\n",
            laf_max[2], BACKGROUND_DBA, span[2], span[0],
            span[2] > 1.0   ? "still heard as a roll"
            : span[2] > 0.0 ? "a brief faint burst"
                            : "inaudible");
    fputc('\n', c.md);

    fprintf(c.md, "## Reading the figures\n\n"
                  "The single N-wave sets the spectral peak: an N-wave of half-duration T has "
                  "the spectrum of the spherical Bessel function j1(2 pi f T), whose energy "
                  "density peaks at 2 pi f T = 2.08, f = 0.33 / T. T0 = 500 µs (table 1) "
                  "stretched by eq. 4 to about 1 ms at kilometres puts single N-waves near "
                  "250-330 Hz, as the table 1 row at 1 km shows (farther, the air takes more "
                  "of the highs); the arrival of thousands of segments "
                  "spreads the sound in time (its duration) but does not move the peak down, "
                  "and absorption removes the highs with distance. With table 1's T0 "
                  "(lightning_table1) the bolt peaks at %.0f Hz at 1 km, above the published "
                  "20-200 Hz, and at %.0f Hz at 3 km, against the 50 Hz near which Holmes et "
                  "al. (1971) found the maximum; that gap is the paper's T0, chosen by ear, "
                  "not the renderer: T scales the whole spectrum. The lightning preset takes "
                  "T0 = 2.5 ms, stretched by eq. 4 "
                  "(sigma0 = 0.524) to about 5 ms at 3 km: 0.33 / T = 66 Hz before the air, "
                  "the 50 Hz band after it, where Holmes et al. (1971) found the maximum; by "
                  "Few's relation f = 0.63 c / R0 (1969) that is a relaxation radius of "
                  "3.3 m. Close strikes stay brighter: T grows with distance (eq. 4) and the "
                  "air removes the highs. Sources and the choice of sigma0: "
                  "docs/sound-model.md, \"The lightning presets\".\n",
            table1_near_hz, table1_3km_hz);
    fclose(c.md);
    printf("validation: 1 km peak %.0f Hz (median %.0f), 8 km peak %.0f Hz (median %.0f), "
           "3 km heard for %.2f s, table 2 %.0f segments %.1f s\n",
           near_hz, near_median, far_hz, far_median, dur, segs, sound);
    return enforce ? c.failed : 0;
}
