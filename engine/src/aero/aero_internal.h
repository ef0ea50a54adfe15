/* The sound-texture generator's parts: shapes, the flow run, the loop.
 * [sim-thread] (offline); nothing here runs on the audio thread except
 * the lookups of aero_texture.c that aero.h marks wait-free. */
#ifndef FULGUR_AERO_INTERNAL_H
#define FULGUR_AERO_INTERNAL_H

#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#include "fulgur/aero.h"

/* aero_shape.c — a validated shape, placed for the flow. */
typedef struct fg_aero_body {
    fg_aero_shape shape;
    int dims;
    double reference_m;
    double radius_m;        /* circle, sphere */
    double *polygon;        /* rectangle, polygon: [2 * vertices], ccw, centroid at 0 */
    uint32_t vertices;
    double *placed;         /* the polygon turned into the flow frame */
    double club_r[2];       /* club: the radii of the handle and tip spheres */
    double club_z[2];       /* club: their centres on the axis */
    double length_m;        /* club: overall length (axis from 0 to length) */
    uint32_t rotation_order;
    uint32_t mirror;
    double mirror_angle_rad;
    double angle_rad;       /* the flow angle the body is placed for */
} fg_aero_body;

/* Validates the shape fields of c and builds the body (centred, ccw, its
 * symmetry found). Errors as fg_aero_generate's for the shape, the field
 * in *why. */
fg_result fg_aero_body_init(fg_aero_body *b, const fg_aero_config *c, fg_aero_check *why);
void fg_aero_body_deinit(fg_aero_body *b);
/* Places the body for a flow along +x that is at angle_rad in its frame
 * (2-D: the body turned by -angle). b must not be shared between threads
 * while placing; fg_aero_body_copy gives each thread its own. */
void fg_aero_body_place(fg_aero_body *b, double angle_rad);
fg_result fg_aero_body_copy(const fg_aero_body *from, fg_aero_body *to);
/* Signed distance (m, negative inside) in the flow frame; user is the body. */
double fg_aero_body_sdf(const double x_m[3], void *body);
/* The largest distance of the surface from the centre (2-D) or from the
 * axis (3-D club: its larger radius). */
double fg_aero_body_radius(const fg_aero_body *b);
/* The width across a flow at angle_rad (2-D), or across x (3-D). */
double fg_aero_body_frontal(const fg_aero_body *b, double angle_rad);
/* The area the force coefficients divide by: reference_m (per metre) in
 * 2-D, the projected frontal area in 3-D. */
double fg_aero_body_area(const fg_aero_body *b);
/* The flow angles to sample: the symmetry's fundamental range every step
 * (or the given angles mapped into it, sorted, repeats dropped). Writes up
 * to FG_AERO_MAX_DIRECTIONS angles; returns the count. */
uint32_t fg_aero_body_directions(const fg_aero_body *b, const fg_aero_config *c,
                                 double *angles);

/* aero_flow.c — one flow past the body, from rest to the recorded loop. */

typedef struct fg_aero_plan {
    int dims;
    double reference_m, speed_m_s, viscosity_m2_s, density_kg_m3;
    double cell_m;
    double rate_hz;           /* texture rate: the force is recorded every substeps */
    uint32_t substeps;
    double dt_s;
    double domain_m[3];       /* upstream, downstream, lateral half-width */
    double transient_s, max_transient_s;
    double seconds;           /* loop length asked for; 0: periods */
    uint32_t periods;
    uint32_t sources;
    double area_m2;           /* what the force coefficients divide by (with rho v0^2 / 2) */
    double band_hz[2];        /* where the shedding frequency is looked for: St 0.02..1 */
} fg_aero_plan;

/* Progress of one run, read by the reporting thread. */
typedef struct fg_aero_watch {
    atomic_int phase;         /* fg_aero_phase */
    atomic_llong steps;       /* flow steps done */
    atomic_llong planned;     /* the current estimate of the steps the run takes */
    atomic_llong cells;       /* of its grid, once made */
} fg_aero_watch;

typedef struct fg_aero_record {
    double *force;            /* [samples][sources][dims], N (per metre in 2-D) */
    size_t samples;
    double transient_s;
    int shedding;             /* 0: no shedding found (a quiet direction) */
} fg_aero_record;

/* The Strouhal number assumed before one is found (and for quiet directions). */
#define FG_AERO_GUESSED_STROUHAL 0.2

#define FG_AERO_MAX_CELLS ((double)(1u << 27))

/* The flow's box around b: cells and origin; returns the cell count. */
double fg_aero_box(const fg_aero_plan *p, const fg_aero_body *b, int cells[3], double origin[3]);

/* Runs the flow past b (placed for its direction): grid, start-up,
 * recording. Errors: NO_MEMORY, NOT_CONVERGED (no shedding by the longest
 * transient, or the flow blew up), ARGUMENT (the grid is too large). */
fg_result fg_aero_run(const fg_aero_plan *p, fg_aero_body *b, fg_aero_watch *w,
                      fg_aero_record *out);
void fg_aero_record_free(fg_aero_record *r);

/* aero_texture.c — the symmetry's map of any angle into the sampled range. */
/* The sampled range [lo, lo + span] (mirror) or [lo, lo + span) (periodic). */
void fg_aero_symmetry_range(uint32_t rotation_order, uint32_t mirror, double mirror_angle,
                            double *lo, double *span);
/* angle mapped into the range; *flip = 1 when the map mirrored the flow. */
double fg_aero_symmetry_map(uint32_t rotation_order, uint32_t mirror, double mirror_angle,
                            double angle, int *flip);

/* aero_loop.c — the recorded force made into a seamless loop of g. */
typedef struct fg_aero_loop {
    double period_s;     /* the shedding period found in the signal */
    uint32_t periods;    /* in the loop */
    uint32_t frames;
    uint32_t fade;       /* cross-fade length, samples */
} fg_aero_loop;

/* The period of x's dominant oscillation (n samples at rate): the peak of
 * its spectrum between lo and hi (and between two periods in the record
 * and a quarter of the rate); 0 when there is no clear peak there. */
double fg_aero_dominant_period(const double *x, size_t n, double rate_hz, double lo_hz,
                               double hi_hz);
/* Chooses the loop (the period searched for between lo and hi): the most
 * whole periods that fit in n samples with one
 * period to spare for the cross-fade (at most want periods when want > 0),
 * the length refined to the lag where the signal best repeats itself.
 * Returns -1 when the signal holds fewer than 2 periods plus the fade. */
int fg_aero_loop_plan(const double *lift, size_t n, double rate_hz, double lo_hz, double hi_hz,
                      uint32_t want, fg_aero_loop *loop);
/* out[0 .. frames) = the loop of x: x[i] for i >= fade, and for i < fade the
 * raised-cosine blend of x[i + frames] (weight 1 at i = 0) into x[i]. */
void fg_aero_loop_crossfade(const double *x, const fg_aero_loop *loop, double *out);
/* g = dF/dt of a periodic signal: centred differences with wrap-around. */
void fg_aero_loop_derivative(const double *f, uint32_t frames, double rate_hz, float *g,
                             size_t stride);

#endif
