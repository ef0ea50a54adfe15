/* Ranges of numbers: the test and the wording. */
#include <math.h>
#include <stdio.h>

#include "number_range.h"

bool number_range_holds(number_range r, double v)
{
    return isfinite(v) && (!r.integer || v == floor(v)) && v >= r.lo && v <= r.hi &&
           !(r.lo_open && v == r.lo) && !(r.hi_open && v == r.hi);
}

void number_range_format(number_range r, char *buf, size_t size)
{
    if (!r.lo_open && !r.hi_open)
        snprintf(buf, size, "%.16g..%.16g", r.lo, r.hi);
    else
        snprintf(buf, size, "%c%.16g, %.16g%c", r.lo_open ? '(' : '[', r.lo, r.hi,
                 r.hi_open ? ')' : ']');
}
