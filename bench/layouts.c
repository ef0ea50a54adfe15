/* What each output layout costs (docs/spatial.md): a lightning bolt of
 * 9 860 segments heard from 3 km, rendered in each layout, with and
 * without the ISO 9613-1 distance buses, in 512-frame blocks at 48 kHz.
 * The layouts take turns within each repeat (paired runs), and the
 * medians give render time per second of sound and its ratio to stereo.
 * The cost split: without absorption the render is the encoding (one add
 * per wave and channel it reaches); the absorption's extra is the
 * filtering (the band IIRs once per block, bus and channel). Writes
 * bench/results/layouts.csv. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_render.h"
#include "bench_util.h"
#include "synth_tree.h"

#define SEGMENTS 9860
#define REPEATS 5

typedef struct layout_case {
    const char *name;
    fg_layout layout;
    uint32_t order;
    int head_shadow;
} layout_case;

int main(void)
{
    static const layout_case cases[] = {
        {"stereo", FG_LAYOUT_STEREO, 0, 0},
        {"stereo, head shadow", FG_LAYOUT_STEREO, 0, 1},
        {"ambisonics order 1", FG_LAYOUT_AMBISONICS, 1, 0},
        {"ambisonics order 2", FG_LAYOUT_AMBISONICS, 2, 0},
        {"ambisonics order 3", FG_LAYOUT_AMBISONICS, 3, 0},
    };
    enum { CASES = sizeof cases / sizeof cases[0] };
    fg_sound_config p;
    fg_node *nodes = synth_far_bolt(SEGMENTS);
    if (fg_preset_sound(FG_PRESET_LIGHTNING, &p) != FG_OK || !nodes)
        return 1;
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    static double plain[CASES][REPEATS], bands[CASES][REPEATS];
    double sound_s = 0;
    for (int k = 0; k < REPEATS; k++) {
        for (int c = 0; c < CASES; c++) {
            for (int air = 0; air < 2; air++) {
                fg_propagation_config prop = {.head_shadow = cases[c].head_shadow,
                                              .absorption = air ? FG_ABSORPTION_ISO9613
                                                                : FG_ABSORPTION_OFF};
                bench_run r = bench_render_tree_layout(nodes, SEGMENTS + 1, &p, &prop, FG_MODEL_WM,
                                                       cases[c].layout, cases[c].order, &head,
                                                       512);
                (air ? bands : plain)[c][k] = r.render_s;
                sound_s = r.sound_s;
            }
        }
    }
    char cpu[256];
    bench_machine(cpu, sizeof cpu);
    FILE *csv = bench_open_result("layouts.csv");
    fprintf(csv, "# %s; %d segments heard from 3 km, 48 kHz, 512-frame blocks, median of %d "
                 "paired runs; encode = render without absorption, filter = the ISO 9613-1 "
                 "buses' extra\n", cpu, SEGMENTS, REPEATS);
    fprintf(csv, "layout,channels,encode_ms_per_s,encode_ns_per_segment,iso9613_ms_per_s,"
                 "filter_ms_per_s,ratio_to_stereo,ratio_to_stereo_iso9613\n");
    double base = 0, base_air = 0;
    for (int c = 0; c < CASES; c++) {
        double enc = 1e3 * bench_median(plain[c], REPEATS) / sound_s;
        double air = 1e3 * bench_median(bands[c], REPEATS) / sound_s;
        if (c == 0) {
            base = enc;
            base_air = air;
        }
        unsigned ch = cases[c].layout == FG_LAYOUT_AMBISONICS
                          ? (cases[c].order + 1) * (cases[c].order + 1) : 2;
        double per_seg = 1e6 * enc * sound_s / SEGMENTS;
        fprintf(csv, "%s,%u,%.3f,%.1f,%.3f,%.3f,%.2f,%.2f\n", cases[c].name, ch, enc, per_seg,
                air, air - enc, enc / base, air / base_air);
        printf("%-22s %2u ch: encode %7.3f ms/s (%6.1f ns/segment), with ISO 9613-1 %7.3f ms/s "
               "(filter %+7.3f); x%.2f stereo, x%.2f with the buses\n",
               cases[c].name, ch, enc, per_seg, air, air - enc, enc / base, air / base_air);
    }
    fclose(csv);
    free(nodes);
    return 0;
}
