/* When and how loud a lone segment arrives, predicted from the geometry
 * alone (DESIGN §2):
 *   t_arrival = t_emit + (return-stroke delay) + r / c   (the N-wave centre)
 *   the wave starts (T + l s / c) before it, T from eq. 4,
 * so the first non-zero sample is the one whose interval [n - 1/2, n + 1/2)
 * holds fs (t_arrival - T - l s / c). Each ear has its own r and s; the two
 * ears differ by the interaural delay (r_right - r_left) / c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>
#include <math.h>

#include "engine_fixture.h"
#include "spatial/spherical_head_internal.h"

#define C_M_S 343.0
#define SPACING_M 0.18

#define CHECK(cond, ...)            \
    do {                            \
        if (!(cond))                \
            fail_msg(__VA_ARGS__);  \
    } while (0)

typedef struct arrival_case {
    const char *name;
    double fs;
    uint32_t channels;
    fg_preset preset;
    double mid[3], dir[3], half_len_m;
    double emit_s;     /* FG_EMIT_NOW: the block after preroll frames */
    size_t preroll;    /* frames rendered before the post */
    uint32_t block;
} arrival_case;

/* The listener stays at the origin facing +y, up +z: the right ear is at
 * +x 0.09 m, the left at -x, on a sphere of that radius. */
static const arrival_case cases[] = {
    {"ahead 3 m, broadside", 48000, 2, FG_PRESET_PLASMA_BALL, {0, 3, 0}, {0, 0, 1}, 0.01, 0.010, 0,
     256},
    {"right 5 m", 48000, 2, FG_PRESET_PLASMA_BALL, {5, 0, 0}, {0, 0, 1}, 0.01, 0.004, 0, 64},
    {"left 4 m, oblique", 96000, 2, FG_PRESET_SPARK_BALLS, {-4, 1, 0.5}, {1, 1, 1}, 0.001, 0.0,
     0, 1000},
    {"right-behind 20 m, lightning", 44100, 2, FG_PRESET_LIGHTNING, {14, -14, 2}, {0.3, 0, 1},
     1.5, 0.02, 0, 4096},
    {"mono 7 m", 44100, 1, FG_PRESET_PLASMA_BALL, {2, 6, 3}, {1, 0, 0}, 0.01, 0.0123, 0, 512},
    {"emit now after preroll", 48000, 2, FG_PRESET_PLASMA_BALL, {-2, 2, 0}, {0, 0, 1}, 0.01,
     FG_EMIT_NOW, 1000, 100},
    {"8 kHz", 8000, 2, FG_PRESET_PLASMA_BALL, {3, 1, 0}, {0, 1, 0}, 0.01, 0.002, 0, 80},
    {"384 kHz", 384000, 2, FG_PRESET_SPARK_BALLS, {1, 1, 0}, {0, 0, 1}, 0.001, 0.001, 0, 4096},
};

static double dist3(const double a[3], const double b[3])
{
    double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

/* Where ear k of the still listener is. */
static void ear_at(uint32_t channels, int k, double out[3])
{
    out[0] = channels == 1 ? 0.0 : (k == 0 ? -0.5 : 0.5) * SPACING_M;
    out[1] = out[2] = 0.0;
}

/* Eq. 3 and 4 at distance r. */
static void n_wave_at(const fg_sound_config *p, double r, double *t_half, double *ps)
{
    double rr = r > p->r0_m ? r : p->r0_m;
    double stretch = sqrt(1.0 + p->sigma0 * log(rr / p->r0_m));
    *t_half = p->t0_s * stretch;
    *ps = p->r0_m * p->ps0_pa / (rr * stretch);
}

static void test_first_sample(void **state)
{
    (void)state;
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
        const arrival_case *ac = &cases[ci];
        fg_engine_config cfg = {.sample_rate_hz = ac->fs, .channels = ac->channels,
                                .speed_of_sound_m_s = C_M_S, .ear_spacing_m = SPACING_M};
        fg_engine *e;
        assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
        fg_node nodes[2];
        fx_segment(nodes, ac->mid, ac->dir, ac->half_len_m);
        fg_discharge d = {.nodes = nodes, .node_count = 2, .emit_time_s = ac->emit_s,
                          .strokes = 1, .seed = 1};
        assert_int_equal(fg_preset_sound(ac->preset, &d.sound), FG_OK);
        d.sound.t0_jitter = 0;

        double r_max = 0;
        for (int k = 0; k < (int)ac->channels; k++) {
            double ear[3];
            ear_at(ac->channels, k, ear);
            r_max = fmax(r_max, dist3(ear, ac->mid));
        }
        size_t frames = ac->preroll + (size_t)(ac->fs * (fmax(ac->emit_s, 0) + r_max / C_M_S +
                                                         0.02));
        float *planes[2] = {calloc(frames, sizeof(float)), calloc(frames, sizeof(float))};
        assert_true(planes[0] && planes[1]);
        if (ac->preroll)
            fx_render(e, planes, ac->channels, ac->preroll, ac->block);
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        float *rest[2] = {planes[0] + ac->preroll, planes[1] + ac->preroll};
        fx_render(e, rest, ac->channels, frames - ac->preroll, ac->block);
        for (size_t k = 0; k < ac->preroll; k++)
            CHECK(planes[0][k] == 0.0f, "%s: sound before the post at %zu", ac->name, k);

        double t_emit = ac->emit_s == FG_EMIT_NOW ? ac->preroll / ac->fs : ac->emit_s;
        /* the return stroke runs from the strike node (1) to the root: it
         * passes the midpoint after l / speed */
        t_emit += ac->half_len_m / d.sound.return_stroke_speed_m_s;
        long onset[2];
        double r[2];
        for (int k = 0; k < (int)ac->channels; k++) {
            double ear[3], to[3], len = 2 * ac->half_len_m;
            ear_at(ac->channels, k, ear);
            r[k] = dist3(ear, ac->mid);
            for (int j = 0; j < 3; j++)
                to[j] = (ear[j] - ac->mid[j]) / r[k];
            double s = fabs(to[0] * (nodes[1].x - nodes[0].x) + to[1] * (nodes[1].y - nodes[0].y) +
                            to[2] * (nodes[1].z - nodes[0].z)) /
                       len;
            double t_half, ps;
            n_wave_at(&d.sound, r[k], &t_half, &ps); /* at the straight distance */
            /* the far ear's way around the spherical head
             * (spatial/spherical_head_internal.h) */
            double origin[3] = {0, 0, 0}, u[3] = {k == 0 ? -1.0 : 1.0, 0, 0};
            if (ac->channels == 2)
                r[k] += fg_head_excess_m(ac->mid, origin, u, 0.5 * SPACING_M, origin, origin, NULL);
            double start = ac->fs * (t_emit + r[k] / C_M_S - t_half - ac->half_len_m * s / C_M_S);
            long want = (long)floor(start + 0.5);
            onset[k] = fx_first_nonzero(planes[k], frames);
            CHECK(onset[k] >= 0, "%s ear %d: silent", ac->name, k);
            CHECK(labs(onset[k] - want) <= 1, "%s ear %d: first sample %ld, predicted %ld (%.3f)",
                  ac->name, k, onset[k], want, start);
        }
        if (ac->channels == 2) {
            double itd = ac->fs * (r[1] - r[0]) / C_M_S;
            CHECK(fabs((double)(onset[1] - onset[0]) - itd) <= 1.0,
                  "%s: ears %ld samples apart, interaural delay %.2f", ac->name,
                  onset[1] - onset[0], itd);
        } else {
            CHECK(fx_peak(planes[1], frames) == 0.0f, "%s: mono wrote a second plane", ac->name);
        }
        free(planes[0]);
        free(planes[1]);
        fg_engine_destroy(e);
    }
}

/* Output in pascals: a broadside segment, long enough in samples that the
 * sample averages reach the N-wave's corners, peaks at ps (eq. 3) on both
 * lobes; and at twice the distance the peak follows eq. 3, not 1/r. */
typedef struct level_case {
    const char *name;
    double fs;
    uint32_t channels;
    double y; /* the segment's distance straight ahead */
} level_case;

static const level_case level_cases[] = {
    {"stereo 50 m", 192000, 2, 50},
    {"stereo 100 m", 192000, 2, 100},
    {"mono 400 m", 96000, 1, 400},
};

static void test_peak_is_ps(void **state)
{
    (void)state;
    for (size_t ci = 0; ci < sizeof level_cases / sizeof level_cases[0]; ci++) {
        const level_case *lc = &level_cases[ci];
        fg_engine_config cfg = {.sample_rate_hz = lc->fs, .channels = lc->channels,
                                .speed_of_sound_m_s = C_M_S, .ear_spacing_m = SPACING_M};
        fg_engine *e;
        assert_int_equal(fg_engine_create(&cfg, &e), FG_OK);
        fg_node nodes[2];
        fx_segment(nodes, (double[3]){0, lc->y, 0}, (double[3]){0, 0, 1}, 1.5);
        fg_discharge d = {.nodes = nodes, .node_count = 2, .strokes = 1, .seed = 3};
        assert_int_equal(fg_preset_sound(FG_PRESET_LIGHTNING, &d.sound), FG_OK);
        d.sound.t0_jitter = 0;
        assert_int_equal(fg_engine_post(e, &d, NULL), FG_OK);
        size_t frames = (size_t)(lc->fs * (lc->y / C_M_S + 0.01));
        float *planes[2] = {calloc(frames, sizeof(float)), calloc(frames, sizeof(float))};
        assert_true(planes[0] && planes[1]);
        fx_render(e, planes, lc->channels, frames, 1024);
        for (int k = 0; k < (int)lc->channels; k++) {
            double ear[3];
            ear_at(lc->channels, k, ear);
            double t_half, ps;
            n_wave_at(&d.sound, dist3(ear, (double[3]){0, lc->y, 0}), &t_half, &ps);
            float hi = -INFINITY, lo = INFINITY;
            for (size_t n = 0; n < frames; n++) {
                hi = fmaxf(hi, planes[k][n]);
                lo = fminf(lo, planes[k][n]);
            }
            /* T spans > 100 samples: the best sample is within 1.5 % of the corner */
            CHECK(hi <= ps * (1 + 1e-5) && hi >= 0.985 * ps, "%s ear %d: peak %.6g Pa, ps %.6g Pa",
                  lc->name, k, hi, ps);
            CHECK(-lo <= ps * (1 + 1e-5) && -lo >= 0.985 * ps,
                  "%s ear %d: trough %.6g Pa, ps %.6g Pa", lc->name, k, lo, ps);
        }
        free(planes[0]);
        free(planes[1]);
        fg_engine_destroy(e);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_sample),
        cmocka_unit_test(test_peak_is_ps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
