/* A progress line for long work on a terminal: nothing for the first
 * PROGRESS_AFTER_S of wall time (short work stays quiet), then one line,
 * rewritten in place at most every PROGRESS_EVERY_S, for the item at hand
 * (fulgur render: the scene being rendered, "[3/40] storm.json"). The
 * caller decides whether there is a terminal to write to (NULL: quiet),
 * clears the line before writing anything else there, and passes the
 * times in, so the line's behaviour is testable. [main-thread] */
#ifndef HOST_COMMON_PROGRESS_H
#define HOST_COMMON_PROGRESS_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#define PROGRESS_AFTER_S 2.0
#define PROGRESS_EVERY_S 0.25

typedef struct progress {
    FILE *to;             /* NULL: quiet */
    const char *unit;     /* the work's unit in the line: "s of sound" */
    const char *label;    /* the item at hand */
    double total;         /* its size in unit; 0: not known */
    uint64_t item_ns;     /* when the item started */
    uint64_t next_ns;     /* the earliest wall time of the next line */
    int width;            /* characters of the line now shown; 0: none */
} progress;

/* Starts the clock at now_ns. unit is borrowed until the last call. */
void progress_begin(progress *p, FILE *to, const char *unit, uint64_t now_ns);

/* The next item, of total units (0: not known), from now_ns; label is
 * borrowed until the next item. */
void progress_item(progress *p, const char *label, double total, uint64_t now_ns);

/* done units of the item so far, at now_ns: (re)writes the line when due:
 * "fulgur: storm.json: 41% (246.0 of 600.0 s of sound, 4.0 s, about 5.8 s left)",
 * or without a total "fulgur: storm.json: 246.0 s of sound (4.0 s)" (the
 * times are the item's). Returns whether it wrote. */
bool progress_update(progress *p, double done, uint64_t now_ns);

/* Erases the line, if one is shown; the next update draws it again. */
void progress_clear(progress *p);

#endif
