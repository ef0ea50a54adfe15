/* One command-line parser for fulgur's subcommands and fulgur-lv2-render.
 *
 * A command describes its options in a table: a name ("--block", "-o")
 * that takes the next argument as its value, or a flag; the value's type
 * and the range it must lie in; one line of help. options_parse reads the
 * arguments against the table, checks every value and collects the
 * operands (the arguments that do not start with '-') in order; --help is
 * written from the same table. An error names the option and what it
 * accepts, "fulgur run: --block 100: expected one of 64, 128, 256, 512",
 * followed by the usage line. [main-thread] */
#ifndef HOST_COMMON_OPTIONS_H
#define HOST_COMMON_OPTIONS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "number_range.h"

typedef enum option_kind {
    OPTION_FLAG,    /* no value: *(bool *)value = true */
    OPTION_TEXT,    /* *(const char **)value = the argument (it points into argv) */
    OPTION_NUMBER,  /* *(double *)value: a number inside range */
    OPTION_INTEGER, /* *(uint32_t *)value: inside range (integer), or one of one_of */
    OPTION_PARSED   /* parse(argument, value, ...) */
} option_kind;

/* Reads text into value (the option's). Returns 0, or -1 with what it
 * expected in why ("expected WIDTHxHEIGHT, each 16..8192"). */
typedef int (*option_parse_fn)(const char *text, void *value, char *why, size_t why_size);

typedef struct option {
    const char *name;       /* "--block" or "-o"; NULL ends the table */
    option_kind kind;
    void *value;            /* where the value goes, of the kind's type */
    const char *value_name; /* the value in the usage ("FILE"); NULL with one_of: "64|128" */
    const char *help;       /* its text in --help; '\n' starts another line */
    number_range range;     /* OPTION_NUMBER; OPTION_INTEGER without one_of */
    const uint32_t *one_of; /* OPTION_INTEGER: the values accepted, 0 ends the list */
    option_parse_fn parse;  /* OPTION_PARSED */
    bool required;
} option;

typedef struct command_line {
    const char *command;      /* "fulgur run": the start of every message */
    const char *operands;     /* the operands in the usage line: "SCENE.json" */
    size_t min_operands, max_operands;
    const char *about;        /* --help, after the usage line: what the command does */
    const char *notes;        /* --help, after the options: exit codes and the like */
    const option *options;    /* at most 32, then one with name NULL */
} command_line;

typedef enum options_result { OPTIONS_OK, OPTIONS_HELP, OPTIONS_BAD } options_result;

/* Reads argv[1..argc) against cl (argv[0] is the command's name). Options
 * and operands may come in any order; a repeated option keeps its last
 * value. The operands go to operands[0..*operand_count), in order;
 * operands has room for cl->max_operands.
 * Returns OPTIONS_OK; OPTIONS_HELP after writing the help to stdout, for
 * "--help" or "-h" (in an option's place); or OPTIONS_BAD after writing the
 * message and the usage line to stderr, for: an unknown option, an option
 * without its value, a value that is not of its type or outside its range,
 * a required option not given, too few or too many operands. Options read
 * before the fault keep the values they were given. */
options_result options_parse(const command_line *cl, int argc, char **argv, const char **operands,
                             size_t *operand_count);

/* Reads text, a whole argument, as a number inside range into *out.
 * Returns 0, or -1 (*out unchanged). */
int option_number(const char *text, number_range range, double *out);

/* A picture's size in pixels, each 16..8192: the value of an
 * OPTION_PARSED "--size WxH" whose parse is option_parse_size. */
typedef struct option_size {
    int width, height;
} option_size;

/* "WxH" into the option_size at size. Returns 0, or -1 with why. */
int option_parse_size(const char *text, void *size, char *why, size_t why_size);

/* A usage error that the command finds after parsing (an option that
 * needs another): "COMMAND: message" and the usage line to stderr.
 * Returns OPTIONS_BAD. */
options_result options_fail(const command_line *cl, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

/* The help: the usage line, cl->about, a row per option, cl->notes. */
void options_help(const command_line *cl, FILE *to);

#endif
