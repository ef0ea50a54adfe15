/* Sound texture synthesis (section 5), streamed.
 *
 * The input p_S (the high-passed dI/dt at the audio rate) is reduced to
 * the coarsest level G_S(L) as it arrives; levels 1 .. L-1 of G_S start as
 * zeros (section 5.1) and are synthesised window by window, each level as
 * far as the finished part of the next coarser one allows: window i of
 * level l needs G_S(l + 1) up to c/2 + h h_f, so the levels run ahead of
 * one another by a few windows and the output (level 1) lags the input by
 * a fixed latency (fg_texture_synth_latency; about 25 ms at 44.1 kHz with
 * the paper's parameters).
 *
 * Each window's feature is searched in its level's dictionary (within
 * 1 + epsilon of the nearest) and the found training window is added under
 * the hat. For level L - 1 the coarse part, from the input, is first
 * mapped to the training's dynamic range (section 5.3, eq. 17): with
 * p_avg the mean magnitude of those samples, r = F_T^-1(F_S(p_avg)) / p_avg.
 * F_S is the distribution of |G_S(L)| over the last level_history_s
 * seconds (the paper, offline, takes the whole signal; a stream can only
 * look back). The synthesised detail is at the training's scale; the
 * output is mapped back, multiplied by 1 / r interpolated between the
 * level-(L-1) windows, so it is in the input's units and scales with it:
 * twice the flux, twice the sound, same details. (The paper does not say
 * how it scales its output.) Silent input (p_avg = 0) gives exactly silent
 * output.
 * [sim-thread]; init allocates, push never does. */
#ifndef FULGUR_FIRE_TEXTURE_SYNTH_INTERNAL_H
#define FULGUR_FIRE_TEXTURE_SYNTH_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "pyramid_internal.h"
#include "texture_internal.h"

typedef struct fg_texture_synth_stats {
    uint64_t queries;   /* nearest-neighbour searches */
    uint64_t silent;    /* level-(L-1) windows of silent input */
    uint64_t choices;   /* a hash of the training windows chosen, in order */
} fg_texture_synth_stats;

typedef struct fg_texture_synth {
    const fg_fire_texture *texture;
    fg_texture_shape shape;
    double epsilon;
    bool dry;                          /* timing only (the latency dry run) */
    fg_reducer reducer[FG_TEXTURE_MAX_LEVELS - 1];
    double *ring[FG_TEXTURE_MAX_LEVELS];   /* level l at ring[l - 1] */
    uint64_t ring_mask;
    int64_t complete[FG_TEXTURE_MAX_LEVELS]; /* samples 0 .. complete - 1 are final */
    int64_t written[FG_TEXTURE_MAX_LEVELS];  /* samples 0 .. written - 1 were cleared */
    uint64_t next_window[FG_TEXTURE_MAX_LEVELS - 1];
    double *gain;                      /* 1 / r of the level-(L-1) windows */
    uint64_t gain_mask;
    uint64_t emitted;                  /* output samples handed out */
    double *history_sorted, *history_fifo;  /* |G_S(L)|: F_S */
    size_t history_cap, history_len, history_head;
    float feature[FG_KD_MAX_DIM];
    fg_texture_synth_stats stats;
} fg_texture_synth;

/* A stream on a trained texture (borrowed; it must outlive the stream).
 * Returns false when out of memory. */
bool fg_texture_synth_init(fg_texture_synth *s, const fg_fire_texture *texture,
                           double level_history_s);
void fg_texture_synth_deinit(fg_texture_synth *s);
void fg_texture_synth_reset(fg_texture_synth *s);

/* The latency, samples: output n is final once the input reaches
 * n + latency. Exact, from a dry run of the schedule. */
size_t fg_texture_synth_latency(const fg_texture_synth *s);

/* Takes p[0 .. n) and writes the output samples they complete to out,
 * returning how many (at most n + latency). */
size_t fg_texture_synth_push(fg_texture_synth *s, const float *p, size_t n, float *out);

#endif
