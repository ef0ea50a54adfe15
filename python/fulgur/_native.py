"""The C side: libfulgur (the engine) and libfulgur-scene (scene files as
fulgur render renders them), loaded with cffi in ABI mode.

The declarations below copy the public headers (engine/include/fulgur/*.h
and host/scene_api/include/fulgur/scene_api.h) for the calls the package
makes; python/tests/test_layout.py compiles a C program against the real
headers that checks every struct's size and field offsets, every constant
and every function's type against these declarations, so they cannot drift.

Where the libraries are looked for, first to last: the directories in
FULGUR_LIBRARY_PATH (separated by ':'), the build tree this copy of the
package was made in (fulgur/_build_paths.py, written by CMake), then the
system's loader (ldconfig's directories and LD_LIBRARY_PATH: where
`cmake --install` puts them).
"""
import os

from cffi import FFI

CDEF = r"""
typedef enum fg_result {
    FG_OK = 0, FG_ERR_NULL = -1, FG_ERR_ARGUMENT = -2, FG_ERR_SAMPLE_RATE = -3,
    FG_ERR_NOT_FINITE = -4, FG_ERR_TREE = -5, FG_ERR_CAPACITY = -6, FG_ERR_POOL_FULL = -7,
    FG_ERR_QUEUE_FULL = -8, FG_ERR_BLOCK_SIZE = -9, FG_ERR_NOT_FOUND = -10,
    FG_ERR_NO_MEMORY = -11, FG_ERR_UNREACHABLE = -12, FG_ERR_NOT_CONVERGED = -13,
    FG_ERR_UNSUPPORTED = -14, FG_ERR_GPU = -15, FG_ERR_IO = -16
} fg_result;
const char *fg_result_str(fg_result r);

/* tree.h */
enum { FG_NODE_MAIN = 1 };
typedef struct fg_node { double x, y, z; int32_t parent; uint32_t flags; } fg_node;
typedef enum fg_tree_fault_kind {
    FG_TREE_FAULT_NONE = 0, FG_TREE_FAULT_TOO_FEW_NODES, FG_TREE_FAULT_ROOT,
    FG_TREE_FAULT_PARENT_ORDER, FG_TREE_FAULT_NOT_FINITE, FG_TREE_FAULT_ZERO_LENGTH,
    FG_TREE_FAULT_TOO_FAR, FG_TREE_FAULT_TOO_SHORT
} fg_tree_fault_kind;
typedef struct fg_tree_fault {
    fg_tree_fault_kind kind; size_t node; int32_t parent; double value;
} fg_tree_fault;
fg_result fg_tree_check(const fg_node *nodes, size_t count, fg_tree_fault *fault);
void fg_tree_fault_describe(const fg_tree_fault *fault, char *buf, size_t size);
typedef struct fg_tree fg_tree;
fg_result fg_tree_create(size_t capacity_hint, fg_tree **out);
void fg_tree_destroy(fg_tree *tree);
fg_node *fg_tree_nodes(fg_tree *tree);
size_t fg_tree_count(const fg_tree *tree);

/* sound.h */
typedef struct fg_sound_config {
    double t0_s; double r0_m; double ps0_pa; double sigma0; double t0_jitter;
    double return_stroke_speed_m_s; double ref_half_len_m;
} fg_sound_config;
typedef enum fg_preset {
    FG_PRESET_SPARK_BALLS = 0, FG_PRESET_PLASMA_BALL = 1, FG_PRESET_LIGHTNING = 2,
    FG_PRESET_LIGHTNING_TABLE1 = 3,
    FG_PRESET_COUNT
} fg_preset;
typedef struct fg_preset_scale { double path_m; double half_step_m; } fg_preset_scale;
fg_result fg_preset_sound(fg_preset preset, fg_sound_config *out);
fg_result fg_preset_get_scale(fg_preset preset, fg_preset_scale *out);
const char *fg_preset_name(fg_preset preset);
fg_result fg_preset_from_name(const char *name, fg_preset *out);
fg_result fg_sound_config_check(const fg_sound_config *config);

/* propagation.h */
typedef enum fg_absorption {
    FG_ABSORPTION_OFF = 0, FG_ABSORPTION_ISO9613 = 1, FG_ABSORPTION_ABE_FIR = 2
} fg_absorption;
typedef struct fg_propagation_config {
    double refraction_radius_m; double turbulence_s; double turbulence_length_m;
    fg_absorption absorption; double abe_fir_distance_m; double ground_reflection;
    int head_shadow;
} fg_propagation_config;
fg_result fg_propagation_config_resolve(const fg_propagation_config *in,
                                        fg_propagation_config *out);

/* engine.h */
typedef struct fg_engine fg_engine;
typedef enum fg_layout { FG_LAYOUT_STEREO = 0, FG_LAYOUT_AMBISONICS = 1,
                         FG_LAYOUT_BINAURAL = 2 } fg_layout;
#define FG_BINAURAL_LATENCY_FRAMES 128
#define FG_HRIR_MAX_LENGTH 8192
#define FG_HRIR_MAX_COUNT 65536
typedef struct fg_hrir_set {
    double sample_rate_hz; uint32_t count; uint32_t length; const double *direction;
    const float *left; const float *right;
} fg_hrir_set;
#define FG_AMBISONIC_ORDER_MIN 1
#define FG_AMBISONIC_ORDER_MAX 3
typedef struct fg_engine_config {
    double sample_rate_hz; uint32_t max_block_frames; uint32_t channels; uint32_t max_voices;
    uint32_t segment_capacity; double speed_of_sound_m_s; double ear_spacing_m;
    double max_lookahead_s; uint32_t max_adopt_per_block; double air_temperature_k;
    double air_humidity_pct; double air_pressure_kpa; uint32_t work_per_frame;
    fg_layout layout; uint32_t ambisonic_order; const fg_hrir_set *hrirs;
    uint32_t chunk_frames;
} fg_engine_config;
typedef enum fg_voice_model { FG_MODEL_WM = 0, FG_MODEL_ABE = 1 } fg_voice_model;
#define FG_MAX_STROKES 32
typedef struct fg_discharge {
    const fg_node *nodes; size_t node_count; fg_sound_config sound; double emit_time_s;
    uint32_t strokes; int continuous; double repeat_min_s; double repeat_max_s;
    double duration_s; uint64_t seed; fg_propagation_config propagation; fg_voice_model model;
} fg_discharge;
typedef uint64_t fg_voice_id;
typedef struct fg_listener {
    double position[3]; double forward[3]; double up[3]; double velocity[3]; double time_s;
    double angular_velocity[3]; int velocity_given;
} fg_listener;
typedef struct fg_engine_report {
    uint64_t posted; uint64_t dropped_posts; uint64_t adopted; uint64_t finished;
    uint64_t collected; uint64_t late_events; uint64_t late_samples; uint64_t skipped_repeats;
    uint64_t skipped_work; uint64_t non_finite_voices; uint64_t non_finite_blocks;
    uint64_t blocks; uint64_t blocks_over_budget; uint64_t work_units; uint64_t peak_block_work;
} fg_engine_report;
uint32_t fg_discharge_stroke_offsets(const fg_discharge *discharge, double *offsets_s,
                                     uint32_t max);
fg_result fg_engine_config_resolve(const fg_engine_config *config, fg_engine_config *out);
fg_result fg_engine_create(const fg_engine_config *config, fg_engine **out);
void fg_engine_destroy(fg_engine *engine);
void fg_engine_get_config(const fg_engine *engine, fg_engine_config *out);
fg_result fg_engine_post(fg_engine *engine, const fg_discharge *discharge, fg_voice_id *id);
fg_result fg_engine_stop(fg_engine *engine, fg_voice_id id);
size_t fg_engine_collect(fg_engine *engine);
fg_result fg_engine_render(fg_engine *engine, float *const *out, uint32_t nframes);
fg_result fg_engine_set_listener(fg_engine *engine, const fg_listener *pose);
void fg_engine_get_listener(const fg_engine *engine, fg_listener *out);
void fg_engine_get_report(const fg_engine *engine, fg_engine_report *out);
uint64_t fg_engine_frames(const fg_engine *engine);
double fg_engine_time_s(const fg_engine *engine);

/* aero.h */
typedef enum fg_aero_shape {
    FG_AERO_CIRCLE = 1, FG_AERO_RECTANGLE = 2, FG_AERO_POLYGON = 3, FG_AERO_SPHERE = 4,
    FG_AERO_CLUB = 5
} fg_aero_shape;
typedef enum fg_aero_tone { FG_AERO_AEOLIAN = 0, FG_AERO_CAVITY = 1 } fg_aero_tone;
typedef struct fg_aero_direction {
    double angle_rad; double frontal_m; double frequency_hz; double strouhal;
    double lift_amplitude; double drag_mean; double transient_s; uint32_t periods;
    uint32_t frames; const float *samples;
} fg_aero_direction;
typedef struct fg_aero_source { double position_m; double span_m; } fg_aero_source;
typedef struct fg_aero_texture_desc {
    fg_aero_shape shape; fg_aero_tone tone; uint32_t dims; uint32_t components;
    double length_m; double height_m; double diameter_m[2]; uint32_t polygon_vertices;
    const double *polygon_xy; double reference_m; double speed_m_s; double viscosity_m2_s;
    double density_kg_m3; double reynolds; double sample_rate_hz; double cells_per_length;
    uint32_t rotation_order; uint32_t mirror; double mirror_angle_rad; uint32_t sources;
    const fg_aero_source *source; uint32_t directions; const fg_aero_direction *direction;
} fg_aero_texture_desc;
typedef struct fg_aero_texture fg_aero_texture;
void fg_aero_texture_destroy(fg_aero_texture *t);
const fg_aero_texture_desc *fg_aero_texture_get(const fg_aero_texture *t);

/* aero_object.h */
#define FG_AERO_OBJECT_MAX_SOURCES 64
typedef enum fg_aero_body { FG_AERO_STICK = 0, FG_AERO_COMPACT = 1 } fg_aero_body;
typedef struct fg_aero_pose {
    double position[3]; double axis[3]; double normal[3]; double velocity[3]; double time_s;
    double angular_velocity[3]; int velocity_given;
} fg_aero_pose;
typedef struct fg_aero_wind {
    double velocity[3]; double gust; double gust_period_s; uint64_t seed;
} fg_aero_wind;
typedef struct fg_aero_object {
    const fg_aero_texture *texture; fg_aero_body body; double start_m, end_m; uint32_t sources;
    double gain; fg_aero_pose pose; fg_aero_wind wind; fg_absorption absorption;
    double emit_time_s; double duration_s;
} fg_aero_object;
typedef struct fg_aero_report {
    uint32_t sources; uint64_t blocks; uint64_t beyond_range_blocks; double max_speed_m_s;
} fg_aero_report;
fg_result fg_aero_object_post(fg_engine *engine, const fg_aero_object *o, fg_voice_id *id);
fg_result fg_aero_object_set_pose(fg_engine *engine, fg_voice_id id, const fg_aero_pose *pose);
fg_result fg_aero_object_set_wind(fg_engine *engine, fg_voice_id id, const fg_aero_wind *wind);
fg_result fg_aero_object_get_report(fg_engine *engine, fg_voice_id id, fg_aero_report *out);

/* fire.h (the sound's configuration) and fire_voice.h */
typedef struct fg_fire_texture fg_fire_texture;
typedef enum fg_fire_extension {
    FG_FIRE_BANDWIDTH_EXTENSION = 0, FG_FIRE_TEXTURE = 1, FG_FIRE_LOW_ONLY = 2
} fg_fire_extension;
typedef struct fg_fire_bwe_config {
    double alpha; double f_cut_hz; double sigma_cut_hz; double blend_low_hz;
    double blend_high_hz; int half_window_frames; int beta_half_window_frames; uint64_t seed;
} fg_fire_bwe_config;
typedef struct fg_fire_sound_config {
    double sample_rate_hz; double sim_rate_hz; double highpass_hz; fg_fire_extension extension;
    fg_fire_bwe_config bwe; const fg_fire_texture *texture; double level_history_s;
} fg_fire_sound_config;
typedef struct fg_fire_pose { double position[3]; double velocity[3]; double time_s; } fg_fire_pose;
typedef struct fg_fire_voice {
    fg_fire_pose pose; double gain; fg_absorption absorption; double emit_time_s; double ring_s;
} fg_fire_voice;
typedef struct fg_fire_voice_report {
    uint64_t capacity_frames; uint64_t pushed_frames; uint64_t held_frames; int64_t read_frame;
    uint64_t underrun_frames; uint64_t underruns; uint64_t blocks; bool closed;
} fg_fire_voice_report;
typedef struct fg_fire_feed fg_fire_feed;
fg_result fg_fire_voice_post(fg_engine *engine, const fg_fire_voice *f, fg_voice_id *id);
fg_result fg_fire_voice_set_pose(fg_engine *engine, fg_voice_id id, const fg_fire_pose *pose);
fg_result fg_fire_voice_push(fg_engine *engine, fg_voice_id id, const float *pa_at_1m,
                             size_t frames, size_t *pushed);
fg_result fg_fire_voice_close(fg_engine *engine, fg_voice_id id);
fg_result fg_fire_voice_get_report(fg_engine *engine, fg_voice_id id, fg_fire_voice_report *out);
fg_result fg_fire_feed_create(const fg_fire_sound_config *config, size_t max_steps,
                              fg_fire_feed **out);
void fg_fire_feed_destroy(fg_fire_feed *feed);
double fg_fire_feed_latency_s(const fg_fire_feed *feed);
fg_result fg_fire_feed_push(fg_fire_feed *feed, fg_engine *engine, fg_voice_id id,
                            const double *flux_m3_s, size_t steps, size_t *taken);
fg_result fg_fire_feed_finish(fg_fire_feed *feed, fg_engine *engine, fg_voice_id id, bool *done);

/* lightning.h */
#define FG_THUNDER_MAX_FEATURES 16
#define FG_LIGHTNING_MAX_SKELETON 65536
typedef enum fg_thunder_kind {
    FG_THUNDER_CLAP = 1, FG_THUNDER_RUMBLE = 2, FG_THUNDER_ROAR = 3
} fg_thunder_kind;
typedef struct fg_thunder_feature {
    fg_thunder_kind kind; double start, end; double amplitude;
} fg_thunder_feature;
typedef struct fg_lightning_config {
    const double *skeleton_m; size_t skeleton_points; double strike_m[2]; double height_m;
    double in_cloud_m; double in_cloud_azimuth_deg;
    double segment_m; double turn_mean_deg; double max_deviation_deg; double lookahead_m;
    double branch_probability; double branch_length_m; uint32_t branch_depth;
    const fg_thunder_feature *features; size_t feature_count; double listener_m[3];
    uint32_t max_nodes; uint64_t seed;
} fg_lightning_config;
typedef struct fg_lightning_stretch {
    size_t first_node, last_node; double distance_m;
} fg_lightning_stretch;
typedef struct fg_lightning_report {
    size_t main_nodes; size_t segments; double main_length_m; double skeleton_length_m;
    size_t in_cloud_first; size_t in_cloud_nodes; double in_cloud_length_m;
    fg_lightning_stretch features[16];
} fg_lightning_report;
fg_result fg_lightning_generate(const fg_lightning_config *config, fg_tree *out,
                                fg_lightning_report *report);

/* charges.h */
typedef struct fg_point_charge { double position_m[3]; double charge_c; } fg_point_charge;
typedef struct fg_charges_config {
    const fg_point_charge *charges; size_t charge_count; double start_m[3]; double step_m;
    uint32_t candidates; uint32_t chosen; double exclusion_m; uint32_t max_tips;
    double target_m[3]; double target_radius_m; uint32_t max_nodes; uint64_t seed;
} fg_charges_config;
fg_result fg_charges_grow(const fg_charges_config *config, fg_tree *out);

/* field.h */
#define FG_FIELD_MAX_SHAPES 64
typedef struct fg_field fg_field;
typedef struct fg_grid_config {
    int size[3]; double min_m[3]; double max_m[3]; size_t max_bytes;
} fg_grid_config;
fg_result fg_field_create(const fg_grid_config *config, fg_field **out);
void fg_field_destroy(fg_field *field);
typedef enum fg_shape_kind {
    FG_SHAPE_SPHERE = 0, FG_SHAPE_BOX, FG_SHAPE_PLANE, FG_SHAPE_POINT, FG_SHAPE_GROUND
} fg_shape_kind;
typedef enum fg_shape_role { FG_ROLE_FIXED = 0, FG_ROLE_ORIGIN, FG_ROLE_TARGET } fg_shape_role;
typedef struct fg_shape {
    fg_shape_kind kind; fg_shape_role role; double potential; double centre_m[3];
    double radius_m; double box_min_m[3], box_max_m[3]; double normal[3]; int outside;
} fg_shape;
fg_result fg_field_set_shapes(fg_field *field, const fg_shape *shapes, size_t count,
                              size_t *bad_shape);
typedef enum fg_solver { FG_SOLVER_MULTIGRID = 0, FG_SOLVER_SOR } fg_solver;
typedef struct fg_solve_config {
    fg_solver solver; double tolerance; int max_iterations; double sor_omega; int cold;
} fg_solve_config;
typedef struct fg_solve_report {
    int iterations; double residual; double initial_residual; int cg_iterations;
} fg_solve_report;
fg_result fg_field_solve(fg_field *field, const fg_solve_config *config,
                         fg_solve_report *report);
typedef struct fg_field_source {
    void *context;
    fg_result (*sample)(void *context, const double *points_m, size_t n, double *out);
    fg_result (*classify)(void *context, const double *points_m, size_t n, uint8_t *out);
    size_t (*origin_sites)(void *context, double *points_m, size_t max);
    double cell_m;
} fg_field_source;
void fg_field_source_init(fg_field *field, fg_field_source *out);

/* growth.h */
typedef struct fg_growth_config {
    double step_m; uint64_t seed; double gamma; int candidates; double cone_rad;
    double branch_probability; int max_tips; double branch_length_m; int all_tips_connect;
    int max_steps; double eta; int dbm_global_every; int dbm_relax_radius;
} fg_growth_config;
typedef struct fg_growth_report {
    size_t nodes; size_t main_nodes; int steps; int solves; int solver_iterations;
} fg_growth_report;
fg_result fg_grow_matsuyama(const fg_field_source *source, const fg_growth_config *config,
                            fg_tree *out, fg_growth_report *report);
fg_result fg_grow_dbm(fg_field *field, const fg_growth_config *config, fg_tree *out,
                      fg_growth_report *report);

/* field_scene.h */
#define FG_FIELD_SCENE_MAX_SHAPES 4
typedef struct fg_field_scene {
    fg_grid_config grid; fg_shape shapes[4]; size_t shape_count; fg_growth_config growth;
} fg_field_scene;
fg_result fg_field_scene_preset(fg_preset preset, int size, fg_field_scene *out);

/* scene_api.h (libfulgur-scene) */
typedef struct fgs_scene fgs_scene;
typedef struct fgs_scene_info {
    double sample_rate_hz; uint32_t channels; uint32_t block_frames; double duration_s;
    uint64_t seed; double gain; size_t discharge_count;
} fgs_scene_info;
typedef struct fgs_render_report {
    uint64_t frames; size_t segments; float peak; int capped; fg_engine_report engine;
} fgs_render_report;
fg_result fgs_scene_parse(const char *json, size_t size, const char *const *sets,
                          size_t set_count, fgs_scene **out, char *err, size_t err_size);
fg_result fgs_scene_load(const char *path, const char *const *sets, size_t set_count,
                         fgs_scene **out, char *err, size_t err_size);
void fgs_scene_destroy(fgs_scene *scene);
void fgs_scene_get_info(const fgs_scene *scene, fgs_scene_info *out);
fg_result fgs_scene_render(fgs_scene *scene, fgs_render_report *report, char *err,
                           size_t err_size);
const float *fgs_scene_samples(const fgs_scene *scene, uint64_t *frames);
fg_result fgs_wav_write(const char *path, const float *samples, uint64_t frames,
                        uint32_t channels, double sample_rate_hz, char *err, size_t err_size);
fg_result fgs_aero_texture_load(const char *path, fg_aero_texture **out, char *err,
                                size_t err_size);
"""

# Which header each function comes from, for the layout test.
ENGINE_HEADERS = ("fulgur/fulgur.h",)
SCENE_HEADERS = ("fulgur/scene_api.h",)

ENGINE_SONAME = "libfulgur.so.0.1"
SCENE_SONAME = "libfulgur-scene.so.0.1"


def library_dirs():
    """The directories searched before the system's loader, in order."""
    dirs = [d for d in os.environ.get("FULGUR_LIBRARY_PATH", "").split(os.pathsep) if d]
    try:
        from . import _build_paths
        dirs += list(_build_paths.LIBRARY_DIRS)
    except ImportError:
        pass
    return dirs


def _locate(soname):
    for d in library_dirs():
        path = os.path.join(d, soname)
        if os.path.exists(path):
            return path
    return soname


ffi = FFI()
ffi.cdef(CDEF)


def _open(soname):
    where = _locate(soname)
    try:
        return ffi.dlopen(where), where
    except OSError as e:
        raise ImportError(
            f"fulgur: cannot load {soname} ({e}); build fulgur (cmake --build BUILD) and set "
            f"FULGUR_LIBRARY_PATH to the folders holding libfulgur.so.0.1 and "
            f"libfulgur-scene.so.0.1 (BUILD/engine:BUILD/host), or install them "
            f"(cmake --install BUILD; ldconfig)") from e


# The engine first: libfulgur-scene's need of libfulgur.so.0.1 is then met by it.
lib, ENGINE_PATH = _open(ENGINE_SONAME)
scene_lib, SCENE_PATH = _open(SCENE_SONAME)

EMIT_NOW = -1.0  # FG_EMIT_NOW
