/* The ISO 9613-1 filters of a band plan's centres, designed once per
 * process for each (sample rate, air, centres).
 *
 * Designing them (absorb_filter_internal.h: four biquads fitted by
 * Levenberg-Marquardt per band, each started from its nearer neighbour's
 * fit) costs 0.15-0.3 s of CPU for the 45 bands of the engine's plan,
 * and every engine of a process with the same rate and weather needs the
 * same filters. The design is deterministic, so a kept design is the one a
 * new design would give, bit for bit. FG_BAND_FILTERS_KEPT designs are
 * kept, the oldest replaced first. */
#ifndef FULGUR_BAND_FILTERS_INTERNAL_H
#define FULGUR_BAND_FILTERS_INTERNAL_H

#include "air_absorption_internal.h"
#include "distance_bands_internal.h"
#include "iir_internal.h"

#define FG_BAND_FILTERS_KEPT 4

/* out[k] (state cleared) for each band centre centre_m[k], k < count
 * (<= FG_BANDS_MAX), at fs_hz through air: a kept design, or a new one
 * that is then kept. Band k's fit starts from band k - 1's. [sim-thread]
 * or [main-thread]: takes a process-wide lock for the copy only; a new
 * design costs up to 20 ms per band, no allocation. */
void fg_band_filters_design(const fg_air *air, const double *centre_m, unsigned count,
                            double fs_hz, fg_iir *out);

#endif
