/* The WM-wave of one segment (Matsuyama eq. 5), its closed-form integral,
 * exact sample averages, and a difference-domain block accumulator. */
#ifndef FULGUR_WMWAVE_INTERNAL_H
#define FULGUR_WMWAVE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

#include "fulgur/sound.h"

/* The shape in the dimensionless time tau = c (t - t_arrival) / l. */
typedef struct wm_shape {
    double b;    /* B, pascals: broadside peak is 4 B psi = ps */
    double s;    /* sin(theta), 0 = broadside, 1 = end-on */
    double psi;  /* c T / l */
} wm_shape;

/* One segment as heard by one ear: its shape, where tau = 0 falls and how
 * many samples one unit of tau lasts. */
typedef struct wm_event {
    wm_shape shape;
    double center;  /* sample position of tau = 0 (sample n covers [n-1/2, n+1/2)) */
    double width;   /* samples per unit of tau: fs * l / c */
} wm_event;

/* Shape of a segment of half-length l_m at distance r_m (clamped to r0)
 * with s = sin(theta), for N-wave parameters p and a baseline T0 t0_s. Fills
 * *t_s with the stretched half-duration T. */
wm_shape wm_shape_at(const fg_sound_params *p, double t0_s, double r_m, double s, double l_m,
                     double c_m_s, double *t_s);

/* The continuous pressure p(tau), pascals (eq. 5, both cases). */
double wm_pressure(const wm_shape *w, double tau);

/* Its running integral P(tau) = int_{-inf}^{tau} p, pascal * tau units.
 * P is even in tau and vanishes outside [-(psi+s), psi+s]. */
double wm_integral(const wm_shape *w, double tau);

/* First and last sample the event touches. */
void wm_event_span(const wm_event *e, long *first, long *last);

/* The exact average of the pressure over sample n's interval. */
double wm_sample(const wm_event *e, long n);

/* Adds the sample averages of samples [0, n) into out: the reference. */
void wm_add_direct(const wm_event *e, double *out, size_t n);

/* A block in the difference domain: y[k] for k in [0, n) is rebuilt from the
 * three samples before the block (state) and third differences (d3). Each
 * block starts from exact values, so rounding never drifts across blocks. */
typedef struct wm_block {
    double *d3;        /* n entries, zeroed by wm_block_begin */
    size_t n;
    double state[3];   /* y[-1], y[-2], y[-3] */
    bool touched;      /* some event contributed */
} wm_block;

typedef enum wm_status {
    WM_PENDING,  /* starts after this block */
    WM_SOUNDING, /* contributes to this block */
    WM_DONE      /* ended before this block: contributes nothing here or later */
} wm_status;

void wm_block_begin(wm_block *b, double *d3, size_t n);

/* Starts the next block of n on the same storage, clearing only what the
 * previous block wrote. The storage must have been zero when first used. */
void wm_block_restart(wm_block *b, size_t n);

/* Adds event e (positions relative to the block start) to the block. The
 * cost is a few closed-form evaluations per breakpoint in the block plus
 * three for the state, whatever the waveform's length. */
wm_status wm_block_add(wm_block *b, const wm_event *e);

/* Integrates the block into y[0..n), adding gain * y into out. An untouched
 * block adds nothing. */
void wm_block_end(const wm_block *b, float *out, float gain);

#endif
