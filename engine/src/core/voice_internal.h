/* A voice: one posted discharge, from fg_engine_post until collected.
 *
 * Ownership moves with the rings: the sim thread fills a free voice and
 * pushes it to the inbox; from then on only the audio thread touches its
 * playback state (and the per-ear caches in its events); once retired onto
 * the garbage ring it belongs to the sim thread again. */
#ifndef FULGUR_VOICE_INTERNAL_H
#define FULGUR_VOICE_INTERNAL_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "sound/abe_voice_internal.h"
#include "fulgur/engine.h"
#include "fg_rng.h"
#include "sound/wmwave_internal.h"

/* Overlapping emissions of one voice: strokes, or repeats of a continuous
 * discharge whose sound outlasts the interval. */
#define FG_MAX_INSTANCES 64

/* One segment, prepared at post time. Times are seconds after the emission
 * of the instance that plays it. */
typedef struct fg_event {
    double mid[3];        /* segment midpoint, metres (mirrored for a ground image) */
    double dir[3];        /* unit vector along the segment */
    double half_len_m;    /* l */
    double t0_s;          /* baseline half-duration with its fluctuation */
    double emit_s;        /* when the return stroke passes the midpoint, plus turbulence */
    double gain;          /* the ground's reflection coefficient for an image, else 1 */
    double start_s;       /* earliest waveform start, either ear, at the post pose */
    uint32_t segment;     /* index of the child node, for a stable order */
    bool main;            /* on the main channel */
    /* per-ear state for the pose with this serial */
    unsigned serial;
    double center_s[2];   /* WM: arrival of tau = 0 */
    union {
        fg_wm_shape shape[2];     /* FG_MODEL_WM */
        fg_abe_wave abe[2];    /* FG_MODEL_ABE: arrival relative to the emission */
    };
    uint8_t bus[2];       /* the filter bus of each ear (bus_internal.h) */
    float shadow[2];      /* head shadow: the share sent to the shadowed twin */
} fg_event;

typedef struct fg_instance {
    double offset_s;      /* emission time after the voice's emit time */
    uint32_t lo, hi;      /* events before lo are done; from hi on not yet begun */
    bool main_only;       /* dart leader: the main channel only */
} fg_instance;

typedef struct fg_voice {
    /* written by the sim thread before the post, read-only afterwards */
    fg_event *events;          /* sorted by start_s */
    uint32_t *main_index;      /* indices into events of the main channel, in order */
    uint32_t event_count, main_count;
    size_t extent;             /* offset of events/main_index in the engine storage */
    fg_sound_params sound;
    fg_propagation propagation;
    fg_voice_model model;
    double emit_time_s;        /* or FG_EMIT_NOW */
    double post_position[3];   /* listener centre when prepared */
    uint32_t strokes;
    double stroke_offset_s[FG_MAX_STROKES];
    bool continuous;
    double repeat_min_s, repeat_max_s, duration_s;
    fg_rng rng;                /* repeat intervals, drawn on the audio thread */
    uint32_t slot, generation;

    atomic_bool stop;          /* set by fg_engine_stop */

    /* audio thread */
    double emit_frame;         /* the emission on the engine clock */
    fg_instance inst[FG_MAX_INSTANCES];
    uint32_t inst_count;
    double next_repeat_s;      /* continuous: next emission; < 0 once ended */
} fg_voice;

#endif
