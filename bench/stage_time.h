/* Where an engine render's time goes, without touching the engine: the
 * benchmark that links stage_time.c is linked with the linker's
 * --wrap=fg_bus_set_end,--wrap=fg_convolver_process, so the engine's calls
 * of those two stages reach the timers here, which time the real ones.
 * The buses' stage integrates the accumulators and runs the distance
 * filters (core/bus_internal.h); the convolver is the binaural decoder's
 * HRIR convolution (dsp/convolver_internal.h); the rest of a render is the
 * sources' encoding into the buses. Off (one branch per call) until
 * bench_stages_start. */
#ifndef FULGUR_BENCH_STAGE_TIME_H
#define FULGUR_BENCH_STAGE_TIME_H

typedef struct bench_stages {
    double buses_s;    /* in fg_bus_set_end */
    double convolve_s; /* in fg_convolver_process */
} bench_stages;

/* Zeroes the sums and starts timing (the thread's CPU clock: four reads
 * per block, a fraction of a microsecond each). */
void bench_stages_start(void);

/* Stops timing and returns the sums since bench_stages_start. */
bench_stages bench_stages_stop(void);

#endif
