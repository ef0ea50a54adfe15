/* The binaural layout's HRIR convolution alone (engine/src/dsp/convolver):
 * its shape, 50 loudspeaker inputs to 2 ears through 558-tap responses
 * (the MIT KEMAR set's length at 48 kHz) in its partitions
 * (FG_BINAURAL_LATENCY_FRAMES), fed
 * 512-frame calls of noise on 50, 10, 4 or 1 of the inputs (the others
 * silent, so skipped), through the multiply-add kernel and transform init
 * chooses for this CPU (AVX2 and FMA: spectrum_mac's and fft_avx2's) and
 * through the portable ones (fft_lanes.c's). The median of 5 runs of 10 s of
 * sound each, in the thread's CPU time, as ms per s of sound. Writes
 * bench/results/convolver.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "dsp/convolver_internal.h"
#include "fg_rng.h"
#include "fulgur/engine.h"

#define INPUTS 50
#define TAPS 558
#define BLOCK FG_BINAURAL_LATENCY_FRAMES
#define CALL 512
#define SECONDS 10
#define REPEATS 5
#define FS 48000.0

static double run_ms_per_s(fg_convolver *c, const float *const *in, float *const *out)
{
    double t0 = bench_cpu_s();
    size_t calls = (size_t)(SECONDS * FS) / CALL;
    for (size_t k = 0; k < calls; k++)
        fg_convolver_process(c, in, out, CALL);
    return 1e3 * (bench_cpu_s() - t0) / ((double)(calls * CALL) / FS);
}

int main(void)
{
    static double h[INPUTS * 2 * TAPS];
    static float x[INPUTS][CALL], y[2][CALL];
    fg_rng rng;
    fg_rng_seed(&rng, 3);
    for (size_t k = 0; k < INPUTS * 2 * TAPS; k++)
        h[k] = fg_rng_range(&rng, -1.0, 1.0) * exp(-(double)(k % TAPS) / 100.0);
    const float *in[INPUTS];
    float *out[2] = {y[0], y[1]};
    for (unsigned i = 0; i < INPUTS; i++)
        in[i] = x[i];
    static const unsigned sounding[] = {50, 10, 4, 1};
    char machine[256];
    bench_machine(machine, sizeof machine);
    FILE *csv = bench_open_result("convolver.csv");
    fprintf(csv,
            "# %s; the binaural convolver: %d inputs, 2 outputs, %d taps, %d-frame partitions, "
            "%d-frame calls of noise on the sounding inputs, median of %d runs of %d s, thread "
            "CPU time\n",
            machine, INPUTS, TAPS, (int)BLOCK, CALL, REPEATS, SECONDS);
    fprintf(csv, "sounding,kernel,ms_per_s\n");
    for (size_t s = 0; s < sizeof sounding / sizeof sounding[0]; s++) {
        for (unsigned i = 0; i < INPUTS; i++)
            for (size_t t = 0; t < CALL; t++)
                x[i][t] = i < sounding[s] ? (float)fg_rng_range(&rng, -1.0, 1.0) : 0.0f;
        for (int plain = 0; plain < 2; plain++) {
            double ms[REPEATS];
            for (int r = 0; r < REPEATS; r++) {
                fg_convolver c;
                if (!fg_convolver_init(&c, INPUTS, 2, TAPS, BLOCK, h)) {
                    fprintf(stderr, "bench_convolver: out of memory\n");
                    return 1;
                }
                if (plain) {
                    c.mac = fg_spectrum_mac_plain;
                    c.fft_avx2 = false;
                }
                const char *kernel = c.mac == fg_spectrum_mac_plain ? "portable" : "avx2+fma";
                ms[r] = run_ms_per_s(&c, in, out);
                fg_convolver_deinit(&c);
                if (r == REPEATS - 1) {
                    double med = bench_median(ms, REPEATS);
                    printf("%2u of %d inputs sounding, %-8s kernel: %7.3f ms per s of sound\n",
                           sounding[s], INPUTS, kernel, med);
                    fprintf(csv, "%u,%s,%.3f\n", sounding[s], kernel, med);
                }
            }
        }
    }
    fclose(csv);
    return 0;
}
