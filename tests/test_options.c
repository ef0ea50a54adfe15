/* host/common/options: the command-line parser that render, analyze, run,
 * view and fulgur-lv2-render share. Each case is an argument list against
 * one table: the result, the values written, and for a refusal the message
 * on stderr, which must name the option and what it accepts. */
#define _POSIX_C_SOURCE 200809L /* fileno, dup */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "common/audio_driver.h"
#include "common/options.h"

typedef struct values {
    const char *out, *operand[2];
    size_t operands;
    double seconds, any;
    uint32_t block, voices;
    bool loud;
    audio_output audio;
} values;

/* Sends stream (stdout or stderr) into a temporary file until
 * capture_end, which reads what was written into buf. */
typedef struct capture {
    FILE *stream, *file;
    int saved;
} capture;

static capture capture_begin(FILE *stream)
{
    capture c = {stream, tmpfile(), -1};
    assert_non_null(c.file);
    fflush(stream);
    c.saved = dup(fileno(stream));
    dup2(fileno(c.file), fileno(stream));
    return c;
}

static void capture_end(capture *c, char *buf, size_t size)
{
    fflush(c->stream);
    dup2(c->saved, fileno(c->stream));
    close(c->saved);
    rewind(c->file);
    size_t n = fread(buf, 1, size - 1, c->file);
    buf[n] = '\0';
    fclose(c->file);
}

/* Runs the table on the words of line ("prog" first); the message written
 * to stderr goes to msg. */
static options_result parse(const char *line, values *v, char *msg, size_t msg_size)
{
    static const uint32_t blocks[] = {64, 128, 256, 512, 0};
    *v = (values){.seconds = -1, .any = NAN};
    const option table[] = {
        {"-o", OPTION_TEXT, &v->out, "OUT.wav", .help = "the output", .required = true},
        {"--seconds", OPTION_NUMBER, &v->seconds, "S", .help = "how long",
         .range = {0, 3600, .lo_open = true}},
        {"--any", OPTION_NUMBER, &v->any, "T", .help = "any time",
         .range = {.lo = -INFINITY, .hi = INFINITY}},
        {"--block", OPTION_INTEGER, &v->block, NULL, .help = "frames", .one_of = blocks},
        {"--voices", OPTION_INTEGER, &v->voices, "N", .help = "pool",
         .range = {.lo = 1, .hi = 4096}},
        {"--loud", OPTION_FLAG, &v->loud, NULL, .help = "louder"},
        {"--audio", OPTION_PARSED, &v->audio, "null|wav:FILE|raw:-", .help = "where",
         .parse = audio_output_parse},
        {0},
    };
    const command_line cl = {"prog", "IN [MORE]", 1, 2, "about\n", "notes\n", table};
    static char copy[512];
    char *argv[32];
    int argc = 0;
    snprintf(copy, sizeof copy, "prog %s", line);
    for (char *w = strtok(copy, " "); w; w = strtok(NULL, " "))
        argv[argc++] = w;
    capture errors = capture_begin(stderr);
    options_result r = options_parse(&cl, argc, argv, v->operand, &v->operands);
    capture_end(&errors, msg, msg_size);
    return r;
}

static void test_accepts(void **state)
{
    (void)state;
    values v;
    char msg[1024];
    assert_int_equal(parse("in.json -o a.wav --seconds 2.5 --block 256 --voices 8 --loud "
                           "--audio wav:x.wav more --any -4",
                           &v, msg, sizeof msg),
                     OPTIONS_OK);
    assert_string_equal(msg, "");
    assert_string_equal(v.out, "a.wav");
    assert_int_equal(v.operands, 2);
    assert_string_equal(v.operand[0], "in.json");
    assert_string_equal(v.operand[1], "more");
    assert_true(v.seconds == 2.5);
    assert_true(v.any == -4);
    assert_int_equal(v.block, 256);
    assert_int_equal(v.voices, 8);
    assert_true(v.loud);
    assert_int_equal(v.audio.kind, AUDIO_DRIVER_WAV);
    assert_string_equal(v.audio.wav_path, "x.wav");
    /* the last of a repeated option wins; options before the operand */
    assert_int_equal(parse("-o a.wav --block 64 --block 512 --seconds 3600 in", &v, msg,
                           sizeof msg),
                     OPTIONS_OK);
    assert_int_equal(v.block, 512);
    assert_true(v.seconds == 3600);
    assert_false(v.loud);
    assert_int_equal(v.audio.kind, AUDIO_DRIVER_NULL);
    assert_true(isnan(v.any)); /* untouched */
}

/* Each refusal: OPTIONS_BAD and a message that starts with the command and
 * names what is wrong, then the usage line. */
static void test_refuses(void **state)
{
    (void)state;
    static const struct {
        const char *line, *message;
    } cases[] = {
        {"in -o a.wav --block 100", "prog: --block 100: expected one of 64, 128, 256, 512\n"},
        {"in -o a.wav --block 64.5", "prog: --block 64.5: expected one of 64, 128, 256, 512\n"},
        {"in -o a.wav --seconds 0", "prog: --seconds 0: expected a number in (0, 3600]\n"},
        {"in -o a.wav --seconds nan", "prog: --seconds nan: expected a number in (0, 3600]\n"},
        {"in -o a.wav --seconds 3600.5",
         "prog: --seconds 3600.5: expected a number in (0, 3600]\n"},
        {"in -o a.wav --seconds 2s", "prog: --seconds 2s: expected a number in (0, 3600]\n"},
        {"in -o a.wav --any inf", "prog: --any inf: expected a finite number\n"},
        {"in -o a.wav --voices 0", "prog: --voices 0: expected an integer in 1..4096\n"},
        {"in -o a.wav --voices 2.5", "prog: --voices 2.5: expected an integer in 1..4096\n"},
        {"in -o a.wav --voices 4097", "prog: --voices 4097: expected an integer in 1..4096\n"},
        {"in -o a.wav --audio pulse", "prog: --audio pulse: expected null, wav:FILE or raw:-\n"},
        {"in -o a.wav --audio wav:", "prog: --audio wav:: expected null, wav:FILE or raw:-\n"},
        {"in -o a.wav --voices", "prog: --voices needs a value: --voices N\n"},
        {"in -o a.wav --unknown 1",
         "prog: unknown option \"--unknown\" (prog --help lists them)\n"},
        {"in", "prog: -o OUT.wav is required\n"},
        {"-o a.wav", "prog: give IN [MORE]\n"},
        {"a b c -o a.wav", "prog: unexpected argument \"c\"\n"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        values v;
        char msg[1024];
        options_result r = parse(cases[i].line, &v, msg, sizeof msg);
        if (r != OPTIONS_BAD || strncmp(msg, cases[i].message, strlen(cases[i].message)) != 0)
            fail_msg("\"%s\": result %d, message \"%s\", expected \"%s\"", cases[i].line, r, msg,
                     cases[i].message);
        /* then the usage line, from the table */
        assert_non_null(strstr(msg, "usage: prog IN [MORE] -o OUT.wav [--seconds S] [--any T] "
                                    "[--block 64|128|256|512]"));
    }
}

static void test_help(void **state)
{
    (void)state;
    values v;
    char msg[64];
    char help[2048];
    capture out = capture_begin(stdout);
    options_result r = parse("in --voices 3 --help --block 7", &v, msg, sizeof msg);
    capture_end(&out, help, sizeof help);
    assert_int_equal(r, OPTIONS_HELP);
    assert_string_equal(msg, ""); /* the help is not an error */
    assert_int_equal(v.voices, 3);
    assert_int_equal(v.block, 0); /* not read past --help */
    /* usage, about, one row per option with its help in one column (the
     * widest option that fits, plus two), notes */
    assert_non_null(strstr(help, "usage: prog IN [MORE] -o OUT.wav [--seconds S]"));
    assert_non_null(strstr(help, "\nabout\n"));
    assert_non_null(strstr(help, "\n  -o OUT.wav              the output\n"));
    assert_non_null(strstr(help, "\n  --block 64|128|256|512  frames\n"));
    assert_non_null(strstr(help, "\n  --loud                  louder\n"));
    /* an option too wide for the column: its help on the next line */
    assert_non_null(
        strstr(help, "\n  --audio null|wav:FILE|raw:-\n                          where\n"));
    assert_true(strlen(help) > 5 && strcmp(help + strlen(help) - 6, "notes\n") == 0);
}

static void test_number_range(void **state)
{
    (void)state;
    static const struct {
        number_range r;
        double v;
        bool holds;
    } cases[] = {
        {{.lo = 0, .hi = 1}, 0, true},
        {{0, 1, .lo_open = true}, 0, false},
        {{0, 1, .hi_open = true}, 1, false},
        {{0, 1, .hi_open = true}, 0.999, true},
        {{1, 8, .integer = true}, 4, true},
        {{1, 8, .integer = true}, 4.5, false},
        {{.lo = -INFINITY, .hi = INFINITY}, -1e300, true},
        {{.lo = -INFINITY, .hi = INFINITY}, INFINITY, false},
        {{.lo = 0, .hi = 1}, NAN, false},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (number_range_holds(cases[i].r, cases[i].v) != cases[i].holds)
            fail_msg("case %zu: %g", i, cases[i].v);
    char buf[64];
    number_range_format((number_range){0, 3600, .lo_open = true}, buf, sizeof buf);
    assert_string_equal(buf, "(0, 3600]");
    number_range_format((number_range){.lo = 1, .hi = 4096}, buf, sizeof buf);
    assert_string_equal(buf, "1..4096");
    double x = 7;
    assert_int_equal(option_number("2e3", (number_range){.lo = 0, .hi = 1e4}, &x), 0);
    assert_true(x == 2000);
    assert_int_equal(option_number("", (number_range){.lo = 0, .hi = 1e4}, &x), -1);
    assert_int_equal(option_number("20000", (number_range){.lo = 0, .hi = 1e4}, &x), -1);
    assert_true(x == 2000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_accepts),
        cmocka_unit_test(test_refuses),
        cmocka_unit_test(test_help),
        cmocka_unit_test(test_number_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
