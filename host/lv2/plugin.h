/* The fulgur LV2 instrument: what its files share.
 *
 * Threads (LV2's classes mapped onto fulgur's tags):
 *   run()                 [audio-thread]  reads the ports and the MIDI, hands
 *                                         each note to the worker through
 *                                         schedule_work, renders the engine
 *   work()                [sim-thread]    the LV2 worker: collects finished
 *                                         voices, grows the tree, posts it,
 *                                         stops held notes; reads a SOFA
 *                                         file into a new engine, destroys
 *                                         the engines run() let go; one at
 *                                         a time
 *   work_response()       [audio-thread]  called by the host inside/after run();
 *                                         a new engine it hands over plays
 *                                         from the next run()
 *   instantiate, cleanup,
 *   state restore         [main-thread]   never concurrent with run() or work()
 *   state save            [main-thread]   may run while run() does (state.c)
 * Everything run() reads that the worker writes comes back through
 * work_response; the engine's own rings carry the voices. */
#ifndef HOST_LV2_PLUGIN_H
#define HOST_LV2_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#include <lv2/atom/forge.h>
#include <lv2/core/lv2.h>
#include <lv2/log/logger.h>
#include <lv2/urid/urid.h>
#include <lv2/worker/worker.h>

#include "fulgur/fulgur.h"

/* FULGUR_LV2_URI, the stereo plugin's URI, comes from
 * host/lv2/CMakeLists.txt, which writes it into the Turtle too; the other
 * layouts' plugins are FULGUR_LV2_URI "-binaural" and "-ambisonics1".."3"
 * (plugin.c's table, the Turtle's variants). */
#ifndef FULGUR_LV2_URI
#error "FULGUR_LV2_URI is defined by host/lv2/CMakeLists.txt"
#endif
/* State property: how many discharges this instance has triggered, the
 * position in its seed stream. */
#define FULGUR_LV2_COUNTER_URI FULGUR_LV2_URI "#discharge-count"
/* The binaural plugin's parameter (patch:writable, an atom:Path): the SOFA
 * file its HRIRs are read from; saved with the state. */
#define FULGUR_LV2_SOFA_URI FULGUR_LV2_URI "#sofa"

/* Port indices, as in fulgur.ttl. Output channel 0 and 1 (the ears; ACN 0
 * and 1) are ports 1 and 2, as they always were; an ambisonic plugin's
 * further channels k = 2.. are ports PORT_COUNT + k - 2, the binaural
 * plugin's notify output (patch:Set of its SOFA file) is port PORT_COUNT
 * and its latency output (lv2:reportsLatency) port PORT_COUNT + 1. */
typedef enum port_index {
    PORT_MIDI_IN = 0,
    PORT_OUT_LEFT,     /* channel 0 */
    PORT_OUT_RIGHT,    /* channel 1 */
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
    PORT_COUNT,
    PORT_NOTIFY = PORT_COUNT,  /* binaural only */
    PORT_LATENCY               /* binaural only: FG_BINAURAL_LATENCY_FRAMES */
} port_index;

/* Output channels at most (third-order ambisonics), and ports. */
#define PLUGIN_CHANNELS_MAX 16u
#define PLUGIN_PORTS_MAX (PORT_COUNT + PLUGIN_CHANNELS_MAX - 2)

/* One plugin of the bundle: its URI and the engine's layout. */
typedef struct plugin_variant {
    LV2_Descriptor descriptor;
    fg_layout layout;
    uint32_t ambisonic_order;   /* ambisonics: 1..3 */
} plugin_variant;

/* The port of output channel k. */
uint32_t plugin_channel_port(uint32_t k);

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

/* What run() asks of the worker. Every request starts with its kind. */
typedef enum request_kind {
    REQUEST_NOTE_ON = 1,
    REQUEST_NOTE_OFF = 2,
    REQUEST_SOFA = 3,     /* sofa_request: read a SOFA file, make an engine of it */
    REQUEST_RETIRE = 4    /* retire_request: an engine the audio thread has let go */
} request_kind;

/* run() -> work(): copied by the host. */
typedef struct work_request {
    request_kind kind;
    uint8_t note, velocity;   /* MIDI, velocity 1..127 */
    uint64_t seed;            /* the discharge's seed */
    note_controls controls;
} work_request;

/* The longest SOFA path the plugin takes, its terminating zero included. */
#define SOFA_PATH_BYTES 4096u

/* run() -> work(): a patch:Set of the SOFA file. Only the path and its
 * zero are sent (the request is cut after them), or an empty path when it
 * was too long (length then says how long it was). */
typedef struct sofa_request {
    request_kind kind;
    uint32_t length;            /* strlen of the path given */
    char path[SOFA_PATH_BYTES];
} sofa_request;

/* run() -> work(): the engine of slot, no longer rendered. */
typedef struct retire_request {
    request_kind kind;
    uint32_t slot;
    uint32_t generation;        /* plugin.generation when sent */
} retire_request;

/* work() -> work_response(): what became of a request; for REQUEST_SOFA,
 * result FG_OK means slot holds the new engine. */
typedef struct work_reply {
    request_kind kind;
    fg_result result;
    uint32_t slot;
    uint32_t generation;        /* plugin.generation when made */
} work_reply;

/* An engine the plugin holds, with the SOFA file it was made from ("" but
 * in binaural). A slot's engine is created and destroyed by the worker
 * (and by instantiate, restore and cleanup); the audio thread renders the
 * slots the responses hand it and hands them back (REQUEST_RETIRE). */
#define ENGINE_SLOTS 4u
typedef struct engine_slot {
    fg_engine *engine;          /* NULL: free */
    char sofa[SOFA_PATH_BYTES];
} engine_slot;

/* After the engine being swapped out has no voice left, it is rendered
 * this much longer (its buses' and filters' tails), then retired. */
#define RETIRE_TAIL_S 0.25

/* Fields of Matsuyama's presets, grown in on the worker. */
typedef struct preset_field {
    fg_field_scene setup;
    fg_field *field;     /* NULL until the first note of the preset (solved then) */
} preset_field;

typedef struct plugin {
    /* [main-thread] set at instantiate */
    const plugin_variant *variant;
    double rate_hz;
    uint32_t channels;          /* output channels: (order + 1)^2 or 2 */
    uint32_t max_block_frames;  /* the engine's */
    LV2_URID urid_midi_event;
    LV2_URID urid_long;
    LV2_URID urid_counter;
    LV2_URID urid_sofa, urid_path, urid_object, urid_blank, urid_urid, urid_patch_set,
        urid_patch_get, urid_patch_property, urid_patch_value;
    LV2_URID_Map *map;
    LV2_Worker_Schedule *schedule;
    LV2_Log_Logger logger;      /* the host's log, else stderr; not from run() */
    /* the engines: see engine_slot */
    engine_slot slots[ENGINE_SLOTS];
    /* [main-thread] restores that replaced the engines: a swap's reply or
     * retire request of an earlier generation names a slot restore has
     * destroyed (and may have reused), and is dropped */
    uint32_t generation;
    /* [audio-thread] */
    void *ports[PLUGIN_PORTS_MAX];
    _Atomic uint32_t playing;   /* the slot rendered (read by state save) */
    int32_t retiring;           /* the slot playing out after a swap, -1 none */
    int32_t swap_to;            /* a swap's reply: the slot to play from the next run(), -1 none */
    uint64_t retire_frames;     /* frames it still plays once its voices are done */
    int notify_pending;         /* the SOFA file to say on the notify port */
    LV2_Atom_Forge forge;       /* writes the notify port */
    float scratch[PLUGIN_CHANNELS_MAX][256]; /* the retiring engine's output */
    sofa_request sofa_out;      /* a request being built */
    uint64_t discharge_count;   /* notes played so far: the seed stream; saved in state */
    uint32_t discharges, failures;
    /* [sim-thread] the worker's own */
    uint32_t posting;           /* the slot notes are posted to: the newest */
    fg_tree *tree;
    fg_node *placed;            /* the tree moved to where the note is heard */
    size_t placed_capacity;
    preset_field fields[2];     /* spark balls, plasma ball */
    fg_voice_id held[128];      /* continuous voice of each held note, 0 if none */
    uint32_t held_slot[128];    /* the slot whose engine holds it */
} plugin;

/* Creates the variant's engine at p->rate_hz into a free slot, reading
 * sofa (binaural; NULL: SOFA_DEFAULT_FILE) for its HRIRs, with the
 * listener set. [main-thread] or [sim-thread] (reads a file, allocates).
 * Returns the slot, or -1 with a message in err naming the file and what
 * is wrong (sofa_hrirs_read's), or that every slot is in use. */
int engine_slot_create(plugin *p, const char *sofa, char *err, size_t err_size);

/* Destroys the slot's engine and frees it; held notes on it are forgotten. */
void engine_slot_destroy(plugin *p, uint32_t slot);

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
