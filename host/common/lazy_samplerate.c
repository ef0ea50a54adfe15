/* libsamplerate for the fulgur program, opened on the first call
 * (lazy_library.h): a SOFA file or a training clip at another rate. */
#include <pthread.h>
#include <samplerate.h>

#include "lazy_library.h"

static struct {
    __typeof__(src_new) *new;
    __typeof__(src_delete) *delete;
    __typeof__(src_process) *process;
    __typeof__(src_reset) *reset;
    __typeof__(src_strerror) *strerror;
} api;

static pthread_once_t once = PTHREAD_ONCE_INIT;

static void load(void)
{
    const library_symbol symbols[] = {
        LIBRARY_SYMBOL(api.new, src_new),           LIBRARY_SYMBOL(api.delete, src_delete),
        LIBRARY_SYMBOL(api.process, src_process),   LIBRARY_SYMBOL(api.reset, src_reset),
        LIBRARY_SYMBOL(api.strerror, src_strerror),
    };
    lazy_library_load(FULGUR_SAMPLERATE_SONAME, symbols, sizeof symbols / sizeof symbols[0]);
}

SRC_STATE *src_new(int converter_type, int channels, int *error)
{
    pthread_once(&once, load);
    return api.new(converter_type, channels, error);
}

SRC_STATE *src_delete(SRC_STATE *state)
{
    pthread_once(&once, load);
    return api.delete(state);
}

int src_process(SRC_STATE *state, SRC_DATA *data)
{
    pthread_once(&once, load);
    return api.process(state, data);
}

int src_reset(SRC_STATE *state)
{
    pthread_once(&once, load);
    return api.reset(state);
}

const char *src_strerror(int error)
{
    pthread_once(&once, load);
    return api.strerror(error);
}
