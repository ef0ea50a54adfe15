/* The filter buses (core/bus_internal.h): a channel costs a filter only
 * while it sounds. A band bus fed one block filters exactly as its ISO
 * 9613-1 filter does alone, its tail ends once the filter's states fall
 * below the floor (what is dropped stays under 1e-10 Pa), and the bus then
 * writes nothing until its next input; channels never fed are never
 * written. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "air/band_filters_internal.h"
#include "core/bus_internal.h"

#define FS 48000.0
#define BLOCK 512u
#define CHANNELS 3u
#define BLOCKS 40u
#define IMPULSE_PA 100.0f
#define DROPPED_MAX_PA 1e-10

/* The farthest band (the slowest poles) and a near one. */
static const unsigned bands[] = {FG_ABSORPTION_BANDS - 1, 10};

static void test_tail_ends(void **state)
{
    (void)state;
    const fg_air air = FG_AIR_DEFAULT;
    for (size_t t = 0; t < sizeof bands / sizeof bands[0]; t++) {
        const unsigned band = bands[t], bus = FG_BUS_BAND0 + band, fed = 1;
        fg_bus_set *s = calloc(1, sizeof *s);
        assert_non_null(s);
        assert_int_equal(fg_bus_set_init(s, CHANNELS, BLOCK, 0, FS, 343.0, 0.0, &air), FG_OK);
        fg_bus_set_design_bands(s);
        /* the same filter alone, run without end over the whole signal */
        fg_iir alone[FG_ABSORPTION_BANDS];
        fg_band_filters_design(&air, s->plan.centre_m, FG_ABSORPTION_BANDS, FS, alone);
        static float ref[BLOCKS * BLOCK], got[CHANNELS][BLOCKS * BLOCK];
        memset(ref, 0, sizeof ref);
        ref[7] = IMPULSE_PA;
        fg_iir_process(&alone[band], ref, BLOCKS * BLOCK);

        unsigned last_written = 0;
        for (unsigned k = 0; k < BLOCKS; k++) {
            float *out[CHANNELS];
            for (unsigned c = 0; c < CHANNELS; c++) {
                out[c] = got[c] + k * BLOCK;
                memset(out[c], 0, BLOCK * sizeof(float));
            }
            fg_bus_set_begin(s, BLOCK, FG_CHUNK_CARRY);
            if (k == 0)
                fg_bus_pre(s, bus, fed)[7] = IMPULSE_PA;
            assert_int_equal(fg_bus_set_end(s, out, BLOCK), 0);
            assert_true((s->written & ~((fg_channel_mask)1 << fed)) == 0);
            if (s->written)
                last_written = k;
        }
        /* it stopped within a block of the time the slowest pole takes to
         * fall from the impulse to the floor (not to iir.c's 1e-30) */
        double radius = 0.0;
        for (unsigned q = 0; q < alone[band].sections; q++) {
            const fg_biquad *b = &alone[band].sec[q];
            double disc = b->a1 * b->a1 - 4.0 * b->a2;
            double r = disc < 0.0 ? sqrt(b->a2)
                                  : fmax(fabs(-b->a1 + sqrt(disc)), fabs(-b->a1 - sqrt(disc))) / 2.0;
            radius = fmax(radius, r);
        }
        double fall = log(IMPULSE_PA / FG_BUS_TAIL_FLOOR_PA) / -log(radius);
        unsigned bound = (unsigned)ceil((7.0 + fall) / BLOCK) + 1;
        print_message("band %u: pole radius %.4f, tail written to block %u (bound %u)\n", band,
                      radius, last_written, bound);
        assert_true(last_written <= bound);
        assert_true(s->ringing[bus] == 0);
        const size_t cut = (size_t)(last_written + 1) * BLOCK;
        for (size_t i = 0; i < BLOCKS * BLOCK; i++) {
            if (i < cut && got[fed][i] != ref[i])
                fail_msg("band %u, sample %zu: %.9g, alone %.9g", band, i, got[fed][i], ref[i]);
            if (i >= cut && (got[fed][i] != 0.0f || fabs(ref[i]) >= DROPPED_MAX_PA))
                fail_msg("band %u, sample %zu after the tail's end: %.3g, alone %.3g", band, i,
                         got[fed][i], ref[i]);
            assert_true(got[0][i] == 0.0f && got[2][i] == 0.0f);
        }
        fg_bus_set_deinit(s);
        free(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tail_ends),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
