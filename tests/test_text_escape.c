/* text_escape: what a message may echo from a scene or an argument. A
 * terminal control sequence (ESC [ 31 m turns a terminal's text red),
 * controls, DEL, C1 controls and bytes of invalid UTF-8 (RFC 3629: lone
 * continuation bytes, overlong forms, surrogates, beyond U+10FFFF, cut
 * sequences) come out as \xHH; printable ASCII and UTF-8 stay. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "common/text_escape.h"

typedef struct escape_case {
    const char *in, *want;
} escape_case;

static const escape_case cases[] = {
    {"spark_balls", "spark_balls"},
    {"", ""},
    {"a\\b \"q\" ~", "a\\b \"q\" ~"},
    {"sp\x1b[31mark", "sp\\x1B[31mark"},
    {"line\nnext\ttab\r", "line\\x0Anext\\x09tab\\x0D"},
    {"del\x7f", "del\\x7F"},
    {"\xff\xfe", "\\xFF\\xFE"},
    /* u-umlaut, micro, euro, a cloud with lightning (4 bytes) */
    {"Z\xc3\xbcrich 1 \xc2\xb5m \xe2\x82\xac \xf0\x9f\x8c\xa9",
     "Z\xc3\xbcrich 1 \xc2\xb5m \xe2\x82\xac \xf0\x9f\x8c\xa9"},
    {"\xc2\x85", "\\xC2\\x85"},             /* NEL, a C1 control */
    {"\xc0\xaf", "\\xC0\\xAF"},             /* overlong '/' */
    {"\xe0\x80\xaf", "\\xE0\\x80\\xAF"},     /* overlong '/', 3 bytes */
    {"\xed\xa0\x80", "\\xED\\xA0\\x80"},     /* a UTF-16 surrogate */
    {"\xf4\x90\x80\x80", "\\xF4\\x90\\x80\\x80"}, /* beyond U+10FFFF */
    {"\x80x", "\\x80x"},                    /* a lone continuation byte */
    {"cut \xe2\x82", "cut \\xE2\\x82"},      /* a sequence cut by the end */
    {"\xe2\x82" "a", "\\xE2\\x82a"},         /* ... and by an ASCII byte */
};

static void escapes_each_case(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char out[128];
        size_t n = text_escape(out, sizeof out, cases[i].in);
        if (strcmp(out, cases[i].want) != 0 || n != strlen(cases[i].want))
            fail_msg("case %zu: got \"%s\" (%zu), want \"%s\"", i, out, n, cases[i].want);
    }
}

/* What does not fit is cut at a whole character or escape, terminated. */
static void cuts_whole(void **state)
{
    (void)state;
    char out[8];
    memset(out, 'z', sizeof out);
    assert_int_equal(text_escape(out, 6, "ab\x01" "cd"), 2); /* \x01 needs 4 more */
    assert_string_equal(out, "ab");
    assert_int_equal(text_escape(out, 7, "ab\x01" "cd"), 6);
    assert_string_equal(out, "ab\\x01");
    assert_int_equal(text_escape(out, 4, "\xc3\xbc\xc3\xbc"), 2); /* not half a u-umlaut */
    assert_string_equal(out, "\xc3\xbc");
    assert_int_equal(text_escape(out, 1, "abc"), 0);
    assert_string_equal(out, "");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(escapes_each_case),
        cmocka_unit_test(cuts_whole),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
