/* Shared helpers of the benchmark programs: a monotonic clock, a CPU clock, medians,
 * a least-squares line, and CSV output. */
#ifndef FULGUR_BENCH_UTIL_H
#define FULGUR_BENCH_UTIL_H

#include <stddef.h>
#include <stdio.h>

double bench_now_s(void);

/* CPU time of the calling thread: what a benchmark costs on a shared
 * machine, where wall time also counts other processes. */
double bench_cpu_s(void);

/* Median of v[0..n) (sorts v in place). */
double bench_median(double *v, size_t n);

/* The value below which a fraction q of v[0..n) lies (sorts v). */
double bench_quantile(double *v, size_t n, double q);

typedef struct bench_fit {
    double slope, intercept, r2;
} bench_fit;

bench_fit bench_fit_line(const double *x, const double *y, size_t n);

/* Opens bench/results/NAME for writing (directory given by the
 * FULGUR_RESULTS environment variable, default bench/results), or exits. */
FILE *bench_open_result(const char *name);

/* One child process's cost, start to exit: CPU time (user + system, from
 * wait4's rusage), wall time, and peak resident memory. */
typedef struct bench_child {
    double cpu_s, wall_s, peak_mib;
} bench_child;

/* Runs argv (argv[0] a path) once, stdin from /dev/null, stdout to
 * stdout_path (NULL: /dev/null), stderr to /dev/null; exits when it cannot
 * start or does not exit 0. */
bench_child bench_run_child(char *const argv[], const char *stdout_path);

/* A one-line description of this machine's processor, for the results. */
void bench_machine(char *buf, size_t size);

#endif
