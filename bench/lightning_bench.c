/* Time to generate lightning trees: the statistical lightning preset (a
 * random ~5 km cloud-to-ground skeleton walked in 2 l = 3 m segments, with
 * branches), the same with a clap/rumble/roar design, and a point-charge
 * leader over a similar height. Median over RUNS seeds; the mean segment
 * count is set against Matsuyama table 2 (9438). Writes
 * bench/results/lightning_gen.csv. Goal: ~10 000 segments in <= 100 ms. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fulgur/fulgur.h"

#define RUNS 101
#define TABLE2_SEGMENTS 9438

typedef fg_result (*gen)(uint64_t seed, double step_m, fg_tree *t);

static fg_result statistical(uint64_t seed, double step_m, fg_tree *t)
{
    fg_lightning_config p = {.segment_m = step_m, .seed = seed};
    return fg_lightning_generate(&p, t, NULL);
}

static fg_result designed(uint64_t seed, double step_m, fg_tree *t)
{
    const fg_thunder_feature features[] = {{FG_THUNDER_ROAR, 0.1, 0.25, 0.5},
                                       {FG_THUNDER_CLAP, 0.3, 0.45, 1},
                                       {FG_THUNDER_RUMBLE, 0.55, 0.8, 1}};
    fg_lightning_config p = {.segment_m = step_m,
                             .features = features,
                             .feature_count = 3,
                             .listener_m = {3000, 0, 1.7},
                             .seed = seed};
    return fg_lightning_generate(&p, t, NULL);
}

static fg_result charges(uint64_t seed, double step_m, fg_tree *t)
{
    static const fg_point_charge cloud[] = {
        {{0, 0, 5500}, -40}, {{0, 0, 8000}, 40}, {{0, 0, -5500}, 40}};
    fg_charges_config p = {.charges = cloud,
                           .charge_count = 3,
                           .start_m = {0, 0, 5000},
                           .step_m = step_m,
                           .seed = seed};
    return fg_charges_grow(&p, t);
}

int main(void)
{
    fg_preset_scale scale;
    if (fg_preset_get_scale(FG_PRESET_LIGHTNING, &scale) != FG_OK)
        return 1;
    double step = 2 * scale.half_step_m;
    const struct {
        const char *name;
        gen fn;
    } gens[] = {{"lightning", statistical}, {"lightning_designed", designed},
                {"charges", charges}};
    FILE *f = bench_open_result("lightning_gen.csv");
    char machine[128];
    bench_machine(machine, sizeof machine);
    fprintf(f, "# %s; one core; %d seeds each; segment %.1f m (2 l of the lightning preset)\n",
            machine, RUNS, step);
    fprintf(f, "# Matsuyama table 2: %d segments on average for lightning\n", TABLE2_SEGMENTS);
    fprintf(f, "generator,runs,median_ms,p90_ms,mean_segments,min_segments,max_segments,"
               "median_ms_per_10k_segments\n");
    fg_tree *t;
    if (fg_tree_create(16384, &t) != FG_OK)
        return 1;
    for (size_t g = 0; g < sizeof gens / sizeof gens[0]; g++) {
        double ms[RUNS], per10k[RUNS], sum = 0;
        size_t lo = (size_t)-1, hi = 0;
        for (int i = 0; i < RUNS; i++) {
            fg_tree_clear(t);
            double t0 = bench_now_s();
            fg_result r = gens[g].fn((uint64_t)i + 1, step, t);
            ms[i] = (bench_now_s() - t0) * 1e3;
            if (r != FG_OK) {
                fprintf(stderr, "%s seed %d: %s\n", gens[g].name, i + 1, fg_result_str(r));
                return 1;
            }
            size_t segs = fg_tree_count(t) - 1;
            per10k[i] = ms[i] * 1e4 / (double)segs;
            sum += (double)segs;
            lo = segs < lo ? segs : lo;
            hi = segs > hi ? segs : hi;
        }
        double median = bench_median(ms, RUNS), p90 = bench_quantile(ms, RUNS, 0.9);
        fprintf(f, "%s,%d,%.3f,%.3f,%.0f,%zu,%zu,%.3f\n", gens[g].name, RUNS, median, p90,
                sum / RUNS, lo, hi, bench_median(per10k, RUNS));
        printf("%-20s median %7.3f ms  p90 %7.3f ms  mean %6.0f segments (table 2: %d)\n",
               gens[g].name, median, p90, sum / RUNS, TABLE2_SEGMENTS);
    }
    fg_tree_destroy(t);
    fclose(f);
    return 0;
}
