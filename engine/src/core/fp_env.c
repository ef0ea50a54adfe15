#include "fp_env_internal.h"

#if defined(__SSE2__)
#include <xmmintrin.h>
/* MXCSR: flush-to-zero (bit 15) and denormals-are-zero (bit 6) */
#define FTZ_DAZ 0x8040u

fg_fp_env fg_fp_env_flush_denormals(void)
{
    fg_fp_env env = {_mm_getcsr()};
    _mm_setcsr((unsigned)env.saved | FTZ_DAZ);
    return env;
}

void fg_fp_env_restore(fg_fp_env env)
{
    _mm_setcsr((unsigned)env.saved);
}
#elif defined(__aarch64__)
/* FPCR.FZ, bit 24 */
#define FPCR_FZ (1ul << 24)

fg_fp_env fg_fp_env_flush_denormals(void)
{
    fg_fp_env env;
    __asm__ volatile("mrs %0, fpcr" : "=r"(env.saved));
    __asm__ volatile("msr fpcr, %0" : : "r"(env.saved | FPCR_FZ));
    return env;
}

void fg_fp_env_restore(fg_fp_env env)
{
    __asm__ volatile("msr fpcr, %0" : : "r"(env.saved));
}
#else
/* No portable control: denormals are left as the platform handles them. */
fg_fp_env fg_fp_env_flush_denormals(void)
{
    return (fg_fp_env){0};
}

void fg_fp_env_restore(fg_fp_env env)
{
    (void)env;
}
#endif
