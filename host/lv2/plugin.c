/* The LV2 entry points: instantiate, ports, run() and cleanup. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <lv2/atom/util.h>
#include <lv2/log/logger.h>
#include <lv2/midi/midi.h>
#include <lv2/state/state.h>

#include "plugin.h"

/* Where the listener stands: 1.7 m up, facing +y, +x on the right. */
static const fg_listener listener = {
    .position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};

static void cleanup(LV2_Handle instance)
{
    plugin *p = instance;
    fg_engine_destroy(p->engine);
    for (size_t i = 0; i < sizeof p->fields / sizeof p->fields[0]; i++)
        fg_field_destroy(p->fields[i].field);
    fg_tree_destroy(p->tree);
    free(p->placed);
    free(p);
}

static LV2_Handle instantiate(const LV2_Descriptor *descriptor, double rate_hz,
                              const char *bundle_path, const LV2_Feature *const *features)
{
    (void)descriptor;
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
    fg_engine_config config;
    if (fg_engine_config_resolve(NULL, &config) != FG_OK) {
        free(p);
        return NULL;
    }
    config.sample_rate_hz = rate_hz;
    p->max_block_frames = config.max_block_frames;
    p->schedule = schedule;
    p->urid_midi_event = map->map(map->handle, LV2_MIDI__MidiEvent);
    p->urid_long = map->map(map->handle, LV2_ATOM__Long);
    p->urid_counter = map->map(map->handle, FULGUR_LV2_COUNTER_URI);
    fg_result r = fg_engine_create(&config, &p->engine);
    if (r == FG_OK)
        r = fg_engine_set_listener(p->engine, &listener);
    if (r == FG_OK)
        r = fg_tree_create(1024, &p->tree);
    if (r != FG_OK) {
        lv2_log_error(&logger, "fulgur.lv2: the engine at %.0f Hz: %s\n", rate_hz,
                      fg_result_str(r));
        cleanup(p);
        return NULL;
    }
    return p;
}

static void connect_port(LV2_Handle instance, uint32_t port, void *data)
{
    plugin *p = instance;
    if (port < PORT_COUNT)
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

static void schedule(plugin *p, const work_request *rq)
{
    if (p->schedule->schedule_work(p->schedule->handle, sizeof *rq, rq) != LV2_WORKER_SUCCESS)
        p->failures++;
}

/* Each note-on and note-off goes to the worker with the controls of now. */
static void read_midi(plugin *p, const note_controls *c)
{
    const LV2_Atom_Sequence *seq = p->ports[PORT_MIDI_IN];
    LV2_ATOM_SEQUENCE_FOREACH(seq, ev)
    {
        if (ev->body.type != p->urid_midi_event || ev->body.size < 3)
            continue;
        const uint8_t *m = LV2_ATOM_BODY_CONST(&ev->body);
        uint8_t status = lv2_midi_message_type(m);
        work_request rq = {.note = m[1] & 127, .velocity = m[2] & 127, .controls = *c};
        if (status == LV2_MIDI_MSG_NOTE_ON && rq.velocity > 0) {
            rq.kind = REQUEST_NOTE_ON;
            rq.seed = (uint64_t)control(p, PORT_SEED, 0, 65535) << 32 | p->discharge_count++;
        } else if (status == LV2_MIDI_MSG_NOTE_ON || status == LV2_MIDI_MSG_NOTE_OFF) {
            rq.kind = REQUEST_NOTE_OFF;
        } else {
            continue;
        }
        schedule(p, &rq);
    }
}

static void run(LV2_Handle instance, uint32_t frames)
{
    plugin *p = instance;
    note_controls c;
    read_controls(p, &c);
    read_midi(p, &c);
    float gain = (float)pow(10, control(p, PORT_GAIN, -100, 20) / 20);
    float *out[2] = {p->ports[PORT_OUT_LEFT], p->ports[PORT_OUT_RIGHT]};
    for (uint32_t done = 0; done < frames;) {
        uint32_t n = frames - done < p->max_block_frames ? frames - done : p->max_block_frames;
        float *planes[2] = {out[0] + done, out[1] + done};
        /* n fits the engine's block and LV2 hosts connect every port before
         * run(), so render has no error to give; one would still be counted */
        if (fg_engine_render(p->engine, planes, n) != FG_OK)
            p->failures++;
        done += n;
    }
    for (uint32_t i = 0; i < frames; i++) {
        out[0][i] *= gain;
        out[1][i] *= gain;
    }
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

static const LV2_Descriptor descriptor = {
    FULGUR_LV2_URI, instantiate, connect_port, NULL, run, NULL, cleanup, extension_data};

LV2_SYMBOL_EXPORT const LV2_Descriptor *lv2_descriptor(uint32_t index)
{
    return index == 0 ? &descriptor : NULL;
}
