/* Discharges as source models: what the WM-wave and Abe's models share.
 *
 * A posted discharge (fg_discharge) becomes one voice of the discharge
 * kind: its segments turned into events sorted by arrival, in the kind's
 * segment storage; its strokes and continuous repeats played as instances
 * of that pattern; the window of events that can sound in each block;
 * lateness. All of that is one implementation (discharge_*.c and
 * discharge_schedule.h). The two models differ only in what an event is to
 * an ear: how many segments make one source point, the wave computed from
 * the ear's geometry, when it starts (fg_discharge_model), and how it is
 * added to the buses (the add function their render is built with). Each
 * model is one fg_source_ops entry (wm_model.c, abe_model.c) whose `model`
 * points at its fg_discharge_model; fg_engine_post picks the entry by
 * fg_discharge.model, in the one table of discharge_post.c. */
#ifndef FULGUR_DISCHARGE_INTERNAL_H
#define FULGUR_DISCHARGE_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "core/arena_internal.h"
#include "core/bus_internal.h"
#include "core/sort_internal.h"
#include "core/source_internal.h"
#include "fg_rng.h"
#include "fulgur/engine.h"
#include "abe_voice_internal.h"
#include "wmwave_internal.h"

/* Overlapping emissions of one voice: strokes, or repeats of a continuous
 * discharge whose sound outlasts the interval. */
#define FG_MAX_INSTANCES 64

/* Abe's wave as an ear keeps it: what depends on the path. The arrival
 * and the rate are the ear's center_s and rate, the rest fg_abe_defaults'
 * (abe_model.c), so that an event stays 224 bytes, not 328. */
typedef struct fg_abe_ear {
    double f0_hz;
    double peak_pa;
    double gamma;
} fg_abe_ear;

/* What one ear hears of one event, evaluated at the moment its wave
 * arrives: at the post (or when a still listener moves to another place)
 * for every instance, or afresh for each instance and block while the
 * listener moves (fg_event_ear_at). */
typedef struct fg_event_ear {
    double center_s;      /* arrival of the wave's centre, seconds after the instance's emission */
    double rate;          /* Doppler: the ear hears the wave rate times as long, 1 / (1 - d travel/dt) */
    union {               /* the model's wave, written by its wave function */
        fg_wm_shape wm;   /* the WM-wave (wm_model.c) */
        fg_abe_ear abe;   /* Abe's wave (abe_model.c) */
    };
    float shadow;         /* head shadow: the weight alpha - 1 sent to the shadowed twin */
    float band_w;         /* the share sent to bus + 1, the next distance band */
    float dir[3];         /* where the wave comes from, unit, in the head's frame (x
                           * ahead, y left, z up): the layout's encoding */
    uint8_t bus;          /* the filter bus (bus_internal.h) */
} fg_event_ear;

/* One source point (a segment, or every stride-th for Abe's model),
 * prepared at post time. Times are seconds after the emission of the
 * instance that plays it. */
typedef struct fg_event {
    double mid[3];        /* segment midpoint, metres (mirrored for a ground image) */
    double dir[3];        /* unit vector along the segment */
    double half_len_m;    /* l */
    double t0_s;          /* baseline half-duration with its fluctuation */
    double emit_s;        /* when the return stroke passes the midpoint, plus turbulence */
    double start_s;       /* earliest waveform start, either ear, at the post pose */
    bool main;            /* on the main channel */
    bool image;           /* the ground's image: weaker by the voice's ground_reflection */
    uint64_t serial;      /* the still listener ear[] was evaluated for */
    fg_event_ear ear[2];
} fg_event;

/* An event as seen from one ear at the moment its wave arrives. */
typedef struct fg_ear_path {
    const double *ear;    /* the ear's position */
    double d[3];          /* ear - midpoint */
    double r_m;           /* |d| */
    double gain;          /* the event's gain times the shadow-zone fade */
    double c_m_s;
} fg_ear_path;

#define FG_PLAY_BUSES 4

/* An ear's wave as one instance places it in one block (the model's
 * place, discharge_schedule.h). */
typedef struct fg_wave_place {
    union {
        fg_wm_event wm;   /* wm_model.c */
        fg_abe_wave abe;  /* abe_model.c */
    };
    long first, last;     /* its first and last sample, relative to the block */
} fg_wave_place;

/* Where ear ch of an event is added in this block, for one instance. */
typedef struct fg_event_play {
    const fg_engine_config *cfg; /* the layout */
    fg_bus_set *buses;
    /* the buses an ear's wave goes to and its weight on each (a zero one
     * is skipped): the distance band and the next one, each plain and
     * head-shadowed (its twin, + FG_BUS_PLAIN) */
    unsigned bus[FG_PLAY_BUSES];
    double share[FG_PLAY_BUSES];
    /* the output channels it goes to, each at its layout gain (never 0)
     * times its share of each bus */
    unsigned channels;
    unsigned ch[FG_LAYOUT_CHANNELS_MAX];
    double gain[FG_LAYOUT_CHANNELS_MAX];
    double origin_frame;  /* the instance's emission, samples after the block's start */
    double offset_s;      /* the instance's emission after the voice's */
    double fs_hz;
    double c_m_s;
    uint32_t frames;
    uint32_t ahead; /* how far the model adds: to the chunk's end (fg_block_context.ahead)
                     * when it writes ahead, else frames */
} fg_event_play;

/* What makes a discharge model, besides its render: fg_discharge_render_with
 * (discharge_schedule.h) bound to the functions that place an event's ear
 * in the block and add it to the buses. */
typedef struct fg_discharge_model {
    /* Segments per source point, for a tree of this many segments. */
    size_t (*stride)(size_t segments);
    /* Writes the wave of ev for an ear on this path into ear (its union;
     * its center_s and rate are set). [sim-thread at the post;
     * audio-thread when the listener moves] */
    void (*wave)(const fg_sound_config *sound, const fg_event *ev, const fg_ear_path *path,
                 fg_event_ear *ear);
    /* When an ear's wave of ev starts sounding, seconds after the emission. */
    double (*start_s)(const fg_event *ev, const fg_event_ear *ear, double c_m_s);
    /* Whether an ear's wave of ev has finite numbers at fs_hz and c_m_s
     * (the post refuses a discharge whose wave has not). */
    bool (*finite)(const fg_event *ev, const fg_event_ear *ear, double fs_hz, double c_m_s);
    /* The work bound's price (fg_engine_config.work_per_frame), beyond
     * the one unit every ear's evaluation costs: the units of adding an
     * ear's wave to one bus of one channel over the block (play's), 0 for
     * a wave that has ended before it; NULL for a wave of a few
     * closed-form terms whatever its length. Units are
     * priced by their measured CPU time (docs/limits.md). [audio-thread] */
    uint64_t (*path_units)(const fg_event_ear *ear, const fg_event_play *play);
    /* Its add writes a wave to the chunk's end (the accumulators), so that
     * a wave is visited once a chunk; else it adds the block alone, and
     * every sounding wave is visited every block. */
    bool writes_ahead;
} fg_discharge_model;

typedef struct fg_instance {
    double offset_s;      /* emission time after the voice's emit time */
    uint32_t lo, hi;      /* events before lo are done; from hi on not yet begun */
    /* a model writing ahead: the ears of the events before `ahead`, and
     * ears before ahead_ear of that one, are written to the chunk's end;
     * the events before `settled` to their own end, within the chunk; the
     * last sample they touch, on the engine clock */
    uint32_t ahead, ahead_ear, settled;
    double last_frame;
    bool main_only;       /* dart leader: the main channel only */
} fg_instance;

/* Whether a wave the instance wrote ahead may still sound from the block
 * starting at start_frame on (fg_wm_event_ended). */
static inline bool fg_instance_sounds_ahead(const fg_instance *in, double start_frame)
{
    return in->last_frame - start_frame >= -3.0;
}

/* A discharge voice's state (the kind's voice_bytes). */
typedef struct fg_discharge_voice {
    /* written by the sim thread before the post, read-only afterwards */
    const fg_discharge_model *model;
    fg_event *events;          /* sorted by start_s */
    uint32_t *main_index;      /* indices into events of the main channel, in order */
    uint32_t event_count, main_count;
    size_t extent;             /* offset of events/main_index in the kind's storage */
    fg_sound_config sound;
    fg_propagation_config propagation;
    double emit_time_s;        /* or FG_EMIT_NOW */
    double post_position[3];   /* listener centre when prepared */
    uint32_t strokes;
    double stroke_offset_s[FG_MAX_STROKES];
    bool continuous;
    double repeat_min_s, repeat_max_s, duration_s;
    fg_rng rng;                /* repeat intervals, drawn on the audio thread */

    /* audio thread */
    double emit_frame;         /* the emission on the engine clock */
    fg_instance inst[FG_MAX_INSTANCES];
    uint32_t inst_count;
    double next_repeat_s;      /* continuous: next emission; < 0 once ended */
    bool non_finite;           /* a wave turned non-finite: the voice is retired */
} fg_discharge_voice;

/* Scratch for preparing one tree, preallocated for the largest. path_m,
 * junction and main are done with before the arrival sort begins: they
 * lie in order_tmp's storage (13 of its 16 bytes a node). */
typedef struct fg_prep_scratch {
    double *path_m;        /* path length from the root */
    uint32_t *junction;    /* deepest main-channel ancestor (or self) */
    uint8_t *main;         /* node lies on the main channel */
    fg_sort_pair *order;   /* the arrival sort, and its scratch */
    fg_sort_pair *order_tmp;
} fg_prep_scratch;

/* The discharge kind's storage: the events of all live voices, by
 * extents of one arena of segment_capacity, and the prepare scratch. */
typedef struct fg_discharge_store {
    fg_event *events;
    uint32_t *main_index;
    fg_arena arena;
    fg_prep_scratch scratch;
} fg_discharge_store;

extern const fg_source_kind fg_discharge_kind;
/* The two entries (wm_model.c, abe_model.c). */
extern const fg_source_ops fg_source_wm;
extern const fg_source_ops fg_source_abe;

/* discharge_post.c: the kind's functions. */
/* How many events a checked discharge becomes under model m. */
size_t fg_discharge_events(const fg_discharge *d, const fg_discharge_model *m);
/* Validates a discharge's parameters other than the tree. */
fg_result fg_discharge_check(const fg_discharge *d);
/* A continuous discharge's repeat interval range, defaults filled in. */
void fg_discharge_repeat_range(const fg_discharge *d, double *min_s, double *max_s);
/* Gives the voice's events back to the storage. [sim-thread] */
void fg_discharge_release(void *voice, void *storage);

/* discharge_prepare.c: fills the voice from a checked discharge.
 * [sim-thread] Errors: FG_ERR_POOL_FULL no segment space now;
 * FG_ERR_NOT_FINITE a wave at the pose now is not finite. */
fg_result fg_discharge_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                               const fg_post_context *post);

/* discharge_schedule.c: takes the voice up. [audio-thread] */
void fg_discharge_adopt(void *voice, const fg_block_context *block);

/* discharge_event.c: event ev of voice v as heard by ear k of still ears,
 * into ev->ear[k], reading the speed of sound and the bus set's bands. */
void fg_event_geometry(const fg_discharge_voice *v, fg_event *ev, const fg_ears *ears, int k,
                       double c_m_s, const fg_bus_set *buses);

/* Event ev of voice v as ear k hears it when the instance emitting at
 * emission_s (engine clock) reaches it along the listener's trajectory:
 * the arrival solved on the trajectory, the geometry and Doppler rate
 * there. [audio-thread] */
void fg_event_ear_at(const fg_discharge_voice *v, const fg_event *ev, const fg_trajectory *traj,
                     const fg_engine_config *cfg, double emission_s, int k,
                     const fg_bus_set *buses, fg_event_ear *out);

#endif
