/* A small lilv host for fulgur.lv2: see lilv_host.h. */
#define _POSIX_C_SOURCE 200809L /* strdup, getcwd */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <lv2/atom/forge.h>
#include <lv2/atom/util.h>
#include <lv2/log/log.h>
#include <lv2/midi/midi.h>
#include <lv2/patch/patch.h>
#include <lv2/presets/presets.h>
#include <lv2/state/state.h>
#include <lv2/urid/urid.h>
#include <lv2/worker/worker.h>

#include "lilv_host.h"

#define MAX_PORTS 32
#define MAX_URIDS 64
#define MAX_JOBS 64
#define JOB_BYTES 4352 /* a path of 4 KiB and its request */
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
    uint32_t audio_ports[LV2_HOST_CHANNELS_MAX];
    unsigned audio_count;
    union { /* LV2 atoms in a sequence are 64-bit aligned */
        _Alignas(8) LV2_Atom_Sequence seq;
        unsigned char bytes[MIDI_BYTES + JOB_BYTES];
    } midi, notify;
    uint32_t notify_port; /* NO_PORT if none */
    char notified[JOB_BYTES], logged[1024];
    LV2_URID_Map map;
    LV2_URID_Unmap unmap;
    LV2_Worker_Schedule schedule;
    LV2_Log_Log log;
    LV2_Feature map_feature, unmap_feature, schedule_feature, log_feature;
    const LV2_Feature *features[5];
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

/* The plugin's log: kept (the last message) and printed to stderr. */
static int log_vprintf(LV2_Log_Handle handle, LV2_URID type, const char *fmt, va_list ap)
{
    (void)type;
    lv2_host *h = handle;
    va_list copy;
    va_copy(copy, ap);
    int n = vsnprintf(h->logged, sizeof h->logged, fmt, copy);
    va_end(copy);
    fputs(h->logged, stderr);
    return n;
}

static int log_printf(LV2_Log_Handle handle, LV2_URID type, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = log_vprintf(handle, type, fmt, ap);
    va_end(ap);
    return n;
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

/* Every control at its default, the MIDI sequence empty; audio outputs in
 * the order of their indices, an atom output as the notify port. */
static void connect_ports(lv2_host *h)
{
    float defaults[MAX_PORTS];
    lilv_plugin_get_port_ranges_float(h->plugin, NULL, NULL, defaults);
    LilvNode *control = lilv_new_uri(h->world, LILV_URI_CONTROL_PORT);
    LilvNode *audio = lilv_new_uri(h->world, LILV_URI_AUDIO_PORT);
    LilvNode *output = lilv_new_uri(h->world, LILV_URI_OUTPUT_PORT);
    h->notify_port = UINT32_MAX;
    for (uint32_t i = 0; i < h->port_count; i++) {
        const LilvPort *port = lilv_plugin_get_port_by_index(h->plugin, i);
        if (lilv_port_is_a(h->plugin, port, control)) {
            h->controls[i] = isnan(defaults[i]) ? 0 : defaults[i];
            lilv_instance_connect_port(h->instance, i, &h->controls[i]);
        } else if (lilv_port_is_a(h->plugin, port, audio)) {
            if (h->audio_count < LV2_HOST_CHANNELS_MAX)
                h->audio_ports[h->audio_count++] = i;
        } else if (lilv_port_is_a(h->plugin, port, output)) {
            h->notify_port = i;
            lilv_instance_connect_port(h->instance, i, &h->notify.seq);
        } else {
            lilv_instance_connect_port(h->instance, i, &h->midi.seq);
        }
    }
    lilv_node_free(control);
    lilv_node_free(audio);
    lilv_node_free(output);
    h->midi.seq.atom.type = map_uri(h, LV2_ATOM__Sequence);
    lv2_atom_sequence_clear(&h->midi.seq);
    /* what run() maps, mapped here: it must not allocate */
    static const char *const run_uris[] = {LV2_ATOM__Chunk, LV2_ATOM__Object, LV2_ATOM__Path,
                                           LV2_PATCH__Set, LV2_PATCH__value};
    for (size_t i = 0; i < sizeof run_uris / sizeof run_uris[0]; i++)
        map_uri(h, run_uris[i]);
}

/* LV2_PATH for lilv, its relative entries made absolute: lilv 0.24 takes
 * "dir/x.lv2" for a URI and crashes in lilv_world_load_bundle. Entries that
 * are absolute or start with ~ (lilv expands it) are kept. Returns 0, or -1
 * when out of memory or the working directory is unknown. */
static int set_lv2_path(LilvWorld *world)
{
    const char *path = getenv("LV2_PATH");
    if (!path)
        return 0;
    char cwd[PATH_MAX];
    if (!getcwd(cwd, sizeof cwd))
        return -1;
    size_t entries = 1;
    for (const char *c = path; *c; c++)
        entries += *c == ':';
    char *out = malloc(strlen(path) + entries * (strlen(cwd) + 1) + 1);
    if (!out)
        return -1;
    char *end = out;
    for (const char *entry = path; entry;) {
        const char *colon = strchr(entry, ':');
        size_t n = colon ? (size_t)(colon - entry) : strlen(entry);
        if (n > 0) {
            if (end != out)
                *end++ = ':';
            if (entry[0] != '/' && entry[0] != '~')
                end += sprintf(end, "%s/", cwd);
            memcpy(end, entry, n);
            end += n;
        }
        entry = colon ? colon + 1 : NULL;
    }
    *end = '\0';
    LilvNode *node = lilv_new_string(world, out);
    free(out);
    if (!node)
        return -1;
    lilv_world_set_option(world, LILV_OPTION_LV2_PATH, node);
    lilv_node_free(node);
    return 0;
}

lv2_host *lv2_host_create(double rate_hz)
{
    return lv2_host_create_plugin(FULGUR_LV2_URI, rate_hz);
}

lv2_host *lv2_host_create_plugin(const char *plugin_uri, double rate_hz)
{
    lv2_host *h = calloc(1, sizeof *h);
    if (!h || !(h->world = lilv_world_new())) {
        fprintf(stderr, "lv2_host: out of memory\n");
        free(h);
        return NULL;
    }
    if (set_lv2_path(h->world) != 0) {
        fprintf(stderr, "lv2_host: out of memory or no working directory for LV2_PATH\n");
        lv2_host_destroy(h);
        return NULL;
    }
    lilv_world_load_all(h->world);
    LilvNode *uri = lilv_new_uri(h->world, plugin_uri);
    h->plugin = lilv_plugins_get_by_uri(lilv_world_get_all_plugins(h->world), uri);
    lilv_node_free(uri);
    if (!h->plugin) {
        fprintf(stderr, "lv2_host: %s not found on LV2_PATH=%s\n", plugin_uri,
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
    h->log = (LV2_Log_Log){h, log_printf, log_vprintf};
    h->log_feature = (LV2_Feature){LV2_LOG__log, &h->log};
    h->features[0] = &h->map_feature;
    h->features[1] = &h->unmap_feature;
    h->features[2] = &h->schedule_feature;
    h->features[3] = &h->log_feature;
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

unsigned lv2_host_channels(const lv2_host *h) { return h->audio_count; }

int lv2_host_set_path(lv2_host *h, const char *property, const char *path)
{
    union {
        _Alignas(8) LV2_Atom_Event event;
        uint8_t bytes[JOB_BYTES];
    } ev;
    LV2_Atom_Forge forge;
    LV2_Atom_Forge_Frame set;
    lv2_atom_forge_init(&forge, &h->map);
    size_t at = offsetof(LV2_Atom_Event, body);
    lv2_atom_forge_set_buffer(&forge, ev.bytes + at, sizeof ev - at);
    ev.event.time.frames = 0;
    if (!lv2_atom_forge_object(&forge, &set, 0, map_uri(h, LV2_PATCH__Set)) ||
        !lv2_atom_forge_key(&forge, map_uri(h, LV2_PATCH__property)) ||
        !lv2_atom_forge_urid(&forge, map_uri(h, property)) ||
        !lv2_atom_forge_key(&forge, map_uri(h, LV2_PATCH__value)) ||
        !lv2_atom_forge_path(&forge, path, (uint32_t)strlen(path)))
        return -1;
    lv2_atom_forge_pop(&forge, &set);
    return lv2_atom_sequence_append_event(&h->midi.seq,
                                          sizeof h->midi - sizeof h->midi.seq.atom, &ev.event)
               ? 0
               : -1;
}

/* The path of each patch:Set on the notify port. */
static void read_notify(lv2_host *h)
{
    LV2_URID set = map_uri(h, LV2_PATCH__Set), value_key = map_uri(h, LV2_PATCH__value);
    LV2_URID object = map_uri(h, LV2_ATOM__Object), path = map_uri(h, LV2_ATOM__Path);
    LV2_ATOM_SEQUENCE_FOREACH(&h->notify.seq, ev)
    {
        const LV2_Atom_Object *obj = (const LV2_Atom_Object *)&ev->body;
        if (ev->body.type != object || obj->body.otype != set)
            continue;
        const LV2_Atom *value = NULL;
        lv2_atom_object_get(obj, value_key, &value, 0);
        if (value && value->type == path)
            snprintf(h->notified, sizeof h->notified, "%.*s", (int)value->size,
                     (const char *)LV2_ATOM_BODY_CONST(value));
    }
}

const char *lv2_host_notified_path(const lv2_host *h) { return h->notified; }
const char *lv2_host_last_log(const lv2_host *h) { return h->logged; }

void lv2_host_run(lv2_host *h, uint32_t frames, float *left, float *right)
{
    if (h->audio_count != 2) /* a caller's error: the plugin has other outputs */
        abort();
    float *const planes[2] = {left, right};
    lv2_host_run_planes(h, frames, planes);
}

void lv2_host_run_planes(lv2_host *h, uint32_t frames, float *const *planes)
{
    for (unsigned k = 0; k < h->audio_count; k++)
        lilv_instance_connect_port(h->instance, h->audio_ports[k], planes[k]);
    /* an output sequence is handed over with its capacity */
    h->notify.seq.atom.size = sizeof h->notify - sizeof h->notify.seq.atom;
    h->notify.seq.atom.type = map_uri(h, LV2_ATOM__Chunk);
    for (unsigned i = 0; i < h->response_count; i++)
        h->worker->work_response(h->instance->lv2_handle, h->responses[i].size,
                                 h->responses[i].data);
    h->responses_given += h->response_count;
    h->response_count = 0;
    lilv_instance_run(h->instance, frames);
    lv2_atom_sequence_clear(&h->midi.seq);
    if (h->notify_port != UINT32_MAX)
        read_notify(h);
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

/* Calls each(h, preset node, its label, user) for every preset of the
 * plugin (loading each), until each returns non-zero; returns that, or 0. */
static int for_each_preset(lv2_host *h,
                           int (*each)(lv2_host *h, const LilvNode *preset, const char *label,
                                       void *user),
                           void *user)
{
    LilvNode *kind = lilv_new_uri(h->world, LV2_PRESETS__Preset);
    LilvNode *rdfs_label = lilv_new_uri(h->world, LILV_NS_RDFS "label");
    LilvNodes *all = lilv_plugin_get_related(h->plugin, kind);
    int rc = 0;
    LILV_FOREACH(nodes, it, all) {
        const LilvNode *preset = lilv_nodes_get(all, it);
        lilv_world_load_resource(h->world, preset);
        LilvNode *text = lilv_world_get(h->world, preset, rdfs_label, NULL);
        rc = each(h, preset, text ? lilv_node_as_string(text) : "", user);
        lilv_node_free(text);
        if (rc)
            break;
    }
    lilv_nodes_free(all);
    lilv_node_free(rdfs_label);
    lilv_node_free(kind);
    return rc;
}

typedef struct label_list {
    char (*labels)[LV2_HOST_LABEL_BYTES];
    unsigned max, count;
} label_list;

static int note_label(lv2_host *h, const LilvNode *preset, const char *label, void *user)
{
    (void)h, (void)preset;
    label_list *l = user;
    if (l->count < l->max)
        snprintf(l->labels[l->count], LV2_HOST_LABEL_BYTES, "%s", label);
    l->count++;
    return 0;
}

unsigned lv2_host_presets(lv2_host *h, char (*labels)[LV2_HOST_LABEL_BYTES], unsigned max)
{
    label_list l = {labels, max, 0};
    for_each_preset(h, note_label, &l);
    return l.count;
}

/* Applies the preset if its label is the one wanted: 1 done, -1 failed. */
static int apply_if_named(lv2_host *h, const LilvNode *preset, const char *label, void *user)
{
    if (strcmp(label, user) != 0)
        return 0;
    LilvState *state = lilv_state_new_from_world(h->world, &h->map, preset);
    if (!state)
        return -1;
    lv2_host_restore(h, state);
    lilv_state_free(state);
    return 1;
}

int lv2_host_preset_apply(lv2_host *h, const char *label)
{
    return for_each_preset(h, apply_if_named, (void *)label) == 1 ? 0 : -1;
}
