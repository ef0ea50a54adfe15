/* fulgur view: a window (or a headless EGL context) over gpu/'s picture,
 * with the engine sounding what it shows. One piece a file:
 *
 *   view.c        [gpu-thread] the frame loop: input events, the camera,
 *                 the picture; starts and joins the other two threads
 *   view_timeline.c [gpu-thread] the scene's timed discharges, played from
 *                 the start (and again on R), and the camera that follows
 *                 them
 *   view_overlay.c [gpu-thread] the controls and live counters over the
 *                 picture (FreeType text)
 *   view_input.c  the one input path: GLFW callbacks (view_window.c) and
 *                 the headless script both become view_events, applied by
 *                 view_apply to the state
 *   view_request.c [gpu-thread] the requests to the sim thread and their
 *                 rings
 *   view_sim.c    [sim-thread] grows trees (generators, charges), posts
 *                 them, answers with the tree and its stroke offsets; feeds
 *                 the scene's fires and moves them
 *   view_audio.c  [audio-thread] pulls fg_engine_render into an audio driver,
 *                 keeping the last callbacks' durations for the overlay
 *   view_gate.c   the headless lock-step between frames and audio; stopping
 *   view_options.c, view_window.c  the command line; GLFW's callbacks
 *
 * The frame thread and the sim thread talk through two single-producer,
 * single-consumer rings (view_ring): requests one way, grown trees back.
 * Time: the picture's clock is the engine's clock, so a flash added at a
 * discharge's emit time lights up when its sound starts there.
 *   window    the audio thread is paced by the monotonic clock, one block
 *             per block period, like a sound card; frames are drawn at the
 *             engine's time as it runs.
 *   headless  lock-step and deterministic: frame k is drawn at k / fps;
 *             before the audio thread may render past it, every request of
 *             that frame has been answered (posted) by the sim thread. */
#ifndef HOST_VIEW_VIEW_H
#define HOST_VIEW_VIEW_H

#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "common/audio_driver.h"
#include "common/live_audio.h"
#include "common/options.h"
#include "common/sofa_hrir.h"
#include "fulgur/gpu.h"
#include "scene/scene.h"
#include "scene/scene_fire_render.h"
#include "fg_ring.h"

#define VIEW_MAX_CHARGES 64
/* A discharge is emitted this long after the frame that asked for it: time
 * for the sim thread to grow and post it before the audio thread is there. */
#define VIEW_LEAD_S 0.05
/* A scene's timed discharge is asked of the sim thread this long before
 * its emit time, so that its leader is drawn from its start. */
#define VIEW_TIMELINE_AHEAD_S 0.25
#define VIEW_RING_SIZE 64 /* requests or trees in flight each way */
/* The audio callbacks whose durations the overlay's p99 is taken over. */
#define VIEW_RECENT_CALLBACKS 512

typedef enum view_event_kind {
    VIEW_EV_DISCHARGE, /* space */
    VIEW_EV_HOLD,      /* H: start a continuous discharge, or stop it */
    VIEW_EV_CLEAR,     /* C: remove the charges */
    VIEW_EV_REPLAY,    /* R: play the scene's timed discharges again, from now */
    VIEW_EV_FRAME,     /* F: frame the scene's latest discharge and follow them again */
    VIEW_EV_OVERLAY,   /* F1: show or hide the controls and counters */
    VIEW_EV_QUIT,      /* Esc, or the window closed */
    VIEW_EV_CLICK,     /* x, y in 0..1 from the top left; sign +1 left, -1 right */
    VIEW_EV_ORBIT,     /* dx, dy: drag in window widths / heights */
    VIEW_EV_ZOOM       /* dy: scroll steps, positive is closer */
} view_event_kind;

typedef struct view_event {
    uint32_t frame;    /* script: the frame it happens before */
    view_event_kind kind;
    double x, y;       /* click position, or drag / scroll amounts */
    int sign;          /* click: +1 positive charge, -1 negative */
} view_event;

/* The requests and the grown trees travel as pointers through fg_ring
 * (one producer thread, one consumer thread each): push returns false when
 * the ring is full, pop NULL when it is empty. */
bool view_ring_push(fg_ring *r, void *item);
void *view_ring_pop(fg_ring *r);

typedef enum view_request_kind {
    VIEW_REQ_ONE,   /* space: the scene's first discharge anew, or a leader between charges */
    VIEW_REQ_HOLD,  /* H: a continuous discharge until the next VIEW_REQ_STOP */
    VIEW_REQ_STOP,
    VIEW_REQ_SCENE  /* one of the scene's timed discharges, as the scene gives it */
} view_request_kind;

/* Frame thread to sim thread: owned by whoever holds it; the sim thread
 * turns it into the reply (same allocation, answered in place). */
typedef struct view_request {
    view_request_kind kind;
    double emit_s;                      /* engine clock */
    size_t scene_index;                 /* VIEW_REQ_SCENE: which discharge */
    uint64_t seed;
    size_t charge_count;                /* 0: the scene's first discharge */
    fg_point_charge charges[VIEW_MAX_CHARGES];
    double step_m;                      /* charges: the leader's step */
    /* the reply */
    fg_node *nodes;                     /* malloc'd by the sim thread; freed by the frame thread */
    size_t node_count;
    double strokes_s[FG_MAX_STROKES];
    uint32_t stroke_count;
    fg_discharge post;                  /* as posted (its nodes: the reply's) */
    fg_preset preset;                   /* its sound's, which also colours its picture */
    char error[256];                    /* non-empty: nothing was posted */
} view_request;

typedef struct view_options {
    const char *scene_path;
    fgg_backend backend;
    audio_output audio;
    uint32_t frames;         /* 0: until Esc (window); headless needs a count */
    double fps;              /* 60 */
    option_size size;        /* 960 x 540 */
    const char *png_dir;     /* headless: frame_0000.png, ... */
    const char *script_path;
    scene_layout_choice layout; /* over the scene's "layout" */
    const char *sofa;        /* the binaural layout's HRIRs, over layout.sofa */
} view_options;

typedef struct view_camera {
    double target_m[3];
    double distance_m, azimuth_rad, elevation_rad, fov_y_deg;
} view_camera;

typedef struct view_overlay view_overlay;

typedef struct view {
    view_options opt;
    scene *s;
    fg_engine *engine;
    fgg_picture *pic;        /* the frame thread's */
    double rate_hz;
    uint32_t block_frames;
    view_camera cam;
    /* the scene's timeline: the discharges by time, when the scene started
     * playing (0, or the last R), and each one's framing, worked out before
     * the threads start */
    size_t *order;
    size_t next, next_framed; /* the next to ask for, and to turn the camera to */
    double timeline_start_s;
    view_camera *framing;
    bool follow;             /* the camera eases to each timed discharge's framing */
    view_camera goal;
    size_t framed;           /* the discharge the camera frames */
    fg_point_charge charges[VIEW_MAX_CHARGES];
    uint32_t markers[VIEW_MAX_CHARGES]; /* each charge's marker on the picture */
    size_t charge_count;
    bool overlay_on;
    view_overlay *overlay;   /* NULL: no font (no FreeType in this build) */
    bool holding;
    uint32_t hold_flash;     /* the held flash's id on the picture; 0 none */
    bool quit;
    uint64_t requests, replies, seed_counter;
    uint64_t posted;         /* replies without an error */
    double now_s;            /* the picture clock of the frame being made */
    uint32_t frames_drawn;

    /* the scene's aero objects and fires, posted before the threads start
     * (each sounds from its own time, once: R replays the discharges only) */
    fg_voice_id *aero_ids;
    bool *aero_done;         /* the frame thread's: collected, no more poses */
    uint32_t *source_ids;    /* the frame thread's: their picture (fires first) */
    char frame_error[512];   /* an object's pose refused: the run ends */
    scene_fire_job fires;    /* the sim thread's once it starts */
    uint64_t fire_pose_tick; /* the sim thread's: the next frame tick of fire poses */
    char sim_error[512];     /* a fire's sound failed: the run ends */
    /* headless: the audio frame the fires must be followed to (their poses
     * published, their rings filled) before the audio may render up to it,
     * set by the frame thread; and how far the sim thread has followed them */
    _Atomic uint64_t fire_target, fire_done;

    fg_ring to_sim, from_sim;
    pthread_mutex_t lock;    /* the gates below; never held by the audio path's render */
    pthread_cond_t changed;
    uint64_t audio_target;   /* headless: the audio thread may render up to here */
    _Atomic uint64_t audio_done; /* frames rendered */
    atomic_bool stop;
    audio_driver driver;
    live_audio *live;        /* window with a live device: its callback renders */
    float *planes[SCENE_MAX_CHANNELS]; /* the layout's channels */
    sofa_hrirs hrirs;        /* the binaural layout's, read at the view's rate */
    char audio_error[512];
    fg_result render_result;
    /* the durations of the last audio callbacks, microseconds, written by
     * the audio thread and read by the overlay */
    _Atomic uint32_t recent_us[VIEW_RECENT_CALLBACKS];
    _Atomic uint64_t callbacks;
} view;

/* Reads the arguments after "view" into *o, as options_parse does
 * (common/options.h): OPTIONS_HELP after the help, OPTIONS_BAD after the
 * message. */
options_result view_parse_options(int argc, char **argv, view_options *o);

/* Reads a script: lines "frame N key space|h|c|r|f|f1|escape", "frame N click X Y
 * left|right", "frame N drag DX DY", "frame N scroll S"; '#' comments.
 * *events is malloc'd, sorted by frame (stable). Returns 0, or -1 with a
 * message naming the line. */
int view_script_load(const char *path, view_event **events, size_t *count, char *err,
                     size_t err_size);

/* The one place input changes the viewer: camera, charges, requests. */
void view_apply(view *v, const view_event *e);

/* The camera as gpu/ takes it. */
void view_camera_get(const view_camera *c, fgg_camera *out);
/* A scene camera as the viewer's orbit. */
void view_camera_set(view_camera *c, const scene_camera *sc);

/* view_request.c: asks the sim thread for a discharge (kind; index for
 * VIEW_REQ_SCENE) emitted at emit_s on the engine clock. */
void view_request_discharge(view *v, view_request_kind kind, size_t index, double emit_s);

/* view_timeline.c — the scene's timeline and the following camera.
 * Works out every discharge's framing (before the threads start).
 * Returns 0, or -1 out of memory. */
int view_timeline_init(view *v);
void view_timeline_deinit(view *v);
/* Asks for the timed discharges due by now_s, and moves the camera one
 * frame of dt_s towards its goal. */
void view_timeline_step(view *v, double dt_s);
/* Plays the scene again from now. */
void view_timeline_replay(view *v);
/* Frames the latest timed discharge and follows them again. */
void view_timeline_frame(view *v);

/* view_overlay.c — the controls and counters. Creates the overlay's font
 * (fontconfig's "monospace" through FreeType) for a picture height.
 * Returns NULL with why in err when there is none. */
view_overlay *view_overlay_create(int picture_height, char *err, size_t err_size);
void view_overlay_destroy(view_overlay *o);
/* Lays the overlay over the picture, or takes it away when hidden. */
void view_overlay_show(view *v);

/* Window input: installs GLFW callbacks that call view_apply. Returns -1
 * when this build has no GLFW. [gpu-thread] */
int view_window_attach(view *v, fgg_context *ctx);
/* Polls the window's events; false once it should close. [gpu-thread] */
bool view_window_poll(view *v, fgg_context *ctx);

/* view_gate.c — asks the other threads to finish and wakes the waiting
 * ones. [any-thread] */
void view_stop(view *v);
/* Headless: the audio thread may render up to engine frame target.
 * [gpu-thread] */
void view_release_audio(view *v, uint64_t target);
/* Headless audio thread at engine frame `frames`: waits for a target past
 * it; the frames of the next block (at most block_frames), 0 on stop. */
uint32_t view_wait_target(view *v, uint64_t frames, uint32_t block_frames);
/* The audio thread has rendered `frames` (audio_done; wakes a waiter). */
void view_announce_audio(view *v, uint64_t frames);
/* Headless: waits until the audio has rendered up to the target, or stop.
 * [gpu-thread] */
void view_wait_audio(view *v);

void *view_sim_thread(void *arg);
void *view_audio_thread(void *arg);
/* The live device's callback: one block into the device's planes, zeros
 * once stopping. [audio-thread] */
void view_live_process(void *user, float *const *planes, uint32_t frames);

/* --audio jack, portaudio or auto (the default) in a window: opens the
 * device (auto: a running JACK server, else PortAudio's default output,
 * else none, which it says on stderr), setting *rate_hz to its rate.
 * Headless runs lock-step and takes no live device: auto is null there, and
 * jack or portaudio are refused. Returns 0, or -1 with a message and *rc
 * (CLI_USAGE when the device asked for is not there). [main-thread] */
int view_open_live(view *v, double *rate_hz, int *rc, char *err, size_t err_size);

#endif
