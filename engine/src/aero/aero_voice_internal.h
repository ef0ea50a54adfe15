/* The aero object as a source model (core/source_internal.h): its kind,
 * its voice state and its model.
 *
 * The frame thread publishes the object's poses into the voice's own pose
 * queue, as fg_listener records (forward: the normal, up: axis x normal,
 * so the trajectory's right is the axis); the audio thread absorbs them
 * into the voice's own fg_trajectory, the listener's interpolation. At
 * every FG_CONTROL_FRAMES-th frame of the engine clock, for every
 * source and ear, the emission time heard there is solved from the two
 * trajectories and the texture position advanced to it; the samples
 * between two such control frames are read with the emission time,
 * texture position and the dipole's projections on the ear interpolated
 * linearly (aero_voice.c). The control frames are the clock's, not the
 * host's blocks: a render does not depend on the block it is rendered
 * in. */
#ifndef FULGUR_AERO_VOICE_INTERNAL_H
#define FULGUR_AERO_VOICE_INTERNAL_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "core/listener_internal.h"
#include "core/source_internal.h"
#include "core/trajectory_internal.h"
#include "fulgur/aero.h"
#include "fulgur/aero_object.h"

/* Where one source stands for one ear at one emission time: a control
 * frame, the end of one interpolation and the start of the next. */
typedef struct fg_aero_end {
    double tau_s;      /* emission time heard at the ear */
    double position;   /* texture position, in texture frames */
    fg_aero_lookup lookup;
    double coef[3];    /* per texture component: the pressure at the ear per
                          unit sample (scale, span, gain, projection, 1/(4 pi c r^2)) */
    double dir[3];     /* unit, the head's frame at the hearing time (x ahead,
                          y left, z up): where the wave comes from, for the
                          layout's gains (spatial/layout_internal.h) */
    double speed_m_s;  /* the cross-flow's there */
} fg_aero_end;

typedef struct fg_aero_source_state {
    double along_m;    /* from the origin along the axis */
    double span_m;     /* 2-D: the span it stands for; 3-D: 1 */
    uint32_t texture_source;
    fg_aero_end end[2];  /* per ear, at the voice's control frame */
    double rate[2];      /* texture frames per second of emission time there */
    fg_aero_end next[2]; /* at the control frame after it, once next_ready */
    double next_rate[2];
} fg_aero_source_state;

/* The frame thread's latest wind for the audio thread: a triple buffer.
 * The one writer fills slot[back] and swaps it for the middle slot, marked
 * fresh; the audio thread, when the middle is fresh, swaps it for its
 * front slot. Both swaps are one atomic exchange (acquire-release), so the
 * slots' contents pass with them: wait-free, no torn value, latest wins. */
typedef struct fg_aero_wind_box {
    fg_aero_wind slot[3];
    atomic_uint middle;        /* the middle slot's index, | FG_AERO_WIND_FRESH unread */
    unsigned back;             /* the writer's */
    unsigned front;            /* the audio thread's */
} fg_aero_wind_box;

#define FG_AERO_WIND_FRESH 4u

typedef struct fg_aero_voice {
    fg_pose_queue queue;       /* the frame thread's poses */
    fg_aero_wind_box wind_box; /* the frame thread's winds */
    fg_trajectory path;        /* audio thread: the poses absorbed */
    uint64_t poses_seen;
    const fg_aero_texture *texture;
    const fg_aero_texture_desc *tex;
    fg_aero_body body;
    /* audio thread: the wind is wind_from until emission time wind_change_s,
     * then blends into wind over FG_AERO_WIND_RAMP_S (aero_wind.c); a newer
     * wind waits in wind_next until every source has passed the blend */
    fg_aero_wind wind_from, wind, wind_next;
    double wind_change_s;
    bool wind_waiting;
    double gain;
    unsigned bus;              /* its distance band (or the dry bus) */
    double next_share;         /* the share of the next band (ISO 9613-1's split) */
    double emit_s;             /* engine clock of the emission's start */
    double end_s;              /* of its end (the start of the fade out); INFINITY until known */
    double duration_s;
    /* audio thread: the sources' end[] are at control_frame once started
     * (from the control frame at or before the emission, or the adoption
     * when that is later), and their next[] at the one after once
     * next_ready */
    uint64_t control_frame;
    bool started, next_ready;
    uint32_t source_count;
    fg_aero_source_state source[FG_AERO_OBJECT_MAX_SOURCES];
    /* read by other threads */
    atomic_uint_least64_t blocks, beyond_range_blocks, max_speed_um_s;
} fg_aero_voice;

/* The aero object kind and its one model. */
extern const fg_source_kind fg_aero_kind;
extern const fg_source_ops fg_aero_ops;

/* The model's prepare (aero_object.c). [sim-thread] */
fg_result fg_aero_prepare(const fg_source_ops *ops, void *voice, const void *desc,
                          const fg_post_context *post);

/* The fg_listener record the trajectory keeps for pose (checked). */
void fg_aero_pose_record(const fg_aero_pose *pose, fg_listener *out);

/* The wind at time t_s: its velocity times (1 + gust n(t)). */
void fg_aero_wind_at(const fg_aero_wind *w, double t_s, double out[3]);

/* The voice's wind at emission time t_s, through its blend. [audio-thread] */
void fg_aero_voice_wind_at(const fg_aero_voice *v, double t_s, double out[3]);

/* Sets the voice's winds to w, nothing waiting or blending. [sim-thread] */
void fg_aero_wind_box_init(fg_aero_voice *v, const fg_aero_wind *w);

/* Publishes w (checked) for the voice. [any-thread but audio, one writer] */
void fg_aero_wind_box_push(fg_aero_voice *v, const fg_aero_wind *w);

/* Takes the newest published wind and, once every source's emission time
 * (oldest_tau_s the earliest) has passed the running blend, starts
 * blending into it at now_s. [audio-thread] */
void fg_aero_voice_take_wind(fg_aero_voice *v, double oldest_tau_s, double now_s);

/* The sources a stick of length_m splits into with texture reference d_m
 * (the correlation length 3 d_m), at least 1. */
uint32_t fg_aero_default_sources(double length_m, double d_m);

#endif
