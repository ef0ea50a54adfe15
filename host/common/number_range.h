/* The accepted values of a number, as scene files and command lines state
 * them: lo..hi, either end open, optionally whole numbers only. */
#ifndef HOST_COMMON_NUMBER_RANGE_H
#define HOST_COMMON_NUMBER_RANGE_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>

typedef struct number_range {
    double lo, hi;          /* finite, or both infinite: any finite number */
    bool lo_open, hi_open;
    bool integer;
} number_range;

/* Whether v is finite, inside r and, when r.integer, whole. Inline: the
 * streaming nodes reader asks it of every number of a tree (five calls a
 * node, 1.7 % of a 10^6-segment render as a call). */
static inline bool number_range_holds(number_range r, double v)
{
    return isfinite(v) && (!r.integer || v == floor(v)) && v >= r.lo && v <= r.hi &&
           !(r.lo_open && v == r.lo) && !(r.hi_open && v == r.hi);
}

/* r for messages: "1..4096" when both ends are closed, "(0, 3600]" and the
 * like when one is open, "(-inf, inf)" for the unbounded range. Always
 * NUL-terminated. */
void number_range_format(number_range r, char *buf, size_t size);

#endif
