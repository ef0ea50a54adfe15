/* The training-clip reader (host/common/fire_training.c) on files made
 * here with libsndfile: a 48 kHz stereo file comes back mono at 44.1 kHz
 * with its 1 kHz tone's amplitude and frequency kept (libsamplerate); a
 * file at the synthesis rate comes back sample for sample; a missing
 * file, a text file, a 0.5 s clip, a 4 kHz file, a NaN frame and a WAV
 * with no data chunk whose LIST libsndfile's own parser would loop on
 * forever (found by fulgur_fuzz_wav) are refused with a message naming the
 * file and the fault, holding nothing;
 * what it reads trains a texture. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <sndfile.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "fg_math.h"
#include "fire_training.h"
#include "fulgur/fire.h"


static char dir[64];

static void path_of(char *out, size_t size, const char *name)
{
    snprintf(out, size, "%s/%s", dir, name);
}

/* A file of `seconds` at rate with `channels`, frame f holding
 * amp sin(2 pi 1000 f / rate) on every channel (and NaN at nan_frame). */
static void write_tone(const char *name, int rate, int channels, double seconds, int format,
                       long nan_frame)
{
    char path[128];
    path_of(path, sizeof path, name);
    SF_INFO info = {.samplerate = rate, .channels = channels, .format = SF_FORMAT_WAV | format};
    SNDFILE *f = sf_open(path, SFM_WRITE, &info);
    assert_non_null(f);
    long frames = (long)(seconds * rate);
    float *buf = malloc(sizeof(float) * (size_t)(frames * channels));
    for (long i = 0; i < frames; i++)
        for (int c = 0; c < channels; c++)
            buf[i * channels + c] =
                i == nan_frame ? NAN : (float)(0.5 * sin(2.0 * FG_PI * 1000.0 * (double)i / rate));
    assert_int_equal(sf_writef_float(f, buf, frames), frames);
    sf_close(f);
    free(buf);
}

static int setup(void **state)
{
    (void)state;
    strcpy(dir, "/tmp/fulgur-fire-wav-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    const char *names[] = {"stereo48k.wav", "mono44k.wav", "short.wav",    "slow.wav",
                           "nan.wav",       "text.wav",    "backwards.wav"};
    char path[128];
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        path_of(path, sizeof path, names[i]);
        unlink(path);
    }
    return rmdir(dir);
}

/* Writes a tone file and reads it back at 44.1 kHz, which must succeed. */
static fire_training tone_at_44k(const char *name, int rate, int channels, double seconds,
                                 int format)
{
    write_tone(name, rate, channels, seconds, format, -1);
    char path[128], err[256] = "";
    path_of(path, sizeof path, name);
    fire_training t;
    assert_int_equal(fire_training_read(path, 44100.0, &t, err, sizeof err), 0);
    return t;
}

static void test_resampled_mono(void **state)
{
    (void)state;
    fire_training t = tone_at_44k("stereo48k.wav", 48000, 2, 2.0, SF_FORMAT_FLOAT);
    assert_true(t.resampled && t.file_channels == 2 && t.file_rate_hz == 48000.0);
    assert_true(labs((long)t.frames - 88200) <= 2);
    /* the tone's amplitude at 1000 Hz on the new clock, away from the ends */
    double c = 0.0, s = 0.0;
    size_t start = 4410, len = 44100 * 1;
    for (size_t i = start; i < start + len; i++) {
        double ph = 2.0 * FG_PI * 1000.0 * (double)i / 44100.0;
        c += t.samples[i] * cos(ph) * 2.0 / (double)len;
        s += t.samples[i] * sin(ph) * 2.0 / (double)len;
    }
    print_message("48 kHz stereo -> 44.1 kHz mono: %zu frames, 1 kHz amplitude %.5f\n", t.frames,
                  hypot(c, s));
    assert_true(fabs(hypot(c, s) - 0.5) < 1e-3);
    /* it trains a texture */
    fg_fire_texture_config tc = {.samples = t.samples, .frames = t.frames,
                                 .sample_rate_hz = 44100.0};
    fg_fire_texture *tex;
    assert_int_equal(fg_fire_texture_create(&tc, &tex), FG_OK);
    fg_fire_texture_destroy(tex);
    fire_training_free(&t);
    assert_null(t.samples);
    fire_training_free(&t);
}

static void test_same_rate(void **state)
{
    (void)state;
    fire_training t = tone_at_44k("mono44k.wav", 44100, 1, 1.5, SF_FORMAT_PCM_16);
    assert_false(t.resampled);
    assert_int_equal(t.frames, 66150);
    for (size_t i = 0; i < t.frames; i++)
        assert_true(fabs(t.samples[i] - 0.5 * sin(2.0 * FG_PI * 1000.0 * (double)i / 44100.0)) <=
                    1.0 / 32768.0);
    fire_training_free(&t);
}

static void expect_refusal(const char *name, double rate, const char *fault)
{
    char path[128], err[256] = "";
    path_of(path, sizeof path, name);
    fire_training t = {.frames = 7};
    assert_int_equal(fire_training_read(path, rate, &t, err, sizeof err), -1);
    print_message("%s\n", err);
    assert_non_null(strstr(err, path));
    assert_non_null(strstr(err, fault));
    assert_null(t.samples);
    assert_int_equal(t.frames, 0);
}

static void test_refusals(void **state)
{
    (void)state;
    expect_refusal("missing.wav", 44100.0, "cannot open it");
    char path[128];
    path_of(path, sizeof path, "text.wav");
    FILE *f = fopen(path, "w");
    fputs("this is not a sound file\n", f);
    fclose(f);
    expect_refusal("text.wav", 44100.0, "not a WAV file");
    write_tone("short.wav", 44100, 1, 0.5, SF_FORMAT_FLOAT, -1);
    expect_refusal("short.wav", 44100.0, "needs at least 1 s");
    write_tone("slow.wav", 4000, 1, 2.0, SF_FORMAT_FLOAT, -1);
    expect_refusal("slow.wav", 44100.0, "sample rate 4000 Hz is outside");
    write_tone("nan.wav", 44100, 2, 1.2, SF_FORMAT_FLOAT, 1000);
    expect_refusal("nan.wav", 44100.0, "frame 1000 is not a finite number");
    write_tone("mono44k.wav", 44100, 1, 1.5, SF_FORMAT_PCM_16, -1);
    expect_refusal("mono44k.wav", 1000.0, "synthesis rate 1000 Hz is outside");
    static const unsigned char backwards[] = {
        0x52, 0x49, 0x46, 0x46, 0xe2, 0x00, 0x00, 0x00, 0x57, 0x41, 0x56, 0x45, 0x66, 0x6d,
        0x74, 0x20, 0x10, 0x00, 0x00, 0x00, 0x03, 0x00, 0x02, 0x00, 0x80, 0xbb, 0x00, 0x00,
        0x00, 0xdc, 0x00, 0x08, 0x05, 0x00, 0x20, 0x00, 0x4c, 0x49, 0x53, 0x54, 0x36, 0x00,
        0x00, 0x00, 0x61, 0x80, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00,
        0xf8, 0xff, 0xff, 0xff, 0x3f, 0x00, 0x00, 0x80, 0xbe, 0x00, 0x00, 0x00, 0x3e, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x3f, 0x00, 0x80, 0xbe, 0x00, 0x00, 0x00, 0x3e, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x3f, 0x00, 0x00, 0x80, 0xbe, 0x00, 0x00, 0x00, 0x3e};
    path_of(path, sizeof path, "backwards.wav");
    f = fopen(path, "wb");
    assert_int_equal(fwrite(backwards, 1, sizeof backwards, f), sizeof backwards);
    fclose(f);
    expect_refusal("backwards.wav", 44100.0, "it has no 'data' chunk");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_resampled_mono),
        cmocka_unit_test(test_same_rate),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
