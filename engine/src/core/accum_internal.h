/* A difference-domain accumulator: one bus and ear over a chunk of audio
 * blocks, into which waves that are piecewise polynomial (the WM-wave) are
 * added as third differences at their breakpoints, so a wave costs per
 * breakpoint, never per sample. Its samples are rebuilt block by block
 * from running sums: a chunk's first block starts them from the three
 * samples before it (state) that its waves add exactly, and each later
 * block of the chunk carries them on, adding the state of a wave that
 * joins late. A chunk starts from exact values, so rounding never drifts
 * across chunks; within one it drifts as within one block of its length.
 * [audio-thread] */
#ifndef FULGUR_ACCUM_INTERNAL_H
#define FULGUR_ACCUM_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct fg_accum {
    double *d3;      /* n entries from the block's first sample to the chunk's end */
    double state[3]; /* what waves add to y[-1], y[-2], y[-3] before the block */
    double sum[3];   /* the running sums at sample -1 carried from the chunk's
                      * blocks before (fg_accum_end_all), 0 at its start */
    uint32_t n;
    int32_t until; /* from this sample on no wave written adds anything
                    * (fg_accum_hold; n + 1 for one sounding past the chunk):
                    * once the block starts there, its sums are 0 exactly,
                    * not their rounding, and it holds nothing */
} fg_accum;

/* Whether a wave written to b still adds to the block: until then it is
 * integrated (fg_accum_end_all); after, it adds nothing. */
static inline bool fg_accum_sounds(const fg_accum *b)
{
    return b->until > 0;
}

/* Where a wave stands relative to the block it is added to. */
typedef enum fg_wave_status {
    FG_WAVE_PENDING,  /* starts after this block */
    FG_WAVE_SOUNDING, /* contributes to this block */
    FG_WAVE_DONE,     /* ended before this block: contributes nothing here or later */
    FG_WAVE_NON_FINITE, /* its numbers are not finite (or place it beyond any sample
                         * index): nothing was added, and nothing of it ever may be */
    FG_WAVE_SKIPPED     /* its price did not fit the block's work bound: nothing was
                         * added (fg_engine_config.work_per_frame) */
} fg_wave_status;

/* Starts a chunk of n samples on d3, which is zero (the storage's
 * allocation, or an earlier chunk's end, left it so). */
void fg_accum_restart(fg_accum *b, double *d3, uint32_t n);

/* Notes that a wave written to b adds nothing from sample end on. */
static inline void fg_accum_hold(fg_accum *b, long end)
{
    if (end > (long)b->n)
        end = (long)b->n + 1;
    if (end > b->until)
        b->until = (int32_t)end;
}

/* Integrates the block's first frames samples of each b[k] (frames <= n)
 * into its y[0..frames), adding y into out[k] (which must not overlap),
 * and zeroes those third differences as it reads them: no pass of its own
 * to clear them. Each is then the next block's: d3 and n move on by
 * frames, the running sums carried (0 once no wave sounds; dropped with
 * the rest of the chunk's waves where they are not finite: waves too large
 * to add up), the state spent. One that does not sound adds nothing and
 * stays where it was. The outs may be written in any order: each one's samples are
 * those it would give alone, with avx2 (where fg_accum_avx2_available said
 * so: four at a time) or without (two at a time). */
void fg_accum_end_all(fg_accum *const *b, float *const *out, unsigned count, uint32_t frames,
                      bool avx2);

/* Whether this CPU runs fg_accum_end_four_avx2. [main-thread] */
bool fg_accum_avx2_available(void);

/* Four accumulators from their running sums at sample -1 (sum[0][c] the
 * second difference of b[c], sum[1][c] the first, sum[2][c] y): samples
 * [0, frames rounded down to a multiple of 4) as fg_accum_end_all ends
 * them, the sums left at the last of those. Returns that count
 * (core/accum_avx2.c; 0 where the build has no AVX2 kernel). */
uint32_t fg_accum_end_four_avx2(fg_accum *const b[4], float *const out[4], double sum[3][4],
                                uint32_t frames);

#endif
