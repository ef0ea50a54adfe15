/* The WAV writer's format choice (issue 14: a 384 kHz stereo render past
 * 1 398 s wrapped the RIFF sizes and libsndfile read 101.9 s back): RF64
 * whenever the output may pass 4 GiB, a plain WAV (the same bytes as
 * before) otherwise, and RF64 that turns back into a WAV at close when the
 * length is not known. Writing 4 GiB is too much for a unit test: the
 * threshold is asserted to the frame and each format read back. */
#define _POSIX_C_SOURCE 200809L /* mkstemp */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>
#include <sndfile.h>

#include "common/audio_file.h"

static void threshold(void **state)
{
    (void)state;
    /* (2^32 - 1 - 4096) / 8 bytes a stereo frame */
    assert_false(audio_needs_rf64(536870399, 2));
    assert_true(audio_needs_rf64(536870400, 2));
    /* 384 kHz stereo: RF64 from about 1398 s, the figure */
    assert_false(audio_needs_rf64((uint64_t)(1398.0 * 384000), 2));
    assert_true(audio_needs_rf64((uint64_t)(1399.0 * 384000), 2));
    /* an hour at 48 kHz stereo (1.38 GB) stays a WAV; mono doubles the room */
    assert_false(audio_needs_rf64(3600u * 48000u, 2));
    assert_false(audio_needs_rf64(536870400, 1));
    assert_true(audio_needs_rf64(AUDIO_FRAMES_UNBOUNDED, 2));
}

/* Writes 100 stereo frames with the bound max_frames; returns the first
 * four bytes of the file and checks what libsndfile reads back. */
static void write_read(uint64_t max_frames, char magic[5], int expect_format)
{
    char path[] = "/tmp/fulgur-audio-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    char err[256];
    audio_wav *wav = audio_wav_open(fd, path, 48000, 2, max_frames, err, sizeof err);
    assert_non_null(wav);
    float frames[200];
    for (int i = 0; i < 200; i++)
        frames[i] = (float)i / 200;
    assert_int_equal(audio_wav_write(wav, frames, 100, err, sizeof err), 0);
    assert_int_equal(audio_wav_close(wav), 0);
    close(fd);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    assert_int_equal(fread(magic, 1, 4, f), 4);
    magic[4] = '\0';
    fclose(f);
    SF_INFO info = {0};
    SNDFILE *in = sf_open(path, SFM_READ, &info);
    assert_non_null(in);
    assert_int_equal(info.frames, 100);
    assert_int_equal(info.format & SF_FORMAT_TYPEMASK, expect_format);
    float back[200];
    assert_int_equal(sf_readf_float(in, back, 100), 100);
    assert_memory_equal(back, frames, sizeof frames);
    sf_close(in);
    unlink(path);
}

static void formats(void **state)
{
    (void)state;
    char magic[5];
    write_read(1000, magic, SF_FORMAT_WAV);
    assert_string_equal(magic, "RIFF");
    write_read(536870400, magic, SF_FORMAT_RF64);
    assert_string_equal(magic, "RF64");
    /* downgraded at close: libsndfile's RF64 becomes a WAVE_FORMAT_EXTENSIBLE WAV */
    write_read(AUDIO_FRAMES_UNBOUNDED, magic, SF_FORMAT_WAVEX);
    assert_string_equal(magic, "RIFF");
}

/* The bytes of a file of `frames` frames of channels written by fill,
 * into buf (size bytes at most); its length. */
static size_t file_bytes(int (*fill)(int fd, uint32_t channels, const float *samples,
                                     uint64_t frames),
                         uint32_t channels, const float *samples, uint64_t frames,
                         unsigned char *buf, size_t size)
{
    char path[] = "/tmp/fulgur-audio-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_int_equal(fill(fd, channels, samples, frames), 0);
    close(fd);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    size_t n = fread(buf, 1, size, f);
    assert_true(n < size);
    fclose(f);
    unlink(path);
    return n;
}

static int write_here(int fd, uint32_t channels, const float *samples, uint64_t frames)
{
    char err[256];
    audio_wav *wav = audio_wav_open(fd, "here", 44100, channels, frames, err, sizeof err);
    if (!wav || audio_wav_write(wav, samples, frames, err, sizeof err) != 0)
        return -1;
    return audio_wav_close(wav);
}

/* libsndfile's WAV as audio_wav_open set it up before it wrote plain
 * WAVs itself */
static int write_libsndfile(int fd, uint32_t channels, const float *samples, uint64_t frames)
{
    SF_INFO info = {
        .samplerate = 44100, .channels = (int)channels, .format = SF_FORMAT_WAV | SF_FORMAT_FLOAT};
    SNDFILE *wav = sf_open_fd(fd, SFM_WRITE, &info, SF_FALSE);
    if (!wav)
        return -1;
    sf_command(wav, SFC_SET_ADD_PEAK_CHUNK, NULL, SF_FALSE);
    sf_count_t n = sf_writef_float(wav, samples, (sf_count_t)frames);
    return sf_close(wav) == 0 && n == (sf_count_t)frames ? 0 : -1;
}

/* A plain WAV written here is byte for byte libsndfile's, for 1, 2 and 16
 * channels (the PAD chunk grows with them) and for no frames at all. */
static void plain_as_libsndfile(void **state)
{
    (void)state;
    static float samples[16 * 300];
    static unsigned char here[32768], theirs[32768];
    for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++)
        samples[i] = (float)i / 4800 - 0.5f;
    const uint32_t channels[] = {1, 2, 16};
    for (int c = 0; c < 3; c++)
        for (uint64_t frames = 0; frames <= 300; frames += 300) {
            size_t n = file_bytes(write_here, channels[c], samples, frames, here, sizeof here);
            size_t m =
                file_bytes(write_libsndfile, channels[c], samples, frames, theirs, sizeof theirs);
            assert_int_equal(n, m);
            assert_memory_equal(here, theirs, n);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(threshold),
        cmocka_unit_test(formats),
        cmocka_unit_test(plain_as_libsndfile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
