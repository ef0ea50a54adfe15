/* The fulgur LV2 instrument: what its files share.
 *
 * Threads (LV2's classes mapped onto fulgur's tags):
 *   run()                 [audio-thread]  reads the ports and the MIDI, hands
 *                                         each note to the worker through
 *                                         schedule_work, renders the engine
 *   work()                [sim-thread]    the LV2 worker: collects finished
 *                                         voices, grows the tree, posts it,
 *                                         stops held notes; one at a time
 *   work_response()       [audio-thread]  called by the host inside/after run()
 *   instantiate, cleanup,
 *   state save/restore    [main-thread]   never concurrent with run()
 * Everything run() reads that the worker writes comes back through
 * work_response; the engine's own rings carry the voices. */
#ifndef HOST_LV2_PLUGIN_H
#define HOST_LV2_PLUGIN_H

#include <stdint.h>

#include <lv2/core/lv2.h>
#include <lv2/urid/urid.h>
#include <lv2/worker/worker.h>

#include "fulgur/fulgur.h"

#define FULGUR_LV2_URI "urn:fulgur:lv2:instrument"
/* State property: how many discharges this instance has triggered, the
 * position in its seed stream. */
#define FULGUR_LV2_COUNTER_URI "urn:fulgur:lv2:discharge-count"

/* Port indices, as in fulgur.ttl. */
typedef enum port_index {
    PORT_MIDI_IN = 0,
    PORT_OUT_LEFT,
    PORT_OUT_RIGHT,
    PORT_PRESET,
    PORT_DISTANCE,
    PORT_AZIMUTH,
    PORT_ELEVATION,
    PORT_T0_SCALE,
    PORT_STROKES,
    PORT_REFRACTION,
    PORT_ABSORPTION,
    PORT_GAIN,
    PORT_SEED,
    PORT_DISCHARGES,
    PORT_FAILURES,
    PORT_COUNT
} port_index;

/* The control values a note is played with, read by run() at the note. */
typedef struct note_controls {
    fg_preset preset;
    double distance_m;   /* at note 60; see note_distance_m */
    double azimuth_deg;  /* 0 ahead, +90 right */
    double elevation_deg;/* 0 level, +90 overhead */
    double t0_scale;
    uint32_t strokes;    /* 0 = the log-series law */
    int refraction;
    int absorption;
} note_controls;

typedef enum request_kind { REQUEST_NOTE_ON = 1, REQUEST_NOTE_OFF = 2 } request_kind;

/* run() -> work(): copied by the host. */
typedef struct work_request {
    request_kind kind;
    uint8_t note, velocity;   /* MIDI, velocity 1..127 */
    uint64_t seed;            /* the discharge's seed */
    note_controls controls;
} work_request;

/* work() -> work_response(): what became of a request. */
typedef struct work_reply {
    request_kind kind;
    fg_result result;
} work_reply;

/* Fields of Matsuyama's presets, grown in on the worker. */
typedef struct preset_field {
    fg_field_scene setup;
    fg_field *field;     /* NULL until the first note of the preset (solved then) */
} preset_field;

typedef struct plugin {
    /* [main-thread] set at instantiate */
    fg_engine *engine;
    uint32_t max_block_frames;  /* the engine's */
    LV2_URID urid_midi_event;
    LV2_URID urid_long;
    LV2_URID urid_counter;
    LV2_Worker_Schedule *schedule;
    /* [audio-thread] */
    void *ports[PORT_COUNT];
    uint64_t discharge_count;   /* notes played so far: the seed stream; saved in state */
    uint32_t discharges, failures;
    /* [sim-thread] the worker's own */
    fg_tree *tree;
    fg_node *placed;            /* the tree moved to where the note is heard */
    size_t placed_capacity;
    preset_field fields[2];     /* spark balls, plasma ball */
    fg_voice_id held[128];      /* continuous voice of each held note, 0 if none */
} plugin;

/* The distance a note is played at: distance_m at note 60, doubled per
 * octave down and halved per octave up, within [0.05 m, 20 km]. */
double note_distance_m(double distance_m, uint8_t note);

/* Grows the tree for request into p->tree and posts it. [sim-thread]
 * Errors: those of the generators and of fg_engine_post. */
fg_result note_post(plugin *p, const work_request *request, fg_voice_id *id);

/* LV2 worker interface. */
LV2_Worker_Status plugin_work(LV2_Handle instance, LV2_Worker_Respond_Function respond,
                              LV2_Worker_Respond_Handle handle, uint32_t size, const void *data);
LV2_Worker_Status plugin_work_response(LV2_Handle instance, uint32_t size, const void *body);

/* LV2 state interface. */
const void *plugin_state_interface(void);

#endif
