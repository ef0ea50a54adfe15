/* FFTW and its threads library for the fulgur program, opened on the first
 * call (lazy_library.h): the HRIR equalization and fulgur analyze. */
#include <fftw3.h>
#include <pthread.h>

#include "lazy_library.h"

static struct {
    __typeof__(fftw_plan_dft_r2c_1d) *plan_dft_r2c_1d;
    __typeof__(fftw_plan_dft_c2r_1d) *plan_dft_c2r_1d;
    __typeof__(fftw_execute) *execute;
    __typeof__(fftw_destroy_plan) *destroy_plan;
    __typeof__(fftw_malloc) *malloc;
    __typeof__(fftw_free) *free;
    __typeof__(fftw_alloc_real) *alloc_real;
    __typeof__(fftw_alloc_complex) *alloc_complex;
    __typeof__(fftw_make_planner_thread_safe) *make_planner_thread_safe;
} api;

static pthread_once_t once = PTHREAD_ONCE_INIT;

static void load(void)
{
    const library_symbol symbols[] = {
        LIBRARY_SYMBOL(api.plan_dft_r2c_1d, fftw_plan_dft_r2c_1d),
        LIBRARY_SYMBOL(api.plan_dft_c2r_1d, fftw_plan_dft_c2r_1d),
        LIBRARY_SYMBOL(api.execute, fftw_execute),
        LIBRARY_SYMBOL(api.destroy_plan, fftw_destroy_plan),
        LIBRARY_SYMBOL(api.malloc, fftw_malloc),
        LIBRARY_SYMBOL(api.free, fftw_free),
        LIBRARY_SYMBOL(api.alloc_real, fftw_alloc_real),
        LIBRARY_SYMBOL(api.alloc_complex, fftw_alloc_complex),
    };
    lazy_library_load(FULGUR_FFTW_SONAME, symbols, sizeof symbols / sizeof symbols[0]);
    /* its threads library needs FFTW, opened above */
    const library_symbol threads[] = {
        LIBRARY_SYMBOL(api.make_planner_thread_safe, fftw_make_planner_thread_safe),
    };
    lazy_library_load(FULGUR_FFTW_THREADS_SONAME, threads, 1);
}

fftw_plan fftw_plan_dft_r2c_1d(int n, double *in, fftw_complex *out, unsigned flags)
{
    pthread_once(&once, load);
    return api.plan_dft_r2c_1d(n, in, out, flags);
}

fftw_plan fftw_plan_dft_c2r_1d(int n, fftw_complex *in, double *out, unsigned flags)
{
    pthread_once(&once, load);
    return api.plan_dft_c2r_1d(n, in, out, flags);
}

void fftw_execute(const fftw_plan plan)
{
    pthread_once(&once, load);
    api.execute(plan);
}

void fftw_destroy_plan(fftw_plan plan)
{
    pthread_once(&once, load);
    api.destroy_plan(plan);
}

void *fftw_malloc(size_t size)
{
    pthread_once(&once, load);
    return api.malloc(size);
}

void fftw_free(void *p)
{
    pthread_once(&once, load);
    api.free(p);
}

double *fftw_alloc_real(size_t n)
{
    pthread_once(&once, load);
    return api.alloc_real(n);
}

fftw_complex *fftw_alloc_complex(size_t n)
{
    pthread_once(&once, load);
    return api.alloc_complex(n);
}

void fftw_make_planner_thread_safe(void)
{
    pthread_once(&once, load);
    api.make_planner_thread_safe();
}
