/* The picture object: its programs and render targets, the discharges it
 * shows (their segments are uploaded lazily, at the next draw), adding any
 * drawable and removing them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gpu_shaders.h"
#include "picture_internal.h"
#include "fg_array.h"

#define DEFAULT_WIDTH 1280
#define DEFAULT_HEIGHT 720
#define DEFAULT_BLOOM 0.6

static fg_result make_target(GLenum format, int w, int h, GLuint *tex, GLuint *fbo)
{
    glGenTextures(1, tex);
    glBindTexture(GL_TEXTURE_2D, *tex);
    glTexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenFramebuffers(1, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *tex, 0);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return fgg_fail(FG_ERR_GPU, "picture: a %d x %d render target is incomplete (0x%x)", w,
                        h, (unsigned)status);
    return fgg_gl_check("picture: creating a render target");
}

static fg_result make_programs(fgg_picture *p)
{
    fg_result r = fgg_program_graphics("picture_segment", fgg_shader_picture_segment_vs,
                                       fgg_shader_picture_segment_fs, &p->prog_segment);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_bright", fgg_shader_picture_quad_vs,
                                 fgg_shader_picture_bright_fs, &p->prog_bright);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_down", fgg_shader_picture_quad_vs,
                                 fgg_shader_picture_down_fs, &p->prog_down);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_up", fgg_shader_picture_quad_vs,
                                 fgg_shader_picture_up_fs, &p->prog_up);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_composite", fgg_shader_picture_quad_vs,
                                 fgg_shader_picture_composite_fs, &p->prog_composite);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_sky", fgg_shader_picture_quad_vs,
                                 fgg_shader_picture_sky_fs, &p->prog_sky);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_round", fgg_shader_picture_round_vs,
                                 fgg_shader_picture_round_fs, &p->prog_round);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_box", fgg_shader_picture_box_vs,
                                 fgg_shader_picture_box_fs, &p->prog_box);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_volume", fgg_shader_picture_box_vs,
                                 fgg_shader_picture_volume_fs, &p->prog_volume);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_marker", fgg_shader_picture_marker_vs,
                                 fgg_shader_picture_marker_fs, &p->prog_marker);
    if (r == FG_OK)
        r = fgg_program_graphics("picture_overlay", fgg_shader_picture_overlay_vs,
                                 fgg_shader_picture_overlay_fs, &p->prog_overlay);
    return r;
}

/* The float target's depth: objects hide what is behind them. */
static fg_result add_depth(fgg_picture *p)
{
    glGenRenderbuffers(1, &p->depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, p->depth_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, p->width, p->height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, p->hdr_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, p->depth_rb);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return fgg_fail(FG_ERR_GPU, "picture: the %d x %d target with depth is incomplete (0x%x)",
                        p->width, p->height, (unsigned)status);
    return FG_OK;
}

static fg_result make_targets(fgg_picture *p)
{
    fg_result r = make_target(GL_RGBA16F, p->width, p->height, &p->hdr_tex, &p->hdr_fbo);
    if (r == FG_OK)
        r = add_depth(p);
    if (r == FG_OK)
        r = make_target(GL_RGBA8, p->width, p->height, &p->ldr_tex, &p->ldr_fbo);
    int w = p->width, h = p->height;
    for (p->levels = 0; r == FG_OK && p->levels < FGG_BLOOM_LEVELS; p->levels++) {
        w = (w + 1) / 2;
        h = (h + 1) / 2;
        if (w < FGG_BLOOM_MIN_SIDE || h < FGG_BLOOM_MIN_SIDE)
            break;
        p->bloom_w[p->levels] = w;
        p->bloom_h[p->levels] = h;
        r = make_target(GL_RGBA16F, w, h, &p->bloom_tex[p->levels], &p->bloom_fbo[p->levels]);
    }
    return r;
}

fg_result fgg_picture_create(fgg_context *context, const fgg_picture_config *config,
                             fgg_picture **out)
{
    if (!context || !out)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_create: %s is NULL",
                        !context ? "context" : "out");
    fgg_picture_config c = config ? *config : (fgg_picture_config){0};
    if (c.width == 0 && c.height == 0) {
        c.width = DEFAULT_WIDTH;
        c.height = DEFAULT_HEIGHT;
    }
    if (c.width < 16 || c.width > 8192 || c.height < 16 || c.height > 8192)
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_create: size %d x %d is outside 16..8192",
                        c.width, c.height);
    if (!isfinite(c.exposure) || c.exposure < 0 || !isfinite(c.bloom))
        return fgg_fail(FG_ERR_ARGUMENT,
                        "fgg_picture_create: exposure %g must be finite and >= 0, bloom %g "
                        "finite", c.exposure, c.bloom);
    for (int k = 0; k < 3; k++) {
        if (!isfinite(c.background[k]) || c.background[k] < 0)
            return fgg_fail(FG_ERR_ARGUMENT,
                            "fgg_picture_create: background[%d] = %g is not a finite value >= 0",
                            k, (double)c.background[k]);
        if (!isfinite(c.ambient[k]) || c.ambient[k] < 0)
            return fgg_fail(FG_ERR_ARGUMENT,
                            "fgg_picture_create: ambient[%d] = %g is not a finite value >= 0", k,
                            (double)c.ambient[k]);
    }
    fgg_picture *p = calloc(1, sizeof *p);
    if (!p)
        return fgg_fail(FG_ERR_NO_MEMORY, "fgg_picture_create: no memory");
    p->context = context;
    p->width = c.width;
    p->height = c.height;
    p->exposure = (float)(c.exposure == 0 ? 1 : c.exposure);
    p->bloom = (float)(c.bloom == 0 ? DEFAULT_BLOOM : c.bloom < 0 ? 0 : c.bloom);
    memcpy(p->background, c.background, sizeof p->background);
    memcpy(p->ambient, c.ambient, sizeof p->ambient);
    p->next_id = 1;
    glGetError(); /* an earlier caller's error is not ours */
    glGenVertexArrays(1, &p->vao);
    glGenBuffers(1, &p->segment_buf);
    glGenBuffers(1, &p->flash_buf);
    glGenBuffers(1, &p->object_buf);
    glGenTextures(1, &p->overlay_tex);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, p->flash_buf);
    glBufferData(GL_SHADER_STORAGE_BUFFER,
                 FGG_PICTURE_MAX_FLASHES * FGG_FLASH_FLOATS * sizeof(float), NULL,
                 GL_DYNAMIC_DRAW);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    fg_result r = make_programs(p);
    if (r == FG_OK)
        r = make_targets(p);
    if (r == FG_OK)
        r = fgg_gl_check("fgg_picture_create");
    if (r != FG_OK) {
        char keep[512];
        strncpy(keep, fgg_error_message(), sizeof keep - 1);
        keep[sizeof keep - 1] = 0;
        fgg_picture_destroy(p);
        return fgg_fail(r, "%s", keep);
    }
    *out = p;
    return FG_OK;
}

static void free_flash(fgg_flash_rec *f)
{
    free(f->strokes_s);
    free(f->segments);
}

void fgg_picture_destroy(fgg_picture *p)
{
    if (!p)
        return;
    for (size_t i = 0; i < p->flash_count; i++)
        free_flash(&p->flashes[i]);
    free(p->flashes);
    free(p->objects);
    free(p->object_floats);
    const GLuint programs[] = {p->prog_segment, p->prog_bright, p->prog_down,
                               p->prog_up,      p->prog_composite, p->prog_sky,
                               p->prog_round,   p->prog_box,    p->prog_volume,
                               p->prog_marker,  p->prog_overlay};
    for (size_t i = 0; i < sizeof programs / sizeof programs[0]; i++)
        glDeleteProgram(programs[i]);
    glDeleteRenderbuffers(1, &p->depth_rb);
    glDeleteFramebuffers(1, &p->hdr_fbo);
    glDeleteFramebuffers(1, &p->ldr_fbo);
    glDeleteTextures(1, &p->hdr_tex);
    glDeleteTextures(1, &p->ldr_tex);
    for (int i = 0; i < FGG_BLOOM_LEVELS; i++) {
        glDeleteFramebuffers(1, &p->bloom_fbo[i]);
        glDeleteTextures(1, &p->bloom_tex[i]);
    }
    glDeleteBuffers(1, &p->segment_buf);
    glDeleteBuffers(1, &p->flash_buf);
    glDeleteBuffers(1, &p->object_buf);
    glDeleteTextures(1, &p->overlay_tex);
    glDeleteVertexArrays(1, &p->vao);
    free(p);
}

static fg_result check_times(const fgg_flash *f)
{
    const double v[] = {f->start_s, f->leader_s, f->radius_m, f->duration_s};
    const char *name[] = {"start_s", "leader_s", "radius_m", "duration_s"};
    for (int k = 0; k < 4; k++) {
        if (!isfinite(v[k]))
            return fgg_fail(FG_ERR_NOT_FINITE, "fgg_picture_add: %s is not finite", name[k]);
        if (k > 0 && v[k] < 0)
            return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_add: %s = %g is negative", name[k],
                            v[k]);
    }
    if (!f->stroke_offsets_s)
        return FG_OK;
    if (f->stroke_count == 0)
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_add: stroke_offsets_s with stroke_count 0");
    for (size_t i = 0; i < f->stroke_count; i++) {
        if (!isfinite(f->stroke_offsets_s[i]))
            return fgg_fail(FG_ERR_NOT_FINITE, "fgg_picture_add: stroke_offsets_s[%zu] is not "
                            "finite", i);
        if (f->stroke_offsets_s[i] < 0)
            return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_add: stroke_offsets_s[%zu] = %g is "
                            "negative", i, f->stroke_offsets_s[i]);
    }
    return FG_OK;
}

static fg_result check_colour(const float *colour, const char *who)
{
    for (int k = 0; k < 3; k++)
        if (!isfinite(colour[k]) || colour[k] < 0)
            return fgg_fail(isfinite(colour[k]) ? FG_ERR_ARGUMENT : FG_ERR_NOT_FINITE,
                            "%s: colour[%d] = %g is not a finite value >= 0", who, k,
                            (double)colour[k]);
    return FG_OK;
}


fg_result fgg_picture_add(fgg_picture *p, const fgg_flash *flash, uint32_t *id)
{
    if (!p || !flash || !flash->nodes)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_add: %s is NULL",
                        !p ? "picture" : !flash ? "flash" : "flash->nodes");
    fg_tree_fault fault;
    if (fg_tree_check(flash->nodes, flash->node_count, &fault) != FG_OK) {
        char why[160];
        fg_tree_fault_describe(&fault, why, sizeof why);
        return fgg_fail(FG_ERR_TREE, "fgg_picture_add: the tree is invalid: %s", why);
    }
    fg_result r = check_times(flash);
    if (r == FG_OK)
        r = check_colour(flash->colour, "fgg_picture_add");
    if (r != FG_OK)
        return r;
    if (p->flash_count == FGG_PICTURE_MAX_FLASHES)
        return fgg_fail(FG_ERR_CAPACITY, "fgg_picture_add: already %d flashes",
                        FGG_PICTURE_MAX_FLASHES);
    fgg_flash_rec rec = {0};
    size_t strokes = flash->stroke_offsets_s ? flash->stroke_count : 1;
    rec.strokes_s = calloc(strokes, sizeof *rec.strokes_s);
    fgg_flash_rec *grown =
        fg_array_grow(p->flashes, &p->flash_capacity, p->flash_count + 1, sizeof *grown, 16);
    if (grown)
        p->flashes = grown;
    if (!rec.strokes_s || !grown) {
        free(rec.strokes_s);
        return fgg_fail(FG_ERR_NO_MEMORY, "fgg_picture_add: no memory");
    }
    r = fgg_picture_tree_segments(flash->nodes, flash->node_count, flash->radius_m,
                                  flash->continuous != 0, &rec);
    if (r != FG_OK) {
        free(rec.strokes_s);
        return r;
    }
    if (flash->stroke_offsets_s)
        memcpy(rec.strokes_s, flash->stroke_offsets_s, strokes * sizeof *rec.strokes_s);
    rec.stroke_count = strokes;
    rec.start_s = flash->start_s;
    rec.leader_s = flash->leader_s;
    rec.continuous = flash->continuous != 0;
    rec.duration_s = flash->duration_s;
    /* the violet-blue of the nitrogen lines that dominate air's spectrum */
    const float nitrogen[3] = {0.55f, 0.65f, 1.0f};
    int given = flash->colour[0] > 0 || flash->colour[1] > 0 || flash->colour[2] > 0;
    memcpy(rec.colour, given ? flash->colour : nitrogen, sizeof rec.colour);
    rec.id = fgg_picture_next_id(p);
    p->flashes[p->flash_count++] = rec;
    p->segments_dirty = 1;
    if (id)
        *id = rec.id;
    return FG_OK;
}

fg_result fgg_picture_add_drawable(fgg_picture *p, const fgg_drawable *d, uint32_t *id)
{
    if (!p || !d)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_add_drawable: %s is NULL",
                        !p ? "picture" : "drawable");
    if (d->kind == FGG_DRAWABLE_DISCHARGE)
        return fgg_picture_add(p, &d->discharge, id);
    fg_result r = fgg_picture_check_object(p, d, "fgg_picture_add_drawable");
    return r != FG_OK ? r : fgg_picture_add_object(p, d, id);
}

void fgg_picture_remove(fgg_picture *p, uint32_t id)
{
    if (!p)
        return;
    if (fgg_picture_remove_objects(p, id) > 0 && id != 0)
        return;
    size_t kept = 0;
    for (size_t i = 0; i < p->flash_count; i++) {
        if (id == 0 || p->flashes[i].id == id)
            free_flash(&p->flashes[i]);
        else
            p->flashes[kept++] = p->flashes[i];
    }
    if (kept != p->flash_count)
        p->segments_dirty = 1;
    p->flash_count = kept;
}

void fgg_picture_size(const fgg_picture *p, int *width, int *height)
{
    if (width)
        *width = p ? p->width : 0;
    if (height)
        *height = p ? p->height : 0;
}
