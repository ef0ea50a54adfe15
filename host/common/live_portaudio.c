/* The PortAudio backend: libportaudio opened with dlopen (live_audio.h
 * says why), a non-interleaved float output stream whose callback pulls
 * the engine. */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <portaudio.h>

#include "live_audio.h"

#define PORTAUDIO_LIBRARY "libportaudio.so.2"

typedef struct pa_api {
    void *lib;
    __typeof__(Pa_Initialize) *initialize;
    __typeof__(Pa_Terminate) *terminate;
    __typeof__(Pa_GetErrorText) *error_text;
    __typeof__(Pa_GetDeviceCount) *device_count;
    __typeof__(Pa_GetDeviceInfo) *device_info;
    __typeof__(Pa_GetDefaultOutputDevice) *default_output;
    __typeof__(Pa_GetHostApiInfo) *host_api_info;
    __typeof__(Pa_OpenStream) *open_stream;
    __typeof__(Pa_StartStream) *start_stream;
    __typeof__(Pa_StopStream) *stop_stream;
    __typeof__(Pa_CloseStream) *close_stream;
} pa_api;

typedef struct pa_state {
    pa_api api;
    PaStream *stream;
} pa_state;

static int load(pa_api *api, char *err, size_t err_size)
{
    const library_symbol symbols[] = {
        LIBRARY_SYMBOL(api->initialize, Pa_Initialize),
        LIBRARY_SYMBOL(api->terminate, Pa_Terminate),
        LIBRARY_SYMBOL(api->error_text, Pa_GetErrorText),
        LIBRARY_SYMBOL(api->device_count, Pa_GetDeviceCount),
        LIBRARY_SYMBOL(api->device_info, Pa_GetDeviceInfo),
        LIBRARY_SYMBOL(api->default_output, Pa_GetDefaultOutputDevice),
        LIBRARY_SYMBOL(api->host_api_info, Pa_GetHostApiInfo),
        LIBRARY_SYMBOL(api->open_stream, Pa_OpenStream),
        LIBRARY_SYMBOL(api->start_stream, Pa_StartStream),
        LIBRARY_SYMBOL(api->stop_stream, Pa_StopStream),
        LIBRARY_SYMBOL(api->close_stream, Pa_CloseStream),
    };
    api->lib = live_library_load("portaudio", PORTAUDIO_LIBRARY, "libportaudio2", symbols,
                                 sizeof symbols / sizeof symbols[0], err, err_size);
    return api->lib ? 0 : -1;
}

/* ALSA and libjack, which PortAudio loads, print a screenful while it looks
 * for devices on a machine without them; fulgur's own message says what
 * was found. Their handlers are set when those libraries are loaded. */
static void alsa_quiet(const char *file, int line, const char *function, int err,
                       const char *format, ...)
{
    (void)file, (void)line, (void)function, (void)err, (void)format;
}

static void jack_quiet(const char *message)
{
    (void)message;
}

static void silence_backends(void)
{
    void *alsa = dlopen("libasound.so.2", RTLD_LAZY | RTLD_NOLOAD);
    if (alsa) {
        int (*set)(void (*)(const char *, int, const char *, int, const char *, ...));
        if ((*(void **)&set = dlsym(alsa, "snd_lib_error_set_handler")))
            set(alsa_quiet);
        dlclose(alsa);
    }
    void *jack = dlopen("libjack.so.0", RTLD_LAZY | RTLD_NOLOAD);
    if (jack) {
        void (*set)(void (*)(const char *));
        if ((*(void **)&set = dlsym(jack, "jack_set_error_function")))
            set(jack_quiet);
        if ((*(void **)&set = dlsym(jack, "jack_set_info_function")))
            set(jack_quiet);
        dlclose(jack);
    }
}

/* [audio-thread] PortAudio's callback thread. */
static int callback(const void *input, void *output, unsigned long frames,
                    const PaStreamCallbackTimeInfo *time, PaStreamCallbackFlags flags, void *arg)
{
    (void)input, (void)time;
    live_audio *a = arg;
    if (flags & (paOutputUnderflow | paOutputOverflow))
        a->xruns++;
    float *const *planes = output; /* paNonInterleaved */
    live_audio_pull(a, planes, (uint32_t)frames);
    return paContinue;
}

/* The device: the default output, or the first whose name contains target. */
static PaDeviceIndex find_device(const pa_api *api, const char *target, char *err, size_t err_size)
{
    if (!target) {
        PaDeviceIndex d = api->default_output();
        if (d == paNoDevice)
            snprintf(err, err_size, "--audio portaudio: no output device here (no sound card or "
                                    "sound server; --audio jack with jackd -d dummy plays without one)");
        return d;
    }
    int count = api->device_count();
    size_t used = (size_t)snprintf(err, err_size,
                                   "--audio portaudio:%s: no output device of that name; there are:",
                                   target);
    for (int i = 0; i < count; i++) {
        const PaDeviceInfo *info = api->device_info(i);
        if (!info || info->maxOutputChannels < 1)
            continue;
        if (strstr(info->name, target))
            return i;
        if (used < err_size)
            used += (size_t)snprintf(err + used, err_size - used, " \"%s\"", info->name);
    }
    return paNoDevice;
}

static live_result pa_open(const live_config *c, live_audio *a, char *err, size_t err_size)
{
    pa_state *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, err_size, "out of memory");
        return LIVE_ERROR;
    }
    if (load(&s->api, err, err_size) != 0) {
        free(s);
        return LIVE_ABSENT;
    }
    /* ALSA prints while PortAudio initialises: quiet it first if it is
     * loaded already, and again after for libjack */
    silence_backends();
    PaError e = s->api.initialize();
    silence_backends();
    if (e != paNoError) {
        snprintf(err, err_size, "--audio portaudio: %s", s->api.error_text(e));
        free(s);
        return LIVE_ERROR;
    }
    PaDeviceIndex device = find_device(&s->api, c->target, err, err_size);
    if (device == paNoDevice) {
        s->api.terminate();
        free(s);
        return LIVE_ABSENT;
    }
    const PaDeviceInfo *info = s->api.device_info(device);
    PaStreamParameters out = {
        .device = device,
        .channelCount = (int)c->channels,
        .sampleFormat = paFloat32 | paNonInterleaved,
        .suggestedLatency = info->defaultLowOutputLatency,
    };
    e = s->api.open_stream(&s->stream, NULL, &out, c->rate_hz, c->block_frames, paNoFlag,
                           callback, a);
    if (e != paNoError) {
        snprintf(err, err_size, "--audio portaudio: %s at %.0f Hz, %u channels: %s", info->name,
                 c->rate_hz, (unsigned)c->channels, s->api.error_text(e));
        s->api.terminate();
        free(s);
        return LIVE_ERROR;
    }
    a->impl = s;
    a->rate_hz = c->rate_hz;
    a->block_frames = c->block_frames;
    const PaHostApiInfo *host = s->api.host_api_info(info->hostApi);
    snprintf(a->description, sizeof a->description, "PortAudio %s: %s, %.0f Hz, %u frames",
             host ? host->name : "?", info->name, a->rate_hz, (unsigned)a->block_frames);
    return LIVE_OK;
}

static int pa_start(live_audio *a, char *err, size_t err_size)
{
    pa_state *s = a->impl;
    PaError e = s->api.start_stream(s->stream);
    if (e != paNoError) {
        snprintf(err, err_size, "--audio portaudio: %s", s->api.error_text(e));
        return -1;
    }
    return 0;
}

static void pa_close(live_audio *a)
{
    pa_state *s = a->impl;
    s->api.stop_stream(s->stream);
    s->api.close_stream(s->stream);
    s->api.terminate();
    free(s);
}

const live_backend live_portaudio_backend = {"portaudio", "portaudio19-dev", pa_open, pa_start,
                                             pa_close};
