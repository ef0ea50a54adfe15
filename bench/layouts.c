/* What each output layout costs (docs/spatial.md): a lightning bolt of
 * 9 860 segments (the issue's) heard from 3 km, rendered in each layout,
 * with and without the ISO 9613-1 distance buses, in 512-frame blocks at
 * 48 kHz; binaural through the MIT KEMAR set that Debian's libmysofa1
 * installs (or the SOFA file named as the first argument). The layouts
 * take turns within each repeat (paired runs); the medians of the render's
 * CPU time give the cost per second of sound and its ratio to stereo.
 * The cost split, from separate runs with the buses timed by stage
 * (stage_time.h, CPU time): "buses" is fg_bus_set_end (the accumulators integrated and the
 * distance filters run, per block, bus and channel), "convolve" the
 * binaural decoder's HRIR convolution (per block and loudspeaker with
 * sound), and "encode" the rest: the sources' waves added into the buses
 * (per wave and channel it reaches). Writes bench/results/layouts.csv. */
#include <stdio.h>
#include <stdlib.h>

#include "bench_render.h"
#include "bench_util.h"
#include "sofa_hrir.h"
#include "stage_time.h"
#include "synth_tree.h"

#define SEGMENTS 9860
#define REPEATS 15
#define BLOCK 512

typedef struct layout_case {
    const char *name;
    fg_layout layout;
    uint32_t order;
    int head_shadow;
} layout_case;

static const layout_case cases[] = {
    {"stereo", FG_LAYOUT_STEREO, 0, 0},
    {"stereo, head shadow", FG_LAYOUT_STEREO, 0, 1},
    {"ambisonics order 1", FG_LAYOUT_AMBISONICS, 1, 0},
    {"ambisonics order 2", FG_LAYOUT_AMBISONICS, 2, 0},
    {"ambisonics order 3", FG_LAYOUT_AMBISONICS, 3, 0},
    {"binaural", FG_LAYOUT_BINAURAL, 0, 0},
};
enum { CASES = sizeof cases / sizeof cases[0] };

static unsigned channels(const layout_case *c)
{
    return c->layout == FG_LAYOUT_AMBISONICS ? (c->order + 1) * (c->order + 1) : 2;
}

int main(int argc, char **argv)
{
    const char *sofa = argc > 1 ? argv[1] : SOFA_DEFAULT_FILE;
    sofa_hrirs kemar;
    char err[512];
    if (sofa_hrirs_read(sofa, 48000.0, &kemar, err, sizeof err) != 0) {
        fprintf(stderr, "bench_layouts: %s\n", err);
        return 1;
    }
    fg_sound_config p;
    fg_node *nodes = synth_far_bolt(SEGMENTS);
    if (fg_preset_sound(FG_PRESET_LIGHTNING, &p) != FG_OK || !nodes)
        return 1;
    fg_listener head = {.position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
    static double plain[CASES][REPEATS], bands[CASES][REPEATS];
    static double buses[CASES][REPEATS], conv[CASES][REPEATS], total[CASES][REPEATS];
    double sound_s = 0;
    for (int k = 0; k < REPEATS; k++) {
        for (int c = 0; c < CASES; c++) {
            const fg_hrir_set *h = cases[c].layout == FG_LAYOUT_BINAURAL ? &kemar.set : NULL;
            for (int air = 0; air < 3; air++) {
                /* 0: no absorption, 1: the ISO 9613-1 buses, 2: the same timed by stage */
                fg_propagation_config prop = {.head_shadow = cases[c].head_shadow,
                                              .absorption = air ? FG_ABSORPTION_ISO9613
                                                                : FG_ABSORPTION_OFF};
                if (air == 2)
                    bench_stages_start();
                bench_run r = bench_render_tree_layout(nodes, SEGMENTS + 1, &p, &prop, FG_MODEL_WM,
                                                       cases[c].layout, cases[c].order, h, &head,
                                                       BLOCK);
                if (air == 2) {
                    bench_stages st = bench_stages_stop();
                    buses[c][k] = st.buses_s;
                    conv[c][k] = st.convolve_s;
                    total[c][k] = r.render_cpu_s;
                } else {
                    (air ? bands : plain)[c][k] = r.render_cpu_s;
                }
                sound_s = r.sound_s;
            }
        }
    }
    char cpu[256];
    bench_machine(cpu, sizeof cpu);
    FILE *csv = bench_open_result("layouts.csv");
    fprintf(csv, "# %s; %d segments heard from 3 km, 48 kHz, %d-frame blocks, median of %d "
                 "paired runs of the render's CPU time; plain = without absorption, iso9613 = "
                 "with the ISO 9613-1 buses; the split (with the buses, CPU time, its own "
                 "runs): encode = the sources into the buses, buses = fg_bus_set_end, convolve = "
                 "the binaural HRIR convolution; binaural through %s\n",
            cpu, SEGMENTS, BLOCK, REPEATS, sofa);
    fprintf(csv, "layout,channels,plain_ms_per_s,iso9613_ms_per_s,ns_per_segment,"
                 "ratio_to_stereo_plain,ratio_to_stereo_iso9613,encode_ms_per_s,buses_ms_per_s,"
                 "convolve_ms_per_s\n");
    double base = 0, base_air = 0;
    for (int c = 0; c < CASES; c++) {
        double enc = 1e3 * bench_median(plain[c], REPEATS) / sound_s;
        double air = 1e3 * bench_median(bands[c], REPEATS) / sound_s;
        double split_bus = 1e3 * bench_median(buses[c], REPEATS) / sound_s;
        double split_conv = 1e3 * bench_median(conv[c], REPEATS) / sound_s;
        double split_total = 1e3 * bench_median(total[c], REPEATS) / sound_s;
        double split_enc = split_total - split_bus - split_conv;
        if (c == 0) {
            base = enc;
            base_air = air;
        }
        double per_seg = 1e6 * air * sound_s / SEGMENTS;
        fprintf(csv, "%s,%u,%.3f,%.3f,%.1f,%.2f,%.2f,%.3f,%.3f,%.3f\n", cases[c].name,
                channels(&cases[c]), enc, air, per_seg, enc / base, air / base_air, split_enc,
                split_bus, split_conv);
        printf("%-20s %2u ch: %7.3f ms/s plain, %7.3f with ISO 9613-1 (%6.1f ns/segment); "
               "x%.2f stereo plain, x%.2f with the buses; split: encode %.3f, buses %.3f, "
               "convolve %.3f ms/s\n",
               cases[c].name, channels(&cases[c]), enc, air, per_seg, enc / base, air / base_air,
               split_enc, split_bus, split_conv);
    }
    fclose(csv);
    free(nodes);
    sofa_hrirs_free(&kemar);
    return 0;
}
