/* The WAV reader (host/common/wav_file.c, wav_read.c) against libsndfile
 * reading the same files itself: files libsndfile wrote (float, 16- and
 * 24-bit PCM, big-endian RIFX, WAVE_FORMAT_EXTENSIBLE, u-law, IMA ADPCM,
 * RF64, a calibration comment) come back with libsndfile's own rate,
 * channels, frames, samples bit for bit and comment. Files libsndfile's
 * header parser loops on forever (a LIST size read as a step backwards,
 * after the samples: found by fulgur_fuzz_wav in CI; an RF64 LIST of
 * 0xFFFFFFFF bytes, and that LIST among an odd count of samples: found by
 * it here) are read or refused at once; a file
 * cut short declares more than it holds; sizes a streaming writer leaves
 * run to the file's end; what is not a WAV, or has no fmt or data chunk,
 * or a chunk past the end before them, is refused, the file named. */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "common/calibration.h"
#include "common/wav_read.h"

#define FRAMES 1000
#define RATE 44100

static char dir[64];

static void path_of(char *out, size_t size, const char *name)
{
    snprintf(out, size, "%s/%s", dir, name);
}

static void write_bytes(const char *name, const void *bytes, size_t size)
{
    char path[128];
    path_of(path, sizeof path, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, size, f), size);
    fclose(f);
}

/* name written by libsndfile in format, channels wide: a ramp with a
 * step, so every frame differs; comment set when not NULL. */
static void write_with_libsndfile(const char *name, int format, int channels, const char *comment)
{
    char path[128];
    path_of(path, sizeof path, name);
    SF_INFO info = {.samplerate = RATE, .channels = channels, .format = format};
    SNDFILE *f = sf_open(path, SFM_WRITE, &info);
    assert_non_null(f);
    if (comment)
        assert_int_equal(sf_set_string(f, SF_STR_COMMENT, comment), 0);
    float *x = malloc(sizeof *x * FRAMES * (size_t)channels);
    for (size_t i = 0; i < (size_t)FRAMES * (size_t)channels; i++)
        x[i] = (float)((double)(i % 397) / 397.0 - 0.5 + (i % 2 ? 0.125 : -0.125));
    assert_int_equal(sf_writef_float(f, x, FRAMES), FRAMES);
    free(x);
    sf_close(f);
}

/* Opens name through wav_open and reads it whole into *w; returns what
 * wav_open returned (err holds its message), or -2 when wav_read failed. */
static int read_ours(const char *name, wav_file *file, wav_audio *w, char *err, size_t err_size)
{
    char path[128];
    path_of(path, sizeof path, name);
    FILE *in = fopen(path, "rb");
    assert_non_null(in);
    int rc = wav_open(file, in, path, err, err_size);
    if (rc == 0) {
        assert_non_null(file->sndfile);
        if (wav_read(file, path, w, err, err_size) != 0)
            rc = -2;
    } else {
        assert_null(file->sndfile);
    }
    wav_close(file);
    fclose(in);
    return rc;
}

/* name read by us and by libsndfile's sf_open: the same. */
static void expect_as_libsndfile(const char *name, const char *comment)
{
    char path[128], err[256] = "";
    path_of(path, sizeof path, name);
    SF_INFO info = {0};
    SNDFILE *f = sf_open(path, SFM_READ, &info);
    assert_non_null(f);
    float *theirs = malloc(sizeof *theirs * (size_t)info.frames * (size_t)info.channels);
    assert_int_equal(sf_readf_float(f, theirs, info.frames), info.frames);
    const char *their_comment = sf_get_string(f, SF_STR_COMMENT);
    if (comment)
        assert_string_equal(their_comment, comment);

    wav_file file;
    wav_audio w;
    int rc = read_ours(name, &file, &w, err, sizeof err);
    if (rc != 0)
        print_message("%s\n", err);
    assert_int_equal(rc, 0);
    assert_int_equal(file.info.format, info.format);
    assert_int_equal(w.channels, info.channels);
    assert_true(w.rate_hz == info.samplerate);
    assert_int_equal(w.frames, info.frames);
    assert_int_equal(w.declared_frames, info.frames);
    assert_memory_equal(w.samples, theirs, sizeof *theirs * w.frames * (size_t)w.channels);
    double full_scale;
    bool calibrated = calibration_parse(their_comment, &full_scale);
    assert_int_equal(w.calibrated, calibrated);
    if (calibrated)
        assert_true(w.full_scale_pa == full_scale);
    free(w.samples);
    free(theirs);
    sf_close(f);
}

static void test_as_libsndfile_reads_them(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int format, channels;
    } files[] = {
        {"float.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 2},
        {"pcm16.wav", SF_FORMAT_WAV | SF_FORMAT_PCM_16, 1},
        {"pcm24.wav", SF_FORMAT_WAV | SF_FORMAT_PCM_24, 3},
        {"rifx.wav", SF_FORMAT_WAV | SF_FORMAT_PCM_16 | SF_ENDIAN_BIG, 2},
        {"wavex.wav", SF_FORMAT_WAVEX | SF_FORMAT_PCM_16, 2},
        {"ulaw.wav", SF_FORMAT_WAV | SF_FORMAT_ULAW, 1},
        {"ima.wav", SF_FORMAT_WAV | SF_FORMAT_IMA_ADPCM, 2},
        {"rf64.wav", SF_FORMAT_RF64 | SF_FORMAT_FLOAT, 2},
    };
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        print_message("%s\n", files[k].name);
        write_with_libsndfile(files[k].name, files[k].format, files[k].channels, NULL);
        expect_as_libsndfile(files[k].name, NULL);
    }
    static const char calibration[] = "fulgur calibration: full scale = 63.25 Pa";
    write_with_libsndfile("calibrated.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, 2, calibration);
    expect_as_libsndfile("calibrated.wav", calibration);
    write_with_libsndfile("calibrated64.wav", SF_FORMAT_RF64 | SF_FORMAT_PCM_24, 1, calibration);
    expect_as_libsndfile("calibrated64.wav", calibration);
}

/* A 44-byte float WAV header, channels 1, 48 kHz, riff and data sizes as
 * given, then data_bytes of zeros. */
static size_t float_wav(unsigned char *out, uint32_t riff, uint32_t data, size_t data_bytes)
{
    static const unsigned char head[44] = {'R', 'I', 'F',  'F',  0,   0,   0,   0,    'W', 'A', 'V',
                                           'E', 'f', 'm',  't',  ' ', 16,  0,   0,    0,   3,   0,
                                           1,   0,   0x80, 0xbb, 0,   0,   0,   0xee, 2,   0,   4,
                                           0,   32,  0,    'd',  'a', 't', 'a', 0,    0,   0,   0};
    memcpy(out, head, sizeof head);
    for (int k = 0; k < 4; k++) {
        out[4 + k] = (unsigned char)(riff >> (8 * k));
        out[40 + k] = (unsigned char)(data >> (8 * k));
    }
    memset(out + 44, 0, data_bytes);
    return 44 + data_bytes;
}

/* The LIST chunk of fulgur_fuzz_wav's 98-byte find: a sub-chunk size of
 * 0xFFFFFFF8, which libsndfile 1.2 reads as 8 bytes back, for ever. */
static const unsigned char list_backwards[62] = {
    'L',  'I', 'S', 'T', 0x36, 0,    0,    0,    0x61, 0x80, 0, 0,    0,    0,    0, 0,
    1,    0,   0,   0,   0xf8, 0xff, 0xff, 0xff, 0x3f, 0,    0, 0x80, 0xbe, 0,    0, 0,
    0x3e, 0,   0,   0,   0,    0,    0x3f, 0,    0x80, 0xbe, 0, 0,    0,    0x3e, 0, 0,
    0,    0,   0,   0,   0,    0x3f, 0,    0,    0x80, 0xbe, 0, 0,    0,    0x3e};

/* name, written from bytes, read whole: frames held, declared as given. */
static void expect_frames(const char *name, const void *bytes, size_t size, size_t frames,
                          uint64_t declared)
{
    char err[256] = "";
    wav_file file;
    wav_audio w;
    write_bytes(name, bytes, size);
    int rc = read_ours(name, &file, &w, err, sizeof err);
    if (rc != 0)
        print_message("%s\n", err);
    assert_int_equal(rc, 0);
    assert_int_equal(w.frames, frames);
    assert_int_equal(w.declared_frames, declared);
    free(w.samples);
}

static void expect_refused(const char *name, const void *bytes, size_t size, const char *fault)
{
    char err[256] = "";
    wav_file file;
    wav_audio w;
    write_bytes(name, bytes, size);
    assert_int_equal(read_ours(name, &file, &w, err, sizeof err), -1);
    print_message("%s\n", err);
    char path[128];
    path_of(path, sizeof path, name);
    assert_non_null(strstr(err, path));
    assert_non_null(strstr(err, fault));
}

static void test_what_libsndfile_loops_on(void **state)
{
    (void)state;
    unsigned char b[2048];
    /* after 200 frames: not read; the frames are */
    size_t n = float_wav(b, 36 + 800 + sizeof list_backwards, 800, 800);
    memcpy(b + n, list_backwards, sizeof list_backwards);
    expect_frames("after.wav", b, n + sizeof list_backwards, 200, 200);
    /* size "not known", 63 sample bytes that hold that LIST: libsndfile
     * seeks over the odd pad byte, past the end, which must end its walk,
     * not put it back among the samples to read them as chunks */
    n = float_wav(b, UINT32_MAX, UINT32_MAX, 0);
    memcpy(b + n, list_backwards, sizeof list_backwards);
    b[n + sizeof list_backwards] = 0;
    expect_frames("odd.wav", b, n + sizeof list_backwards + 1, 15, 15);
    /* RF64, its first chunk a LIST of 0xFFFFFFFF bytes */
    memcpy(b, "RF64\xff\xff\xff\xffWAVELIST", 16);
    memset(b + 16, 0xff, 110);
    memcpy(b + 126, "\xe8\xe8\xe8\xff\xff\xff", 6);
    expect_refused("rf64list.wav", b, 132,
                   "its 'LIST' chunk at byte 12 claims 4294967295 bytes, past the file's end "
                   "(132 bytes)");
}

static void test_sizes(void **state)
{
    (void)state;
    unsigned char b[4096];
    /* cut short: 200 frames declared, 100 held */
    size_t n = float_wav(b, 36 + 800, 800, 400);
    expect_frames("cut.wav", b, n, 100, 200);
    /* a streaming writer's sizes: to the file's end */
    n = float_wav(b, UINT32_MAX, UINT32_MAX, 1200);
    expect_frames("stream.wav", b, n, 300, 300);
    /* never closed (RIFF 8, data 0), as libsndfile reads it: to the end */
    n = float_wav(b, 8, 0, 400);
    expect_frames("unclosed.wav", b, n, 100, 100);
    /* no frames, then a chunk claiming past the end: 0 frames */
    n = float_wav(b, 36, 0, 0);
    memcpy(b + n, "JUNK\xff\x00\x00\x00", 8);
    expect_frames("empty.wav", b, n + 8, 0, 0);
}

static void test_refusals(void **state)
{
    (void)state;
    unsigned char b[512];
    expect_refused("text.wav", "this is not a sound file\n", 25, "not a WAV file");
    expect_refused("short.wav", "RIFF", 4, "not a WAV file");
    size_t n = float_wav(b, 36 + 40, 40, 40);
    memcpy(b + 12, "fmt_", 4);
    expect_refused("nofmt.wav", b, n, "it has no 'fmt ' chunk");
    n = float_wav(b, 36 + 40, 40, 40);
    memcpy(b + 36, "date", 4);
    expect_refused("nodata.wav", b, n, "it has no 'data' chunk");
    n = float_wav(b, 36 + 40, 40, 40);
    b[16] = 12;
    expect_refused("fmt12.wav", b, n, "its 'fmt ' chunk holds 12 bytes, outside 16..1024");
    n = float_wav(b, 36 + 40, 40, 40);
    b[16] = 0xff, b[17] = 0xff;
    expect_refused("fmtbig.wav", b, n, "its 'fmt ' chunk at byte 12 claims 65535 bytes, past");
    n = float_wav(b, 36 + 40, 40, 40);
    memmove(b + 20, b + 12, n - 12);
    memcpy(b + 12, "LIST\x00\x00\x00\x10", 8);
    expect_refused("listbig.wav", b, n + 8, "its 'LIST' chunk at byte 12 claims 268435456 bytes");
}

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/fulgur-wav-file-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char command[128];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    return system(command) == 0 ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_as_libsndfile_reads_them),
        cmocka_unit_test(test_what_libsndfile_loops_on),
        cmocka_unit_test(test_sizes),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
