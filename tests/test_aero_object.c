/* Aero objects in the engine (fulgur/aero_object.h), against closed forms
 * on textures made by hand (a drag or lift that is one pure tone, so
 * every number below has an exact value): the pitch law f_out / f_tex =
 * v / v0; the level law, +18.06 dB per doubling of speed for an aeolian
 * tone, +12.04 dB for a cavity tone (the corrected eq. 3); an inclined
 * stick at 30 degrees (x 0.8660, -3.75 dB); Doppler at 34.3 m/s
 * (x 1 / 0.9 approaching, x 1 / 1.1 receding, from the solved emission
 * times alone); the arrival r / c; the dipole's cos theta and 1 / r; the
 * number of sources (Dobashi et al.'s 50 cm rod of 1 cm: 16; their 70 cm
 * sword: 10); the real-time guard and a frame thread publishing poses
 * and winds; the wind changed after the post (pitch, level, no click);
 * aero objects in ambisonics (the direction decoded); a resting pose
 * re-published (no change, no speed) and a body coming to rest; the path
 * between a swing's poses (on the arc at the exact rate) and its pitch;
 * the refusals and the Reynolds range (silent below, counted above). */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "aero/aero_voice_internal.h"
#include "fg_math.h"
#include "fulgur/aero.h"
#include "fulgur/aero_object.h"
#include "fulgur/engine.h"
#include "rt_guard.h"

#define FS 48000.0
#define C 343.0
#define V0 10.0
#define TEX_RATE 16000.0
#define TEX_FRAMES 1600
#define TEX_PERIODS 20 /* f_tex = 200 Hz at v0 */
#define F_TEX (TEX_PERIODS * TEX_RATE / TEX_FRAMES)
#define DEG (FG_PI / 180.0)

enum { DRAG_ONLY, LIFT_ONLY };

static float samples[TEX_FRAMES * 2];

/* A circular rod's texture, D = 1 cm, whose drag or lift is cos(2 pi f t). */
static fg_aero_texture *make_texture(int which, fg_aero_tone tone, double reference_m)
{
    for (int i = 0; i < TEX_FRAMES; i++) {
        float g = (float)cos(2.0 * FG_PI * TEX_PERIODS * i / TEX_FRAMES);
        samples[2 * i] = which == DRAG_ONLY ? g : 0.0f;
        samples[2 * i + 1] = which == LIFT_ONLY ? g : 0.0f;
    }
    static const fg_aero_source one = {0.0, 1.0};
    fg_aero_direction dir = {.frontal_m = reference_m, .frequency_hz = F_TEX,
                             .strouhal = F_TEX * reference_m / V0, .lift_amplitude = 0.3,
                             .drag_mean = 1.2, .transient_s = 0.1, .periods = TEX_PERIODS,
                             .frames = TEX_FRAMES, .samples = samples};
    fg_aero_texture_desc d = {.shape = FG_AERO_CIRCLE, .tone = tone, .dims = 2, .components = 2,
                              .length_m = reference_m, .reference_m = reference_m,
                              .speed_m_s = V0, .viscosity_m2_s = 1.5e-5, .density_kg_m3 = 1.204,
                              .sample_rate_hz = TEX_RATE, .cells_per_length = 32, .sources = 1,
                              .source = &one, .directions = 1, .direction = &dir};
    d.reynolds = d.reference_m * d.speed_m_s / d.viscosity_m2_s;
    fg_aero_texture *t;
    assert_int_equal(fg_aero_texture_create(&d, &t), FG_OK);
    return t;
}

static fg_engine *make_engine(uint32_t channels)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .speed_of_sound_m_s = C,
                            .max_block_frames = 256, .channels = channels};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    return e;
}

/* A rod along z through `at`, its cross-section's x along x, 1 cm long
 * (one source) unless told. */
static fg_aero_object rod(const fg_aero_texture *t, const double at[3], double wind_x)
{
    return (fg_aero_object){.texture = t, .body = FG_AERO_STICK, .start_m = -0.005,
                            .end_m = 0.005,
                            .pose = {.position = {at[0], at[1], at[2]}, .axis = {0, 0, 1},
                                     .normal = {1, 0, 0}},
                            .wind = {.velocity = {wind_x, 0, 0}}};
}

/* Renders seconds of e into plane 0 (allocated; the caller frees it). */
static float *render(fg_engine *e, double seconds, size_t *frames)
{
    size_t n = (size_t)(seconds * FS) / 256 * 256;
    float *left = calloc(n, sizeof *left), *right = calloc(n, sizeof *right);
    for (size_t at = 0; at < n; at += 256) {
        float *planes[2] = {left + at, right + at};
        assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
    }
    free(right);
    *frames = n;
    return left;
}

/* The frequency of a steady tone between seconds a and b, from its
 * upward zero crossings (each placed by linear interpolation). */
static double frequency(const float *x, double a, double b)
{
    size_t lo = (size_t)(a * FS), hi = (size_t)(b * FS);
    double first = -1, last = -1;
    long count = 0;
    for (size_t n = lo; n + 1 < hi; n++)
        if (x[n] < 0.0f && x[n + 1] >= 0.0f) {
            double t = n + x[n] / (double)(x[n] - x[n + 1]);
            if (first < 0)
                first = t;
            last = t;
            count++;
        }
    assert_true(count > 10);
    return (count - 1) / ((last - first) / FS);
}

static double rms(const float *x, double a, double b)
{
    size_t lo = (size_t)(a * FS), hi = (size_t)(b * FS);
    double s = 0;
    for (size_t n = lo; n < hi; n++)
        s += (double)x[n] * x[n];
    return sqrt(s / (hi - lo));
}

typedef struct tone {
    double f, rms;
} tone;

/* Posts o alone on a fresh engine and measures its tone at the left ear. */
static tone hear(const fg_aero_object *o, uint32_t channels)
{
    fg_engine *e = make_engine(channels);
    assert_int_equal(fg_aero_object_post(e, o, NULL), FG_OK);
    size_t n;
    float *x = render(e, 1.2, &n);
    tone out = {frequency(x, 0.2, 1.2), rms(x, 0.2, 1.2)};
    free(x);
    fg_engine_destroy(e);
    return out;
}

static void pitch_follows_speed(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    static const double at[3] = {0, 10, 0};
    const double ratios[] = {0.5, 1.0, 2.0, 4.0};
    for (size_t i = 0; i < 4; i++) {
        fg_aero_object o = rod(t, at, ratios[i] * V0);
        o.start_m = -0.25, o.end_m = 0.25; /* 16 sources */
        tone h = hear(&o, 2);
        double got = h.f / F_TEX;
        print_message("v/v0 %.1f: f_out/f_tex %.6f\n", ratios[i], got);
        if (fabs(got / ratios[i] - 1.0) > 1e-3)
            fail_msg("v/v0 %.1f: f_out/f_tex %.6f", ratios[i], got);
    }
    fg_aero_texture_destroy(t);
}

static void level_law(void **state)
{
    (void)state;
    static const double at[3] = {0, 10, 0};
    const fg_aero_tone tones[] = {FG_AERO_AEOLIAN, FG_AERO_CAVITY};
    const double want[] = {18.06, 12.04};
    for (int k = 0; k < 2; k++) {
        fg_aero_texture *t = make_texture(LIFT_ONLY, tones[k], 0.01);
        for (double v = 0.5 * V0; v <= 2.0 * V0; v *= 2.0) {
            fg_aero_object slow = rod(t, at, v), fast = rod(t, at, 2.0 * v);
            double db = 20.0 * log10(hear(&fast, 1).rms / hear(&slow, 1).rms);
            print_message("%s, %g -> %g m/s: %+.3f dB\n", k ? "cavity" : "aeolian", v, 2 * v, db);
            if (fabs(db - want[k]) > 0.1)
                fail_msg("%s: %+.3f dB per doubling, want %+.2f", k ? "cavity" : "aeolian", db,
                         want[k]);
        }
        fg_aero_texture_destroy(t);
    }
}

/* Tilted 30 degrees out of the plane across the wind: the cross-flow is
 * v cos 30, the lift still along y, toward the listener. */
static void inclined_stick(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    static const double at[3] = {0, 10, 0};
    fg_aero_object upright = rod(t, at, V0), tilted = upright;
    tilted.pose.axis[0] = sin(30 * DEG), tilted.pose.axis[2] = cos(30 * DEG);
    tilted.pose.normal[0] = cos(30 * DEG), tilted.pose.normal[2] = -sin(30 * DEG);
    tone a = hear(&upright, 1), b = hear(&tilted, 1);
    double ratio = b.f / a.f, db = 20.0 * log10(b.rms / a.rms);
    print_message("30 degrees: frequency x%.5f, level %+.3f dB\n", ratio, db);
    if (fabs(ratio - 0.8660) > 0.8660e-3 || fabs(db + 3.75) > 0.05)
        fail_msg("30 degrees: x%.5f (want 0.8660), %+.3f dB (want -3.75)", ratio, db);
    fg_aero_texture_destroy(t);
}

/* A rod flying at 34.3 m/s along y, through still air, toward the
 * listener or away; the drag radiates along the path. The texture plays
 * at 3.43 x its rate; Doppler multiplies that by 1 / (1 -+ 0.1). */
static void doppler(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(DRAG_ONLY, FG_AERO_AEOLIAN, 0.01);
    const double speed = 34.3, start[2] = {100.0, 10.0}, dir[2] = {-1.0, 1.0};
    const double want[2] = {1.0 / 0.9, 1.0 / 1.1};
    for (int k = 0; k < 2; k++) {
        fg_engine *e = make_engine(1);
        static const double at[3] = {0, 0, 0};
        fg_aero_object o = rod(t, at, 0.0);
        o.pose.position[1] = start[k];
        o.pose.velocity[1] = dir[k] * speed;
        fg_voice_id id;
        assert_int_equal(fg_aero_object_post(e, &o, &id), FG_OK);
        fg_aero_pose later = o.pose;
        later.time_s = 2.5;
        later.position[1] = start[k] + dir[k] * speed * 2.5;
        assert_int_equal(fg_aero_object_set_pose(e, id, &later), FG_OK);
        size_t n;
        float *x = render(e, 1.6, &n);
        double got = frequency(x, 0.5, 1.5) / (F_TEX * speed / V0);
        print_message("%s: Doppler x%.5f (want x%.5f)\n", k ? "receding" : "approaching", got,
                      want[k]);
        if (fabs(got / want[k] - 1.0) > 2e-3)
            fail_msg("%s: x%.5f, want x%.5f", k ? "receding" : "approaching", got, want[k]);
        free(x);
        fg_engine_destroy(e);
    }
    fg_aero_texture_destroy(t);
}

/* A still rod 34.3 m away in the wind, emitting from 0.05 s: the first
 * sample heard is at (0.05 + r / c) fs, within one sample. */
static void arrival(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    static const double at[3] = {0, 34.3, 0};
    fg_engine *e = make_engine(1);
    fg_aero_object o = rod(t, at, V0);
    o.emit_time_s = 0.05;
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_OK);
    size_t n;
    float *x = render(e, 0.3, &n);
    long first = -1;
    for (size_t i = 0; i < n && first < 0; i++)
        if (x[i] != 0.0f)
            first = (long)i;
    double want = (0.05 + 34.3 / C) * FS;
    print_message("first sample %ld, r/c at %.2f\n", first, want);
    if (first < 0 || fabs(first - want) > 1.0)
        fail_msg("first sample %ld, want %.2f +- 1", first, want);
    free(x);
    fg_engine_destroy(e);
    fg_aero_texture_destroy(t);
}

/* The lift dipole seen at theta from its axis, r away: cos theta / r. */
static double dipole_rms(const fg_aero_texture *t, double r, double theta)
{
    double at[3] = {-r * sin(theta), -r * cos(theta), 0};
    fg_aero_object o = rod(t, at, V0);
    return hear(&o, 1).rms;
}

static void directivity_and_distance(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    double on = dipole_rms(t, 10.0, 0.0), at60 = dipole_rms(t, 10.0, 60 * DEG);
    double far = dipole_rms(t, 20.0, 0.0);
    double ratio = at60 / on, db = 20.0 * log10(far / on);
    print_message("60 degrees: %.5f of on-axis; 10 -> 20 m: %+.3f dB\n", ratio, db);
    if (fabs(ratio - 0.5) > 0.005)
        fail_msg("60 degrees: %.5f, want 0.500 +- 1 %%", ratio);
    if (fabs(db + 6.02) > 0.05)
        fail_msg("doubling the distance: %+.3f dB, want -6.02 +- 0.05", db);
    fg_aero_texture_destroy(t);
}

static void source_count(void **state)
{
    (void)state;
    fg_aero_texture *rod1 = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    fg_aero_texture *blade = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.0225);
    fg_engine *e = make_engine(2);
    static const double at[3] = {0, 5, 0};
    fg_aero_object a = rod(rod1, at, V0), b = rod(blade, at, V0);
    a.start_m = 0.0, a.end_m = 0.5;
    b.start_m = 0.1, b.end_m = 0.8; /* a 70 cm blade past a 10 cm hilt */
    fg_voice_id ia, ib;
    assert_int_equal(fg_aero_object_post(e, &a, &ia), FG_OK);
    assert_int_equal(fg_aero_object_post(e, &b, &ib), FG_OK);
    fg_aero_report ra, rb;
    assert_int_equal(fg_aero_object_get_report(e, ia, &ra), FG_OK);
    assert_int_equal(fg_aero_object_get_report(e, ib, &rb), FG_OK);
    assert_int_equal(ra.sources, 16);
    assert_int_equal(rb.sources, 10);
    fg_engine_destroy(e);
    fg_aero_texture_destroy(rod1);
    fg_aero_texture_destroy(blade);
}

/* A 16-source rod swung about its end, a pose per 90 Hz frame published
 * between blocks: rendering allocates, locks, sleeps and does I/O zero
 * times, and the output is finite and not silent. Then a stop fades it
 * out and the voice comes back through collect. */
static void real_time_guard_and_stop(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    fg_engine *e = make_engine(2);
    static const double at[3] = {0, 3, 0};
    const double w = 20.0; /* rad/s about y */
    fg_aero_object o = rod(t, at, 0.0);
    o.start_m = 0.0, o.end_m = 0.5;
    o.pose.angular_velocity[1] = w; /* already swinging; the poses' rate is derived */
    fg_voice_id id;
    assert_int_equal(fg_aero_object_post(e, &o, &id), FG_OK);
    float l[256], r[256];
    float *planes[2] = {l, r};
    double peak = 0;
    for (int b = 0; b < 400; b++) {
        double now = b * 256 / FS;
        if (b % 2 == 0) {
            double a = w * (now + 0.011);
            fg_aero_pose p = {.position = {0, 3, 0}, .axis = {sin(a), 0, cos(a)},
                              .normal = {cos(a), 0, -sin(a)}, .time_s = now + 0.011};
            assert_int_equal(fg_aero_object_set_pose(e, id, &p), FG_OK);
        }
        rt_guard_arm();
        fg_result res = fg_engine_render(e, planes, 256);
        rt_guard_counts counts = rt_guard_disarm();
        assert_int_equal(res, FG_OK);
        assert_int_equal(rt_guard_total(&counts), 0);
        for (int n = 0; n < 256; n++) {
            assert_true(isfinite(l[n]) && isfinite(r[n]));
            peak = fmax(peak, fabs(l[n]));
        }
    }
    fg_aero_report rep;
    assert_int_equal(fg_aero_object_get_report(e, id, &rep), FG_OK);
    /* g of 1 N/s per metre: 16 sources of 3.1 cm, 3 m away, up to
     * 16 * 0.031 / (4 pi c 3 m) = 3.9e-5 Pa */
    assert_true(peak > 5e-6 && peak < 4e-5);
    print_message("swing at 20 rad/s: peak %.4g Pa, fastest cross-flow %.3f m/s\n", peak,
                  rep.max_speed_m_s);
    /* the outermost source, 31/64 of 0.5 m out: w r = 9.6875 m/s (0.01 %) */
    if (fabs(rep.max_speed_m_s - 9.6875) > 1e-3)
        fail_msg("fastest cross-flow %.5f m/s, want 9.6875", rep.max_speed_m_s);
    assert_int_equal(fg_engine_stop(e, id), FG_OK);
    for (int b = 0; b < 20; b++)
        assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
    assert_int_equal(fg_engine_collect(e), 1);
    assert_int_equal(fg_aero_object_set_pose(e, id, &o.pose), FG_ERR_NOT_FOUND);
    fg_engine_destroy(e);
    fg_aero_texture_destroy(t);
}

typedef struct publisher {
    fg_engine *e;
    fg_voice_id id;
    atomic_bool done;
} publisher;

static void *publish_main(void *arg)
{
    publisher *p = arg;
    for (int k = 0; !atomic_load(&p->done); k++) {
        double a = 0.01 * k;
        fg_aero_pose pose = {.position = {0, 3, 0}, .axis = {sin(a), 0, cos(a)},
                             .normal = {cos(a), 0, -sin(a)}};
        if (fg_aero_object_set_pose(p->e, p->id, &pose) != FG_OK)
            return NULL;
        fg_aero_wind wind = {.velocity = {V0 * (1.0 + 0.1 * (k % 7)), 0, 0}};
        if (fg_aero_object_set_wind(p->e, p->id, &wind) != FG_OK)
            return NULL;
        fg_aero_report rep;
        if (fg_aero_object_get_report(p->e, p->id, &rep) != FG_OK)
            return NULL;
    }
    return NULL;
}

/* A frame thread publishing poses and winds as fast as it can while this thread
 * renders (ThreadSanitizer watches this in build-tsan/). */
static void frame_thread_publishes(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    fg_engine *e = make_engine(2);
    static const double at[3] = {0, 3, 0};
    fg_aero_object o = rod(t, at, V0);
    o.start_m = 0.0, o.end_m = 0.5;
    publisher p = {.e = e};
    assert_int_equal(fg_aero_object_post(e, &o, &p.id), FG_OK);
    pthread_t th;
    assert_int_equal(pthread_create(&th, NULL, publish_main, &p), 0);
    float l[256], r[256];
    float *planes[2] = {l, r};
    for (int b = 0; b < 300; b++) {
        assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
        for (int n = 0; n < 256; n++)
            assert_true(isfinite(l[n]) && isfinite(r[n]));
    }
    atomic_store(&p.done, true);
    assert_int_equal(pthread_join(th, NULL), 0);
    fg_engine_destroy(e);
    fg_aero_texture_destroy(t);
}

/* The largest step between neighbouring samples of x in [a, b) s. */
static double largest_step(const float *x, double a, double b)
{
    double m = 0.0;
    for (size_t n = (size_t)(a * FS) + 1; n < (size_t)(b * FS); n++)
        m = fmax(m, fabs((double)x[n] - x[n - 1]));
    return m;
}

/* The wind changed after the post (fg_aero_object_set_wind): a rod 3.43 m
 * away (10 ms) in 10 m/s, the wind raised to 14 m/s at 0.4 s from the
 * frame side between blocks. Before 0.4 s + r/c the tone is v0's; after
 * the blend it is x1.4 in pitch and +8.77 dB (the v^3 law) within 0.1 %
 * and 0.1 dB; no sample step in the blend is larger than the largest in
 * the steady tone after it (no click), which is 1.4^4 times the one before; rendering allocates and locks
 * nothing; bad winds are refused and change nothing. */
static void wind_changes_after_post(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    fg_engine *e = make_engine(1);
    static const double at[3] = {0, -3.43, 0};
    fg_aero_object o = rod(t, at, V0);
    fg_voice_id id;
    assert_int_equal(fg_aero_object_post(e, &o, &id), FG_OK);
    const size_t frames = (size_t)(1.2 * FS) / 256 * 256;
    float *x = calloc(frames, sizeof *x);
    const fg_aero_wind faster = {.velocity = {1.4 * V0, 0, 0}};
    for (size_t n = 0; n < frames; n += 256) {
        if (n == 75 * 256) /* 0.4 s */
            assert_int_equal(fg_aero_object_set_wind(e, id, &faster), FG_OK);
        float *planes[1] = {x + n};
        rt_guard_arm();
        fg_result res = fg_engine_render(e, planes, 256);
        rt_guard_counts counts = rt_guard_disarm();
        assert_int_equal(res, FG_OK);
        assert_int_equal(rt_guard_total(&counts), 0);
    }
    const double heard = 0.4 + 3.43 / C, blended = heard + FG_AERO_WIND_RAMP_S;
    double f0 = frequency(x, 0.1, heard), f1 = frequency(x, blended + 0.01, 1.2);
    double db = 20.0 * log10(rms(x, blended + 0.01, 1.2) / rms(x, 0.1, heard));
    double before = largest_step(x, 0.1, heard), during = largest_step(x, heard - 0.005, blended),
           after = largest_step(x, blended + 0.01, 1.2);
    print_message("wind 10 -> 14 m/s: %.3f -> %.3f Hz (x%.5f), %+.3f dB; largest step %.4g before, "
                  "%.4g in the blend, %.4g after (x%.4f)\n", f0, f1, f1 / f0, db, before, during,
                  after, after / before);
    if (fabs(f0 / F_TEX - 1.0) > 1e-3 || fabs(f1 / f0 / 1.4 - 1.0) > 1e-3)
        fail_msg("pitch %.4f -> %.4f Hz, want %.1f -> %.1f", f0, f1, F_TEX, 1.4 * F_TEX);
    if (fabs(db - 60.0 * log10(1.4)) > 0.1)
        fail_msg("level %+.3f dB, want %+.3f", db, 60.0 * log10(1.4));
    assert_true(during <= after);
    /* a step of a tone is its amplitude times 2 pi f / fs: x 1.4^3 x 1.4 */
    if (fabs(after / before / pow(1.4, 4) - 1.0) > 0.02)
        fail_msg("largest step x%.4f after the blend, want x%.4f", after / before, pow(1.4, 4));

    /* refused, nothing published: the tone stays at 14 m/s */
    fg_aero_wind bad = faster;
    bad.velocity[1] = NAN;
    assert_int_equal(fg_aero_object_set_wind(e, id, &bad), FG_ERR_NOT_FINITE);
    bad = faster, bad.velocity[0] = 120.0;
    assert_int_equal(fg_aero_object_set_wind(e, id, &bad), FG_ERR_ARGUMENT);
    bad = faster, bad.gust = -0.5;
    assert_int_equal(fg_aero_object_set_wind(e, id, &bad), FG_ERR_ARGUMENT);
    bad = faster, bad.gust_period_s = 0.01;
    assert_int_equal(fg_aero_object_set_wind(e, id, &bad), FG_ERR_ARGUMENT);
    assert_int_equal(fg_aero_object_set_wind(NULL, id, &faster), FG_ERR_NULL);
    assert_int_equal(fg_aero_object_set_wind(e, id, NULL), FG_ERR_NULL);
    assert_int_equal(fg_aero_object_set_wind(e, 12345, &faster), FG_ERR_NOT_FOUND);
    for (size_t n = 0; n < frames; n += 256) {
        float *planes[1] = {x + n};
        assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
    }
    double f2 = frequency(x, 0.1, 1.2);
    if (fabs(f2 / f1 - 1.0) > 1e-3)
        fail_msg("after the refusals %.4f Hz, want %.4f", f2, f1);
    free(x);
    fg_engine_destroy(e);
    fg_aero_texture_destroy(t);
}

/* An engine in AmbiX of the given order (fulgur/engine.h), the listener
 * at the origin facing forward, up +z. */
static fg_engine *make_ambisonic_engine(uint32_t order, const double forward[3])
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .speed_of_sound_m_s = C,
                            .max_block_frames = 256, .layout = FG_LAYOUT_AMBISONICS,
                            .ambisonic_order = order};
    fg_engine *e;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    fg_listener head = {.forward = {forward[0], forward[1], forward[2]}, .up = {0, 0, 1}};
    assert_int_equal(fg_engine_set_listener(e, &head), FG_OK);
    return e;
}

#define AMBI_FRAMES (256 * 150) /* 0.8 s */

/* Renders AMBI_FRAMES of e into planes[0..channels). */
static void render_planes(fg_engine *e, float **planes, unsigned channels)
{
    float *at[16];
    for (size_t n = 0; n < AMBI_FRAMES; n += 256) {
        for (unsigned c = 0; c < channels; c++)
            at[c] = planes[c] + n;
        assert_int_equal(fg_engine_render(e, at, 256), FG_OK);
    }
}

static double dot_from(const float *a, const float *b, size_t from)
{
    double s = 0.0;
    for (size_t n = from; n < AMBI_FRAMES; n++)
        s += (double)a[n] * b[n];
    return s;
}

/* A rod 5 m from the listener in the unit direction u (world frame), its
 * axis across the line of sight and the wind across both, so that its lift
 * dipole points at the listener. */
static fg_aero_object rod_towards(const fg_aero_texture *t, const double u[3])
{
    double axis[3] = {-u[1], u[0], 0.0};
    if (fabs(u[2]) > 0.99)
        axis[0] = 1.0, axis[1] = 0.0;
    double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    for (int k = 0; k < 3; k++)
        axis[k] /= len;
    /* drag = u x axis, so lift = axis x drag = u */
    double drag[3] = {u[1] * axis[2] - u[2] * axis[1], u[2] * axis[0] - u[0] * axis[2],
                      u[0] * axis[1] - u[1] * axis[0]};
    fg_aero_object o = {.texture = t, .body = FG_AERO_STICK, .start_m = -0.005, .end_m = 0.005,
                        .pose = {.axis = {axis[0], axis[1], axis[2]},
                                 .normal = {drag[0], drag[1], drag[2]}}};
    for (int k = 0; k < 3; k++) {
        o.pose.position[k] = 5.0 * u[k];
        o.wind.velocity[k] = V0 * drag[k];
    }
    return o;
}

/* Aero objects in ambisonics (orders 1-3): a rod at a known direction
 * decodes by the first-order intensity vector (W times X, Y, Z) to that
 * direction within 5 degrees; W, the pressure at the head's centre, is
 * what the one-ear stereo layout renders, sample for sample; and a
 * listener turned by theta hears what the rod turned by -theta gives. */
static void ambisonics_direction(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    float *planes[16], *mono = calloc(AMBI_FRAMES, sizeof *mono);
    for (int c = 0; c < 16; c++)
        planes[c] = calloc(AMBI_FRAMES, sizeof *planes[c]);
    static const double ahead[3] = {1, 0, 0};
    const size_t from = (size_t)(0.1 * FS); /* after the 14.6 ms travel and the fade */
    double worst = 0.0, w_diff = 0.0;
    for (uint32_t order = 1; order <= 3; order++) {
        const unsigned channels = (order + 1) * (order + 1);
        for (double az = -150.0; az <= 180.0; az += 30.0) {
            for (double el = -60.0; el <= 60.0; el += 30.0) {
                double a = az * DEG, b = el * DEG;
                double u[3] = {cos(b) * cos(a), cos(b) * sin(a), sin(b)};
                fg_aero_object o = rod_towards(t, u);
                fg_engine *e = make_ambisonic_engine(order, ahead);
                assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_OK);
                for (unsigned c = 0; c < channels; c++)
                    memset(planes[c], 0, AMBI_FRAMES * sizeof(float));
                render_planes(e, planes, channels);
                fg_engine_destroy(e);
                /* ACN 1, 2, 3 are Y, Z, X */
                double ix = dot_from(planes[0], planes[3], from),
                       iy = dot_from(planes[0], planes[1], from),
                       iz = dot_from(planes[0], planes[2], from);
                double len = sqrt(ix * ix + iy * iy + iz * iz);
                assert_true(len > 0.0);
                double cosine = (ix * u[0] + iy * u[1] + iz * u[2]) / len;
                double err = acos(fmin(1.0, cosine)) / DEG;
                worst = fmax(worst, err);
                if (!(err < 5.0))
                    fail_msg("order %u az %.0f el %.0f: decoded %.2f deg off", order, az, el, err);
                if (order == 1 && el == 0.0) {
                    fg_engine *m = make_engine(1);
                    fg_listener head = {.forward = {1, 0, 0}, .up = {0, 0, 1}};
                    assert_int_equal(fg_engine_set_listener(m, &head), FG_OK);
                    assert_int_equal(fg_aero_object_post(m, &o, NULL), FG_OK);
                    memset(mono, 0, AMBI_FRAMES * sizeof *mono);
                    render_planes(m, &mono, 1);
                    fg_engine_destroy(m);
                    for (size_t n = 0; n < AMBI_FRAMES; n++)
                        w_diff = fmax(w_diff, fabs((double)planes[0][n] - mono[n]));
                }
            }
        }
    }
    print_message("aero in ambisonics: intensity vector worst %.3g deg off; W - mono %.3g Pa\n",
                  worst, w_diff);
    assert_true(w_diff == 0.0);

    /* the listener turned by 40 degrees to the left = the rod turned by -40 */
    const double th = 40.0 * DEG;
    const double turned[3] = {cos(th), sin(th), 0.0};
    double u[3] = {cos(70 * DEG), sin(70 * DEG), 0.0}, v[3] = {cos(30 * DEG), sin(30 * DEG), 0.0};
    fg_aero_object o1 = rod_towards(t, u), o2 = rod_towards(t, v);
    float *other[16];
    for (int c = 0; c < 16; c++)
        other[c] = calloc(AMBI_FRAMES, sizeof *other[c]);
    fg_engine *e1 = make_ambisonic_engine(3, turned), *e2 = make_ambisonic_engine(3, ahead);
    assert_int_equal(fg_aero_object_post(e1, &o1, NULL), FG_OK);
    assert_int_equal(fg_aero_object_post(e2, &o2, NULL), FG_OK);
    for (int c = 0; c < 16; c++)
        memset(planes[c], 0, AMBI_FRAMES * sizeof(float));
    render_planes(e1, planes, 16);
    render_planes(e2, other, 16);
    fg_engine_destroy(e1);
    fg_engine_destroy(e2);
    double peak = 0.0, diff = 0.0;
    for (int c = 0; c < 16; c++)
        for (size_t n = 0; n < AMBI_FRAMES; n++) {
            peak = fmax(peak, fabs(other[c][n]));
            diff = fmax(diff, fabs((double)planes[c][n] - other[c][n]));
        }
    print_message("turned listener vs turned rod: largest difference %.3g of the peak\n",
                  diff / peak);
    assert_true(peak > 0.0 && diff < 1e-5 * peak);
    for (int c = 0; c < 16; c++) {
        free(planes[c]);
        free(other[c]);
    }
    free(mono);
    fg_aero_texture_destroy(t);
}

static void refuses_bad_input(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    fg_engine *e = make_engine(2);
    static const double at[3] = {0, 3, 0};
    fg_aero_object good = rod(t, at, V0), o;
    assert_int_equal(fg_aero_object_post(NULL, &good, NULL), FG_ERR_NULL);
    o = good, o.texture = NULL;
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_NULL);
    o = good, o.end_m = o.start_m; /* zero length */
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    o = good, o.body = FG_AERO_COMPACT; /* a 2-D texture for a compact body */
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    o = good, o.pose.position[0] = NAN;
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_NOT_FINITE);
    o = good, o.pose.normal[0] = 0, o.pose.normal[2] = 1; /* along the axis */
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    o = good, o.pose.velocity[0] = 150.0;
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    o = good, o.wind.gust = 2.0;
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    o = good, o.start_m = 0.0, o.end_m = 10.0; /* 333 correlation lengths */
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    o.sources = 64;
    fg_voice_id long_rod;
    assert_int_equal(fg_aero_object_post(e, &o, &long_rod), FG_OK);
    o = good, o.absorption = FG_ABSORPTION_ABE_FIR;
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    o = good, o.emit_time_s = -2.0;
    assert_int_equal(fg_aero_object_post(e, &o, NULL), FG_ERR_ARGUMENT);
    fg_engine_report rep;
    fg_engine_get_report(e, &rep);
    assert_int_equal(rep.posted, 1);

    /* poses refused, nothing published */
    fg_voice_id ok;
    assert_int_equal(fg_aero_object_post(e, &good, &ok), FG_OK);
    fg_aero_pose p = good.pose;
    p.axis[1] = INFINITY;
    assert_int_equal(fg_aero_object_set_pose(e, ok, &p), FG_ERR_NOT_FINITE);
    p = good.pose, p.time_s = -1.0;
    assert_int_equal(fg_aero_object_set_pose(e, ok, &p), FG_ERR_ARGUMENT);
    p = good.pose, p.velocity[2] = 101.0;
    assert_int_equal(fg_aero_object_set_pose(e, ok, &p), FG_ERR_ARGUMENT);
    p = good.pose, p.angular_velocity[0] = 1.0001e4;
    assert_int_equal(fg_aero_object_set_pose(e, ok, &p), FG_ERR_ARGUMENT);
    p = good.pose, p.angular_velocity[1] = NAN;
    assert_int_equal(fg_aero_object_set_pose(e, ok, &p), FG_ERR_NOT_FINITE);
    assert_int_equal(fg_aero_object_set_pose(e, 12345, &good.pose), FG_ERR_NOT_FOUND);
    fg_engine_destroy(e);
    fg_aero_texture_destroy(t);
}

/* Below the onset of shedding (Re 47) a rod is silent; above the drag
 * crisis (Re 2e5) it plays on and the blocks are counted. */
/* Renders `blocks` blocks of 256 frames of e into ears[0] and ears[1]
 * (allocated; the caller frees them), calling publish(e, id, b, arg)
 * before block b when it is given. */
static void render_ears(fg_engine *e, fg_voice_id id, int blocks,
                        void (*publish)(fg_engine *, fg_voice_id, int, void *), void *arg,
                        float *ears[2])
{
    ears[0] = calloc((size_t)blocks * 256, sizeof(float));
    ears[1] = calloc((size_t)blocks * 256, sizeof(float));
    for (int b = 0; b < blocks; b++) {
        if (publish)
            publish(e, id, b, arg);
        float *planes[2] = {ears[0] + b * 256, ears[1] + b * 256};
        assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
    }
}

/* The pose a VR app sends again every frame for a body at rest: the same
 * bits, at time 0 (now), or stamped a little ahead of or behind the
 * engine's clock as a frame clock is. */
static void send_again(fg_engine *e, fg_voice_id id, int b, void *arg)
{
    fg_aero_pose p = *(const fg_aero_pose *)arg;
    double now = fg_engine_time_s(e);
    p.time_s = b % 3 == 0 ? 0.0 : b % 3 == 1 ? now + 0.004 : fmax(now - 0.003, 1e-9);
    assert_int_equal(fg_aero_object_set_pose(e, id, &p), FG_OK);
}

/* A body at rest whose unchanged pose is published again before every
 * block (a VR app re-sending it each frame) sounds exactly as with the
 * one pose of its post: a 50 cm rod in a 10 m/s wind, both ears byte for
 * byte over 1.6 s, its fastest cross-flow the wind's; in still air
 * nothing at all (no speed comes of poses that do not move); the same
 * when it was posted 1.5 m away and put here before it sounded (that
 * pose replaces the post's, and its repeats are dropped too). Its axis
 * and normal have lengths other than 1 and are not perpendicular, so the
 * record's normalisation is repeated too. */
static void resting_pose_republished(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    static const double at[3] = {0, 3, 0};
    for (int still_air = 0; still_air < 2; still_air++) {
        fg_aero_object o = rod(t, at, still_air ? 0.0 : V0);
        o.start_m = -0.25, o.end_m = 0.25;
        o.pose.axis[0] = 0.3, o.pose.axis[2] = 2.0;
        o.pose.normal[0] = 3.0, o.pose.normal[1] = 0.2, o.pose.normal[2] = -0.1;
        float *once[2], *again[2], *moved[2];
        fg_aero_report r_once, r_again, r_moved;
        for (int k = 0; k < 3; k++) {
            fg_engine *e = make_engine(2);
            fg_voice_id id;
            fg_aero_object first = o;
            first.pose.position[0] = k == 2 ? 1.5 : first.pose.position[0];
            assert_int_equal(fg_aero_object_post(e, &first, &id), FG_OK);
            /* k == 2: posted elsewhere and put here before it sounds, at
             * the same time (the pose replaces the post's) */
            if (k == 2)
                assert_int_equal(fg_aero_object_set_pose(e, id, &o.pose), FG_OK);
            float **out = k == 0 ? once : k == 1 ? again : moved;
            render_ears(e, id, 300, k ? send_again : NULL, &o.pose, out);
            assert_int_equal(fg_aero_object_get_report(e, id,
                                                       k == 0 ? &r_once : k == 1 ? &r_again
                                                                                 : &r_moved),
                             FG_OK);
            fg_engine_destroy(e);
        }
        size_t n = 300 * 256;
        double peak = 0;
        for (size_t i = 0; i < n; i++)
            peak = fmax(peak, fabs(once[0][i]));
        print_message("%s: peak %.4g Pa, fastest cross-flow %.6f / %.6f m/s\n",
                      still_air ? "still air" : "10 m/s wind", peak, r_once.max_speed_m_s,
                      r_again.max_speed_m_s);
        for (int k = 1; k < 3; k++)
            for (int ch = 0; ch < 2; ch++) {
                const float *x = k == 1 ? again[ch] : moved[ch];
                if (memcmp(once[ch], x, n * sizeof(float)) != 0) {
                    size_t i = 0;
                    while (once[ch][i] == x[i])
                        i++;
                    fail_msg("%s, ear %d: sample %zu is %.9g once, %.9g re-published%s",
                             still_air ? "still air" : "wind", ch, i, once[ch][i], x[i],
                             k == 2 ? " after a move before it sounds" : "");
                }
            }
        assert_true(r_again.max_speed_m_s == r_once.max_speed_m_s);
        assert_true(r_moved.max_speed_m_s == r_once.max_speed_m_s);
        if (still_air) {
            assert_true(peak == 0.0);
            assert_true(r_again.max_speed_m_s == 0.0);
        } else {
            assert_true(peak > 1e-6);
            /* the wind less its part along the tilted axis */
            double along = 0.3 / sqrt(0.3 * 0.3 + 2.0 * 2.0);
            assert_true(fabs(r_again.max_speed_m_s - V0 * sqrt(1 - along * along)) < 1e-5);
        }
        for (int ch = 0; ch < 2; ch++)
            free(once[ch]), free(again[ch]), free(moved[ch]);
    }
    fg_aero_texture_destroy(t);
}

/* A body moved and then held still, its resting pose sent again every
 * block: v_move along `dir`, a pose per block carrying its velocity, for
 * move_blocks blocks; from then on the pose at rest where it stopped. */
typedef struct stopping {
    fg_aero_pose start;
    double dir[3], speed_m_s;
    int move_blocks;
} stopping;

static void stop_and_rest(fg_engine *e, fg_voice_id id, int b, void *arg)
{
    const stopping *s = arg;
    fg_aero_pose p = s->start;
    int k = b < s->move_blocks ? b : s->move_blocks;
    double t = k * 256 / FS;
    for (int i = 0; i < 3; i++) {
        p.position[i] += s->dir[i] * s->speed_m_s * t;
        p.velocity[i] = b < s->move_blocks ? s->dir[i] * s->speed_m_s : 0.0;
    }
    p.time_s = b <= s->move_blocks ? t : 0.0;
    assert_int_equal(fg_aero_object_set_pose(e, id, &p), FG_OK);
}

/* The same body, its pose at rest published once where it stops, told
 * at rest (velocity_given), and no more. */
static void stop_once(fg_engine *e, fg_voice_id id, int b, void *arg)
{
    const stopping *s = arg;
    if (b > s->move_blocks)
        return;
    fg_aero_pose p = s->start;
    double t = b * 256 / FS;
    for (int i = 0; i < 3; i++) {
        p.position[i] += s->dir[i] * s->speed_m_s * t;
        p.velocity[i] = b < s->move_blocks ? s->dir[i] * s->speed_m_s : 0.0;
    }
    p.time_s = t;
    p.velocity_given = 1;
    assert_int_equal(fg_aero_object_set_pose(e, id, &p), FG_OK);
}

/* A rod about z through (-0.5, 3, 0) swung about y at 20 rad/s, a pose
 * per block without its angular velocity, for *arg blocks; from then on
 * the pose at rest where it stopped. */
static void swing_and_rest(fg_engine *e, fg_voice_id id, int b, void *arg)
{
    int stop = *(const int *)arg, k = b < stop ? b : stop;
    double angle = 20.0 * k * 256 / FS;
    fg_aero_pose p = {.position = {-0.5, 3, 0}, .axis = {sin(angle), 0, cos(angle)},
                      .normal = {cos(angle), 0, -sin(angle)},
                      .time_s = b <= stop ? k * 256 / FS : 0.0};
    assert_int_equal(fg_aero_object_set_pose(e, id, &p), FG_OK);
}

/* A body that comes to rest, its resting pose re-published: it does not
 * carry on along its last velocity. A 50 cm rod swept at 10 m/s across
 * the line to the listener (3 m) for 0.1 s in still air, then held: once
 * the last sound of the motion has arrived (a pose interval, r / c and a
 * block of interpolation later) there is nothing to hear; nor when its
 * pose at rest is published once, told at rest (velocity_given); nor for the
 * rod swung about its middle at 20 rad/s and held (its angular velocity
 * taken from the poses: the resting pose's first repeat stops the turn
 * as it stops a move). Then moved
 * 0.51 m away from the listener at 5 m/s in a 10 m/s wind and held: 1.5 s
 * later it sounds as loud as the same rod posted at rest where it stopped
 * (within 0.01 dB; 0.51 m farther would be -1.2 dB). */
/* Posts o and renders 120 blocks of 256 frames, publish moving it: the
 * louder ear peaks above min_pa while it moves (before rest_s) and is
 * exactly silent from quiet_s on. */
static void expect_silent_at_rest(const fg_aero_object *o,
                                  void (*publish)(fg_engine *, fg_voice_id, int, void *),
                                  void *arg, double rest_s, double quiet_s, double min_pa,
                                  const char *what)
{
    fg_engine *e = make_engine(2);
    fg_voice_id id;
    assert_int_equal(fg_aero_object_post(e, o, &id), FG_OK);
    float *ears[2];
    render_ears(e, id, 120, publish, arg, ears);
    fg_engine_destroy(e);
    double moving = 0.0, after = 0.0;
    for (size_t i = 0; i < 120 * 256; i++) {
        double x = fmax(fabs(ears[0][i]), fabs(ears[1][i]));
        if (i / FS < rest_s)
            moving = fmax(moving, x);
        else if (i / FS >= quiet_s)
            after = fmax(after, x);
    }
    print_message("%s: peak %.4g Pa moving, %.4g Pa from %.1f ms after the stop\n", what, moving,
                  after, 1e3 * (quiet_s - rest_s));
    assert_true(moving > min_pa);
    if (after != 0.0)
        fail_msg("%s: still sounds %.4g Pa after it stopped", what, after);
    free(ears[0]), free(ears[1]);
}

static void coming_to_rest(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    const double block_s = 256 / FS;
    static const double from[3] = {-0.5, 3, 0};
    fg_aero_object o = rod(t, from, 0.0);
    o.start_m = -0.25, o.end_m = 0.25;
    stopping s = {.start = o.pose, .dir = {1, 0, 0}, .speed_m_s = 10.0, .move_blocks = 19};
    double rest_s = s.move_blocks * block_s, quiet_s = rest_s + 2 * block_s + 3.1 / C;
    expect_silent_at_rest(&o, stop_and_rest, &s, rest_s, quiet_s, 1e-6,
                          "swept at 10 m/s, then held");
    /* swept the same way and told once that it is at rest where it stops */
    expect_silent_at_rest(&o, stop_once, &s, rest_s, quiet_s, 1e-6,
                          "swept at 10 m/s, told once it rests");
    /* swung at 20 rad/s about its middle and held: no turn goes on (its
     * halves' lifts are opposed: they mostly cancel) */
    int swing_blocks = s.move_blocks;
    expect_silent_at_rest(&o, swing_and_rest, &swing_blocks, rest_s, quiet_s, 1e-8,
                          "swung at 20 rad/s, then held");

    fg_engine *e;
    fg_voice_id id;
    float *ears[2];
    static const double near[3] = {0, 3, 0};
    fg_aero_object moved = rod(t, near, V0);
    moved.start_m = -0.25, moved.end_m = 0.25;
    stopping away = {.start = moved.pose, .dir = {0, 1, 0}, .speed_m_s = 5.0, .move_blocks = 19};
    const double far[3] = {0, 3 + away.speed_m_s * rest_s, 0};
    fg_aero_object held = rod(t, far, V0);
    held.start_m = -0.25, held.end_m = 0.25;
    double level[2];
    for (int k = 0; k < 2; k++) {
        e = make_engine(2);
        assert_int_equal(fg_aero_object_post(e, k ? &held : &moved, &id), FG_OK);
        render_ears(e, id, 400, k ? NULL : stop_and_rest, &away, ears);
        level[k] = rms(ears[0], 1.6, 2.1);
        fg_engine_destroy(e);
        free(ears[0]), free(ears[1]);
    }
    double db = 20 * log10(level[0] / level[1]);
    print_message("moved 0.51 m away and held: %+.4f dB against posted there\n", db);
    if (fabs(db) > 0.01)
        fail_msg("held where it stopped, it sounds %+.4f dB against a body posted there", db);
    fg_aero_texture_destroy(t);
}

/* A steady swing of w rad/s about y through `pivot` as the k-th of a
 * 90 Hz pose stream (angle w k h), its angular velocity given or not. */
static fg_aero_pose swing_pose(double w, int k, const double pivot[3], bool rate_given)
{
    const double h = 1.0 / 90.0, angle = w * k * h;
    fg_aero_pose p = {.position = {pivot[0], pivot[1], pivot[2]},
                      .axis = {sin(angle), 0, cos(angle)},
                      .normal = {cos(angle), 0, -sin(angle)}, .time_s = k * h};
    if (rate_given)
        p.angular_velocity[1] = w;
    return p;
}

/* The path between poses of a turning body, as the voice evaluates it
 * (the trajectory of fg_aero_pose_record's records, the listener's): a
 * steady swing of 20 rad/s about y posed at 90 Hz (0.222 rad a pose).
 * With the angular velocity given, and without it (the turn between the
 * two poses over their interval, from the second pose on), a source stays
 * on its arc and the tip of a 70 cm blade crosses the air at w r within
 * 0.01 %. The chord's rate this replaced was 0.21 % to 0.82 % low. */
static void swing_path_between_poses(void **state)
{
    (void)state;
    const double w = 20.0, h = 1.0 / 90.0, tip = 0.7;
    static const double pivot[3] = {0, 0, 0};
    for (int given = 0; given < 2; given++) {
        fg_trajectory path;
        for (int k = 0; k < 40; k++) {
            fg_aero_pose p = swing_pose(w, k, pivot, given);
            fg_listener record;
            fg_aero_pose_record(&p, &record);
            if (k == 0)
                fg_trajectory_init(&path, &record, 1);
            else
                fg_trajectory_push(&path, &record, (uint64_t)k + 1);
        }
        /* from the first pose when given, else from the second */
        double lo = INFINITY, hi = -INFINITY, off_arc = 0;
        for (int i = 1; i <= 38000; i++) {
            double t = (given ? 0 : h) + i * h / 1000;
            fg_head head;
            fg_trajectory_head(&path, t, &head);
            off_arc = fmax(off_arc, fabs(remainder(atan2(head.right[0], head.right[2]) - w * t,
                                                   2 * FG_PI)));
            double v[3], along = 0, cross = 0;
            for (int k = 0; k < 3; k++)
                v[k] = tip * head.right_rate[k], along += v[k] * head.right[k];
            for (int k = 0; k < 3; k++)
                cross += (v[k] - along * head.right[k]) * (v[k] - along * head.right[k]);
            double err = sqrt(cross) / (w * tip) - 1;
            lo = fmin(lo, err), hi = fmax(hi, err);
        }
        print_message("swing 20 rad/s at 90 Hz, rate %s: off the arc %.3g rad; tip cross-flow "
                      "%+.2e to %+.2e of w r\n", given ? "given" : "from the poses", off_arc, lo,
                      hi);
        if (off_arc > 1e-9 || fabs(lo) > 1e-4 || fabs(hi) > 1e-4)
            fail_msg("rate %s: off the arc %.3g rad, tip cross-flow %+.4f %% to %+.4f %%",
                     given ? "given" : "from the poses", off_arc, 100 * lo, 100 * hi);
    }
}

/* What a 20 rad/s swing sounds like: one source 70 cm out on a blade
 * swung about y through (0, 3, 0), posed at 90 Hz just ahead of the
 * audio, heard at the origin, on the axis of the turn (no Doppler, and
 * the lift's projection on the ear is constant): a steady tone at
 * f_tex w r / v0 = 280 Hz, within 0.1 %, with the angular velocity given
 * or taken from the poses. The chord's rate had it 0.4 % flat. */
static void swing_pitch(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    const double w = 20.0, r = 0.7, h = 1.0 / 90.0;
    static const double pivot[3] = {0, 3, 0};
    for (int given = 0; given < 2; given++) {
        fg_aero_object o = rod(t, pivot, 0.0);
        o.start_m = r - 0.02, o.end_m = r + 0.02;
        o.pose = swing_pose(w, 0, pivot, given);
        fg_engine *e = make_engine(1);
        fg_voice_id id;
        assert_int_equal(fg_aero_object_post(e, &o, &id), FG_OK);
        size_t n = (size_t)(0.8 * FS) / 256 * 256;
        float *x = calloc(n, sizeof *x);
        int next = 1;
        for (size_t at = 0; at < n; at += 256) {
            for (; next * h <= (at + 256) / FS + 2 * h; next++) {
                fg_aero_pose p = swing_pose(w, next, pivot, given);
                assert_int_equal(fg_aero_object_set_pose(e, id, &p), FG_OK);
            }
            float *planes[1] = {x + at};
            assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
        }
        double f = frequency(x, 0.1, 0.8), want = F_TEX * w * r / V0;
        print_message("swing 20 rad/s, rate %s: %.3f Hz, want %.3f (%+.4f %%)\n",
                      given ? "given" : "from the poses", f, want, 100 * (f / want - 1));
        if (fabs(f / want - 1) > 1e-3)
            fail_msg("rate %s: %.3f Hz, want %.3f Hz within 0.1 %%",
                     given ? "given" : "from the poses", f, want);
        free(x);
        fg_engine_destroy(e);
    }
    fg_aero_texture_destroy(t);
}

/* The swing of swing_pitch as hosts render it: in blocks of 256 frames,
 * and in the uneven blocks of a host that splits its buffer (1 to 500
 * frames), the poses published 0.2 s ahead of the audio either way. The
 * voice solves the source at the engine clock's control frames, not at
 * block ends, so the two are the same samples, bit for bit (evaluated at
 * block ends, the blocks of 64 and 256 frames of sword_swing.json were
 * 8 % of its peak apart). */
static void any_block_same_samples(void **state)
{
    (void)state;
    fg_aero_texture *t = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    const double w = 20.0, r = 0.7, h = 1.0 / 90.0;
    static const double pivot[3] = {0, 3, 0};
    static const uint32_t uneven[] = {1, 37, 500, 64, 129, 256, 11, 300, 3};
    const size_t n = (size_t)(0.5 * FS);
    float *x[2];
    for (int run = 0; run < 2; run++) {
        fg_aero_object o = rod(t, pivot, 0.0);
        o.start_m = r - 0.02, o.end_m = r + 0.02;
        o.pose = swing_pose(w, 0, pivot, false);
        fg_engine_config cfg = {
            .sample_rate_hz = FS, .speed_of_sound_m_s = C, .max_block_frames = 512, .channels = 1};
        fg_engine *e;
        assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
        fg_voice_id id;
        assert_int_equal(fg_aero_object_post(e, &o, &id), FG_OK);
        x[run] = calloc(n, sizeof *x[run]);
        int next = 1;
        size_t k = 0;
        for (size_t at = 0; at < n;) {
            uint32_t frames = run == 0 ? 256 : uneven[k++ % (sizeof uneven / sizeof uneven[0])];
            size_t b = frames < n - at ? frames : n - at;
            for (; next * h <= (at + b) / FS + 0.2; next++) {
                fg_aero_pose p = swing_pose(w, next, pivot, false);
                assert_int_equal(fg_aero_object_set_pose(e, id, &p), FG_OK);
            }
            float *planes[1] = {x[run] + at};
            assert_int_equal(fg_engine_render(e, planes, (uint32_t)b), FG_OK);
            at += b;
        }
        fg_engine_destroy(e);
    }
    size_t differ = 0;
    double peak = 0;
    for (size_t i = 0; i < n; i++) {
        differ += x[0][i] != x[1][i];
        peak = fmax(peak, fabs(x[0][i]));
    }
    print_message("a swing in blocks of 256 and of 1 to 500 frames: %zu of %zu samples differ "
                  "(peak %.3g Pa)\n",
                  differ, n, peak);
    if (differ || !(peak > 0))
        fail_msg("%zu samples differ between the two block patterns", differ);
    free(x[0]);
    free(x[1]);
    fg_aero_texture_destroy(t);
}

static void reynolds_range(void **state)
{
    (void)state;
    fg_aero_texture *thin = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.01);
    fg_aero_texture *thick = make_texture(LIFT_ONLY, FG_AERO_AEOLIAN, 0.05);
    static const double at[3] = {0, 3, 0};
    fg_aero_object breeze = rod(thin, at, 0.03); /* Re 20 */
    fg_engine *e = make_engine(1);
    fg_voice_id id;
    assert_int_equal(fg_aero_object_post(e, &breeze, &id), FG_OK);
    size_t n;
    float *x = render(e, 0.2, &n);
    for (size_t i = 0; i < n; i++)
        assert_true(x[i] == 0.0f);
    free(x);
    fg_aero_report r;
    assert_int_equal(fg_aero_object_get_report(e, id, &r), FG_OK);
    assert_int_equal(r.beyond_range_blocks, 0);
    fg_engine_destroy(e);

    fg_aero_object gale = rod(thick, at, 80.0), ok = rod(thick, at, 20.0); /* Re 2.7e5, 6.7e4 */
    e = make_engine(1);
    fg_voice_id fast, fine;
    assert_int_equal(fg_aero_object_post(e, &gale, &fast), FG_OK);
    assert_int_equal(fg_aero_object_post(e, &ok, &fine), FG_OK);
    x = render(e, 0.2, &n);
    double peak = 0;
    for (size_t i = 0; i < n; i++)
        peak = fmax(peak, fabs(x[i]));
    free(x);
    assert_true(peak > 0.0);
    fg_aero_report rf, rk;
    assert_int_equal(fg_aero_object_get_report(e, fast, &rf), FG_OK);
    assert_int_equal(fg_aero_object_get_report(e, fine, &rk), FG_OK);
    assert_true(rf.beyond_range_blocks > 0);
    assert_int_equal(rk.beyond_range_blocks, 0);
    assert_true(fabs(rf.max_speed_m_s - 80.0) < 1e-3);
    fg_engine_destroy(e);
    fg_aero_texture_destroy(thin);
    fg_aero_texture_destroy(thick);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pitch_follows_speed),
        cmocka_unit_test(level_law),
        cmocka_unit_test(inclined_stick),
        cmocka_unit_test(doppler),
        cmocka_unit_test(arrival),
        cmocka_unit_test(directivity_and_distance),
        cmocka_unit_test(source_count),
        cmocka_unit_test(real_time_guard_and_stop),
        cmocka_unit_test(frame_thread_publishes),
        cmocka_unit_test(wind_changes_after_post),
        cmocka_unit_test(ambisonics_direction),
        cmocka_unit_test(refuses_bad_input),
        cmocka_unit_test(reynolds_range),
        cmocka_unit_test(resting_pose_republished),
        cmocka_unit_test(coming_to_rest),
        cmocka_unit_test(swing_path_between_poses),
        cmocka_unit_test(swing_pitch),
        cmocka_unit_test(any_block_same_samples),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
