/* A small lilv host for fulgur.lv2: see lilv_host.h. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lv2/atom/util.h>
#include <lv2/midi/midi.h>
#include <lv2/state/state.h>
#include <lv2/urid/urid.h>
#include <lv2/worker/worker.h>

#include "lilv_host.h"

#define PLUGIN_URI "urn:fulgur:lv2:instrument"
#define MAX_PORTS 32
#define MAX_URIDS 64
#define MAX_JOBS 64
#define JOB_BYTES 256
#define MIDI_BYTES 4096
#define MAX_FRAMES 4096

typedef struct job {
    uint32_t size;
    unsigned char data[JOB_BYTES];
} job;

struct lv2_host {
    LilvWorld *world;
    const LilvPlugin *plugin;
    LilvInstance *instance;
    const LV2_Worker_Interface *worker;
    uint32_t port_count;
    float controls[MAX_PORTS];
    uint32_t audio_ports[2];
    union {
        LV2_Atom_Sequence seq;
        unsigned char bytes[MIDI_BYTES];
    } midi;
    LV2_URID_Map map;
    LV2_URID_Unmap unmap;
    LV2_Worker_Schedule schedule;
    LV2_Feature map_feature, unmap_feature, schedule_feature;
    const LV2_Feature *features[4];
    /* requests from run(), and responses from the worker: each list is
     * written by one thread while the other is not running */
    job requests[MAX_JOBS], responses[MAX_JOBS];
    unsigned request_count, response_count;
    unsigned work_calls, responses_given;
};

/* One URID table for the process, as a host has (kept until exit): a state
 * saved by one instance carries URIDs that another must read alike. Called
 * from the main thread only (instantiate, state, lv2_host_midi). */
static char *uris[MAX_URIDS];
static uint32_t uri_count;

static LV2_URID map_uri(LV2_URID_Map_Handle handle, const char *uri)
{
    (void)handle;
    for (uint32_t i = 0; i < uri_count; i++)
        if (!strcmp(uris[i], uri))
            return i + 1;
    if (uri_count == MAX_URIDS)
        return 0;
    uris[uri_count] = strdup(uri);
    return ++uri_count;
}

static const char *unmap_uri(LV2_URID_Unmap_Handle handle, LV2_URID urid)
{
    (void)handle;
    return urid >= 1 && urid <= uri_count ? uris[urid - 1] : NULL;
}

/* Copies a job into queue (*count held): no allocation. */
static LV2_Worker_Status queue_job(job *queue, unsigned *count, uint32_t size, const void *data)
{
    if (size > JOB_BYTES || *count == MAX_JOBS)
        return LV2_WORKER_ERR_NO_SPACE;
    job *j = &queue[(*count)++];
    j->size = size;
    memcpy(j->data, data, size);
    return LV2_WORKER_SUCCESS;
}

/* [audio-thread] */
static LV2_Worker_Status schedule_work(LV2_Worker_Schedule_Handle handle, uint32_t size,
                                       const void *data)
{
    lv2_host *h = handle;
    return queue_job(h->requests, &h->request_count, size, data);
}

static LV2_Worker_Status respond(LV2_Worker_Respond_Handle handle, uint32_t size,
                                 const void *data)
{
    lv2_host *h = handle;
    return queue_job(h->responses, &h->response_count, size, data);
}

/* The index of the control port named symbol, or NO_PORT. */
#define NO_PORT UINT32_MAX
static uint32_t control_index(const lv2_host *h, const char *symbol)
{
    LilvNode *sym = lilv_new_string(h->world, symbol);
    LilvNode *control = lilv_new_uri(h->world, LILV_URI_CONTROL_PORT);
    const LilvPort *port = lilv_plugin_get_port_by_symbol(h->plugin, sym);
    int is_control = port && lilv_port_is_a(h->plugin, port, control);
    lilv_node_free(sym);
    lilv_node_free(control);
    return is_control ? lilv_port_get_index(h->plugin, port) : NO_PORT;
}

/* Every control at its default, the MIDI sequence empty. */
static void connect_ports(lv2_host *h)
{
    float defaults[MAX_PORTS];
    lilv_plugin_get_port_ranges_float(h->plugin, NULL, NULL, defaults);
    LilvNode *control = lilv_new_uri(h->world, LILV_URI_CONTROL_PORT);
    LilvNode *audio = lilv_new_uri(h->world, LILV_URI_AUDIO_PORT);
    unsigned audio_seen = 0;
    for (uint32_t i = 0; i < h->port_count; i++) {
        const LilvPort *port = lilv_plugin_get_port_by_index(h->plugin, i);
        if (lilv_port_is_a(h->plugin, port, control)) {
            h->controls[i] = isnan(defaults[i]) ? 0 : defaults[i];
            lilv_instance_connect_port(h->instance, i, &h->controls[i]);
        } else if (lilv_port_is_a(h->plugin, port, audio) && audio_seen < 2) {
            h->audio_ports[audio_seen++] = i;
        } else {
            lilv_instance_connect_port(h->instance, i, &h->midi.seq);
        }
    }
    lilv_node_free(control);
    lilv_node_free(audio);
    h->midi.seq.atom.type = map_uri(h, LV2_ATOM__Sequence);
    lv2_atom_sequence_clear(&h->midi.seq);
}

lv2_host *lv2_host_create(double rate_hz)
{
    lv2_host *h = calloc(1, sizeof *h);
    if (!h || !(h->world = lilv_world_new())) {
        fprintf(stderr, "lv2_host: out of memory\n");
        free(h);
        return NULL;
    }
    lilv_world_load_all(h->world);   /* reads LV2_PATH */
    LilvNode *uri = lilv_new_uri(h->world, PLUGIN_URI);
    h->plugin = lilv_plugins_get_by_uri(lilv_world_get_all_plugins(h->world), uri);
    lilv_node_free(uri);
    if (!h->plugin) {
        fprintf(stderr, "lv2_host: %s not found on LV2_PATH=%s\n", PLUGIN_URI,
                getenv("LV2_PATH") ? getenv("LV2_PATH") : "(unset)");
        lv2_host_destroy(h);
        return NULL;
    }
    h->map = (LV2_URID_Map){h, map_uri};
    h->unmap = (LV2_URID_Unmap){h, unmap_uri};
    h->schedule = (LV2_Worker_Schedule){h, schedule_work};
    h->map_feature = (LV2_Feature){LV2_URID__map, &h->map};
    h->unmap_feature = (LV2_Feature){LV2_URID__unmap, &h->unmap};
    h->schedule_feature = (LV2_Feature){LV2_WORKER__schedule, &h->schedule};
    h->features[0] = &h->map_feature;
    h->features[1] = &h->unmap_feature;
    h->features[2] = &h->schedule_feature;
    h->port_count = lilv_plugin_get_num_ports(h->plugin);
    if (h->port_count > MAX_PORTS) {
        fprintf(stderr, "lv2_host: %u ports, more than the %d this host holds\n", h->port_count,
                MAX_PORTS);
        lv2_host_destroy(h);
        return NULL;
    }
    h->instance = lilv_plugin_instantiate(h->plugin, rate_hz, h->features);
    if (!h->instance) {
        fprintf(stderr, "lv2_host: instantiate at %.0f Hz failed\n", rate_hz);
        lv2_host_destroy(h);
        return NULL;
    }
    h->worker = lilv_instance_get_extension_data(h->instance, LV2_WORKER__interface);
    connect_ports(h);
    lilv_instance_activate(h->instance);
    return h;
}

void lv2_host_destroy(lv2_host *h)
{
    if (!h)
        return;
    if (h->instance) {
        lilv_instance_deactivate(h->instance);
        lilv_instance_free(h->instance);
    }
    lilv_world_free(h->world);
    free(h);
}

int lv2_host_set(lv2_host *h, const char *symbol, float value)
{
    uint32_t i = control_index(h, symbol);
    if (i == NO_PORT)
        return -1;
    h->controls[i] = value;
    return 0;
}

float lv2_host_get(const lv2_host *h, const char *symbol)
{
    uint32_t i = control_index(h, symbol);
    return i == NO_PORT ? NAN : h->controls[i];
}

int lv2_host_midi(lv2_host *h, uint32_t frame, uint8_t status, uint8_t data1, uint8_t data2)
{
    struct {
        LV2_Atom_Event event;
        uint8_t msg[3];
    } ev = {{.time.frames = frame, .body = {3, map_uri(h, LV2_MIDI__MidiEvent)}},
            {status, data1, data2}};
    return lv2_atom_sequence_append_event(&h->midi.seq, MIDI_BYTES - sizeof h->midi.seq.atom,
                                          &ev.event)
               ? 0
               : -1;
}

void lv2_host_run(lv2_host *h, uint32_t frames, float *left, float *right)
{
    lilv_instance_connect_port(h->instance, h->audio_ports[0], left);
    lilv_instance_connect_port(h->instance, h->audio_ports[1], right);
    for (unsigned i = 0; i < h->response_count; i++)
        h->worker->work_response(h->instance->lv2_handle, h->responses[i].size,
                                 h->responses[i].data);
    h->responses_given += h->response_count;
    h->response_count = 0;
    lilv_instance_run(h->instance, frames);
    lv2_atom_sequence_clear(&h->midi.seq);
}

unsigned lv2_host_work(lv2_host *h)
{
    unsigned n = h->request_count;
    for (unsigned i = 0; i < n; i++)
        h->worker->work(h->instance->lv2_handle, respond, h, h->requests[i].size,
                        h->requests[i].data);
    h->work_calls += n;
    h->request_count = 0;
    return n;
}

unsigned lv2_host_work_calls(const lv2_host *h) { return h->work_calls; }
unsigned lv2_host_responses(const lv2_host *h) { return h->responses_given; }

static const void *get_port_value(const char *symbol, void *user_data, uint32_t *size,
                                  uint32_t *type)
{
    lv2_host *h = user_data;
    uint32_t i = control_index(h, symbol);
    if (i == NO_PORT)
        return NULL;
    LilvNode *input = lilv_new_uri(h->world, LILV_URI_INPUT_PORT);
    int is_input = lilv_port_is_a(h->plugin, lilv_plugin_get_port_by_index(h->plugin, i), input);
    lilv_node_free(input);
    *size = sizeof(float);
    *type = map_uri(h, LV2_ATOM__Float);
    return is_input ? &h->controls[i] : NULL;
}

static void set_port_value(const char *symbol, void *user_data, const void *value, uint32_t size,
                           uint32_t type)
{
    lv2_host *h = user_data;
    uint32_t i = control_index(h, symbol);
    if (i != NO_PORT && size == sizeof(float) && type == map_uri(h, LV2_ATOM__Float))
        memcpy(&h->controls[i], value, sizeof(float));
}

LilvState *lv2_host_save(lv2_host *h)
{
    return lilv_state_new_from_instance(h->plugin, h->instance, &h->map, NULL, NULL, NULL, NULL,
                                        get_port_value, h, LV2_STATE_IS_POD | LV2_STATE_IS_PORTABLE,
                                        h->features);
}

void lv2_host_restore(lv2_host *h, const LilvState *state)
{
    lilv_state_restore(state, h->instance, set_port_value, h, 0, h->features);
}
