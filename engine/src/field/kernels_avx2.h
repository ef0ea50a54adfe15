/* The field solver's vector kernels built again for AVX2. Each of
 * laplace_avx2.c, fine_kernels_avx2.c, coarse_kernels_avx2.c and
 * transfer_avx2.c includes this header and then its portable file; the
 * build compiles them with -mavx2 on x86-64 with GCC or Clang and defines
 * FG_FIELD_AVX2 (engine/CMakeLists.txt). Here the kernels take the AVX2
 * build's names, and util/fg_simd.h's vectors are eight floats wide.
 * kernels_avx2.c puts them in fg_field_kernels_avx2, which
 * fg_field_kernels_pick chooses where the CPU has AVX2. */
#ifndef FULGUR_FIELD_KERNELS_AVX2_H
#define FULGUR_FIELD_KERNELS_AVX2_H

#define FG_SIMD_WIDE 1

#define fg_lap_residual fg_lap_residual_avx2
#define fg_lap_correct_residual fg_lap_correct_residual_avx2
#define fg_fine_smooth fg_fine_smooth_avx2
#define fg_fine_residual fg_fine_residual_avx2
#define fg_coarse_sweep_from_zero fg_coarse_sweep_from_zero_avx2
#define fg_coarse_sweep fg_coarse_sweep_avx2
#define fg_coarse_residual fg_coarse_residual_avx2
#define fg_restrict fg_restrict_avx2
#define fg_prolong_add fg_prolong_add_avx2

#endif
