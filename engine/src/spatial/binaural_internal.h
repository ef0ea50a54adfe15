/* The binaural layout: waves are panned onto a fixed set of 50 virtual
 * loudspeakers around the head, each of which is heard through the
 * measured HRIR pair (fg_hrir_set: what the host read from a SOFA file) of
 * the set's direction nearest to it; each loudspeaker's channel is filtered
 * once per block, so the cost is per wave (an add into each of the up to
 * four loudspeakers it is panned to) and per block (a partitioned
 * convolution per loudspeaker that has sound, dsp/convolver_internal.h),
 * never per wave and filter.
 *
 * The loudspeakers stand on seven rings of elevation -90, -60, -30, 0, 30,
 * 60 and 90 degrees with 1, 6, 12, 12, 12, 6 and 1 of them, evenly spaced
 * in azimuth from straight ahead (counter-clockwise seen from above, to the
 * left, as SOFA counts it). A wave from elevation e and azimuth a goes to
 * the two rings around e with linear weights, and on each ring to the two
 * loudspeakers around a with linear weights (the gains sum to 1, so the
 * low-frequency pressure is kept): a wave from a loudspeaker's own
 * direction is heard through exactly that measured pair. Between
 * loudspeakers two to four pairs are mixed, whose different delays comb
 * the sum above about 1.5 kHz (the price of a bounded set of filters).
 * A set with no measurement near a loudspeaker (MIT KEMAR stops at -40
 * degrees) gives it its nearest.
 *
 * The set is scaled so that its diffuse-field average in the 500 Hz -
 * 2 kHz band has unit gain: the level of a free-field ear, as stereo's
 * ears have. */
#ifndef FULGUR_BINAURAL_INTERNAL_H
#define FULGUR_BINAURAL_INTERNAL_H

#include "dsp/convolver_internal.h"
#include "fulgur/engine.h"

#define FG_BINAURAL_SPEAKERS 50u
#define FG_BINAURAL_MIN_DIRECTIONS 16u

typedef struct fg_binaural {
    fg_convolver conv; /* FG_BINAURAL_SPEAKERS inputs, 2 outputs */
} fg_binaural;

/* Loudspeaker k's unit direction in the head's frame (x ahead, y left,
 * z up). */
void fg_binaural_speaker(unsigned k, double dir[3]);

/* The loudspeakers a wave from the unit direction dir (head frame) is
 * panned to: at most four, two on each of the rings of loudspeakers above
 * and below it, their indices ascending in index[] and their gains, summing
 * to 1, in gain[]; returns how many. [audio-thread] */
unsigned fg_binaural_pan(const double dir[3], unsigned index[4], double gain[4]);

/* The same as all FG_BINAURAL_SPEAKERS gains, the others 0. [audio-thread] */
void fg_binaural_gains(const double dir[3], double *gain);

/* The index of the set's measurement nearest the unit direction u. */
size_t fg_hrir_nearest(const fg_hrir_set *hrirs, const double u[3]);

/* Whether the HRIR set is one fg_binaural_init takes for an engine at
 * fs_hz: FG_ERR_NULL a NULL array, FG_ERR_ARGUMENT a count or length
 * outside the limits (fulgur/engine.h) or a zero direction,
 * FG_ERR_NOT_FINITE a non-finite direction or tap, FG_ERR_SAMPLE_RATE
 * another rate. [any-thread] */
fg_result fg_binaural_check(const fg_hrir_set *hrirs, double fs_hz);

/* Gives each loudspeaker its pair from the (checked) set and prepares the
 * convolution. [main-thread] Errors: FG_ERR_NO_MEMORY. */
fg_result fg_binaural_init(fg_binaural *b, const fg_hrir_set *hrirs);
void fg_binaural_deinit(fg_binaural *b);

/* speakers[k][0..n): the loudspeakers' channels; writes ears[0] (left)
 * and ears[1] (right), FG_BINAURAL_LATENCY_FRAMES late. [audio-thread] */
static inline void fg_binaural_process(fg_binaural *b, const float *const *speakers,
                                       float *const *ears, uint32_t n)
{
    fg_convolver_process(&b->conv, speakers, ears, n);
}

#endif
