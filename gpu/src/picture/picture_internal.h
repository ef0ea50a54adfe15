/* The insides of fgg_picture, shared by its files: picture.c (targets,
 * flashes), picture_tree.c (a tree into segment instances), picture_draw.c
 * (the timeline, the camera, the passes), picture_png.c. */
#ifndef FULGUR_GPU_PICTURE_INTERNAL_H
#define FULGUR_GPU_PICTURE_INTERNAL_H

#include "fulgur/gpu_picture.h"
#include "context/gpu_internal.h"

/* At most this many flashes at once. */
#define FGG_PICTURE_MAX_FLASHES 1024
/* Bloom levels at most (halving each), and the smallest level's side. */
#define FGG_BLOOM_LEVELS 6
#define FGG_BLOOM_MIN_SIDE 4

/* Floats per segment instance: four vec4 (see picture_segment_vs.glsl). */
#define FGG_SEGMENT_FLOATS 16

typedef struct fgg_flash_rec {
    uint32_t id;
    double origin_m[3];     /* node 0: segment positions are relative to it */
    double start_s, leader_s, duration_s;
    double path_m;          /* the longest path from the root: the leader's full length */
    double *strokes_s;      /* stroke offsets, the first 0 */
    size_t stroke_count;
    int continuous;
    float *segments;        /* FGG_SEGMENT_FLOATS per segment, slot field filled at upload */
    size_t segment_count;
} fgg_flash_rec;

struct fgg_picture {
    fgg_context *context;
    int width, height;
    float exposure, bloom;
    float background[3];
    GLuint vao;
    GLuint prog_segment, prog_bright, prog_down, prog_up, prog_composite;
    GLuint hdr_tex, hdr_fbo;
    GLuint ldr_tex, ldr_fbo;
    int levels;
    GLuint bloom_tex[FGG_BLOOM_LEVELS], bloom_fbo[FGG_BLOOM_LEVELS];
    int bloom_w[FGG_BLOOM_LEVELS], bloom_h[FGG_BLOOM_LEVELS];
    GLuint segment_buf, flash_buf;
    size_t segment_buf_count;  /* segments in segment_buf */
    int segments_dirty;        /* flashes changed since the upload */
    fgg_flash_rec *flashes;
    size_t flash_count, flash_capacity;
    uint32_t next_id;
};

/* Builds the segment instances of a checked tree into rec (segments,
 * segment_count, origin_m, path_m). radius_m 0: 1 % of the extent.
 * Errors: FG_ERR_NO_MEMORY. */
fg_result fgg_picture_tree_segments(const fg_node *nodes, size_t count, double radius_m,
                                    fgg_flash_rec *rec);

/* The level law: half-width and brightness factors at a branching depth. */
double fgg_picture_level_width(int depth);
double fgg_picture_level_brightness(int depth);

#endif
