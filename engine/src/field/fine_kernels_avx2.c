/* fine_kernels.c built for AVX2 (kernels_avx2.h). */
#include "kernels_avx2.h"

#include "fine_kernels.c"
