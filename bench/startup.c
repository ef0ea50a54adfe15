/* bench_startup: what one whole fulgur process costs, start to exit, for
 * `fulgur --help` and a 1-segment render: CPU time (user + system, from
 * wait4's rusage, microseconds), wall time and peak resident memory, the
 * median over RUNS runs each (the peak: the largest). The goals (issue 16):
 * a 1-segment render <= 3 ms CPU, --help <= 12 MiB peak. /bin/true is
 * timed the same way, as the machine's floor (a loaded machine inflates
 * every process's CPU time alike). stdout and stderr go to /dev/null.
 * usage: bench_startup FULGUR SCENE.json [RUNS]; writes startup.csv. */
#define _DEFAULT_SOURCE /* wait4, mkstemps */
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_util.h"

extern char **environ;

typedef struct one_run {
    double cpu_s, wall_s, peak_mib;
} one_run;

/* Runs argv once with stdout and stderr to /dev/null; exits on failure. */
static one_run run_once(char *const argv[])
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    double t0 = bench_now_s();
    pid_t pid;
    if (posix_spawn(&pid, argv[0], &fa, NULL, argv, environ) != 0) {
        fprintf(stderr, "bench_startup: cannot start %s\n", argv[0]);
        exit(1);
    }
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "bench_startup: %s %s failed\n", argv[0], argv[1]);
        exit(1);
    }
    posix_spawn_file_actions_destroy(&fa);
    one_run r = {.wall_s = bench_now_s() - t0};
    r.cpu_s = (double)ru.ru_utime.tv_sec + ru.ru_utime.tv_usec * 1e-6 + (double)ru.ru_stime.tv_sec +
              ru.ru_stime.tv_usec * 1e-6;
    r.peak_mib = ru.ru_maxrss / 1024.0; /* Linux: KiB */
    return r;
}

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
            one_run r = run_once(cases[c].argv);
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
