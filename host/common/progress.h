/* A progress line for long work on a terminal: nothing for the first
 * PROGRESS_AFTER_S of wall time (short renders stay quiet), then one line,
 * rewritten in place at most every PROGRESS_EVERY_S, and erased at the end.
 * The caller decides whether there is a terminal to write to (NULL: quiet);
 * times are passed in, so the line's behaviour is testable. [main-thread] */
#ifndef HOST_COMMON_PROGRESS_H
#define HOST_COMMON_PROGRESS_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#define PROGRESS_AFTER_S 2.0
#define PROGRESS_EVERY_S 0.25

typedef struct progress {
    FILE *to;             /* NULL: quiet */
    const char *label;    /* what is being done: "storm.json" */
    double total;         /* the work's size (e.g. seconds of sound); 0: not known */
    const char *unit;     /* its unit in the line: "s of sound" */
    uint64_t start_ns;
    uint64_t next_ns;     /* the earliest wall time of the next line */
    int width;            /* characters of the line now shown; 0: none */
} progress;

/* Starts the clock at now_ns. label and unit are borrowed until
 * progress_end. */
void progress_begin(progress *p, FILE *to, const char *label, double total, const char *unit,
                    uint64_t now_ns);

/* done of total so far, at now_ns: (re)writes the line when it is due:
 * "fulgur: storm.json: 41% (246.0 of 600.0 s of sound, 4.0 s, about 5.8 s left)",
 * or without a total "fulgur: storm.json: 246.0 s of sound (4.0 s)".
 * Returns whether it wrote. */
bool progress_update(progress *p, double done, uint64_t now_ns);

/* Erases the line, if one is shown. */
void progress_end(progress *p);

#endif
