/* The AVX2 build's kernels (kernels_avx2.h) as the solver calls them. */
#include "kernels_avx2.h"
#include "field_internal.h"

const fg_field_kernels fg_field_kernels_avx2 = {
    fg_lap_residual,   fg_lap_correct_residual,   fg_fine_smooth,
    fg_fine_residual,  fg_coarse_sweep_from_zero, fg_coarse_sweep,
    fg_coarse_residual, fg_restrict,              fg_prolong_add,
};
