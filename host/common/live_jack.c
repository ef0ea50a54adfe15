/* The JACK backend: libjack opened with dlopen (live_audio.h says why), a
 * client with one output port per channel, the process callback pulling
 * the engine. */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jack/jack.h>

#include "live_audio.h"

#define JACK_LIBRARY "libjack.so.0"

/* The calls used, resolved once per open. */
typedef struct jack_api {
    void *lib;
    __typeof__(jack_client_open) *client_open;
    __typeof__(jack_client_close) *client_close;
    __typeof__(jack_get_sample_rate) *get_sample_rate;
    __typeof__(jack_get_buffer_size) *get_buffer_size;
    __typeof__(jack_port_register) *port_register;
    __typeof__(jack_port_get_buffer) *port_get_buffer;
    __typeof__(jack_port_name) *port_name;
    __typeof__(jack_set_process_callback) *set_process_callback;
    __typeof__(jack_set_xrun_callback) *set_xrun_callback;
    __typeof__(jack_on_shutdown) *on_shutdown;
    __typeof__(jack_activate) *activate;
    __typeof__(jack_deactivate) *deactivate;
    __typeof__(jack_get_ports) *get_ports;
    __typeof__(jack_connect) *connect;
    __typeof__(jack_free) *free;
    __typeof__(jack_set_error_function) *set_error_function;
    __typeof__(jack_set_info_function) *set_info_function;
} jack_api;

typedef struct jack_state {
    jack_api api;
    jack_client_t *client;
    jack_port_t *ports[2];
} jack_state;

static int load(jack_api *api, char *err, size_t err_size)
{
    const library_symbol symbols[] = {
        LIBRARY_SYMBOL(api->client_open, jack_client_open),
        LIBRARY_SYMBOL(api->client_close, jack_client_close),
        LIBRARY_SYMBOL(api->get_sample_rate, jack_get_sample_rate),
        LIBRARY_SYMBOL(api->get_buffer_size, jack_get_buffer_size),
        LIBRARY_SYMBOL(api->port_register, jack_port_register),
        LIBRARY_SYMBOL(api->port_get_buffer, jack_port_get_buffer),
        LIBRARY_SYMBOL(api->port_name, jack_port_name),
        LIBRARY_SYMBOL(api->set_process_callback, jack_set_process_callback),
        LIBRARY_SYMBOL(api->set_xrun_callback, jack_set_xrun_callback),
        LIBRARY_SYMBOL(api->on_shutdown, jack_on_shutdown),
        LIBRARY_SYMBOL(api->activate, jack_activate),
        LIBRARY_SYMBOL(api->deactivate, jack_deactivate),
        LIBRARY_SYMBOL(api->get_ports, jack_get_ports),
        LIBRARY_SYMBOL(api->connect, jack_connect),
        LIBRARY_SYMBOL(api->free, jack_free),
        LIBRARY_SYMBOL(api->set_error_function, jack_set_error_function),
        LIBRARY_SYMBOL(api->set_info_function, jack_set_info_function),
    };
    api->lib = live_library_load("jack", JACK_LIBRARY, "libjack-jackd2-0", symbols,
                                 sizeof symbols / sizeof symbols[0], err, err_size);
    return api->lib ? 0 : -1;
}

/* libjack prints its own lines ("Cannot connect to server socket ...");
 * the message fulgur gives instead says what to do. */
static void quiet(const char *message)
{
    (void)message;
}

/* [audio-thread] JACK's process thread. */
static int process(jack_nframes_t frames, void *arg)
{
    live_audio *a = arg;
    jack_state *s = a->impl;
    float *planes[2] = {NULL, NULL};
    for (uint32_t ch = 0; ch < a->config.channels; ch++)
        planes[ch] = s->api.port_get_buffer(s->ports[ch], frames);
    live_audio_pull(a, planes, frames);
    return 0;
}

static int xrun(void *arg)
{
    live_audio *a = arg;
    a->xruns++;
    return 0;
}

static void server_gone(void *arg)
{
    live_audio *a = arg;
    a->lost = 1;
}

static live_result jack_open(const live_config *c, live_audio *a, char *err, size_t err_size)
{
    jack_state *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, err_size, "out of memory");
        return LIVE_ERROR;
    }
    if (load(&s->api, err, err_size) != 0) {
        free(s);
        return LIVE_ABSENT;
    }
    s->api.set_error_function(quiet);
    s->api.set_info_function(quiet);
    jack_status_t status = 0;
    jack_options_t options = JackNoStartServer | (c->target ? JackServerName : 0);
    s->client = c->target ? s->api.client_open(c->client_name, options, &status, c->target)
                          : s->api.client_open(c->client_name, options, &status);
    if (!s->client) {
        const char *server = c->target ? c->target : "default";
        if (status & JackServerFailed)
            snprintf(err, err_size,
                     "--audio jack: no JACK server \"%s\" is running (start one: jackd -d alsa, "
                     "or jackd -d dummy without a sound card; or use --audio portaudio)",
                     server);
        else
            snprintf(err, err_size, "--audio jack: the server \"%s\" refused the client (status 0x%x)",
                     server, (unsigned)status);
        dlclose(s->api.lib);
        free(s);
        return (status & JackServerFailed) ? LIVE_ABSENT : LIVE_ERROR;
    }
    static const char *const stereo[] = {"out_left", "out_right"}, *const mono[] = {"out_mono"};
    const char *const *names = c->channels == 2 ? stereo : mono;
    for (uint32_t ch = 0; ch < c->channels; ch++)
        if (!(s->ports[ch] = s->api.port_register(s->client, names[ch], JACK_DEFAULT_AUDIO_TYPE,
                                                  JackPortIsOutput | JackPortIsTerminal, 0))) {
            snprintf(err, err_size, "--audio jack: cannot register the port %s", names[ch]);
            s->api.client_close(s->client);
            dlclose(s->api.lib);
            free(s);
            return LIVE_ERROR;
        }
    a->impl = s;
    a->rate_hz = s->api.get_sample_rate(s->client);
    a->block_frames = s->api.get_buffer_size(s->client);
    s->api.set_process_callback(s->client, process, a);
    s->api.set_xrun_callback(s->client, xrun, a);
    s->api.on_shutdown(s->client, server_gone, a);
    snprintf(a->description, sizeof a->description, "JACK server %s, %.0f Hz, %u frames",
             c->target ? c->target : "default", a->rate_hz, (unsigned)a->block_frames);
    return LIVE_OK;
}

static int jack_start(live_audio *a, char *err, size_t err_size)
{
    jack_state *s = a->impl;
    if (s->api.activate(s->client) != 0) {
        snprintf(err, err_size, "--audio jack: the server would not activate the client");
        return -1;
    }
    /* the first physical playback ports, as jack_connect would be told */
    const char **playback =
        s->api.get_ports(s->client, NULL, JACK_DEFAULT_AUDIO_TYPE, JackPortIsPhysical | JackPortIsInput);
    for (uint32_t i = 0; playback && playback[i] && i < 2; i++) {
        jack_port_t *from = s->ports[a->config.channels == 2 ? i : 0];
        s->api.connect(s->client, s->api.port_name(from), playback[i]);
    }
    if (playback)
        s->api.free(playback);
    return 0;
}

static void jack_close(live_audio *a)
{
    jack_state *s = a->impl;
    if (!a->lost)
        s->api.deactivate(s->client);
    s->api.client_close(s->client);
    /* libjack keeps threads and handlers of its own: it stays loaded */
    free(s);
}

const live_backend live_jack_backend = {"jack", "libjack-jackd2-dev", jack_open, jack_start,
                                        jack_close};
