/* libsndfile for the fulgur program, opened on the first call
 * (lazy_library.h): reading WAV files (analyze, a scene's clips), and
 * writing RF64 or a calibrated WAV (audio_file.h); a plain WAV render
 * does not call it. */
#include <pthread.h>
#include <sndfile.h>

#include "lazy_library.h"

static struct {
    __typeof__(sf_open_virtual) *open_virtual;
    __typeof__(sf_open_fd) *open_fd;
    __typeof__(sf_close) *close;
    __typeof__(sf_strerror) *strerror;
    __typeof__(sf_command) *command;
    __typeof__(sf_readf_float) *readf_float;
    __typeof__(sf_writef_float) *writef_float;
    __typeof__(sf_set_string) *set_string;
    __typeof__(sf_get_string) *get_string;
} api;

static pthread_once_t once = PTHREAD_ONCE_INIT;

static void load(void)
{
    const library_symbol symbols[] = {
        LIBRARY_SYMBOL(api.open_virtual, sf_open_virtual),
        LIBRARY_SYMBOL(api.open_fd, sf_open_fd),
        LIBRARY_SYMBOL(api.close, sf_close),
        LIBRARY_SYMBOL(api.strerror, sf_strerror),
        LIBRARY_SYMBOL(api.command, sf_command),
        LIBRARY_SYMBOL(api.readf_float, sf_readf_float),
        LIBRARY_SYMBOL(api.writef_float, sf_writef_float),
        LIBRARY_SYMBOL(api.set_string, sf_set_string),
        LIBRARY_SYMBOL(api.get_string, sf_get_string),
    };
    lazy_library_load(FULGUR_SNDFILE_SONAME, symbols, sizeof symbols / sizeof symbols[0]);
}

SNDFILE *sf_open_virtual(SF_VIRTUAL_IO *io, int mode, SF_INFO *info, void *user)
{
    pthread_once(&once, load);
    return api.open_virtual(io, mode, info, user);
}

SNDFILE *sf_open_fd(int fd, int mode, SF_INFO *info, int close_desc)
{
    pthread_once(&once, load);
    return api.open_fd(fd, mode, info, close_desc);
}

int sf_close(SNDFILE *file)
{
    pthread_once(&once, load);
    return api.close(file);
}

const char *sf_strerror(SNDFILE *file)
{
    pthread_once(&once, load);
    return api.strerror(file);
}

int sf_command(SNDFILE *file, int command, void *data, int size)
{
    pthread_once(&once, load);
    return api.command(file, command, data, size);
}

sf_count_t sf_readf_float(SNDFILE *file, float *frames, sf_count_t count)
{
    pthread_once(&once, load);
    return api.readf_float(file, frames, count);
}

sf_count_t sf_writef_float(SNDFILE *file, const float *frames, sf_count_t count)
{
    pthread_once(&once, load);
    return api.writef_float(file, frames, count);
}

int sf_set_string(SNDFILE *file, int type, const char *text)
{
    pthread_once(&once, load);
    return api.set_string(file, type, text);
}

const char *sf_get_string(SNDFILE *file, int type)
{
    pthread_once(&once, load);
    return api.get_string(file, type);
}
