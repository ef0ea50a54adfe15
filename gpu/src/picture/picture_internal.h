/* The insides of fgg_picture, shared by its files:
 *   picture.c          targets, programs, the discharges, removal
 *   picture_objects.c  the other drawables: checks, poses, their instances
 *   picture_tree.c     a tree into segment instances and light points
 *   picture_timeline.c a discharge's gains at a time; its lights
 *   picture_frame.c    a frame's camera and light, the shaders' shared uniforms
 *   picture_draw.c     the frame's passes, the segments, bloom, tonemap
 *   picture_scene.c    the passes of the surroundings and the objects
 *   picture_overlay.c  markers and the overlay image, over the 8-bit frame
 *   picture_png.c      PNG output */
#ifndef FULGUR_GPU_PICTURE_INTERNAL_H
#define FULGUR_GPU_PICTURE_INTERNAL_H

#include "fulgur/gpu_picture.h"
#include "context/gpu_internal.h"

/* At most this many discharges, and other drawables, at once. */
#define FGG_PICTURE_MAX_FLASHES 1024
#define FGG_PICTURE_MAX_OBJECTS 1024
/* Bloom levels at most (halving each), and the smallest level's side. */
#define FGG_BLOOM_LEVELS 6
#define FGG_BLOOM_MIN_SIDE 4

/* Floats per segment instance: four vec4 (see segment_vs.glsl). */
#define FGG_SEGMENT_FLOATS 16
/* Floats per discharge's state: origin, gains, colour (segment_vs.glsl). */
#define FGG_FLASH_FLOATS 12
/* Floats per object instance: five vec4 (object.inc.glsl). */
#define FGG_OBJECT_FLOATS 20
/* Light points per discharge, and lights per frame (light.inc.glsl). */
#define FGG_FLASH_LIGHTS 6
#define FGG_MAX_LIGHTS 32

typedef struct fgg_flash_rec {
    uint32_t id;
    double origin_m[3];     /* node 0: segment positions are relative to it */
    double start_s, leader_s, duration_s;
    double path_m;          /* the longest path from the root: the leader's full length */
    double extent_m;        /* the tree's bounding-box diagonal */
    double *strokes_s;      /* stroke offsets, the first 0 */
    size_t stroke_count;
    int continuous;
    float colour[3];        /* the halo's linear RGB */
    float *segments;        /* FGG_SEGMENT_FLOATS per segment, slot field filled at upload */
    size_t segment_count;
    /* where the discharge's light comes from: points spread evenly over its
     * length weighted by brightness, relative to the origin */
    double light_m[FGG_FLASH_LIGHTS][3];
    double light_path_m[FGG_FLASH_LIGHTS]; /* path length from the root there */
    unsigned char light_main[FGG_FLASH_LIGHTS];
    size_t light_count, light_main_count;
} fgg_flash_rec;

typedef struct fgg_object_rec {
    uint32_t id;
    fgg_drawable d;         /* as given, in its body frame */
    fgg_pose pose;          /* identity unless moved */
} fgg_object_rec;

/* The gains of a discharge at a time (picture_timeline.c). */
typedef struct fgg_gains {
    double front_m;         /* the leader's front (path length); -1: the whole tree */
    double leader, all, main;
} fgg_gains;

/* One frame's camera and light, shared by the passes. */
typedef struct fgg_frame {
    const fgg_camera *camera;
    double time_s;
    float rot[9];           /* world -> view, rows: right, up, back */
    float proj[16];         /* row-major */
    float focal, aspect;    /* 1 / tan(fov / 2), width / height */
    int light_count;
    float light_pos[FGG_MAX_LIGHTS][4]; /* eye-relative world xyz, softening radius (m) */
    float light_col[FGG_MAX_LIGHTS][4]; /* linear RGB intensity (irradiance x m^2) */
    const fgg_ground *ground;          /* NULL: indoors */
} fgg_frame;

/* The object instances of one frame, in draw order (picture_objects.c). */
typedef struct fgg_object_ranges {
    size_t round_opaque, round_glass;  /* spheres and rods */
    size_t box_opaque, box_glass;      /* boxes and planes */
    size_t volume, marker;
    size_t total;
} fgg_object_ranges;

struct fgg_picture {
    fgg_context *context;
    int width, height;
    float exposure, bloom;
    float background[3], ambient[3];
    GLuint vao;
    GLuint prog_segment, prog_bright, prog_down, prog_up, prog_composite;
    GLuint prog_sky, prog_round, prog_box, prog_volume, prog_marker, prog_overlay;
    GLuint hdr_tex, hdr_fbo, depth_rb;
    GLuint ldr_tex, ldr_fbo;
    int levels;
    GLuint bloom_tex[FGG_BLOOM_LEVELS], bloom_fbo[FGG_BLOOM_LEVELS];
    int bloom_w[FGG_BLOOM_LEVELS], bloom_h[FGG_BLOOM_LEVELS];
    GLuint segment_buf, flash_buf, object_buf;
    size_t segment_buf_count;  /* segments in segment_buf */
    int segments_dirty;        /* flashes changed since the upload */
    fgg_flash_rec *flashes;
    size_t flash_count, flash_capacity;
    fgg_object_rec *objects;
    size_t object_count, object_capacity;
    float *object_floats;      /* FGG_OBJECT_FLOATS per object: the frame's instances */
    size_t object_floats_capacity;
    GLuint overlay_tex;
    int overlay_w, overlay_h, overlay_x, overlay_y; /* overlay_w 0: none */
    uint32_t next_id;
};

/* The next id of the picture's one sequence (never 0). */
static inline uint32_t fgg_picture_next_id(fgg_picture *p)
{
    uint32_t id = p->next_id++;
    if (p->next_id == 0)
        p->next_id = 1;
    return id;
}

/* Builds the segment instances and light points of a checked tree into rec
 * (segments, segment_count, origin_m, path_m, extent_m, light_*).
 * radius_m 0: 1 % of the extent. continuous: the flatter level law of a
 * glow discharge.
 * Errors: FG_ERR_NO_MEMORY. */
fg_result fgg_picture_tree_segments(const fg_node *nodes, size_t count, double radius_m,
                                    int continuous, fgg_flash_rec *rec);

/* The level law: half-width and brightness factors at a branching depth,
 * for a discharge that flashes (continuous 0) or glows. */
double fgg_picture_level_width(int depth, int continuous);
double fgg_picture_level_brightness(int depth, int continuous);

/* A discharge's gains at picture time t. */
fgg_gains fgg_flash_gains(const fgg_flash_rec *f, double t);
/* Whether those gains light anything. */
int fgg_gains_lit(const fgg_gains *g);
/* A flame's colour at a temperature (0: 1500 K): Planck's law, luminance 1. */
void fgg_volume_colour(double temperature_k, float rgb[3]);

/* Fills the frame's lights: the discharges lit at its time and the
 * volumes, brightest first when there are more than FGG_MAX_LIGHTS. */
void fgg_picture_lights(const fgg_picture *p, fgg_frame *frame);

/* Checks an object drawable (any kind but a discharge).
 * Errors: as fgg_picture_add_drawable. */
fg_result fgg_picture_check_object(const fgg_picture *p, const fgg_drawable *d,
                                   const char *who);
/* Adds a checked object. Errors: FG_ERR_CAPACITY, FG_ERR_NO_MEMORY. */
fg_result fgg_picture_add_object(fgg_picture *p, const fgg_drawable *d, uint32_t *id);
/* Removes objects by id (0: all); returns how many were removed. */
size_t fgg_picture_remove_objects(fgg_picture *p, uint32_t id);
/* The ground, or NULL. */
const fgg_ground *fgg_picture_ground(const fgg_picture *p);
/* The world position of an object's body point. */
void fgg_object_to_world(const fgg_object_rec *o, const double body[3], double world[3]);

/* Writes the frame's object instances (eye-relative) to object_buf and
 * says where each kind's range starts. Errors: FG_ERR_GPU. */
fg_result fgg_picture_upload_objects(fgg_picture *p, const fgg_frame *frame,
                                     fgg_object_ranges *ranges);

/* The frame's camera and light at time_s (picture_frame.c).
 * Errors: as fgg_picture_draw's for the camera. */
fg_result fgg_frame_begin(const fgg_picture *p, const fgg_camera *camera, double time_s,
                          fgg_frame *frame);
/* Sets the camera and light uniforms the scene shaders share. */
void fgg_frame_uniforms(const fgg_picture *p, const fgg_frame *frame, GLuint prog);

/* The passes into the float target (picture_scene.c): the surroundings
 * (sky, clouds, ground, haze), the opaque objects, then (after the
 * segments) glass and volumes. */
void fgg_draw_surroundings(fgg_picture *p, const fgg_frame *frame);
void fgg_draw_opaque(fgg_picture *p, const fgg_frame *frame, const fgg_object_ranges *r);
void fgg_draw_translucent(fgg_picture *p, const fgg_frame *frame, const fgg_object_ranges *r);

/* Over the 8-bit frame (picture_overlay.c): markers, then the overlay. */
void fgg_draw_overlay(fgg_picture *p, const fgg_frame *frame, const fgg_object_ranges *r);

#endif
