/* From the simulation rate to the audio rate: the flux I, known at
 * t_i = i dt, is interpolated with the Mitchell-Netravali cubic k (eq. 10,
 * psi_i(t) = k(t/dt - i)) and differentiated analytically (eq. 11):
 *     p(t) = (1/dt) sum_i k'(t/dt - i) I_i.
 * B = C = 1/3, Mitchell and Netravali's recommendation (the paper names
 * the filter, not its parameters). k has support |x| < 2, sums to one
 * and reproduces linear functions for every B, C, so a linear I gives its
 * slope exactly. Before I_0 the flux is held at I_0.
 *
 * Streaming: audio sample n (t = n / fs) needs I up to index
 * floor(n r) + 2, r = f_sim / fs: a latency of 2 simulation steps.
 * [sim-thread]; never allocates. */
#ifndef FULGUR_FIRE_MITCHELL_INTERNAL_H
#define FULGUR_FIRE_MITCHELL_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#define FG_MN_B (1.0 / 3.0)
#define FG_MN_C (1.0 / 3.0)
/* The flux samples kept: the 4 a sample needs, and room for the step that
 * follows. */
#define FG_MN_HISTORY 8

/* The kernel and its derivative at x (units of dt). */
double fg_mn_kernel(double x);
double fg_mn_kernel_derivative(double x);

typedef struct fg_mn_stream {
    double sim_rate_hz, sample_rate_hz;
    double flux[FG_MN_HISTORY]; /* I_i at flux[i % FG_MN_HISTORY] */
    uint64_t steps;             /* flux samples taken */
    uint64_t next_frame;        /* the next audio sample to produce */
} fg_mn_stream;

void fg_mn_init(fg_mn_stream *s, double sim_rate_hz, double sample_rate_hz);

/* The audio samples that become computable when one more flux sample is
 * taken, at most: ceil(fs / f_sim) + 1. */
size_t fg_mn_max_frames_per_step(const fg_mn_stream *s);

/* Takes one flux sample and writes the audio samples it completes to
 * p[0 ..), returning how many (at most fg_mn_max_frames_per_step). */
size_t fg_mn_push(fg_mn_stream *s, double flux, double *p);

#endif
