#include <stdbool.h>

#include "bench_util.h"
#include "core/bus_internal.h"
#include "dsp/convolver_internal.h"
#include "stage_time.h"

static bool timing;
static bench_stages sums;

uint64_t __real_fg_bus_set_end(fg_bus_set *s, float *const *out, uint32_t n);
uint64_t __wrap_fg_bus_set_end(fg_bus_set *s, float *const *out, uint32_t n);
void __real_fg_convolver_process(fg_convolver *c, const float *const *in, float *const *out,
                                 size_t n);
void __wrap_fg_convolver_process(fg_convolver *c, const float *const *in, float *const *out,
                                 size_t n);

uint64_t __wrap_fg_bus_set_end(fg_bus_set *s, float *const *out, uint32_t n)
{
    if (!timing)
        return __real_fg_bus_set_end(s, out, n);
    double t0 = bench_cpu_s();
    uint64_t dropped = __real_fg_bus_set_end(s, out, n);
    sums.buses_s += bench_cpu_s() - t0;
    return dropped;
}

void __wrap_fg_convolver_process(fg_convolver *c, const float *const *in, float *const *out,
                                 size_t n)
{
    if (!timing) {
        __real_fg_convolver_process(c, in, out, n);
        return;
    }
    double t0 = bench_cpu_s();
    __real_fg_convolver_process(c, in, out, n);
    sums.convolve_s += bench_cpu_s() - t0;
}

void bench_stages_start(void)
{
    sums = (bench_stages){0};
    timing = true;
}

bench_stages bench_stages_stop(void)
{
    timing = false;
    return sums;
}
