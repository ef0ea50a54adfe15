/* fulgur run: the engine embedded the way a VR application embeds it, with
 * three threads sharing one run_ctx.
 *
 *   frame thread  run_frame.c  the listener at 90 Hz: fg_engine_set_listener,
 *                              and each aero object's pose from its motion
 *   sim thread    run_sim.c    builds trees, fg_engine_post at their time,
 *                              retries a full pool/queue, fg_engine_collect;
 *                              feeds each fire's sound and moves it
 *   audio thread  run_audio.c  a driver pulling fg_engine_render per block
 *
 * Two ways to keep time (run_gate.c):
 *   paced      (--audio null) the audio thread sleeps to absolute deadlines
 *              one block period apart, like a sound card; the frame thread
 *              to its own 90 Hz deadlines; the sim thread polls the engine
 *              clock every RUN_SIM_POLL_NS. Timing is real, output varies.
 *              A live device (--audio jack, portaudio) is paced by its own
 *              clock: its callback takes the audio thread's place.
 *   lock-step  (wav, raw) as fast as possible and deterministic: before
 *              each block the audio thread waits until the sim thread has
 *              posted everything due at the engine clock and the frame
 *              thread has set the pose of the latest 90 Hz tick on that
 *              clock. Equal scene and options give equal samples.
 *
 * Aero objects and fires are posted by run.c before the threads start
 * (each sounds from its own emit time), so the first adoptions are theirs
 * and the frame thread knows the objects' ids from its first tick. The
 * fires' job (scene_fire_render.h) is the sim thread's once they start:
 * each pass it publishes the moving fires' poses at the 90 Hz ticks up to
 * a tick past the block and pushes each stream as far as its ring takes,
 * so in lock-step a block never starts short of its fire samples.
 *
 * Ownership: everything in run_ctx is allocated by run.c before the
 * threads start and freed after they are joined. Each measurement array is
 * written by one thread only and read by run_report.c after the join. */
#ifndef HOST_RUN_RUN_H
#define HOST_RUN_RUN_H

#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "common/audio_driver.h"
#include "common/live_audio.h"
#include "common/options.h"
#include "common/sofa_hrir.h"
#include "run_hist.h"
#include "scene/scene.h"
#include "scene/scene_fire_render.h"

/* The sim thread's polling period in paced mode: part of the post path. */
#define RUN_SIM_POLL_NS 500000
/* A discharge refused for a full pool or queue is retried each block for
 * this long after its time (engine clock), then dropped and counted. */
#define RUN_RETRY_LIMIT_S 1.0
/* Random head motion for a scene with one fixed pose: peak translation and
 * yaw (the frame thread's sway, run_frame.c). */
#define RUN_SWAY_M 0.03
#define RUN_SWAY_YAW_RAD 0.17
/* The frame thread publishes each tick the head's pose this many ticks
 * ahead (a VR runtime's predicted display time). */
#define RUN_POSE_LEAD_TICKS 1
/* The largest segment capacity run asks of the engine (--segments). */
#define RUN_MAX_SEGMENTS (1u << 24)

typedef struct run_options {
    const char *scene_path;
    audio_output audio;
    uint32_t block_frames;    /* 0: the scene's */
    uint32_t rate_hz;         /* 0: the scene's */
    double seconds;           /* 0: the scene's duration, else until all have sounded */
    double frame_hz;          /* 90 */
    uint32_t voices;          /* 0: the engine's default (64) */
    uint32_t segments;        /* 0: the engine's default, or the explicit trees' total */
    const char *report_path;  /* NULL: stdout, or stderr when the audio is on stdout */
    scene_layout_choice layout; /* over the scene's "layout" */
    const char *sofa;         /* the binaural layout's HRIRs, over layout.sofa */
} run_options;

/* The lock-step handshake: a mutex and condition over three clocks. */
typedef struct run_gate {
    pthread_mutex_t lock;
    pthread_cond_t changed;
    uint64_t engine_frames;   /* published by the audio thread after each block */
    uint64_t sim_frames;      /* everything due before this engine clock is posted */
    uint64_t frame_tick;      /* the latest 90 Hz tick whose pose is set */
    bool frame_started;       /* frame_tick is valid */
} run_gate;

typedef struct run_ctx {
    run_options opt;
    scene *s;
    fg_engine *engine;
    bool paced;
    uint32_t block_frames;
    double rate_hz;
    uint64_t limit_frames;    /* stop here (the cap when until_done) */
    bool until_done;          /* stop when every discharge has sounded */
    size_t *order;            /* discharge indices in posting order */
    uint64_t start_ns;        /* CLOCK_MONOTONIC when the threads start */
    run_gate gate;
    atomic_bool stop;
    atomic_bool sim_done;     /* every discharge posted or dropped, every fire over */

    /* sim thread's */
    size_t posts;             /* successful posts: the first `posts` of each array */
    uint64_t *post_frame;     /* engine clock at post, frames */
    uint64_t *post_ns;        /* wall clock at post */
    double *post_event_s;     /* the discharge's time */
    uint64_t refused;         /* posts refused for a full pool or queue */
    size_t dropped;           /* discharges given up after RUN_RETRY_LIMIT_S */
    run_hist post_call;       /* fg_engine_post's own duration */
    char sim_error[512];      /* a build or post error ends the run */
    bool sim_error_in_scene;  /* ... and it was the scene's fault (a generator's) */
    scene_fire_job fires;     /* posted by run.c, then fed and moved here */
    uint64_t fire_pose_tick;  /* the next 90 Hz tick whose fire poses are due */

    /* audio thread's (or the live device's callback's) */
    audio_driver driver;
    live_audio *live;         /* --audio jack or portaudio: NULL otherwise */
    char live_description[160]; /* what it was, for the report */
    uint64_t live_xruns;      /* the device's over- and underruns, once closed */
    float *planes[SCENE_MAX_CHANNELS]; /* the layout's channels */
    uint64_t adopted;         /* voices seen adopted */
    uint64_t *adopt_frame;    /* block start, by post order */
    uint64_t *adopt_ns;       /* wall clock at that block's render call */
    run_hist callback;        /* fg_engine_render's duration */
    uint64_t over_budget, over_half_budget;
    uint64_t frames_out;
    fg_result render_result;  /* a failed render ends the run */
    char audio_error[512];    /* a failed driver write ends the run */

    /* set before the threads start */
    fg_voice_id *aero_ids;    /* per aero object, posted in scene order */
    sofa_hrirs hrirs;         /* the binaural layout's, read at the run's rate */

    /* frame thread's */
    bool *aero_done;          /* collected: its poses are no longer set */
    uint64_t aero_poses_set;
    char frame_error[512];    /* an aero pose refused ends the run */
    uint64_t frames_set;
    run_hist jitter;          /* wake-up minus deadline, paced only */
} run_ctx;

/* Reads the arguments after "run" (argv[0]) into *o, as options_parse
 * does (common/options.h): OPTIONS_HELP after the help, OPTIONS_BAD after
 * the message. */
options_result run_parse_options(int argc, char **argv, run_options *o);

void *run_frame_thread(void *arg);
void *run_sim_thread(void *arg);
void *run_audio_thread(void *arg);
/* The live device's callback: what run_audio_thread does for one block,
 * then zeros once the run is over. [audio-thread] */
void run_live_process(void *user, float *const *planes, uint32_t frames);

/* The report as JSON text (caller frees), NULL when out of memory. */
char *run_report_json(const run_ctx *run, double wall_s);

#endif
