/* Ranges of numbers: the wording (the test is inline in the header). */
#include <stdio.h>

#include "number_range.h"

void number_range_format(number_range r, char *buf, size_t size)
{
    if (!r.lo_open && !r.hi_open)
        snprintf(buf, size, "%.16g..%.16g", r.lo, r.hi);
    else
        snprintf(buf, size, "%c%.16g, %.16g%c", r.lo_open ? '(' : '[', r.lo, r.hi,
                 r.hi_open ? ')' : ']');
}
