#define _POSIX_C_SOURCE 200809L /* nanosleep */
/* The fire voice (fulgur/fire_voice.h) against closed forms: the level
 * falls 6.02 dB per doubling of distance and the sound arrives r / c
 * after it leaves (within a sample); a fire carried away at 30 m/s is
 * heard at c / (c + v) of its pitch (within 0.2 %); a producer that stops
 * is counted to the frame and faded, never clicked; a stream fed from a
 * flux series is p = rho0 / (4 pi) dI/dt at 1 m; ambisonics from the
 * direction of arrival; the real-time guard; a producer, an audio and a
 * frame thread at once (for ThreadSanitizer); the refusals. */
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cmocka.h>

#include "fg_math.h"
#include "fulgur/engine.h"
#include "fulgur/fire_voice.h"
#include "rt_guard.h"

#define FS 48000.0
#define C 343.0
#define BLOCK 256

static fg_engine *make_engine(uint32_t channels, fg_layout layout, uint32_t order)
{
    fg_engine_config cfg = {.sample_rate_hz = FS, .channels = channels, .speed_of_sound_m_s = C,
                            .layout = layout, .ambisonic_order = order};
    fg_engine *e = NULL;
    assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
    return e;
}

static fg_voice_id post_at(fg_engine *e, double x, double y, double z, double ring_s)
{
    fg_fire_voice f = {.pose = {.position = {x, y, z}}, .emit_time_s = 0.0, .ring_s = ring_s};
    fg_voice_id id = 0;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_OK);
    return id;
}

/* The stream's frame n: a sine of 1 Pa at 1 m, f_hz. */
static float sine(double f_hz, uint64_t n)
{
    return (float)sin(2.0 * FG_PI * f_hz * (double)n / FS);
}

/* Renders frames frames of channel ch into out (NULL: discarded), pushing
 * before each block the next frames of the signal (sine at f_hz; f_hz 0:
 * an impulse at frame 0) up to `limit` frames of stream, as far as the
 * ring takes. */
typedef struct feeder {
    uint64_t next, limit;
    double f_hz;
} feeder;

static void feed(fg_engine *e, fg_voice_id id, feeder *fd)
{
    float buf[BLOCK];
    while (fd->next < fd->limit) {
        size_t n = fd->limit - fd->next < BLOCK ? (size_t)(fd->limit - fd->next) : BLOCK;
        for (size_t i = 0; i < n; i++)
            buf[i] = fd->f_hz > 0.0 ? sine(fd->f_hz, fd->next + i) : (fd->next + i == 0 ? 1.0f : 0.0f);
        size_t pushed = 0;
        assert_int_equal(fg_fire_voice_push(e, id, buf, n, &pushed), FG_OK);
        fd->next += pushed;
        if (pushed < n)
            break;
    }
}

static void play(fg_engine *e, fg_voice_id id, feeder *fd, uint32_t channels, unsigned ch,
                 float *out, size_t frames)
{
    float planes[16][BLOCK];
    float *p[16];
    for (unsigned k = 0; k < 16; k++)
        p[k] = planes[k];
    for (size_t done = 0; done < frames; done += BLOCK) {
        if (fd)
            feed(e, id, fd);
        uint32_t n = frames - done < BLOCK ? (uint32_t)(frames - done) : BLOCK;
        assert_int_equal(fg_engine_render(e, p, n), FG_OK);
        if (out)
            memcpy(out + done, planes[ch], n * sizeof(float));
    }
    (void)channels;
}

static double rms(const float *x, size_t a, size_t b)
{
    double s = 0.0;
    for (size_t i = a; i < b; i++)
        s += (double)x[i] * x[i];
    return sqrt(s / (double)(b - a));
}

static void level_falls_6db_per_doubling(void **state)
{
    (void)state;
    const size_t frames = 48000;
    float *out = malloc(frames * sizeof *out);
    double level[3];
    for (int i = 0; i < 3; i++) {
        double r = 5.0 * (1 << i);
        fg_engine *e = make_engine(1, FG_LAYOUT_STEREO, 0);
        fg_voice_id id = post_at(e, r, 0.0, 0.0, 0.0);
        feeder fd = {.limit = UINT64_MAX, .f_hz = 500.0};
        play(e, id, &fd, 1, 0, out, frames);
        level[i] = 20.0 * log10(rms(out, 24000, frames));
        /* 1 Pa at 1 m: 1 / (r sqrt 2) rms at r */
        assert_true(fabs(level[i] - 20.0 * log10(1.0 / (r * sqrt(2.0)))) < 0.01);
        fg_fire_voice_report rep;
        assert_int_equal(fg_fire_voice_get_report(e, id, &rep), FG_OK);
        assert_int_equal(rep.underrun_frames, 0);
        fg_engine_destroy(e);
    }
    print_message("level at 5, 10, 20 m: %.3f %.3f %.3f dB (steps %.4f %.4f)\n", level[0],
                  level[1], level[2], level[1] - level[0], level[2] - level[1]);
    assert_true(fabs(level[1] - level[0] + 6.0206) < 0.01);
    assert_true(fabs(level[2] - level[1] + 6.0206) < 0.01);
    free(out);
}

static void arrival_is_r_over_c(void **state)
{
    (void)state;
    const size_t frames = 8192;
    float *out = malloc(frames * sizeof *out);
    const double r[] = {3.0, 17.3, 40.0};
    for (int i = 0; i < 3; i++) {
        fg_engine *e = make_engine(1, FG_LAYOUT_STEREO, 0);
        fg_voice_id id = post_at(e, 0.0, r[i], 0.0, 0.0);
        feeder fd = {.limit = 8192, .f_hz = 0.0};
        feed(e, id, &fd);
        assert_int_equal(fg_fire_voice_close(e, id), FG_OK);
        play(e, id, NULL, 1, 0, out, frames);
        size_t peak = 0;
        for (size_t n = 0; n < frames; n++)
            if (fabsf(out[n]) > fabsf(out[peak]))
                peak = n;
        double expect = r[i] / C * FS;
        print_message("r %.1f m: peak at %zu, r / c = %.2f frames, peak %.4f Pa\n", r[i], peak,
                      expect, out[peak]);
        assert_true(fabs((double)peak - expect) <= 1.0);
        assert_true(out[peak] > 0.5 / r[i] && out[peak] <= 1.0001 / r[i]);
        fg_engine_destroy(e);
    }
    free(out);
}

/* Frequency from zero crossings (rising, linearly interpolated) in [a, b). */
static double frequency(const float *x, size_t a, size_t b)
{
    double first = -1.0, last = -1.0;
    int count = 0;
    for (size_t n = a + 1; n < b; n++)
        if (x[n - 1] < 0.0f && x[n] >= 0.0f) {
            double t = (double)(n - 1) + x[n - 1] / (double)(x[n - 1] - x[n]);
            if (first < 0.0)
                first = t;
            else
                count++;
            last = t;
        }
    return count > 0 ? count * FS / (last - first) : 0.0;
}

static void doppler_of_a_carried_torch(void **state)
{
    (void)state;
    const double v = 30.0, f = 1000.0, x0 = 10.0;
    const size_t frames = 96000;
    float *out = malloc(frames * sizeof *out);
    fg_engine *e = make_engine(1, FG_LAYOUT_STEREO, 0);
    fg_fire_voice fire = {.pose = {.position = {x0, 0, 0}, .velocity = {v, 0, 0}, .time_s = 1e-9}};
    fg_voice_id id;
    assert_int_equal(fg_fire_voice_post(e, &fire, &id), FG_OK);
    for (int k = 1; k <= 8; k++) {
        fg_fire_pose p = {.position = {x0 + v * 0.5 * k, 0, 0}, .velocity = {v, 0, 0},
                          .time_s = 0.5 * k};
        assert_int_equal(fg_fire_voice_set_pose(e, id, &p), FG_OK);
    }
    feeder fd = {.limit = UINT64_MAX, .f_hz = f};
    play(e, id, &fd, 1, 0, out, frames);
    double heard = frequency(out, 24000, frames);
    double expect = f * C / (C + v);
    print_message("receding at %.0f m/s: %.3f Hz, c / (c + v) gives %.3f Hz (%.4f %%)\n", v,
                  heard, expect, 100.0 * (heard / expect - 1.0));
    assert_true(fabs(heard / expect - 1.0) < 0.002);
    /* and the level follows 1 / r along the way: at 1.5 s it is ~ x0 + v (1.5 - r/c) */
    fg_engine_destroy(e);
    free(out);
}

/* A producer that stops after `pushed` frames: the frames missing are
 * counted exactly, and the sound fades out rather than stopping dead. */
static void underruns_counted_and_faded(void **state)
{
    (void)state;
    const size_t frames = 24000;
    const uint64_t pushed = 9000;
    float *out = malloc(frames * sizeof *out);
    fg_engine *e = make_engine(1, FG_LAYOUT_STEREO, 0);
    fg_voice_id id = post_at(e, 3.43, 0, 0, 0.0);
    feeder fd = {.limit = pushed, .f_hz = 200.0};
    play(e, id, &fd, 1, 0, out, frames);
    fg_fire_voice_report rep;
    assert_int_equal(fg_fire_voice_get_report(e, id, &rep), FG_OK);
    /* the stream frame heard at the end: frames - 480 (3.43 m at 343 m/s) */
    print_message("read frame %lld (expect %zu), underrun frames %llu, underruns %llu\n",
                  (long long)rep.read_frame, frames - 480, (unsigned long long)rep.underrun_frames,
                  (unsigned long long)rep.underruns);
    assert_true(llabs(rep.read_frame - (long long)(frames - 480)) <= 1);
    assert_int_equal(rep.underrun_frames, (uint64_t)(rep.read_frame + 1) - pushed);
    assert_int_equal(rep.underruns, 1);
    assert_int_equal(rep.pushed_frames, pushed);
    /* faded: no step larger than the sine's own, silence after */
    double steady = 0.0, worst = 0.0;
    for (size_t n = 2000; n < 8000; n++)
        steady = fmax(steady, fabs(out[n] - out[n - 1]));
    for (size_t n = 8000; n < frames; n++)
        worst = fmax(worst, fabs(out[n] - out[n - 1]));
    print_message("largest step: steady %.5f, around the underrun %.5f\n", steady, worst);
    assert_true(worst <= steady * 1.25); /* a click would be 40 times it */
    assert_true(fabs(out[frames / 2]) == 0.0f && rms(out, 12000, frames) == 0.0);
    assert_true(rms(out, 4000, 8000) > 0.01);
    /* the producer comes back: the voice plays again from the frame due */
    feeder late = {.next = pushed, .limit = UINT64_MAX, .f_hz = 200.0};
    play(e, id, &late, 1, 0, out, frames);
    assert_true(rms(out, frames / 2, frames) > 0.01);
    assert_int_equal(fg_fire_voice_get_report(e, id, &rep), FG_OK);
    assert_int_equal(rep.underruns, 1);
    fg_engine_destroy(e);
    free(out);
}

static void refusals(void **state)
{
    (void)state;
    fg_engine *e = make_engine(2, FG_LAYOUT_STEREO, 0);
    fg_fire_voice f = {.pose = {.position = {1, 0, 0}}};
    fg_voice_id id;
    assert_int_equal(fg_fire_voice_post(NULL, &f, &id), FG_ERR_NULL);
    f.pose.position[1] = NAN;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_NOT_FINITE);
    f.pose.position[1] = 2e7;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_ARGUMENT);
    f.pose.position[1] = 0.0;
    f.pose.velocity[0] = 101.0;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_ARGUMENT);
    f.pose.velocity[0] = 0.0;
    f.gain = -1.0;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_ARGUMENT);
    f.gain = 0.0;
    f.absorption = FG_ABSORPTION_ABE_FIR;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_ARGUMENT);
    f.absorption = FG_ABSORPTION_OFF;
    f.ring_s = 9.0;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_ARGUMENT);
    f.ring_s = 0.01;
    f.emit_time_s = -2.0;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_ARGUMENT);
    f.emit_time_s = 0.0;
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_OK);

    /* NaN and huge samples: nothing pushed */
    float x[1000];
    for (int i = 0; i < 1000; i++)
        x[i] = 0.5f;
    x[700] = NAN;
    size_t pushed = 99;
    assert_int_equal(fg_fire_voice_push(e, id, x, 1000, &pushed), FG_ERR_NOT_FINITE);
    assert_int_equal(pushed, 0);
    x[700] = 2e9f;
    assert_int_equal(fg_fire_voice_push(e, id, x, 1000, &pushed), FG_ERR_ARGUMENT);
    fg_fire_voice_report rep;
    assert_int_equal(fg_fire_voice_get_report(e, id, &rep), FG_OK);
    assert_int_equal(rep.pushed_frames, 0);
    /* a full ring takes what fits and says so: 0.01 s at 48 kHz -> 512 */
    x[700] = 0.5f;
    assert_int_equal(rep.capacity_frames, 512);
    assert_int_equal(fg_fire_voice_push(e, id, x, 1000, &pushed), FG_OK);
    assert_int_equal(pushed, 512);
    assert_int_equal(fg_fire_voice_push(e, id, x, 1000, &pushed), FG_OK);
    assert_int_equal(pushed, 0);
    assert_int_equal(fg_fire_voice_push(e, id, NULL, 3, &pushed), FG_ERR_NULL);
    assert_int_equal(fg_fire_voice_push(e, id + 1, x, 3, &pushed), FG_ERR_NOT_FOUND);
    assert_int_equal(fg_fire_voice_close(e, id), FG_OK);
    assert_int_equal(fg_fire_voice_push(e, id, x, 3, &pushed), FG_ERR_ARGUMENT);
    fg_fire_pose p = {.position = {INFINITY, 0, 0}};
    assert_int_equal(fg_fire_voice_set_pose(e, id, &p), FG_ERR_NOT_FINITE);

    /* a flux series with a NaN: refused, nothing taken */
    fg_fire_sound_config sc = {.sample_rate_hz = FS, .extension = FG_FIRE_LOW_ONLY};
    fg_fire_feed *feed = NULL;
    assert_int_equal(fg_fire_feed_create(&sc, 0, &feed), FG_OK);
    fg_voice_id other = post_at(e, 1, 0, 0, 0.0);
    double flux[4] = {1.0, NAN, 1.0, 1.0};
    size_t taken = 9;
    assert_int_equal(fg_fire_feed_push(feed, e, other, flux, 4, &taken), FG_ERR_NOT_FINITE);
    assert_int_equal(taken, 0);
    assert_int_equal(fg_fire_voice_get_report(e, other, &rep), FG_OK);
    assert_int_equal(rep.pushed_frames, 0);
    fg_fire_feed_destroy(feed);
    /* a feed at another rate than the engine's */
    sc.sample_rate_hz = 44100.0;
    assert_int_equal(fg_fire_feed_create(&sc, 0, &feed), FG_OK);
    flux[1] = 1.0;
    assert_int_equal(fg_fire_feed_push(feed, e, other, flux, 4, &taken), FG_ERR_SAMPLE_RATE);
    fg_fire_feed_destroy(feed);
    /* the fire pool: FG_FIRE_VOICE_MAX alive at once */
    unsigned alive = 2;
    while (alive < FG_FIRE_VOICE_MAX) {
        (void)post_at(e, 1, 0, 0, 0.01);
        alive++;
    }
    assert_int_equal(fg_fire_voice_post(e, &f, &id), FG_ERR_POOL_FULL);
    fg_engine_destroy(e);
}

/* p = rho0 / (4 pi) dI/dt at 1 m: a flux I = A sin(2 pi f t) gives
 * rho0 A f / 2 Pa peak, A = 0.01 m^3/s, f = 20 Hz (the high-pass off). */
static void feed_gives_pascals(void **state)
{
    (void)state;
    const size_t frames = 96000;
    float *out = malloc(frames * sizeof *out);
    fg_engine *e = make_engine(1, FG_LAYOUT_STEREO, 0);
    fg_engine_config cfg;
    fg_engine_get_config(e, &cfg);
    const double rho = 101325.0 / (287.05 * 293.15);
    assert_true(fabs(fg_fire_pascals_per_flux_rate(&cfg) - rho / (4.0 * FG_PI)) < 1e-12);
    fg_fire_sound_config sc = {.sample_rate_hz = FS, .extension = FG_FIRE_LOW_ONLY,
                               .highpass_hz = -1.0};
    fg_fire_feed *fd = NULL;
    assert_int_equal(fg_fire_feed_create(&sc, 16, &fd), FG_OK);
    fg_voice_id id = post_at(e, 1.0, 0, 0, 1.0);
    const double A = 0.01, f = 20.0, sim = 360.0;
    double flux[720];
    for (int i = 0; i < 720; i++)
        flux[i] = A * sin(2.0 * FG_PI * f * i / sim);
    size_t given = 0;
    while (given < 720) {
        size_t taken = 0;
        assert_int_equal(fg_fire_feed_push(fd, e, id, flux + given, 720 - given, &taken), FG_OK);
        given += taken;
        if (given < 720)
            play(e, id, NULL, 1, 0, NULL, BLOCK);
    }
    print_message("feed latency %.4f s, pending %zu\n", fg_fire_feed_latency_s(fd),
                  fg_fire_feed_pending(fd));
    bool done = false;
    while (!done) {
        assert_int_equal(fg_fire_feed_finish(fd, e, id, &done), FG_OK);
        if (!done)
            play(e, id, NULL, 1, 0, NULL, BLOCK);
    }
    fg_fire_voice_report rep;
    assert_int_equal(fg_fire_voice_get_report(e, id, &rep), FG_OK);
    assert_true(rep.closed);
    /* drained: every frame up to the last flux sample's time, 719 / 360 s */
    assert_int_equal(rep.pushed_frames, 719 * 48000 / 360 + 1);
    fg_engine_destroy(e);
    /* again, rendering from the start, the stream pre-filled by a big ring */
    e = make_engine(1, FG_LAYOUT_STEREO, 0);
    fg_fire_feed_destroy(fd);
    assert_int_equal(fg_fire_feed_create(&sc, 16, &fd), FG_OK);
    fg_fire_voice big = {.pose = {.position = {1.0, 0, 0}}, .ring_s = 4.0};
    assert_int_equal(fg_fire_voice_post(e, &big, &id), FG_OK);
    size_t taken = 0;
    assert_int_equal(fg_fire_feed_push(fd, e, id, flux, 720, &taken), FG_OK);
    assert_int_equal(taken, 720);
    play(e, id, NULL, 1, 0, out, frames);
    double peak = 0.0;
    for (size_t n = 24000; n < 72000; n++)
        peak = fmax(peak, fabs(out[n]));
    double expect = rho / (4.0 * FG_PI) * A * 2.0 * FG_PI * f;
    print_message("flux sine: %.6f Pa peak at 1 m, rho0 A f / 2 = %.6f Pa (%.3f %%)\n", peak,
                  expect, 100.0 * (peak / expect - 1.0));
    assert_true(fabs(peak / expect - 1.0) < 0.01);
    fg_fire_feed_destroy(fd);
    fg_engine_destroy(e);
    free(out);
}

/* First order ambisonics: a fire straight ahead is W = X, Y = Z = 0; to
 * the left, W = Y. */
static void ambisonics_from_direction(void **state)
{
    (void)state;
    const size_t frames = 9600;
    float *w = malloc(frames * sizeof *w), *a = malloc(frames * sizeof *a);
    const struct { double pos[3]; unsigned ch; } cases[] = {{{0, 5, 0}, 3}, {{-5, 0, 0}, 1}};
    for (int c = 0; c < 2; c++) {
        for (unsigned ch = 0; ch < 2; ch++) {
            fg_engine *e = make_engine(4, FG_LAYOUT_AMBISONICS, 1);
            fg_voice_id id = post_at(e, cases[c].pos[0], cases[c].pos[1], cases[c].pos[2], 0.0);
            feeder fd = {.limit = UINT64_MAX, .f_hz = 300.0};
            play(e, id, &fd, 4, ch == 0 ? 0 : cases[c].ch, ch == 0 ? w : a, frames);
            fg_engine_destroy(e);
        }
        double rw = rms(w, 4800, frames), ra = rms(a, 4800, frames);
        print_message("ACN %u / W: %.6f\n", cases[c].ch, ra / rw);
        assert_true(fabs(ra / rw - 1.0) < 1e-4);
    }
    free(w);
    free(a);
}

static void realtime_guard(void **state)
{
    (void)state;
    fg_engine *e = make_engine(2, FG_LAYOUT_STEREO, 0);
    fg_voice_id ids[4];
    feeder fd[4];
    for (int i = 0; i < 4; i++) {
        ids[i] = post_at(e, 3.0 + i, 1.0, 0.0, 0.0);
        fd[i] = (feeder){.limit = i == 3 ? 3000 : UINT64_MAX, .f_hz = 200.0 * (i + 1)};
    }
    float l[BLOCK], r[BLOCK];
    float *p[2] = {l, r};
    unsigned long total = 0;
    for (int b = 0; b < 200; b++) {
        for (int i = 0; i < 4; i++)
            if (i != 1 || b < 150)
                feed(e, ids[i], &fd[i]);
        fg_fire_pose pose = {.position = {3.0 + 0.01 * b, 1.0, 0.0}};
        assert_int_equal(fg_fire_voice_set_pose(e, ids[0], &pose), FG_OK);
        if (b == 150)
            assert_int_equal(fg_engine_stop(e, ids[1]), FG_OK);
        rt_guard_arm();
        fg_result res = fg_engine_render(e, p, BLOCK);
        rt_guard_counts counts = rt_guard_disarm();
        assert_int_equal(res, FG_OK);
        total += rt_guard_total(&counts);
        (void)fg_engine_collect(e);
    }
    assert_int_equal(total, 0);
    fg_fire_voice_report rep;
    assert_int_equal(fg_fire_voice_get_report(e, ids[3], &rep), FG_OK);
    assert_true(rep.underrun_frames > 0);
    assert_int_equal(fg_fire_voice_get_report(e, ids[1], &rep), FG_ERR_NOT_FOUND); /* stopped, collected */
    fg_engine_destroy(e);
}

/* Three threads: a producer feeding flux through bandwidth extension, the
 * audio thread rendering, a frame thread moving the fire. */
typedef struct shared {
    fg_engine *e;
    fg_voice_id id;
    atomic_bool stop;
    atomic_uint_least64_t blocks;
} shared;

static void *audio(void *arg)
{
    shared *s = arg;
    float l[BLOCK], r[BLOCK];
    float *p[2] = {l, r};
    while (!atomic_load(&s->stop)) {
        fg_result res = fg_engine_render(s->e, p, BLOCK);
        if (res != FG_OK)
            break;
        atomic_fetch_add(&s->blocks, 1);
        nanosleep(&(struct timespec){0, 1000000}, NULL); /* 5 times real time */
    }
    return NULL;
}

static void *frame(void *arg)
{
    shared *s = arg;
    for (int k = 0; !atomic_load(&s->stop); k++) {
        fg_fire_pose pose = {.position = {-20.0 + 0.02 * (k % 2000), 2.0, 0.0}};
        fg_result res = fg_fire_voice_set_pose(s->e, s->id, &pose);
        if (res != FG_OK)
            break;
        for (volatile int spin = 0; spin < 20000; spin++)
            ;
    }
    return NULL;
}

static void threads_stream(void **state)
{
    (void)state;
    shared s = {.e = make_engine(2, FG_LAYOUT_STEREO, 0)};
    atomic_init(&s.stop, false);
    atomic_init(&s.blocks, 0);
    fg_fire_voice f = {.pose = {.position = {-20, 2, 0}}, .ring_s = 0.2};
    assert_int_equal(fg_fire_voice_post(s.e, &f, &s.id), FG_OK);
    fg_fire_sound_config sc = {.sample_rate_hz = FS};
    fg_fire_feed *fd = NULL;
    assert_int_equal(fg_fire_feed_create(&sc, 8, &fd), FG_OK);
    pthread_t ta, tf;
    assert_int_equal(pthread_create(&ta, NULL, audio, &s), 0);
    assert_int_equal(pthread_create(&tf, NULL, frame, &s), 0);
    uint64_t step = 0, pushed = 0;
    double flux[8];
    while (atomic_load(&s.blocks) < 400) {
        for (int i = 0; i < 8; i++)
            flux[i] = 0.01 * (1.0 + sin(0.3 * (double)(step + i)));
        size_t taken = 0;
        assert_int_equal(fg_fire_feed_push(fd, s.e, s.id, flux, 8, &taken), FG_OK);
        step += taken;
        pushed += taken;
        (void)fg_engine_collect(s.e);
    }
    atomic_store(&s.stop, true);
    pthread_join(ta, NULL);
    pthread_join(tf, NULL);
    fg_fire_voice_report rep;
    assert_int_equal(fg_fire_voice_get_report(s.e, s.id, &rep), FG_OK);
    print_message("%llu blocks, %llu flux steps, %llu frames pushed, %llu underrun frames\n",
                  (unsigned long long)atomic_load(&s.blocks), (unsigned long long)pushed,
                  (unsigned long long)rep.pushed_frames, (unsigned long long)rep.underrun_frames);
    /* whatever the threads' speeds (ThreadSanitizer slows the producer
     * most): the underruns are at most the frames whose time has passed */
    assert_true(rep.pushed_frames > 0 && rep.read_frame >= 0);
    /* no emission time is after the engine's clock (the frame thread's
     * jumps make the fire's emission times go back, so read_frame is no
     * bound) */
    assert_true(rep.underrun_frames <= atomic_load(&s.blocks) * BLOCK + 1);
    assert_true(rep.held_frames <= rep.capacity_frames);
    fg_engine_report er;
    fg_engine_get_report(s.e, &er);
    assert_int_equal(er.non_finite_voices, 0);
    fg_fire_feed_destroy(fd);
    fg_engine_destroy(s.e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(level_falls_6db_per_doubling),
        cmocka_unit_test(arrival_is_r_over_c),
        cmocka_unit_test(doppler_of_a_carried_torch),
        cmocka_unit_test(underruns_counted_and_faded),
        cmocka_unit_test(refusals),
        cmocka_unit_test(feed_gives_pascals),
        cmocka_unit_test(ambisonics_from_direction),
        cmocka_unit_test(realtime_guard),
        cmocka_unit_test(threads_stream),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
