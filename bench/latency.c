/* Latency through the real host: `fulgur run` on the clock-paced null
 * device, one discharge per run at a range of distances, for a spark and a
 * lightning bolt (whose tree is grown on the sim thread at its time, as a
 * game would). Each discharge is due 0.1 ms after a block boundary, the
 * worst phase: the sim thread sees its time pass only when that block has
 * been rendered. Reads each run's JSON report and writes
 * bench/results/latency.csv: post -> adoption, and how much of the first
 * sound was late (had already passed the ear when the voice was adopted)
 * against the source's distance. */
#define _POSIX_C_SOURCE 200809L
#include <cjson/cJSON.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_util.h"

extern char **environ;

#define RUN_SECONDS "1.0"
#define REPEATS 3

typedef struct kind {
    const char *name;
    const char *discharge; /* printf format: the offset's distance */
} kind;

static const kind kinds[] = {
    {"spark", "{\"time\":0.2001,\"preset\":\"spark_balls\",\"offset\":[0,%g,1.7],"
              "\"generator\":{\"type\":\"spark_gap\"}}"},
    {"lightning", "{\"time\":0.2001,\"preset\":\"lightning\",\"strokes\":1,\"offset\":[0,%g,0],"
                  "\"generator\":{\"type\":\"lightning\",\"height\":300}}"},
};

static const double distances_m[] = {0.3, 0.5, 1, 2, 3, 10, 30, 100};

static double number(const cJSON *root, const char *object, const char *key)
{
    const cJSON *o = cJSON_GetObjectItemCaseSensitive(root, object);
    const cJSON *v = o ? cJSON_GetObjectItemCaseSensitive(o, key) : NULL;
    return cJSON_IsNumber(v) ? v->valuedouble : -1;
}

static double p50(const cJSON *root, const char *object, const char *key)
{
    const cJSON *o = cJSON_GetObjectItemCaseSensitive(root, object);
    const cJSON *v = o ? cJSON_GetObjectItemCaseSensitive(o, key) : NULL;
    const cJSON *p = v ? cJSON_GetObjectItemCaseSensitive(v, "p50") : NULL;
    return cJSON_IsNumber(p) ? p->valuedouble : -1;
}

/* Runs fulgur run on scene, the report into report; returns its exit code. */
static int run(const char *fulgur, const char *scene, const char *report)
{
    char *argv[] = {(char *)fulgur, "run", (char *)scene, "--audio", "null", "--block", "128",
                    "--seconds", RUN_SECONDS, "--report", (char *)report, NULL};
    pid_t pid;
    if (posix_spawn(&pid, fulgur, NULL, NULL, argv, environ) != 0)
        return -1;
    int status;
    if (waitpid(pid, &status, 0) < 0)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static cJSON *read_report(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    static char text[1 << 16];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = 0;
    return cJSON_Parse(text);
}

int main(int argc, char **argv)
{
    const char *fulgur = argc > 1 ? argv[1] : FULGUR_BIN;
    char dir[] = "/tmp/fulgur-latency-XXXXXX";
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    char cpu[256], scene[512], report[512];
    bench_machine(cpu, sizeof cpu);
    snprintf(scene, sizeof scene, "%s/scene.json", dir);
    snprintf(report, sizeof report, "%s/report.json", dir);
    FILE *csv = bench_open_result("latency.csv");
    fprintf(csv, "# %s; fulgur run, null device paced at 48 kHz, 128-frame blocks, one "
                 "discharge at 0.2001 s per run, %d runs (seeds) per row; late_ms sums the lost samples "
                 "over the late events\n",
            cpu, REPEATS);
    fprintf(csv, "kind,distance_m,runs,late_events_mean,late_events_max,late_ms_mean,"
                 "adoption_ms_p50_mean,event_lag_max_ms,safe_distance_m\n");
    int failed = 0;
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        for (size_t i = 0; i < sizeof distances_m / sizeof distances_m[0]; i++) {
            double events = 0, events_max = 0, lost_ms = 0, adoption_ms = 0, lag_ms = 0, safe_m = 0;
            int runs = 0;
            for (int rep = 0; rep < REPEATS; rep++) {
                FILE *f = fopen(scene, "w");
                if (!f)
                    return 1;
                fprintf(f, "{\"sample_rate\":48000,\"block\":128,\"seed\":%d,"
                           "\"listener\":{\"position\":[0,0,1.7]},\"discharges\":[",
                        rep + 1);
                fprintf(f, kinds[k].discharge, distances_m[i]);
                fprintf(f, "]}\n");
                fclose(f);
                cJSON *r = run(fulgur, scene, report) == 0 ? read_report(report) : NULL;
                if (!r) {
                    fprintf(stderr, "latency: %s at %g m: no report\n", kinds[k].name,
                            distances_m[i]);
                    failed = 1;
                    continue;
                }
                double e = number(r, "late", "events");
                events += e;
                events_max = e > events_max ? e : events_max;
                lost_ms += number(r, "late", "samples") / 48.0;
                adoption_ms += p50(r, "adoption", "latency_ms");
                double lag = number(r, "adoption", "event_lag_max_ms");
                lag_ms = lag > lag_ms ? lag : lag_ms;
                double safe = number(r, "adoption", "safe_distance_m");
                safe_m = safe > safe_m ? safe : safe_m;
                runs++;
                cJSON_Delete(r);
            }
            if (runs == 0)
                continue;
            fprintf(csv, "%s,%g,%d,%.2f,%.0f,%.3f,%.3f,%.3f,%.3f\n", kinds[k].name, distances_m[i],
                    runs, events / runs, events_max, lost_ms / runs, adoption_ms / runs, lag_ms,
                    safe_m);
            printf("%-9s %6g m: late events %6.1f (max %3.0f, %.2f ms lost), adoption %.3f ms\n",
                   kinds[k].name, distances_m[i], events / runs, events_max, lost_ms / runs,
                   adoption_ms / runs);
        }
    }
    fclose(csv);
    remove(scene);
    remove(report);
    rmdir(dir);
    return failed;
}
