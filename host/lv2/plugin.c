/* The LV2 entry points: instantiate, ports, run() and cleanup, for every
 * layout's plugin (one code path: the variant names the layout, the
 * channels follow from it). */
#define _POSIX_C_SOURCE 200809L /* strnlen */
#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include <lv2/atom/util.h>
#include <lv2/midi/midi.h>
#include <lv2/patch/patch.h>
#include <lv2/state/state.h>

#include "plugin.h"

static void cleanup(LV2_Handle instance)
{
    plugin *p = instance;
    for (uint32_t s = 0; s < ENGINE_SLOTS; s++)
        engine_slot_destroy(p, s);
    for (size_t i = 0; i < sizeof p->fields / sizeof p->fields[0]; i++)
        fg_field_destroy(p->fields[i].field);
    fg_tree_destroy(p->tree);
    free(p->placed);
    free(p);
}

uint32_t plugin_channel_port(uint32_t k)
{
    return k < 2 ? PORT_OUT_LEFT + k : PORT_COUNT + k - 2;
}

static const plugin_variant *variant_of(const char *uri);

static LV2_Handle instantiate(const LV2_Descriptor *descriptor, double rate_hz,
                              const char *bundle_path, const LV2_Feature *const *features)
{
    (void)bundle_path;
    LV2_URID_Map *map = NULL;
    LV2_Worker_Schedule *schedule = NULL;
    LV2_Log_Log *log = NULL;
    for (size_t i = 0; features && features[i]; i++) {
        if (!features[i]->URI) /* some hosts pass one (lv2file) */
            continue;
        if (!strcmp(features[i]->URI, LV2_URID__map))
            map = features[i]->data;
        else if (!strcmp(features[i]->URI, LV2_WORKER__schedule))
            schedule = features[i]->data;
        else if (!strcmp(features[i]->URI, LV2_LOG__log))
            log = features[i]->data;
    }
    /* the host's log if it has one, else stderr */
    LV2_Log_Logger logger;
    lv2_log_logger_init(&logger, map, log);
    const plugin_variant *variant = variant_of(descriptor ? descriptor->URI : NULL);
    if (!variant) {
        lv2_log_error(&logger, "fulgur.lv2: no plugin %s in this module\n",
                      descriptor && descriptor->URI ? descriptor->URI : "(none)");
        return NULL;
    }
    /* the engine's rates; 0 would have silently run at its default 48 kHz */
    if (!(rate_hz >= FG_SAMPLE_RATE_MIN_HZ && rate_hz <= FG_SAMPLE_RATE_MAX_HZ)) {
        lv2_log_error(&logger, "fulgur.lv2: a sample rate of %g Hz, outside %g..%g\n", rate_hz,
                      FG_SAMPLE_RATE_MIN_HZ, FG_SAMPLE_RATE_MAX_HZ);
        return NULL;
    }
    if (!map || !schedule) {
        lv2_log_error(&logger, "fulgur.lv2: the host does not provide %s\n",
                      !map ? LV2_URID__map : LV2_WORKER__schedule);
        return NULL;
    }
    plugin *p = calloc(1, sizeof *p);
    if (!p) {
        lv2_log_error(&logger, "fulgur.lv2: out of memory\n");
        return NULL;
    }
    p->variant = variant;
    p->rate_hz = rate_hz;
    uint32_t order = variant->ambisonic_order;
    p->channels = variant->layout == FG_LAYOUT_AMBISONICS ? (order + 1) * (order + 1) : 2;
    p->logger = logger;
    p->map = map;
    p->schedule = schedule;
    p->retiring = -1;
    p->swap_to = -1;
    p->urid_midi_event = map->map(map->handle, LV2_MIDI__MidiEvent);
    p->urid_long = map->map(map->handle, LV2_ATOM__Long);
    p->urid_counter = map->map(map->handle, FULGUR_LV2_COUNTER_URI);
    p->urid_sofa = map->map(map->handle, FULGUR_LV2_SOFA_URI);
    p->urid_path = map->map(map->handle, LV2_ATOM__Path);
    p->urid_object = map->map(map->handle, LV2_ATOM__Object);
    p->urid_blank = map->map(map->handle, LV2_ATOM__Blank);
    p->urid_urid = map->map(map->handle, LV2_ATOM__URID);
    p->urid_patch_set = map->map(map->handle, LV2_PATCH__Set);
    p->urid_patch_get = map->map(map->handle, LV2_PATCH__Get);
    p->urid_patch_property = map->map(map->handle, LV2_PATCH__property);
    p->urid_patch_value = map->map(map->handle, LV2_PATCH__value);
    lv2_atom_forge_init(&p->forge, map);
    char err[600];
    int slot = engine_slot_create(p, NULL, err, sizeof err);
    if (slot < 0 || fg_tree_create(1024, &p->tree) != FG_OK) {
        lv2_log_error(&logger, "fulgur.lv2: %s\n", slot < 0 ? err : "out of memory");
        cleanup(p);
        return NULL;
    }
    fg_engine_config config;
    fg_engine_get_config(p->slots[slot].engine, &config);
    p->max_block_frames = config.max_block_frames;
    atomic_store_explicit(&p->playing, (uint32_t)slot, memory_order_relaxed);
    p->posting = (uint32_t)slot;
    /* a host's patch:Get is answered, and the file said once at the start */
    p->notify_pending = variant->layout == FG_LAYOUT_BINAURAL;
    return p;
}

static void connect_port(LV2_Handle instance, uint32_t port, void *data)
{
    plugin *p = instance;
    if (port < PLUGIN_PORTS_MAX)
        p->ports[port] = data;
}

/* A control port's value within [lo, hi]; NaN reads as lo. */
static double control(const plugin *p, port_index port, double lo, double hi)
{
    double v = *(const float *)p->ports[port];
    return !(v >= lo) ? lo : v > hi ? hi : v;
}

static void read_controls(const plugin *p, note_controls *c)
{
    c->preset = (fg_preset)(int)(control(p, PORT_PRESET, 0, FG_PRESET_COUNT - 1) + 0.5);
    c->distance_m = control(p, PORT_DISTANCE, 0.1, 20000);
    c->azimuth_deg = control(p, PORT_AZIMUTH, -180, 180);
    c->elevation_deg = control(p, PORT_ELEVATION, -90, 90);
    c->t0_scale = control(p, PORT_T0_SCALE, 0.25, 4);
    c->strokes = (uint32_t)(control(p, PORT_STROKES, 0, 10) + 0.5);
    c->refraction = control(p, PORT_REFRACTION, 0, 1) >= 0.5;
    c->absorption = control(p, PORT_ABSORPTION, 0, 1) >= 0.5;
}

static void schedule(plugin *p, const void *request, uint32_t size)
{
    if (p->schedule->schedule_work(p->schedule->handle, size, request) != LV2_WORKER_SUCCESS)
        p->failures++;
}

/* A note-on or note-off goes to the worker with the controls of now. */
static void read_note(plugin *p, const note_controls *c, const uint8_t *m)
{
    uint8_t status = lv2_midi_message_type(m);
    work_request rq = {.note = m[1] & 127, .velocity = m[2] & 127, .controls = *c};
    if (status == LV2_MIDI_MSG_NOTE_ON && rq.velocity > 0) {
        rq.kind = REQUEST_NOTE_ON;
        rq.seed = (uint64_t)control(p, PORT_SEED, 0, 65535) << 32 | p->discharge_count++;
    } else if (status == LV2_MIDI_MSG_NOTE_ON || status == LV2_MIDI_MSG_NOTE_OFF) {
        rq.kind = REQUEST_NOTE_OFF;
    } else {
        return;
    }
    schedule(p, &rq, sizeof rq);
}

/* The binaural plugin's patch messages: a patch:Set of its SOFA file goes
 * to the worker (which reads it and makes an engine of it); a patch:Get is
 * answered on the notify port. Other properties are not the plugin's. */
static void read_patch(plugin *p, const LV2_Atom_Object *obj)
{
    if (p->variant->layout != FG_LAYOUT_BINAURAL)
        return;
    if (obj->body.otype == p->urid_patch_get) {
        p->notify_pending = 1;
        return;
    }
    if (obj->body.otype != p->urid_patch_set)
        return;
    const LV2_Atom *property = NULL, *value = NULL;
    lv2_atom_object_get(obj, p->urid_patch_property, &property, p->urid_patch_value, &value, 0);
    if (!property || property->type != p->urid_urid ||
        ((const LV2_Atom_URID *)property)->body != p->urid_sofa)
        return;
    if (!value || value->type != p->urid_path) {
        p->failures++; /* a host's error: not a path (nothing to name here) */
        return;
    }
    /* the body is the path and its zero; hosts may leave out the zero */
    const char *path = LV2_ATOM_BODY_CONST(value);
    uint32_t length = (uint32_t)strnlen(path, value->size);
    sofa_request *rq = &p->sofa_out;
    rq->kind = REQUEST_SOFA;
    rq->length = length;
    uint32_t sent = length < SOFA_PATH_BYTES ? length : 0;
    memcpy(rq->path, path, sent);
    rq->path[sent] = '\0';
    schedule(p, rq, (uint32_t)offsetof(sofa_request, path) + sent + 1);
}

static void read_events(plugin *p, const note_controls *c)
{
    const LV2_Atom_Sequence *seq = p->ports[PORT_MIDI_IN];
    LV2_ATOM_SEQUENCE_FOREACH(seq, ev)
    {
        if (ev->body.type == p->urid_midi_event && ev->body.size >= 3)
            read_note(p, c, LV2_ATOM_BODY_CONST(&ev->body));
        else if (ev->body.type == p->urid_object || ev->body.type == p->urid_blank)
            read_patch(p, (const LV2_Atom_Object *)&ev->body);
    }
}

/* Renders engine into planes (channels of them), frames in the engine's
 * blocks. */
static void render(plugin *p, fg_engine *engine, float *const *planes, uint32_t frames)
{
    for (uint32_t done = 0; done < frames;) {
        uint32_t n = frames - done < p->max_block_frames ? frames - done : p->max_block_frames;
        float *at[PLUGIN_CHANNELS_MAX];
        for (uint32_t k = 0; k < p->channels; k++)
            at[k] = planes[k] + done;
        /* n fits the engine's block and LV2 hosts connect every port before
         * run(), so render has no error to give; one would still be counted */
        if (fg_engine_render(engine, at, n) != FG_OK)
            p->failures++;
        done += n;
    }
}

/* Hands the retiring engine back to the worker. */
static void retire(plugin *p)
{
    retire_request rq = {.kind = REQUEST_RETIRE, .slot = (uint32_t)p->retiring,
                         .generation = p->generation};
    schedule(p, &rq, sizeof rq);
    p->retiring = -1;
}

/* The engine swapped out plays its voices to their end, and its tails
 * RETIRE_TAIL_S longer, added to the output: no note is cut. */
static void play_out(plugin *p, float *const *out, uint32_t frames)
{
    fg_engine *engine = p->slots[p->retiring].engine;
    const uint32_t chunk = sizeof p->scratch[0] / sizeof p->scratch[0][0];
    float *scratch[PLUGIN_CHANNELS_MAX];
    for (uint32_t k = 0; k < p->channels; k++)
        scratch[k] = p->scratch[k];
    for (uint32_t done = 0; done < frames; done += chunk) {
        uint32_t n = frames - done < chunk ? frames - done : chunk;
        render(p, engine, scratch, n);
        for (uint32_t k = 0; k < p->channels; k++)
            for (uint32_t i = 0; i < n; i++)
                out[k][done + i] += scratch[k][i];
    }
    fg_engine_report report;
    fg_engine_get_report(engine, &report);
    if (report.finished < report.posted) /* a voice still waits or sounds */
        return;
    if (p->retire_frames > frames)
        p->retire_frames -= frames;
    else
        retire(p);
}

/* The SOFA file in use, as a patch:Set on the notify port (what hosts show
 * for the parameter), when it changed or a host asked. */
static void notify(plugin *p)
{
    LV2_Atom_Sequence *port = p->ports[PORT_NOTIFY];
    if (p->variant->layout != FG_LAYOUT_BINAURAL || !port)
        return;
    uint32_t capacity = port->atom.size;
    lv2_atom_forge_set_buffer(&p->forge, (uint8_t *)port, capacity);
    LV2_Atom_Forge_Frame seq, set;
    if (!lv2_atom_forge_sequence_head(&p->forge, &seq, 0))
        return;
    if (p->notify_pending) {
        const char *sofa = p->slots[atomic_load_explicit(&p->playing, memory_order_relaxed)].sofa;
        if (lv2_atom_forge_frame_time(&p->forge, 0) &&
            lv2_atom_forge_object(&p->forge, &set, 0, p->urid_patch_set) &&
            lv2_atom_forge_key(&p->forge, p->urid_patch_property) &&
            lv2_atom_forge_urid(&p->forge, p->urid_sofa) &&
            lv2_atom_forge_key(&p->forge, p->urid_patch_value) &&
            lv2_atom_forge_path(&p->forge, sofa, (uint32_t)strlen(sofa))) {
            lv2_atom_forge_pop(&p->forge, &set);
            p->notify_pending = 0;
        } else {
            /* too small a buffer this time: an empty sequence, said later */
            lv2_atom_forge_set_buffer(&p->forge, (uint8_t *)port, capacity);
            lv2_atom_forge_sequence_head(&p->forge, &seq, 0);
        }
    }
    lv2_atom_forge_pop(&p->forge, &seq);
}

/* A swap's engine in slot plays from now; the one it replaces plays out. */
static void swap_in(plugin *p, uint32_t slot)
{
    if (p->retiring >= 0) /* a swap still playing out: it ends here */
        retire(p);
    p->retiring = (int32_t)atomic_load_explicit(&p->playing, memory_order_relaxed);
    p->retire_frames = (uint64_t)(RETIRE_TAIL_S * p->rate_hz);
    atomic_store_explicit(&p->playing, slot, memory_order_relaxed);
}

static void run(LV2_Handle instance, uint32_t frames)
{
    plugin *p = instance;
    if (p->swap_to >= 0) {
        swap_in(p, (uint32_t)p->swap_to);
        p->swap_to = -1;
    }
    note_controls c;
    read_controls(p, &c);
    read_events(p, &c);
    float gain = (float)pow(10, control(p, PORT_GAIN, -100, 20) / 20);
    float *out[PLUGIN_CHANNELS_MAX];
    for (uint32_t k = 0; k < p->channels; k++)
        out[k] = p->ports[plugin_channel_port(k)];
    render(p, p->slots[atomic_load_explicit(&p->playing, memory_order_relaxed)].engine, out,
           frames);
    if (p->retiring >= 0)
        play_out(p, out, frames);
    for (uint32_t k = 0; k < p->channels; k++)
        for (uint32_t i = 0; i < frames; i++)
            out[k][i] *= gain;
    notify(p);
    if (p->variant->layout == FG_LAYOUT_BINAURAL && p->ports[PORT_LATENCY])
        *(float *)p->ports[PORT_LATENCY] = (float)FG_BINAURAL_LATENCY_FRAMES;
    *(float *)p->ports[PORT_DISCHARGES] = (float)p->discharges;
    *(float *)p->ports[PORT_FAILURES] = (float)p->failures;
}

static const void *extension_data(const char *uri)
{
    static const LV2_Worker_Interface worker = {plugin_work, plugin_work_response, NULL};
    if (!uri)
        return NULL;
    if (!strcmp(uri, LV2_WORKER__interface))
        return &worker;
    if (!strcmp(uri, LV2_STATE__interface))
        return plugin_state_interface();
    return NULL;
}

#define VARIANT(suffix, layout, order)                                                          \
    {{FULGUR_LV2_URI suffix, instantiate, connect_port, NULL, run, NULL, cleanup,              \
      extension_data},                                                                          \
     layout, order}
static const plugin_variant variants[] = {
    VARIANT("", FG_LAYOUT_STEREO, 0),
    VARIANT("-binaural", FG_LAYOUT_BINAURAL, 0),
    VARIANT("-ambisonics1", FG_LAYOUT_AMBISONICS, 1),
    VARIANT("-ambisonics2", FG_LAYOUT_AMBISONICS, 2),
    VARIANT("-ambisonics3", FG_LAYOUT_AMBISONICS, 3),
};
#define VARIANT_COUNT (sizeof variants / sizeof variants[0])

static const plugin_variant *variant_of(const char *uri)
{
    for (size_t i = 0; uri && i < VARIANT_COUNT; i++)
        if (!strcmp(variants[i].descriptor.URI, uri))
            return &variants[i];
    return NULL;
}

LV2_SYMBOL_EXPORT const LV2_Descriptor *lv2_descriptor(uint32_t index)
{
    return index < VARIANT_COUNT ? &variants[index].descriptor : NULL;
}
