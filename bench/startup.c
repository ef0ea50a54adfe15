/* bench_startup: what one whole fulgur process costs, start to exit, for
 * `fulgur --help` and a 1-segment render: CPU time (user + system, from
 * wait4's rusage, microseconds), wall time and peak resident memory, the
 * median over RUNS runs each (the peak: the largest). The goals (issue 16):
 * a 1-segment render <= 3 ms CPU, --help <= 12 MiB peak. /bin/true is
 * timed the same way, as the machine's floor (a loaded machine inflates
 * every process's CPU time alike). stdout and stderr go to /dev/null.
 * usage: bench_startup FULGUR SCENE.json [RUNS]; writes startup.csv. */
#define _DEFAULT_SOURCE /* mkstemps */
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "bench_util.h"

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: bench_startup FULGUR SCENE.json [RUNS]\n");
        return 2;
    }
    int runs = argc > 3 ? atoi(argv[3]) : 50;
    if (runs < 1 || runs > 10000) {
        fprintf(stderr, "bench_startup: RUNS must be 1..10000\n");
        return 2;
    }
    char out[] = "/tmp/bench_startup_XXXXXX.wav";
    int fd = mkstemps(out, 4);
    if (fd < 0) {
        perror("bench_startup: mkstemps");
        return 1;
    }
    close(fd);
    char *floor[] = {"/bin/true", NULL};
    char *help[] = {argv[1], "--help", NULL};
    char *render[] = {argv[1], "render", argv[2], "-o", out, NULL};
    struct {
        const char *name;
        char **argv;
    } cases[] = {{"bin_true", floor}, {"help", help}, {"render_1_segment", render}};
    double *cpu = malloc(runs * sizeof *cpu), *wall = malloc(runs * sizeof *wall);
    if (!cpu || !wall)
        return 1;
    FILE *csv = bench_open_result("startup.csv");
    char machine[256];
    bench_machine(machine, sizeof machine);
    double load = -1; /* the 1-minute load average: the floor's context */
    getloadavg(&load, 1);
    fprintf(csv, "# %s; load average %.1f; %d runs each\ncase,cpu_median_ms,wall_median_ms,peak_rss_mib\n",
            machine, load, runs);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double peak = 0;
        for (int i = 0; i < runs; i++) {
            bench_child r = bench_run_child(cases[c].argv, NULL);
            cpu[i] = r.cpu_s, wall[i] = r.wall_s;
            peak = r.peak_mib > peak ? r.peak_mib : peak;
        }
        double cpu_ms = bench_median(cpu, runs) * 1e3, wall_ms = bench_median(wall, runs) * 1e3;
        fprintf(csv, "%s,%.2f,%.2f,%.1f\n", cases[c].name, cpu_ms, wall_ms, peak);
        printf("%-18s CPU %.2f ms  wall %.2f ms (medians)  peak %.1f MiB\n", cases[c].name,
               cpu_ms, wall_ms, peak);
    }
    fclose(csv);
    unlink(out);
    free(cpu);
    free(wall);
    return 0;
}
