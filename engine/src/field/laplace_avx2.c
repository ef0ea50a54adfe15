/* laplace.c built for AVX2 (kernels_avx2.h). */
#include "kernels_avx2.h"

#include "laplace.c"
