/* The WM-wave's exact sample averages, one sample at a time from the
 * closed-form integral: the reference the difference-domain accumulator
 * (fg_wm_accum_add, fg_accum_end) is checked against. Test code only. */
#ifndef FULGUR_TEST_WM_REFERENCE_H
#define FULGUR_TEST_WM_REFERENCE_H

#include <stddef.h>

#include "sound/wmwave_internal.h"

/* Adds the sample averages of e over samples [0, n) into out: each is the
 * difference of the running integral P at the sample's two edges. */
void ref_wm_add_direct(const fg_wm_event *e, double *out, size_t n);

#endif
