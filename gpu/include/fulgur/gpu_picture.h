/* fulgur gpu/ — the picture of a scene: glowing discharges, the objects
 * they happen between, and what they light.
 *
 * A picture holds a list of drawables (fgg_drawable, a tagged value):
 *
 *   DISCHARGE  a tree of glowing segments on the flash timeline (fgg_flash):
 *              each segment an additive camera-facing quad, wide and bright
 *              on the main channel, thinner and dimmer with the branching
 *              depth; the leader grows dim from the root, the return stroke
 *              lights the whole tree, decays, and later strokes re-flash
 *              the main channel (fg_discharge_stroke_offsets, so the
 *              picture flashes with the sound). A discharge is also a
 *              light: it lights every surface near it while it glows.
 *   SPHERE     a ball: an electrode, a plasma ball's glass globe, a
 *              compact body moving through the air
 *   ROD        a round bar between two points (a capsule): an electrode's
 *              stem, a stick, a sword
 *   BOX        a box, its edges along its body axes: a box electrode, a
 *              base, a table, a blade
 *   PLANE      a square: a plane electrode, a floor
 *   GROUND     the outdoors: the ground up to the horizon, a dim night sky,
 *              a cloud deck, the haze of the air, all lit by the flashes
 *   MARKER     a signed point charge: a disc of fixed size in pixels, drawn
 *              over everything
 *   VOLUME     an emissive volume: a flame, flickering, of a temperature's
 *              colour; it lights the surfaces near it
 *
 * Objects (sphere, rod, box, plane, marker, volume) are given in their own
 * body frame and may be moved rigidly (fgg_picture_set_pose) or changed in
 * place (fgg_picture_update) every frame, which is how a moving stick or a
 * flickering fire is shown. A bloom (bright pass, a chain of downsampled
 * blurs, added back) and a tonemap give the glow; frames can be read back
 * or written as PNG. docs/picture.md gives every constant. */
#ifndef FULGUR_GPU_PICTURE_H
#define FULGUR_GPU_PICTURE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/engine.h"
#include "fulgur/gpu_context.h"
#include "fulgur/tree.h"

typedef struct fgg_picture fgg_picture;

typedef struct fgg_picture_config {
    int width, height;      /* pixels; 0 means 1280 x 720 */
    double exposure;        /* tonemap exposure; 0 means 1 */
    double bloom;           /* bloom strength; 0 means 0.6, negative means none */
    float background[3];    /* linear RGB of the sky behind; zero is black */
    float ambient[3];       /* linear RGB radiance of the surroundings that lights
                               every surface (a dim room); zero is none */
} fgg_picture_config;

typedef struct fgg_camera {
    double eye_m[3];
    double target_m[3];
    double up[3];           /* need not be unit length; zero means +z */
    double fov_y_deg;       /* vertical field of view; 0 means 45 */
} fgg_camera;

/* One discharge shown on the picture's timeline. */
typedef struct fgg_flash {
    const fg_node *nodes;   /* borrowed for the duration of fgg_picture_add */
    size_t node_count;
    double start_s;         /* picture clock time of the first return stroke */
    double leader_s;        /* how long the leader grows before it; 0: none shown */
    double radius_m;        /* main channel half-width; 0 means 1 % of the tree's extent */
    const double *stroke_offsets_s; /* strokes after start_s (first 0); NULL: one */
    size_t stroke_count;
    int continuous;         /* nonzero: glows steadily (plasma ball), flickering */
    double duration_s;      /* continuous: how long; 0: until removed */
    float colour[3];        /* linear RGB of the glow around the white core; zero
                               means the violet-blue of nitrogen (air) */
} fgg_flash;

/* How a surface looks. Every surface is lit by the discharges' and
 * volumes' light (inverse square, softened near the source) and by the
 * config's ambient. */
typedef enum fgg_material {
    FGG_MATERIAL_METAL = 0, /* polished metal, brass by default: electrodes */
    FGG_MATERIAL_MATTE,     /* a diffuse surface, grey by default: insulators, tables */
    FGG_MATERIAL_GLASS      /* clear glass: a bright rim, highlights, the light it
                               scatters (a plasma ball's globe lit from inside) */
} fgg_material;

typedef struct fgg_surface {
    fgg_material material;
    float colour[3];        /* linear RGB albedo (glass: its tint); zero means the
                               material's default */
} fgg_surface;

typedef struct fgg_sphere {
    double centre_m[3];
    double radius_m;        /* > 0 */
    fgg_surface surface;
} fgg_sphere;

typedef struct fgg_rod {
    double a_m[3], b_m[3];  /* the axis' ends; the ends are rounded (a capsule) */
    double radius_m;        /* > 0 */
    fgg_surface surface;
} fgg_rod;

typedef struct fgg_box {
    double min_m[3], max_m[3]; /* opposite corners in the body frame, max >= min */
    fgg_surface surface;
} fgg_box;

typedef struct fgg_plane {
    double centre_m[3];
    double normal[3];       /* need not be unit length; not zero */
    double half_size_m;     /* half the side of the square, > 0 */
    fgg_surface surface;
} fgg_plane;

/* The outdoors, at most one per picture. */
typedef struct fgg_ground {
    double height_m;        /* the ground is the plane z = height_m */
    double cloud_base_m;    /* z of the cloud deck's base, above the ground;
                               0: a clear sky */
    double cloud_centre_m[2]; /* x, y of the storm cell the deck belongs to */
    double cloud_radius_m;  /* the cell's radius; 0 means 12 km */
    double haze_per_m;      /* how much the air scatters the flashes' light
                               towards the eye, per metre; 0 means 4e-6 */
} fgg_ground;

typedef struct fgg_marker {
    double position_m[3];
    int sign;               /* +1 a positive charge (red, "+"), -1 negative (blue,
                               "-"), 0 neutral (grey) */
    double radius_px;       /* 0 means 7 */
} fgg_marker;

/* A flame: a flickering plume rising from a disc. */
typedef struct fgg_volume {
    double base_m[3];       /* the centre of its base */
    double radius_m;        /* the base's radius, > 0 */
    double height_m;        /* how tall it stands, > 0 */
    double temperature_k;   /* the colour of its hottest part (Planck); 0 means
                               1500 K; 800..3000 */
    double intensity;       /* light emitted, 1 nominal; 0 is dark; >= 0 */
    uint32_t seed;          /* the flicker's phase */
} fgg_volume;

typedef enum fgg_drawable_kind {
    FGG_DRAWABLE_DISCHARGE = 1, /* .discharge */
    FGG_DRAWABLE_SPHERE,        /* .sphere */
    FGG_DRAWABLE_ROD,           /* .rod */
    FGG_DRAWABLE_BOX,           /* .box */
    FGG_DRAWABLE_PLANE,         /* .plane */
    FGG_DRAWABLE_GROUND,        /* .ground */
    FGG_DRAWABLE_MARKER,        /* .marker */
    FGG_DRAWABLE_VOLUME         /* .volume */
} fgg_drawable_kind;

/* One thing to draw: kind names the member that holds it. */
typedef struct fgg_drawable {
    fgg_drawable_kind kind;
    union {
        fgg_flash discharge;
        fgg_sphere sphere;
        fgg_rod rod;
        fgg_box box;
        fgg_plane plane;
        fgg_ground ground;
        fgg_marker marker;
        fgg_volume volume;
    };
} fgg_drawable;

/* A rigid motion of an object's body frame: world = rotation * body +
 * position_m. */
typedef struct fgg_pose {
    double position_m[3];
    double rotation[9];     /* row-major, orthonormal with determinant +1; all
                               zero means the identity */
} fgg_pose;

/* Creates a picture with its render targets. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_ARGUMENT a size outside 16..8192 or a
 * non-finite exposure; FG_ERR_GPU; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fgg_picture_create(fgg_context *context,
                                                 const fgg_picture_config *config,
                                                 fgg_picture **out);

/* NULL is a no-op. [gpu-thread] */
FG_API void fgg_picture_destroy(fgg_picture *picture);

/* Adds a discharge; its tree is checked (fg_tree_check) and copied to the
 * GPU. Returns its id in *id (may be NULL). [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_TREE; FG_ERR_NOT_FINITE a time;
 * FG_ERR_ARGUMENT negative times or counts; FG_ERR_CAPACITY too many
 * flashes; FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_add(fgg_picture *picture, const fgg_flash *flash,
                                              uint32_t *id);

/* Adds any drawable (a discharge as fgg_picture_add does). Its id goes in
 * *id (may be NULL); ids are shared by all kinds. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE a coordinate or number;
 * FG_ERR_ARGUMENT an unknown kind, a size <= 0, a box with max < min, a
 * zero plane normal, a sign outside -1..1, a temperature outside
 * 800..3000 K, a negative intensity or radius, a cloud base at or below
 * the ground, a second ground; FG_ERR_CAPACITY more than 1024 discharges
 * or 1024 other drawables; as fgg_picture_add for a discharge. Nothing is
 * added on an error. */
FG_API FG_NODISCARD fg_result fgg_picture_add_drawable(fgg_picture *picture,
                                                       const fgg_drawable *drawable,
                                                       uint32_t *id);

/* Replaces the object id with drawable, of the same kind (its pose
 * stays): a flame's new intensity, a charge's new place. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FOUND no such object (discharges and
 * the ground cannot be updated: remove and add them); FG_ERR_ARGUMENT
 * another kind; as fgg_picture_add_drawable. Nothing changes on an error. */
FG_API FG_NODISCARD fg_result fgg_picture_update(fgg_picture *picture, uint32_t id,
                                                 const fgg_drawable *drawable);

/* Moves the object id rigidly (its body frame to the pose); NULL puts it
 * back where it was given. [gpu-thread]
 * Errors: FG_ERR_NULL picture; FG_ERR_NOT_FOUND no such object (not a
 * discharge or the ground); FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT a rotation
 * that is not orthonormal with determinant +1 (within 1e-6). */
FG_API FG_NODISCARD fg_result fgg_picture_set_pose(fgg_picture *picture, uint32_t id,
                                                   const fgg_pose *pose);

/* How many discharges and volumes give light at time_s: 0 means that a
 * frame drawn then shows no flash (only objects, lit by the ambient).
 * A NULL picture is 0. [gpu-thread] */
FG_API size_t fgg_picture_lit_count(const fgg_picture *picture, double time_s);

/* Lays an 8-bit sRGB RGBA image (straight alpha, rows top first, copied)
 * over the frame with its top left corner at pixel (x, y) from the top
 * left: text, a legend. rgba NULL removes it. [gpu-thread]
 * Errors: FG_ERR_NULL picture; FG_ERR_ARGUMENT a size outside 1..8192;
 * FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_set_overlay(fgg_picture *picture,
                                                      const uint8_t *rgba, int width,
                                                      int height, int x, int y);

/* Removes one drawable, or all of every kind when id is 0. [gpu-thread] */
FG_API void fgg_picture_remove(fgg_picture *picture, uint32_t id);

/* Draws the picture as it looks at time_s from the camera, into the
 * picture's target. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT a degenerate
 * camera (eye at target, up along the view); FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_draw(fgg_picture *picture, const fgg_camera *camera,
                                               double time_s);

/* Copies the last drawn frame to the current default framebuffer (the
 * window), scaled to width x height. [gpu-thread] */
FG_API void fgg_picture_blit(fgg_picture *picture, int width, int height);

/* The last drawn frame as 8-bit sRGB RGBA, rows top first, into
 * rgba[0 .. 4 * width * height). [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_read_rgba8(fgg_picture *picture, uint8_t *rgba);

/* Writes the last drawn frame as a PNG (libpng), through a temporary file
 * renamed into place, so a failure leaves no partial file. [gpu-thread]
 * Errors: FG_ERR_NULL; FG_ERR_ARGUMENT the file cannot be written (the
 * message names it and why); FG_ERR_GPU. */
FG_API FG_NODISCARD fg_result fgg_picture_write_png(fgg_picture *picture, const char *path);

/* The picture's size in pixels. [gpu-thread] */
FG_API void fgg_picture_size(const fgg_picture *picture, int *width, int *height);

#endif
