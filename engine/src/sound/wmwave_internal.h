/* The WM-wave of one segment (Matsuyama eq. 5), its closed-form integral,
 * exact sample averages, and how it enters a difference-domain
 * accumulator (core/accum_internal.h). */
#ifndef FULGUR_WMWAVE_INTERNAL_H
#define FULGUR_WMWAVE_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>

#include "core/accum_internal.h"
#include "fulgur/sound.h"

/* The shape in the dimensionless time tau = c (t - t_arrival) / l. */
typedef struct fg_wm_shape {
    double b;    /* B, pascals: broadside peak is 4 B psi = ps */
    double s;    /* sin(theta), 0 = broadside, 1 = end-on */
    double psi;  /* c T / l */
} fg_wm_shape;

/* One segment as heard by one ear: its shape, where tau = 0 falls and how
 * many samples one unit of tau lasts. */
typedef struct fg_wm_event {
    fg_wm_shape shape;
    double center;  /* sample position of tau = 0 (sample n covers [n-1/2, n+1/2)) */
    double width;   /* samples per unit of tau: fs * l / c */
} fg_wm_event;

/* Shape of a segment of half-length l_m at distance r_m (clamped to r0)
 * with s = sin(theta), for N-wave parameters p and a baseline T0 t0_s. Fills
 * *t_s with the stretched half-duration T. */
fg_wm_shape fg_wm_shape_at(const fg_sound_config *p, double t0_s, double r_m, double s, double l_m,
                     double c_m_s, double *t_s);

/* The continuous pressure p(tau), pascals (eq. 5, both cases). */
double fg_wm_pressure(const fg_wm_shape *w, double tau);

/* Its running integral P(tau) = int_{-inf}^{tau} p, pascal * tau units.
 * P is even in tau and vanishes outside [-(psi+s), psi+s]. */
double fg_wm_integral(const fg_wm_shape *w, double tau);

/* The sample holding position x: floor(x + 1/2), without a libm call on
 * targets where floor is not an instruction. */
static inline long fg_wm_sample_at(double x)
{
    double y = x + 0.5;
    long m = (long)y;
    return m - ((double)m > y);
}

/* Sample positions beyond 2^62 are no block's: their index would not fit. */
#define FG_WM_SAMPLE_INDEX_LIMIT 4.6e18

/* Whether e's numbers are finite and every sample it touches has an index
 * a long holds: what fg_wm_event_span and fg_wm_accum_add need. Inline:
 * the audio thread places every sounding wave once per block and ear. */
static inline bool fg_wm_event_in_range(const fg_wm_event *e)
{
    const fg_wm_shape *w = &e->shape;
    if (!isfinite(w->b) || !(w->s >= 0.0 && w->s <= 1.0) || !(w->psi > 0.0) ||
        !isfinite(w->psi) || !(e->width > 0.0) || !isfinite(e->width) || !isfinite(e->center))
        return false;
    double half = (w->psi + w->s) * e->width;
    return fabs(e->center) + half < FG_WM_SAMPLE_INDEX_LIMIT;
}

/* First and last sample the event touches (e in range). */
static inline void fg_wm_event_span(const fg_wm_event *e, long *first, long *last)
{
    double half = (e->shape.psi + e->shape.s) * e->width;
    *first = fg_wm_sample_at(e->center - half);
    *last = fg_wm_sample_at(e->center + half);
}

/* Whether an event whose last sample is last ends before the block it
 * would be added to, even the accumulator's state before it: then
 * fg_wm_accum_add of it (in range) adds nothing and returns
 * FG_WAVE_DONE. */
static inline bool fg_wm_event_ended(long last)
{
    return last < -3;
}

/* Adds event e (positions relative to the block start) to the block's
 * accumulator. The cost is a few closed-form evaluations per breakpoint in
 * the block plus three for the state, whatever the waveform's length.
 * FG_WAVE_NON_FINITE, adding nothing, when e is out of range or a value
 * it would add is not finite. */
fg_wave_status fg_wm_accum_add(fg_accum *b, const fg_wm_event *e);

/* What one wave adds to a block's accumulator: the values of the samples
 * around its breakpoints (and the state before the block), or, where the
 * breakpoints lie a sample or more apart, their taps in closed form. */
enum { FG_WM_RANGE_MAX = 32, FG_WM_RANGES_MAX = 5 };
typedef struct fg_wm_taps {
    bool closed_form;
    int count;                    /* breakpoints (closed form) or ranges */
    bool state;                   /* closed form: y[0] holds the state's three samples */
    long lo[FG_WM_RANGES_MAX], hi[FG_WM_RANGES_MAX];
    double y[FG_WM_RANGES_MAX][FG_WM_RANGE_MAX];
    long m[4];                    /* closed form: the sample holding each breakpoint */
    double taps[4][4];            /* its third differences at m .. m + 3 */
    long end;                     /* the wave adds nothing from this sample on */
} fg_wm_taps;

/* Evaluates, for a block of n frames, event e in range but perhaps for
 * its B (checked), whose span first .. last (fg_wm_event_span) is known:
 * FG_WAVE_SOUNDING and *t when it adds to the block; else it adds nothing
 * (FG_WAVE_DONE, FG_WAVE_PENDING or FG_WAVE_NON_FINITE). One wave placed
 * and evaluated once is then added to several channels at several gains
 * (fg_wm_taps_add). */
fg_wave_status fg_wm_taps_eval(const fg_wm_event *e, long first, long last, long n,
                               fg_wm_taps *t);

/* Adds gain times the evaluated wave to the accumulator of a block of the
 * length it was evaluated for; a gain of 1 adds what fg_wm_accum_add
 * would, bit for bit. */
void fg_wm_taps_add(fg_accum *b, const fg_wm_taps *t, double gain);

/* The edges of the state's samples, -3 .. -1, in tau, and the one piece
 * that holds all four (1 the rising shell, 2 the middle, 3 the falling
 * shell), or -1: what of the state does not depend on B. */
typedef struct fg_wm_state_edges {
    double edge[4];
    int piece;
} fg_wm_state_edges;

/* The state of a wave of shape w whose edges s lie in one piece, as
 * fg_wm_taps_eval gives it, bit for bit; false when it is not finite. */
bool fg_wm_state_values(const fg_wm_state_edges *s, const fg_wm_shape *w, double y[3]);

/* Whether e, in range, whose span is first .. last, adds to a block of n
 * its state alone, which lies in one piece (*s), and fg_wm_taps_eval of
 * it with any B of no greater size gives the closed form's state and no
 * breakpoint: a long wave sounding through a block. Its buses then share
 * the edges and differ in fg_wm_state_values. */
bool fg_wm_through(const fg_wm_event *e, long first, long last, long n, fg_wm_state_edges *s);

/* Adds gain times a state y (samples -3 .. -1) to the accumulator, as
 * fg_wm_taps_add adds a closed form's. */
void fg_wm_state_add(fg_accum *b, const double y[3], double gain);

#endif
