/* Live audio devices for fulgur run and fulgur view: a sound server or
 * card calls back for each buffer, on its own real-time thread, and the
 * callback pulls the engine (the engine knows no audio API).
 *
 *   jack        a JACK server (libjack, jackd2 or PipeWire's JACK): the
 *               server's rate and buffer size; output ports out_left and
 *               out_right (out_mono for one channel) of a client named
 *               after the program, connected to the first physical
 *               playback ports. "jack:NAME" picks the server named NAME.
 *   portaudio   PortAudio's default output device (ALSA's "default", which
 *               PulseAudio or PipeWire serve on a desktop), at the rate and
 *               block asked for. "portaudio:NAME" picks the first output
 *               device whose name contains NAME (e.g. "system", PortAudio's
 *               JACK device).
 *
 * Why both libraries are opened with dlopen: libjack maps libstdc++ and
 * libdb, libportaudio libasound and libjack; a process that does not play
 * live (fulgur render, --help) maps none of them, and a machine without
 * them gets a message naming the package instead of a loader error.
 *
 * The callback is [audio-thread]: it gets planes of at most
 * max_chunk_frames (a larger device buffer is handed over in chunks) and
 * must fill them; it must not block, allocate or print. */
#ifndef HOST_COMMON_LIVE_AUDIO_H
#define HOST_COMMON_LIVE_AUDIO_H

#include <stddef.h>
#include <stdint.h>

#include "library_load.h"

typedef enum live_kind { LIVE_JACK, LIVE_PORTAUDIO } live_kind;

/* Fills planes[ch][0..frames) for ch < channels. [audio-thread] */
typedef void (*live_process_fn)(void *user, float *const *planes, uint32_t frames);

typedef struct live_config {
    live_kind kind;
    const char *target;        /* NULL: the default server or device */
    const char *client_name;   /* JACK's client name, e.g. "fulgur" */
    uint32_t channels;         /* 1 or 2 */
    double rate_hz;            /* PortAudio: the rate to open; JACK: the server's rules */
    uint32_t block_frames;     /* PortAudio: frames per buffer; JACK: the server's */
    uint32_t max_chunk_frames; /* the most frames one process call gets */
    live_process_fn process;
    void *user;
} live_config;

typedef struct live_audio live_audio;

/* What open answers. */
typedef enum live_result {
    LIVE_OK = 0,
    LIVE_ERROR = -1,    /* the library or server failed (the message says how) */
    LIVE_ABSENT = -2    /* no server running, no such device, library not installed */
} live_result;

/* Connects to the server or opens the device, not yet running: its rate and
 * block are known from here on. On failure nothing is left open and err
 * says what to do. [main-thread] */
live_result live_audio_open(const live_config *config, live_audio **out, char *err,
                            size_t err_size);

/* The rate the device runs at, and its buffer size in frames. */
double live_audio_rate_hz(const live_audio *a);
uint32_t live_audio_block_frames(const live_audio *a);

/* Starts the callbacks (JACK: activates and connects to the playback
 * ports). Returns 0, or -1 with a message. [main-thread] */
int live_audio_start(live_audio *a, char *err, size_t err_size);

/* Over- and underruns the server or device reported so far. [any-thread] */
uint64_t live_audio_xruns(const live_audio *a);

/* Non-zero once the server has gone away (it shut down, or dropped the
 * client): no more callbacks will come. [any-thread] */
int live_audio_lost(const live_audio *a);

/* E.g. "JACK server default, client fulgur", "PortAudio ALSA: default". */
const char *live_audio_describe(const live_audio *a);

/* Stops the callbacks and closes; NULL is a no-op. [main-thread] */
void live_audio_close(live_audio *a);

/* The backends (live_jack.c, live_portaudio.c). One built without its
 * library's headers (live_audio.c) has no functions, only its name and
 * the package that builds it, for live_audio_open's message. */
typedef struct live_backend {
    const char *driver;      /* as --audio names it: "jack" */
    const char *dev_package; /* the Debian package of its headers */
    live_result (*open)(const live_config *config, live_audio *a, char *err, size_t err_size);
    int (*start)(live_audio *a, char *err, size_t err_size);
    void (*close)(live_audio *a);
} live_backend;
extern const live_backend live_jack_backend;
extern const live_backend live_portaudio_backend;

/* What the backends share with live_audio.c. */
struct live_audio {
    live_config config;
    const live_backend *backend;
    void *impl;
    double rate_hz;
    uint32_t block_frames;
    _Atomic uint64_t xruns;
    _Atomic int lost;
    char description[160];
};

/* dlopens library and resolves the count symbols (library_load). Returns
 * its handle, or NULL with a message naming --audio driver and the Debian
 * package that installs the library (nothing left open). [main-thread] */
void *live_library_load(const char *driver, const char *library, const char *package,
                        const library_symbol *symbols, size_t count, char *err, size_t err_size);

/* Calls config.process over frames in chunks of at most max_chunk_frames,
 * planes advanced for each. [audio-thread] */
void live_audio_pull(live_audio *a, float *const *planes, uint32_t frames);

#endif
