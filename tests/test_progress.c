/* The progress line (common/progress.h) with the clock passed in: quiet
 * for the first 2 s of the whole work, then a line at most every 0.25 s
 * for the item at hand, rewritten in place (shorter lines blanked),
 * erased on request; nothing when quiet. */
#define _POSIX_C_SOURCE 200809L /* open_memstream */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "common/progress.h"

#define S(x) ((uint64_t)((x) * 1e9))

static void test_known_total(void **state)
{
    (void)state;
    char *text = NULL;
    size_t size = 0;
    FILE *to = open_memstream(&text, &size);
    progress p;
    progress_begin(&p, to, "s of sound", S(10));
    progress_item(&p, "storm.json", 600.0, S(10));
    assert_false(progress_update(&p, 100.0, S(11.99)));   /* 1.99 s: quiet */
    assert_true(progress_update(&p, 300.0, S(12)));       /* 2 s */
    assert_false(progress_update(&p, 310.0, S(12.2)));    /* within 0.25 s */
    assert_true(progress_update(&p, 450.0, S(13)));       /* 3 s: 75 %, 1 s left */
    progress_clear(&p);
    fclose(to);
    const char *first = "\rfulgur: storm.json: 50% (300.0 of 600.0 s of sound, 2.0 s, "
                        "about 2.0 s left)";
    const char *second = "\rfulgur: storm.json: 75% (450.0 of 600.0 s of sound, 3.0 s, "
                         "about 1.0 s left)";
    size_t width = strlen(first) - 1;
    char expected[512];
    snprintf(expected, sizeof expected, "%s%s\r%*s\r", first, second, (int)width, "");
    assert_string_equal(text, expected);
    free(text);
}

static void test_unknown_total_and_shorter_lines(void **state)
{
    (void)state;
    char *text = NULL;
    size_t size = 0;
    FILE *to = open_memstream(&text, &size);
    progress p;
    progress_begin(&p, to, "s of sound", 0);
    progress_item(&p, "[1/2] a.json", 0.0, 0);
    assert_false(progress_update(&p, 800.0, S(1.5)));
    progress_item(&p, "[2/2] b.json", 0.0, S(1.5)); /* the 2 s run over the items */
    assert_true(progress_update(&p, 1000.0, S(2.5)));
    assert_true(progress_update(&p, 5.0, S(3)));    /* shorter: its tail blanked */
    fclose(to);
    assert_string_equal(text, "\rfulgur: [2/2] b.json: 1000.0 s of sound (1.0 s)"
                              "\rfulgur: [2/2] b.json: 5.0 s of sound (1.5 s)   ");
    free(text);
}

static void test_quiet(void **state)
{
    (void)state;
    progress p;
    progress_begin(&p, NULL, "s of sound", 0);
    progress_item(&p, "a.json", 10.0, 0);
    assert_false(progress_update(&p, 5.0, S(100)));
    progress_clear(&p); /* nothing to erase, nothing written */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_known_total),
        cmocka_unit_test(test_unknown_total_and_shorter_lines),
        cmocka_unit_test(test_quiet),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
