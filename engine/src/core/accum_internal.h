/* A difference-domain accumulator: one audio block of one bus and ear,
 * into which waves that are piecewise polynomial (the WM-wave) are added as
 * third differences at their breakpoints, so a wave costs per breakpoint,
 * never per sample. y[k] for k in [0, n) is rebuilt from the three samples
 * before the block (state) and the third differences (d3). Each block
 * starts from exact values, so rounding never drifts across blocks.
 * [audio-thread] apart from fg_accum_begin, which sets up the storage. */
#ifndef FULGUR_ACCUM_INTERNAL_H
#define FULGUR_ACCUM_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

typedef struct fg_accum {
    double *d3;        /* n entries, zeroed by fg_accum_begin */
    size_t n;
    double state[3];   /* y[-1], y[-2], y[-3] */
    bool touched;      /* some wave contributed */
} fg_accum;

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

void fg_accum_begin(fg_accum *b, double *d3, size_t n);

/* Starts the next block of n on the same storage, which the previous
 * block's end left zero (or fg_accum_begin zeroed). */
void fg_accum_restart(fg_accum *b, size_t n);

/* Integrates each block b[k] into its y[0..n), adding y into out[k]
 * (which must not overlap), and zeroes its third differences as it reads
 * them, for the next block: no pass of its own to clear them. An untouched
 * block adds nothing. The outs may be written in any order: each block's
 * samples are those it would give alone, with avx2 (where
 * fg_accum_avx2_available said so: four blocks of one length at a time)
 * or without (two at a time). */
void fg_accum_end_all(fg_accum *const *b, float *const *out, unsigned count, bool avx2);

/* Whether this CPU runs fg_accum_end_four_avx2. [main-thread] */
bool fg_accum_avx2_available(void);

/* Four blocks of one length n from their running sums at sample -1
 * (sum[0][c] the second difference of block c, sum[1][c] the first, sum[2][c]
 * y): samples [0, n rounded down to a multiple of 4) as fg_accum_end_all
 * ends them, the sums left at the last of those. Returns that count
 * (core/accum_avx2.c; 0 where the build has no AVX2 kernel). */
size_t fg_accum_end_four_avx2(fg_accum *const b[4], float *const out[4], double sum[3][4]);

#endif
