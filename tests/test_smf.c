/* The MIDI file reader of fulgur-lv2-render: tempo maps across tracks,
 * running status, SMPTE time, and files it must refuse with a message. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "smf.h"

#define PATH "test_smf.mid"

static void write_file(const uint8_t *bytes, size_t n)
{
    FILE *f = fopen(PATH, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, n, f), n);
    fclose(f);
}

/* Format 1, 480 ticks per quarter. Track 0: 1 s per quarter, then from tick
 * 960 0.5 s per quarter. Track 1: note-on at tick 480 (1 s), a program
 * change (not kept), its note-off at tick 960 (2 s), and by running status a
 * note-on at tick 1440 (2 s + 480 ticks at 0.5 s = 2.5 s). */
static const uint8_t tempo_map[] = {
    'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 1, 0, 2, 0x01, 0xe0,
    'M', 'T', 'r', 'k', 0, 0, 0, 19,
    0x00, 0xff, 0x51, 3, 0x0f, 0x42, 0x40,      /* 1 000 000 us */
    0x87, 0x40, 0xff, 0x51, 3, 0x07, 0xa1, 0x20, /* +960: 500 000 us */
    0x00, 0xff, 0x2f, 0,
    'M', 'T', 'r', 'k', 0, 0, 0, 21,
    0x83, 0x60, 0x91, 60, 100,                   /* +480 note-on ch 2 */
    0x00, 0xc1, 5,                               /* program change */
    0x83, 0x60, 0x91, 60, 0,                     /* +480: a new status */
    0x83, 0x60, 62, 90,                          /* +480 running status */
    0x00, 0xff, 0x2f, 0,
};

static void test_tempo_map(void **state)
{
    (void)state;
    write_file(tempo_map, sizeof tempo_map);
    smf_event *ev;
    size_t n;
    char err[256];
    assert_int_equal(smf_read(PATH, &ev, &n, err, sizeof err), 0);
    assert_int_equal(n, 3);
    const double t[] = {1.0, 2.0, 2.5};
    const uint8_t key[] = {60, 60, 62}, vel[] = {100, 0, 90};
    for (size_t i = 0; i < n; i++) {
        assert_float_equal(ev[i].time_s, t[i], 1e-12);
        assert_int_equal(ev[i].status, 0x91);
        assert_int_equal(ev[i].data1, key[i]);
        assert_int_equal(ev[i].data2, vel[i]);
    }
    free(ev);
}

/* 25 frames per second, 40 ticks per frame: 1000 ticks a second. */
static void test_smpte(void **state)
{
    (void)state;
    const uint8_t smpte[] = {
        'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 0xe7, 40,
        'M', 'T', 'r', 'k', 0, 0, 0, 9,
        0x93, 0x44, 0x80, 64, 127,                  /* +2500 ticks */
        0x00, 0xff, 0x2f, 0,
    };
    write_file(smpte, sizeof smpte);
    smf_event *ev;
    size_t n;
    char err[256];
    assert_int_equal(smf_read(PATH, &ev, &n, err, sizeof err), 0);
    assert_int_equal(n, 1);
    assert_float_equal(ev[0].time_s, 2.5, 1e-12);
    assert_int_equal(ev[0].status, 0x80);
    free(ev);
}

/* A header and a chunk of an unknown type: no events, no error. */
static void test_no_tracks(void **state)
{
    (void)state;
    const uint8_t empty[] = {'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 1, 0xe0,
                             'X', 'Y', 'Z', 'W', 0, 0, 0, 2, 7, 7};
    write_file(empty, sizeof empty);
    smf_event *ev;
    size_t n = 99;
    char err[256];
    assert_int_equal(smf_read(PATH, &ev, &n, err, sizeof err), 0);
    assert_int_equal(n, 0);
    free(ev);
}

typedef struct bad_case {
    uint8_t bytes[40];
    size_t size;
    const char *message;
} bad_case;

static const bad_case bad[] = {
    {{'R', 'I', 'F', 'F', 0, 0, 0, 6, 0, 0, 0, 1, 1, 0xe0}, 14, "no MThd header"},
    {{'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 2, 0, 1, 1, 0xe0}, 14, "format 2"},
    {{'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 0, 0}, 14, "division 0"},
    {{'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 1, 0xe0, 'M', 'T', 'r', 'k', 0, 0, 0, 40, 0},
     23, "chunk runs past the end"},
    {{'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 1, 0xe0, 'M', 'T', 'r', 'k', 0, 0, 0, 4, 0, 60,
      100, 0},
     26, "running status with no status"},
    {{'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 1, 0xe0, 'M', 'T', 'r', 'k', 0, 0, 0, 4, 0, 0x90,
      60, 100},
     26, "without an end-of-track"},
    {{'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 1, 0xe0, 'M', 'T', 'r', 'k', 0, 0, 0, 3, 0, 0x90,
      60},
     25, "truncated channel message"},
};

static void test_refused(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_file(bad[i].bytes, bad[i].size);
        smf_event *ev = (smf_event *)&ev;   /* must stay untouched */
        size_t n = 12345;
        char err[256] = "";
        assert_int_equal(smf_read(PATH, &ev, &n, err, sizeof err), -1);
        assert_ptr_equal(ev, (smf_event *)&ev);
        assert_int_equal(n, 12345);
        assert_non_null(strstr(err, PATH));
        if (!strstr(err, bad[i].message))
            fail_msg("case %zu: '%s' lacks '%s'", i, err, bad[i].message);
    }
    char err[256];
    smf_event *ev;
    size_t n;
    assert_int_equal(smf_read("no/such/file.mid", &ev, &n, err, sizeof err), -1);
    assert_non_null(strstr(err, "cannot open"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tempo_map),
        cmocka_unit_test(test_smpte),
        cmocka_unit_test(test_no_tracks),
        cmocka_unit_test(test_refused),
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    remove(PATH);
    return failed;
}
