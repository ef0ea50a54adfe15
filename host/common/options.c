/* The option table's parser, its messages and its help. */
#include <assert.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"
#include "text_escape.h"

#define USAGE_WIDTH 90   /* the usage line wraps here */
#define HELP_COLUMN 30   /* where an option's help starts, at most */
#define MAX_OPTIONS 32   /* options in one table */

/* The one_of list, the values apart by separator. */
static const char *one_of_text(const uint32_t *list, const char *separator, char *buf,
                               size_t size)
{
    buf[0] = '\0';
    for (const uint32_t *v = list; *v; v++)
        snprintf(buf + strlen(buf), size - strlen(buf), "%s%u", v == list ? "" : separator,
                 (unsigned)*v);
    return buf;
}

/* The value as the usage writes it: value_name, or the one_of list. */
static const char *value_text(const option *o, char *buf, size_t size)
{
    if (o->value_name || !o->one_of)
        return o->value_name ? o->value_name : "VALUE";
    return one_of_text(o->one_of, "|", buf, size);
}

/* "--block 64|128|256|512", "-o FILE" or a flag's name. */
static void option_text(const option *o, char *buf, size_t size)
{
    char value[96];
    if (o->kind == OPTION_FLAG)
        snprintf(buf, size, "%s", o->name);
    else
        snprintf(buf, size, "%s %s", o->name, value_text(o, value, sizeof value));
}

/* Writes piece after the others, wrapping at USAGE_WIDTH under indent. */
static void usage_piece(FILE *to, const char *piece, int indent, int *column)
{
    int len = (int)strlen(piece);
    if (*column > indent && *column + 1 + len > USAGE_WIDTH)
        *column = fprintf(to, "\n%*s", indent - 1, "") - 1;
    *column += fprintf(to, " %s", piece);
}

static void usage_line(const command_line *cl, FILE *to)
{
    int indent = (int)strlen("usage: ") + (int)strlen(cl->command) + 1;
    int column = fprintf(to, "usage: %s", cl->command);
    usage_piece(to, cl->operands, indent, &column);
    for (const option *o = cl->options; o->name; o++) {
        char piece[128], text[120];
        option_text(o, text, sizeof text);
        snprintf(piece, sizeof piece, o->required ? "%s" : "[%s]", text);
        usage_piece(to, piece, indent, &column);
    }
    fputc('\n', to);
}

void options_help(const command_line *cl, FILE *to)
{
    usage_line(cl, to);
    if (cl->about)
        fputs(cl->about, to);
    int column = 0;
    for (const option *o = cl->options; o->name; o++) {
        char text[128];
        option_text(o, text, sizeof text);
        int width = (int)strlen(text) + 4;
        if (width > column && width <= HELP_COLUMN)
            column = width;
    }
    for (const option *o = cl->options; o->name; o++) {
        char text[128];
        option_text(o, text, sizeof text);
        int at = fprintf(to, "  %s", text);
        if (at + 2 > column) {
            fputc('\n', to);
            at = 0;
        }
        /* each line of the help at the column */
        for (const char *line = o->help; line && *line;) {
            size_t n = strcspn(line, "\n");
            fprintf(to, "%*s%.*s\n", column - at, "", (int)n, line);
            at = 0;
            line += n + (line[n] == '\n');
        }
        if ((!o->help || !*o->help) && at > 0)
            fputc('\n', to);
    }
    if (cl->notes)
        fputs(cl->notes, to);
}

static options_result fail_va(const command_line *cl, const char *format, va_list ap)
{
    /* the message echoes arguments: their control and invalid bytes are escaped */
    char text[1024], safe[4 * sizeof text];
    vsnprintf(text, sizeof text, format, ap);
    text_escape(safe, sizeof safe, text);
    fprintf(stderr, "%s: %s\n", cl->command, safe);
    usage_line(cl, stderr);
    return OPTIONS_BAD;
}

options_result options_fail(const command_line *cl, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    options_result r = fail_va(cl, format, ap);
    va_end(ap);
    return r;
}

/* A whole argument read as a number; NAN when it is not one. */
static double number_of(const char *text)
{
    char *end;
    double v = strtod(text, &end);
    return end == text || *end ? NAN : v;
}

int option_number(const char *text, number_range range, double *out)
{
    double v = number_of(text);
    if (!number_range_holds(range, v))
        return -1;
    *out = v;
    return 0;
}

static bool is_one_of(const uint32_t *list, double v)
{
    for (; *list; list++)
        if (v == *list)
            return true;
    return false;
}

/* Reads the argument text of o into its value. */
int option_parse_size(const char *text, void *size, char *why, size_t why_size)
{
    option_size *o = size;
    char *end;
    long w = strtol(text, &end, 10), h = 0;
    if (*end == 'x')
        h = strtol(end + 1, &end, 10);
    if (*end || w < 16 || h < 16 || w > 8192 || h > 8192) {
        snprintf(why, why_size, "expected WIDTHxHEIGHT in pixels, each 16..8192");
        return -1;
    }
    o->width = (int)w, o->height = (int)h;
    return 0;
}

static options_result read_value(const command_line *cl, const option *o, const char *text)
{
    char range[96], why[256];
    double v = number_of(text);
    number_range r = o->range;
    switch (o->kind) {
    case OPTION_FLAG:
        break;
    case OPTION_TEXT:
        *(const char **)o->value = text;
        break;
    case OPTION_NUMBER:
        if (!number_range_holds(r, v) && isinf(r.lo) && isinf(r.hi))
            return options_fail(cl, "%s %s: expected a finite number", o->name, text);
        if (!number_range_holds(r, v)) {
            number_range_format(r, range, sizeof range);
            return options_fail(cl, "%s %s: expected a number in %s", o->name, text, range);
        }
        *(double *)o->value = v;
        break;
    case OPTION_INTEGER:
        r.integer = true;
        if (o->one_of && !is_one_of(o->one_of, v))
            return options_fail(cl, "%s %s: expected one of %s", o->name, text,
                                one_of_text(o->one_of, ", ", range, sizeof range));
        if (!o->one_of && !number_range_holds(r, v)) {
            number_range_format(r, range, sizeof range);
            return options_fail(cl, "%s %s: expected an integer in %s", o->name, text, range);
        }
        *(uint32_t *)o->value = (uint32_t)v;
        break;
    case OPTION_PARSED:
        why[0] = '\0';
        if (o->parse(text, o->value, why, sizeof why) != 0)
            return options_fail(cl, "%s %s: %s", o->name, text, why[0] ? why : "not accepted");
        break;
    }
    return OPTIONS_OK;
}

static const option *find(const command_line *cl, const char *name)
{
    for (const option *o = cl->options; o->name; o++)
        if (strcmp(o->name, name) == 0)
            return o;
    return NULL;
}

options_result options_parse(const command_line *cl, int argc, char **argv, const char **operands,
                             size_t *operand_count)
{
    bool given[MAX_OPTIONS] = {false};
    *operand_count = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (a[0] != '-') {
            if (*operand_count == cl->max_operands)
                return options_fail(cl, "unexpected argument \"%s\"", a);
            operands[(*operand_count)++] = a;
            continue;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            options_help(cl, stdout);
            return OPTIONS_HELP;
        }
        const option *o = find(cl, a);
        if (!o)
            return options_fail(cl, "unknown option \"%s\" (%s --help lists them)", a,
                                cl->command);
        assert(o - cl->options < MAX_OPTIONS);
        given[o - cl->options] = true;
        if (o->kind == OPTION_FLAG) {
            *(bool *)o->value = true;
            continue;
        }
        char value[96];
        if (i + 1 == argc)
            return options_fail(cl, "%s needs a value: %s %s", a, a,
                                value_text(o, value, sizeof value));
        if (read_value(cl, o, argv[++i]) != OPTIONS_OK)
            return OPTIONS_BAD;
    }
    for (const option *o = cl->options; o->name; o++) {
        char text[128];
        option_text(o, text, sizeof text);
        if (o->required && !given[o - cl->options])
            return options_fail(cl, "%s is required", text);
    }
    if (*operand_count < cl->min_operands)
        return options_fail(cl, "give %s", cl->operands);
    return OPTIONS_OK;
}
