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
    SNDFILE *wav = audio_wav_open(fd, path, 48000, 2, max_frames, err, sizeof err);
    assert_non_null(wav);
    float frames[200];
    for (int i = 0; i < 200; i++)
        frames[i] = (float)i / 200;
    assert_int_equal(sf_writef_float(wav, frames, 100), 100);
    assert_int_equal(sf_close(wav), 0);
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(threshold),
        cmocka_unit_test(formats),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
