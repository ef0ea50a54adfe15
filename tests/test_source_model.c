/* The source-model seam (core/source_internal.h) with a model the library
 * does not know: a point source replaying a looped "sound texture" (one
 * period of a cosine, 64 points, read with a fractional position), heard
 * at each ear r / c after it is emitted, at a level of 1 / r, its pose
 * published by another call through a latest-value cell like the
 * listener's. It is not a tree of segments, has no shared storage and
 * renders sample by sample into the buses' float buffers: what an
 * aerodynamic or a fire source will do. Nothing in the engine names it.
 *
 * Checked against the closed form p(t) = (A / r) cos(2 pi f (t - r / c)):
 * each ear's first sample, the level, the interaural delay, the level
 * after the source moves, the end of the sound and the voice's return
 * through collect; and, under the real-time guard, that rendering it
 * allocates, locks, sleeps and does I/O zero times. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "core/source_internal.h"
#include "fg_math.h"
#include "fg_vec3.h"
#include "rt_guard.h"

#define FS 48000.0
#define C 343.0
#define TEXTURE 64

/* ---- the model ---------------------------------------------------------- */

typedef struct texture_source {
    double amplitude_pa_m;  /* pressure at 1 m */
    double frequency_hz;    /* loops of the texture per second */
    double duration_s;
    double emit_time_s;     /* engine clock, or FG_EMIT_NOW */
    fg_listener pose;       /* position used; the rest is ignored */
} texture_source;

typedef struct texture_voice {
    fg_listener_cell pose;  /* written by the sim thread, read each block */
    fg_listener seen;       /* the pose of this block */
    unsigned serial;
    double amplitude_pa_m, frequency_hz, duration_s, emit_time_s;
    double emit_frame;
} texture_voice;

static float texture[TEXTURE];

/* The texture at phase (in loops), linearly interpolated. */
static double texture_at(double phase)
{
    double x = (phase - floor(phase)) * TEXTURE;
    size_t i = (size_t)x;
    double f = x - (double)i;
    return (1.0 - f) * texture[i % TEXTURE] + f * texture[(i + 1) % TEXTURE];
}

static fg_result texture_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                                 const fg_post_context *post)
{
    (void)ops;
    (void)post;
    const texture_source *d = desc;
    texture_voice *v = voice;
    fg_listener_cell_init(&v->pose, &d->pose);
    v->seen = d->pose;
    v->amplitude_pa_m = d->amplitude_pa_m;
    v->frequency_hz = d->frequency_hz;
    v->duration_s = d->duration_s;
    v->emit_time_s = d->emit_time_s;
    return FG_OK;
}

static void texture_adopt(void *voice, const fg_block_context *block)
{
    texture_voice *v = voice;
    v->emit_frame = v->emit_time_s == FG_EMIT_NOW ? block->start_frame
                                                  : v->emit_time_s * block->cfg->sample_rate_hz;
}

static bool texture_render(void *voice, bool stopping, const fg_block_context *block)
{
    (void)stopping;
    texture_voice *v = voice;
    fg_listener_cell_try_read(&v->pose, &v->seen, &v->serial);
    const double fs = block->cfg->sample_rate_hz, c = block->cfg->speed_of_sound_m_s;
    bool sounding_later = false;
    for (unsigned ch = 0; ch < block->ears->count; ch++) {
        double r = fg_v3_len(
            fg_v3_sub(fg_v3_load(block->ears->pos[ch]), fg_v3_load(v->seen.position)));
        double level = v->amplitude_pa_m / r;
        /* t of sample 0 of this block at the source: retarded by r / c */
        double t0 = (block->start_frame - v->emit_frame) / fs - r / c;
        float *out = fg_bus_pre(block->buses, FG_BUS_DRY, ch);
        for (uint32_t n = 0; n < block->frames; n++) {
            double t = t0 + n / fs;
            if (t >= 0.0 && t < v->duration_s)
                out[n] += (float)(level * texture_at(v->frequency_hz * t));
        }
        if (t0 + block->frames / fs < v->duration_s)
            sounding_later = true;
    }
    return !sounding_later;
}

static const fg_source_kind texture_kind = {
    .name = "test texture",
    .voice_bytes = sizeof(texture_voice),
};

static const fg_source_ops texture_ops = {
    .name = "texture",
    .kind = &texture_kind,
    .prepare = texture_prepare,
    .adopt = texture_adopt,
    .render = texture_render,
};

/* ---- the test ------------------------------------------------------------- */

static fg_engine *make_engine(void)
{
    for (int i = 0; i < TEXTURE; i++)
        texture[i] = (float)cos(2.0 * FG_PI * i / TEXTURE);
    const fg_source_kind *kinds[] = {&texture_kind};
    fg_engine_config cfg = {.sample_rate_hz = FS, .speed_of_sound_m_s = C, .max_block_frames = 256};
    fg_engine *e;
    assert_int_equal(fg_engine_create_with(&cfg, kinds, 1, &e), FG_OK);
    return e;
}

/* The closed form the texture approximates (linear interpolation of 64
 * points errs by at most (2 pi / 64)^2 / 8 = 1.2e-3 of the level). */
static double expected(double amplitude, double f, double r, double t)
{
    double retarded = t - r / C;
    return retarded < 0 ? 0.0 : amplitude / r * cos(2.0 * FG_PI * f * retarded);
}

typedef struct texture_case {
    const char *name;
    double position[3];
    double frequency_hz;
    double emit_time_s;
} texture_case;

static const texture_case cases[] = {
    {"ahead, 10 m", {0, 10, 0}, 440.0, 0.05},
    {"left, 34.3 m", {-34.3, 0, 0}, 250.0, 0.0},
    {"right and up, 100 m", {80, 0, 60}, 1000.0, 0.2},
};

static void renders_the_closed_form(void **state)
{
    (void)state;
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
        const texture_case *tc = &cases[ci];
        fg_engine *e = make_engine();
        texture_source d = {.amplitude_pa_m = 2.0, .frequency_hz = tc->frequency_hz,
                            .duration_s = 0.1, .emit_time_s = tc->emit_time_s,
                            .pose.position = {tc->position[0], tc->position[1], tc->position[2]}};
        fg_voice_id id;
        assert_int_equal(fg_engine_post_source(e, &texture_ops, &d, &id), FG_OK);
        texture_voice *v = fg_engine_voice_state(e, id, &texture_kind);
        assert_non_null(v);
        assert_null(fg_engine_voice_state(e, id, fg_builtin_kinds[0]));

        enum { FRAMES = 188 * 256 }; /* 1.003 s */
        float *left = calloc(FRAMES, sizeof *left), *right = calloc(FRAMES, sizeof *right);
        float *planes[2] = {left, right};
        rt_guard_arm();
        for (size_t at = 0; at < FRAMES; at += 256) {
            float *block[2] = {left + at, right + at};
            if (fg_engine_render(e, block, 256) != FG_OK)
                fail_msg("render");
        }
        rt_guard_counts counts = rt_guard_disarm();
        assert_int_equal(rt_guard_total(&counts), 0);

        /* the listener stands at the origin, ears 0.175 m apart on x (this
         * model hears point ears: it does not ask the head for the way round) */
        for (int ch = 0; ch < 2; ch++) {
            double ear[3] = {ch == 0 ? -0.0875 : 0.0875, 0, 0};
            double r = sqrt(pow(tc->position[0] - ear[0], 2) + pow(tc->position[1], 2) +
                            pow(tc->position[2], 2));
            double arrival = (tc->emit_time_s + r / C) * FS;
            long first = -1, last = -1;
            double worst = 0, peak = 0;
            for (long n = 0; n < FRAMES; n++) {
                if (planes[ch][n] != 0.0f) {
                    if (first < 0)
                        first = n;
                    last = n;
                }
                double want = expected(2.0, tc->frequency_hz, r, n / FS - tc->emit_time_s);
                if (n / FS - tc->emit_time_s - r / C >= 0.1)
                    want = 0;
                worst = fmax(worst, fabs(planes[ch][n] - want));
                peak = fmax(peak, fabs(planes[ch][n]));
            }
            /* the first sample at or after the arrival; it is the texture's
             * first point, cos 0 = 1, times the level */
            assert_int_equal(first, (long)ceil(arrival));
            assert_int_equal(last, (long)ceil(arrival + 0.1 * FS) - 1);
            /* the sample nearest a crest lies at most half a sample from
             * it: the sampled peak is within 1 - cos(pi f / fs) below, and
             * the interpolation's 1.2e-3 */
            double level = 2.0 / r, crest = 1.0 - cos(FG_PI * tc->frequency_hz / FS);
            if (fabs(peak - level) > (1.3e-3 + crest) * level || worst > 2e-3 * level)
                fail_msg("%s, ear %d: peak %.6g for 2/r = %.6g, worst error %.3g", tc->name, ch,
                         peak, level, worst);
        }
        fg_engine_report st;
        fg_engine_get_report(e, &st);
        assert_int_equal(st.posted, 1);
        assert_int_equal(st.adopted, 1);
        assert_int_equal(st.finished, 1);
        assert_int_equal(fg_engine_collect(e), 1);
        assert_null(fg_engine_voice_state(e, id, &texture_kind));
        free(left);
        free(right);
        fg_engine_destroy(e);
    }
}

/* The pose is the model's own latest-value cell: a new position takes
 * effect at the next block, at the new level and delay. */
static void follows_its_published_pose(void **state)
{
    (void)state;
    fg_engine *e = make_engine();
    texture_source d = {.amplitude_pa_m = 1.0, .frequency_hz = 100.0, .duration_s = 10.0,
                        .emit_time_s = 0.0, .pose.position = {0, 5, 0}};
    fg_voice_id id;
    assert_int_equal(fg_engine_post_source(e, &texture_ops, &d, &id), FG_OK);
    float l[256], r[256];
    float *planes[2] = {l, r};
    for (int b = 0; b < 40; b++)
        assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
    texture_voice *v = fg_engine_voice_state(e, id, &texture_kind);
    fg_listener moved = {.position = {0, 20, 0}};
    fg_listener_cell_write(&v->pose, &moved);
    assert_int_equal(fg_engine_render(e, planes, 256), FG_OK);
    double start = 40 * 256 / FS, radius = sqrt(20.0 * 20.0 + 0.09 * 0.09);
    double worst = 0;
    for (int n = 0; n < 256; n++)
        worst = fmax(worst, fabs(l[n] - expected(1.0, 100.0, radius, start + n / FS)));
    if (worst > 2e-3 / radius)
        fail_msg("after the move: worst error %.3g of the level %.4g", worst, 1.0 / radius);
    fg_engine_destroy(e);
}

/* A kind the engine was not created with cannot be posted to; a kind
 * given twice is refused. */
static void refuses_unknown_and_repeated_kinds(void **state)
{
    (void)state;
    fg_engine *e;
    assert_int_equal(fg_engine_create(NULL, &e), FG_OK);
    texture_source d = {.amplitude_pa_m = 1.0, .frequency_hz = 100.0, .duration_s = 1.0};
    assert_int_equal(fg_engine_post_source(e, &texture_ops, &d, NULL), FG_ERR_UNSUPPORTED);
    fg_engine_report st;
    fg_engine_get_report(e, &st);
    assert_int_equal(st.posted, 0);
    fg_engine_destroy(e);
    const fg_source_kind *twice[] = {&texture_kind, &texture_kind};
    static char unset;
    e = (fg_engine *)(void *)&unset;
    assert_int_equal(fg_engine_create_with(NULL, twice, 2, &e), FG_ERR_ARGUMENT);
    assert_null(e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(renders_the_closed_form),
        cmocka_unit_test(follows_its_published_pose),
        cmocka_unit_test(refuses_unknown_and_repeated_kinds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
