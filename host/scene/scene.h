/* A scene file: what to render, parsed from JSON (docs/scene-format.md).
 *
 * Two steps. scene_parse checks the whole file and fills a plain struct:
 * explicit trees are read and checked with fg_tree_check, generator objects
 * are kept as their JSON (only their type is checked). scene_build then runs
 * each generator (scene/generator.h) to give every discharge its tree.
 * Errors name the JSON path: "discharges[2].tree.nodes[7]: parent 9 is not
 * before node 7". A failed call leaves nothing allocated. */
#ifndef HOST_SCENE_SCENE_H
#define HOST_SCENE_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <cjson/cJSON.h>

#include "fulgur/fulgur.h"

/* Longest scene, and the default length's cap. */
#define SCENE_MAX_DURATION_S 3600.0
/* The largest scene file: a 10^6-segment tree written at 17 significant
 * digits a coordinate is ~70 MB, and three times that fits; reading one
 * holds the text and 32 bytes a node of explicit trees (about half the
 * text's size again). A read from a device or a runaway generator stops
 * here. */
#define SCENE_MAX_FILE_BYTES (256u << 20)

typedef struct scene_pose {
    double time_s;
    double position_m[3];
    double forward[3];
    double up[3];
} scene_pose;

/* The explicit trees the streaming reader took (scene_internal.h). */
typedef struct scene_node_lists scene_node_lists;

/* One discharge of the scene: what is posted, and where it came from. */
typedef struct scene_discharge {
    /* What fg_engine_post takes, as it takes it: the tree (owned by the
     * scene, from fg_big_calloc (fg_big_alloc.h): explicit, or built by
     * scene_build; the offset applied; NULL until built), the preset's
     * sound with the overrides, the emit time on the engine clock, strokes
     * (0: drawn by the engine), the continuous repeat (duration 0: until
     * the scene ends), the seed, the propagation
     * (the scene's, with this discharge's keys over it) and the model. */
    fg_discharge post;
    fg_preset preset;
    double offset_m[3];        /* added to every node */
    const cJSON *generator;    /* the generator object inside scene.json, or NULL */
} scene_discharge;

/* How an aero object moves (docs/scene-format.md, "aero_objects"). */
typedef enum scene_motion_kind {
    SCENE_MOTION_FIXED = 0, /* still: wind mode */
    SCENE_MOTION_SWING = 1, /* about a fixed pivot */
    SCENE_MOTION_THROW = 2  /* a ballistic arc, spinning */
} scene_motion_kind;

typedef struct scene_motion {
    scene_motion_kind kind;
    double position_m[3];   /* fixed, throw: the origin (at the start); swing: the pivot */
    double axis[3], normal[3]; /* unit, at the start */
    double turn_axis[3];    /* unit: what the swing and the spin turn about */
    double peak_rad_s;      /* swing: speed peak * sin^2(pi (t - start) / duration) */
    double start_s, duration_s;
    double velocity_m_s[3]; /* throw: at the start */
    double spin_rad_s;
    double gravity_m_s2;    /* throw: along -z */
} scene_motion;

/* One aero object: what fg_aero_object_post takes (its texture owned by
 * the scene, its first pose the motion's at its emit time, the scene's
 * wind) and how it moves. */
typedef struct scene_aero {
    fg_aero_object post;
    fg_aero_texture *texture;
    scene_motion motion;
} scene_aero;

/* One fire (docs/scene-format.md, "fires"): where it is, along a path of
 * timed points (one point: fixed), and its flux series, which
 * scene_render turns into sound with fg_fire_feed and streams into a
 * fire voice. */
typedef struct scene_fire_point {
    double time_s;
    double position_m[3];
} scene_fire_point;

typedef struct scene_fire {
    fg_fire_voice post;         /* the first pose the path's at its emit time */
    fg_fire_sound_config sound; /* sample rate the scene's; the texture set by the render */
    scene_fire_point *path;     /* ascending times */
    size_t path_count;
    double *flux_m3_s;          /* I at sound.sim_rate_hz, from the flux file or the
                                   simulation run at load; NULL for a live one */
    size_t flux_count;          /* its steps (a live simulation's to come) */
    bool live;                  /* "simulation" with "live": run step by step as the
                                   fire sounds (scene_fire_render.h), from sim */
    fg_flame_sim_config sim;
} scene_fire;

/* What the picture looks through (the "camera" block). */
typedef struct scene_camera {
    bool given;                /* false: none in the file (see scene_camera_framing) */
    double eye_m[3], target_m[3];
    double up[3];              /* default +z */
    double fov_y_deg;          /* vertical field of view, default 45 */
} scene_camera;

/* Output channels at most: third-order ambisonics. */
#define SCENE_MAX_CHANNELS 16

/* "block" when a scene gives none: a live host's device buffer (fulgur
 * run, view). A render takes SCENE_RENDER_BLOCK_FRAMES (scene_render.h). */
#define SCENE_BLOCK_FRAMES 256

typedef struct scene {
    double sample_rate_hz;
    uint32_t channels;         /* the layout's: 1 or 2 for stereo, (order + 1)^2 ambisonic */
    fg_layout layout;          /* "layout".type, or a host's --layout; FG_LAYOUT_STEREO */
    uint32_t ambisonic_order;  /* FG_LAYOUT_AMBISONICS: 1..3; 0 otherwise */
    char *sofa_file;           /* "layout".sofa resolved (owned); NULL: the default */
    const fg_hrir_set *hrirs;  /* FG_LAYOUT_BINAURAL: borrowed from the host that read them */
    uint32_t block_frames;     /* "block": a device's buffer, SCENE_BLOCK_FRAMES when not given */
    bool block_given;          /* the scene (or a --set) gave "block" */
    double duration_s;         /* 0: until every discharge has finished sounding */
    uint64_t seed;
    double gain;
    double speed_of_sound_m_s;
    double temperature_c;      /* the air, for ISO 9613-1 absorption */
    double humidity_pct;
    double pressure_kpa;
    fg_propagation_config propagation; /* every discharge's default */
    scene_pose *poses;         /* ascending times; one pose for a fixed listener */
    size_t pose_count;
    scene_discharge *discharges;
    size_t discharge_count;
    scene_camera camera;
    scene_aero *aeros;         /* "aero_objects" */
    size_t aero_count;
    scene_fire *fires;         /* "fires" */
    size_t fire_count;
    cJSON *json;               /* the parsed document the generator specs live in */
    scene_node_lists *node_lists; /* while parsing: the trees read from the text */
} scene;

/* Parses text (size bytes, need not be NUL-terminated) into *out. Returns 0,
 * or -1 with the message in err; *out is then zeroed. */
int scene_parse(const char *text, size_t size, scene *out, char *err, size_t err_size);

/* Reads the file at path and parses it (texture files named in it are
 * found relative to its folder); the message of a read error names
 * the file. A path that is not a regular file (a device, FIFO, directory)
 * or a file over SCENE_MAX_FILE_BYTES is refused before it is read. */
int scene_load(const char *path, scene *out, char *err, size_t err_size);

/* Reads the whole file at path into *text (not NUL-terminated; the caller
 * frees it with fg_big_free, fg_big_alloc.h) and *size. Returns 0, or -1
 * with a message naming the file. */
int scene_read_file(const char *path, char **text, size_t *size, char *err, size_t err_size);

/* As scene_parse and scene_load, with each of sets[0..set_count)
 * ("KEY=VALUE", scene/scene_override.h) set in the document, in order,
 * before it is checked. */
int scene_parse_with(const char *text, size_t size, const char *const *sets, size_t set_count,
                     scene *out, char *err, size_t err_size);
int scene_load_with(const char *path, const char *const *sets, size_t set_count, scene *out,
                    char *err, size_t err_size);

/* As scene_parse_with, the texture files it names found relative to dir
 * (NULL: the working directory). */
int scene_parse_in(const char *text, size_t size, const char *const *sets, size_t set_count,
                   const char *dir, scene *out, char *err, size_t err_size);

/* The folder of the file at path, in buf (NULL when path names none). */
const char *scene_dir_of(const char *path, char *buf, size_t size);

/* Runs the generators, once per parsed scene: every discharge gets its tree.
 * Returns 0, or -1 with a message naming the generator's path; the scene is
 * then as parsed. */
int scene_build(scene *s, char *err, size_t err_size);

/* Builds one discharge's tree (generation happens on the calling thread);
 * nothing to do for an explicit tree or a discharge already built. Returns 0,
 * or -1 with a message naming the generator's path; d is then unchanged. */
int scene_build_discharge(scene *s, size_t index, char *err, size_t err_size);

/* Frees the tree scene_build gave a generator's discharge, so that the
 * next build grows a new one; an explicit tree stays. */
void scene_discharge_unbuild(scene_discharge *d);

/* An output layout as a host names it (--layout) or the scene's "layout"
 * block does. */
typedef struct scene_layout {
    fg_layout layout;
    uint32_t order; /* FG_LAYOUT_AMBISONICS: 1..3 */
} scene_layout;

/* Reads "stereo", "binaural" or "ambisonics:ORDER" (ORDER 1..3). Returns
 * 0, or -1 with why the text is none of them in why. */
int scene_layout_from_text(const char *text, scene_layout *out, char *why, size_t why_size);

/* "stereo", "ambisonics" or "binaural": the layout's name in a scene's
 * layout.type. */
const char *scene_layout_name(fg_layout layout);

/* A host's --layout: whether it was given, and the layout. */
typedef struct scene_layout_choice {
    bool given;
    scene_layout layout;
} scene_layout_choice;

/* --layout's parser for common/options.h (OPTION_PARSED): value is a
 * scene_layout_choice; the text as scene_layout_from_text reads it. */
int scene_layout_option(const char *text, void *value, char *why, size_t why_size);

/* The hosts' --layout and --sofa entries of their option tables
 * (common/options.h; SOFA_DEFAULT_FILE from common/sofa_hrir.h), over the
 * scene's "layout"; where is what the host's ambisonics plays to. */
#define SCENE_LAYOUT_OPTIONS(choice, sofa_path, where)                                        \
    {"--layout", OPTION_PARSED, (choice), "LAYOUT", .parse = scene_layout_option,          \
     .help = "stereo, binaural (HRIRs of --sofa) or ambisonics:ORDER (1..3:\n"              \
             "AmbiX, 4, 9 or 16 channels" where "), over the scene's\n"                      \
             "\"layout\" (default stereo)"},                                                 \
    {"--sofa", OPTION_TEXT, (sofa_path), "FILE",                                            \
     .help = "the SOFA file (AES69 SimpleFreeFieldHRIR) of the binaural\n"                  \
             "layout, over the scene's layout.sofa (default\n" SOFA_DEFAULT_FILE ")"}

/* Sets s's layout to l (a host's --layout overriding the scene's) with its
 * channels: (order + 1)^2 ambisonic, 2 binaural and stereo (the scene's
 * "layout" of type stereo keeps its "channels" instead). */
void scene_set_layout(scene *s, scene_layout l);

struct sofa_hrirs;

/* A binaural s's HRIRs at rate_hz into *out (the caller frees it with
 * sofa_hrirs_free after the engine is gone), and s->hrirs pointing at them:
 * from sofa (a host's --sofa, may be NULL), else the scene's
 * "layout".sofa, else SOFA_DEFAULT_FILE. Returns 0 (nothing read for
 * another layout), or -1 with a message naming the option or key and the
 * file: unreadable or a SOFA file the binaural layout cannot use
 * (sofa_hrir.h), or sofa given for a layout other than binaural. */
int scene_read_hrirs(scene *s, const char *sofa, double rate_hz, struct sofa_hrirs *out, char *err,
                     size_t err_size);

/* Frees what parse and build allocated; zeroes *s. NULL is a no-op. */
void scene_deinit(scene *s);

/* The listener at time t: positions interpolated linearly, directions by
 * normalised lerp, held before the first and after the last pose; velocity
 * is the path's slope (0 when held). */
void scene_listener_at(const scene *s, double t_s, fg_listener *out);

/* Aero object a's pose at t (time_s = t), with its exact velocity and
 * angular velocity (velocity_given: zeros are at rest). */
void scene_aero_pose_at(const scene_aero *a, double t_s, fg_aero_pose *out);

/* Posts every aero object now (each sounds from its own emit time), the
 * voices' ids in ids[aero_count]: what a live host does before its
 * threads start. Returns FG_OK, or the engine's refusal with a message
 * naming the object (nothing posted after it). [main-thread] */
fg_result scene_aero_post_all(const scene *s, fg_engine *e, fg_voice_id *ids, char *err,
                              size_t err_size);

/* Publishes aero object i's pose at t_s to its voice id in e; when the
 * voice has since been collected, sets *done instead. Returns FG_OK, or
 * the engine's refusal with a message naming the object (a motion faster
 * than FG_AERO_MAX_SPEED_M_S). [any-thread] but not the audio thread, one
 * publisher per object */
fg_result scene_aero_publish_pose(const scene *s, size_t i, fg_engine *e, fg_voice_id id,
                                  double t_s, bool *done, char *err, size_t err_size);

/* Fire f's pose at t (time_s = t): linear along its path, velocity the
 * chord's, held before the first point and after the last. */
void scene_fire_pose_at(const scene_fire *f, double t_s, fg_fire_pose *out);

/* What a discharge happens among, as the picture shows it. */
typedef enum scene_apparatus_kind {
    SCENE_APPARATUS_NONE = 0,    /* open air: lightning, a charges leader, any other tree */
    SCENE_APPARATUS_SPARK_GAP,   /* two ball electrodes */
    SCENE_APPARATUS_PLASMA_BALL, /* a central electrode inside a glass globe */
    SCENE_APPARATUS_FIELD        /* the "field" generator's conductors */
} scene_apparatus_kind;

typedef struct scene_apparatus {
    scene_apparatus_kind kind;
    /* the conductors, in the scene's frame (the offset applied); a "ground"
     * shape becomes the plane z = offset z, its normal +z */
    fg_shape shapes[FG_FIELD_MAX_SHAPES];
    size_t shape_count;
    double box_min_m[3], box_max_m[3]; /* the field's grid box, scene frame */
} scene_apparatus;

/* The apparatus of discharge index: a field generator's shapes
 * (spark_gap, plasma_ball, field); for an explicit tree of the spark_balls
 * preset two balls fitted to it (radius half the distance from the root
 * to the main channel's end, one beyond each), of the plasma_ball preset
 * a globe around its root through its farthest node with an electrode of
 * 0.15 of that radius (the preset's proportions, docs/picture.md); none
 * otherwise. The discharge must be built. Returns 0, or -1 with a message
 * naming the generator's path. */
int scene_discharge_apparatus(const scene *s, size_t index, scene_apparatus *out, char *err,
                              size_t err_size);

/* How much room a fire takes in the default framing, m each way. */
#define SCENE_FRAME_FIRE_M 0.5

/* The scene's camera, or when it gives none a default framing of
 * discharge index (built) and its apparatus, for a picture of aspect
 * width / height: lightning seen from the ground at the listener's
 * height, from the listener's side, the horizon low in the frame and the
 * channel's top near its top edge; anything else seen from the
 * listener's side and a little above (12 degrees), close enough that its
 * bounds fill the 45 degree vertical view or the horizontal one. A scene
 * without discharges (index is then ignored) frames its fires and aero
 * objects that way: each fire's points with SCENE_FRAME_FIRE_M around
 * them, each object's reach around where it starts. */
void scene_camera_framing(const scene *s, size_t index, double aspect, scene_camera *out);

/* The engine configuration the scene asks for (rate, block, channels and
 * layout, the air); voices and segments are left at 0 (the defaults) for
 * the caller. */
void scene_engine_config(const scene *s, fg_engine_config *out);

/* The discharge indices by time, then index: the posting order. NULL when
 * out of memory; the caller frees. */
size_t *scene_post_order(const scene *s);

/* The seed a discharge gets when it names none: a hash of the scene's seed
 * and the discharge's index. */
uint64_t scene_discharge_seed(uint64_t scene_seed, size_t index);

#endif
