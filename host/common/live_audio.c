/* The live device's common part: the backend table, loading a backend's
 * library, chunking, queries. */
#include <stdio.h>
#include <stdlib.h>

#include "live_audio.h"

/* A backend built without its library's headers: live_audio_open says so. */
#ifndef FULGUR_HAVE_JACK
const live_backend live_jack_backend = {"jack", "libjack-jackd2-dev", NULL, NULL, NULL};
#endif
#ifndef FULGUR_HAVE_PORTAUDIO
const live_backend live_portaudio_backend = {"portaudio", "portaudio19-dev", NULL, NULL, NULL};
#endif

live_result live_audio_open(const live_config *config, live_audio **out, char *err,
                            size_t err_size)
{
    live_audio *a = calloc(1, sizeof *a);
    if (!a) {
        snprintf(err, err_size, "out of memory");
        return LIVE_ERROR;
    }
    a->config = *config;
    a->backend = config->kind == LIVE_JACK ? &live_jack_backend : &live_portaudio_backend;
    if (!a->backend->open) {
        snprintf(err, err_size, "--audio %s: this fulgur was built without %s; install it and "
                                "reconfigure", a->backend->driver, a->backend->dev_package);
        free(a);
        return LIVE_ABSENT;
    }
    live_result r = a->backend->open(config, a, err, err_size);
    if (r != LIVE_OK) {
        free(a);
        return r;
    }
    *out = a;
    return LIVE_OK;
}

void *live_library_load(const char *driver, const char *library, const char *package,
                        const library_symbol *symbols, size_t count, char *err, size_t err_size)
{
    char why[512];
    void *lib = library_load(library, symbols, count, why, sizeof why);
    if (!lib)
        snprintf(err, err_size, "--audio %s: %s (Debian: %s)", driver, why, package);
    return lib;
}

double live_audio_rate_hz(const live_audio *a)
{
    return a->rate_hz;
}

uint32_t live_audio_block_frames(const live_audio *a)
{
    return a->block_frames;
}

int live_audio_start(live_audio *a, char *err, size_t err_size)
{
    return a->backend->start(a, err, err_size);
}

uint64_t live_audio_xruns(const live_audio *a)
{
    return a->xruns;
}

int live_audio_lost(const live_audio *a)
{
    return a->lost;
}

const char *live_audio_describe(const live_audio *a)
{
    return a->description;
}

void live_audio_close(live_audio *a)
{
    if (!a)
        return;
    a->backend->close(a);
    free(a);
}

void live_audio_pull(live_audio *a, float *const *planes, uint32_t frames)
{
    uint32_t chunk = a->config.max_chunk_frames;
    for (uint32_t done = 0; done < frames;) {
        uint32_t n = frames - done < chunk ? frames - done : chunk;
        float *at[2] = {planes[0] + done, a->config.channels > 1 ? planes[1] + done : NULL};
        a->config.process(a->config.user, at, n);
        done += n;
    }
}
