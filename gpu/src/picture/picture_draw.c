/* Drawing a frame: the camera, the discharges' state and light at the
 * frame's time, the passes into the float target (surroundings, opaque
 * objects, segments, glass and volumes), the bloom chain, the tonemap into
 * the 8-bit frame, and what goes over it. Constants are in
 * docs/picture.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "picture_internal.h"
#include "fg_vec3.h"


/* Bloom's bright pass. */
#define BLOOM_THRESHOLD 1.0f
#define BLOOM_KNEE 0.5f
/* The narrowest half-width a segment is drawn with, in pixels. */
#define MIN_HALF_WIDTH_PX 0.75f
/* How much of the halo's colour the white-hot core takes: a spark's or a
 * bolt's core is white, a glow discharge's (a plasma ball's) coloured. */
#define FLASH_CORE_TINT 0.3f
#define GLOW_CORE_TINT 0.65f
/* Channel above a cloud base fades into the cloud over this fraction of
 * the base's height. */
#define CLOUD_FADE 0.04

static fg_result upload_segments(fgg_picture *p)
{
    size_t total = 0;
    for (size_t i = 0; i < p->flash_count; i++)
        total += p->flashes[i].segment_count;
    float *all = malloc((total ? total : 1) * FGG_SEGMENT_FLOATS * sizeof *all);
    if (!all)
        return fgg_fail(FG_ERR_NO_MEMORY, "fgg_picture_draw: no memory for %zu segments", total);
    size_t at = 0;
    for (size_t i = 0; i < p->flash_count; i++) {
        const fgg_flash_rec *f = &p->flashes[i];
        memcpy(all + at * FGG_SEGMENT_FLOATS, f->segments,
               f->segment_count * FGG_SEGMENT_FLOATS * sizeof *all);
        for (size_t k = 0; k < f->segment_count; k++)
            all[(at + k) * FGG_SEGMENT_FLOATS + 12] = (float)i;
        at += f->segment_count;
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, p->segment_buf);
    glBufferData(GL_SHADER_STORAGE_BUFFER,
                 (GLsizeiptr)((total ? total : 1) * FGG_SEGMENT_FLOATS * sizeof *all), all,
                 GL_STATIC_DRAW);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    free(all);
    p->segment_buf_count = total;
    p->segments_dirty = 0;
    return fgg_gl_check("fgg_picture_draw: uploading segments");
}

static void upload_flashes(fgg_picture *p, const fgg_camera *c, double t)
{
    float state[FGG_PICTURE_MAX_FLASHES * FGG_FLASH_FLOATS];
    for (size_t i = 0; i < p->flash_count; i++) {
        const fgg_flash_rec *f = &p->flashes[i];
        float *s = &state[FGG_FLASH_FLOATS * i];
        for (int k = 0; k < 3; k++)
            s[k] = (float)(f->origin_m[k] - c->eye_m[k]);
        s[3] = 0;
        fgg_gains g = fgg_flash_gains(f, t);
        s[4] = (float)g.front_m;
        s[5] = (float)g.leader;
        s[6] = (float)g.all;
        s[7] = (float)g.main;
        memcpy(&s[8], f->colour, 3 * sizeof *s);
        s[11] = f->continuous ? GLOW_CORE_TINT : FLASH_CORE_TINT;
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, p->flash_buf);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                    (GLsizeiptr)(p->flash_count * FGG_FLASH_FLOATS * sizeof(float)), state);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

static void draw_segments(fgg_picture *p, const fgg_frame *f)
{
    if (p->segment_buf_count == 0)
        return;
    GLuint prog = p->prog_segment;
    glUseProgram(prog);
    glUniformMatrix3fv(glGetUniformLocation(prog, "u_view"), 1, GL_TRUE, f->rot);
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_proj"), 1, GL_TRUE, f->proj);
    glUniform1f(glGetUniformLocation(prog, "u_focal_px"), f->focal * 0.5f * (float)p->height);
    glUniform1f(glGetUniformLocation(prog, "u_min_px"), MIN_HALF_WIDTH_PX);
    /* the cloud base relative to the eye, and the depth it hides channel in */
    float base = 1e30f, fade = 1;
    if (f->ground && f->ground->cloud_base_m != 0) {
        base = (float)(f->ground->cloud_base_m - f->camera->eye_m[2]);
        fade = (float)(CLOUD_FADE * (f->ground->cloud_base_m - f->ground->height_m));
    }
    glUniform2f(glGetUniformLocation(prog, "u_cloud"), base, fade);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, p->segment_buf);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, p->flash_buf);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)p->segment_buf_count);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

/* A full-viewport pass of prog reading src (w x h) into fbo (vw x vh). */
static void pass(GLuint prog, GLuint src, int w, int h, GLuint fbo, int vw, int vh)
{
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, vw, vh);
    glUseProgram(prog);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, src);
    glUniform1i(glGetUniformLocation(prog, "u_src"), 0);
    glUniform2f(glGetUniformLocation(prog, "u_texel"), 1.0f / (float)w, 1.0f / (float)h);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

static void bloom(fgg_picture *p)
{
    if (p->levels == 0 || p->bloom <= 0)
        return;
    glUseProgram(p->prog_bright);
    glUniform1f(glGetUniformLocation(p->prog_bright, "u_threshold"), BLOOM_THRESHOLD);
    glUniform1f(glGetUniformLocation(p->prog_bright, "u_knee"), BLOOM_KNEE);
    pass(p->prog_bright, p->hdr_tex, p->width, p->height, p->bloom_fbo[0], p->bloom_w[0],
         p->bloom_h[0]);
    for (int i = 1; i < p->levels; i++)
        pass(p->prog_down, p->bloom_tex[i - 1], p->bloom_w[i - 1], p->bloom_h[i - 1],
             p->bloom_fbo[i], p->bloom_w[i], p->bloom_h[i]);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    for (int i = p->levels - 2; i >= 0; i--)
        pass(p->prog_up, p->bloom_tex[i + 1], p->bloom_w[i + 1], p->bloom_h[i + 1],
             p->bloom_fbo[i], p->bloom_w[i], p->bloom_h[i]);
    glDisable(GL_BLEND);
}

static void composite(fgg_picture *p)
{
    GLuint prog = p->prog_composite;
    glBindFramebuffer(GL_FRAMEBUFFER, p->ldr_fbo);
    glViewport(0, 0, p->width, p->height);
    glUseProgram(prog);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, p->hdr_tex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, p->levels > 0 ? p->bloom_tex[0] : p->hdr_tex);
    glUniform1i(glGetUniformLocation(prog, "u_scene"), 0);
    glUniform1i(glGetUniformLocation(prog, "u_bloom"), 1);
    /* The levels are summed on the way up: divide so that the strength does
     * not depend on how many there are. */
    float strength = p->levels > 0 ? p->bloom / (float)p->levels : 0;
    glUniform1f(glGetUniformLocation(prog, "u_bloom_strength"), strength);
    glUniform1f(glGetUniformLocation(prog, "u_exposure"), p->exposure);
    glUniform3f(glGetUniformLocation(prog, "u_background"), p->background[0], p->background[1],
                p->background[2]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glActiveTexture(GL_TEXTURE0);
}

fg_result fgg_picture_draw(fgg_picture *p, const fgg_camera *camera, double time_s)
{
    if (!p || !camera)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_draw: %s is NULL", !p ? "picture" : "camera");
    if (!isfinite(time_s))
        return fgg_fail(FG_ERR_NOT_FINITE, "fgg_picture_draw: time_s is not finite");
    fgg_frame frame;
    fg_result r = fgg_frame_begin(p, camera, time_s, &frame);
    if (r != FG_OK)
        return r;
    glGetError();
    if (p->segments_dirty && (r = upload_segments(p)) != FG_OK)
        return r;
    upload_flashes(p, camera, time_s);
    fgg_object_ranges ranges;
    if ((r = fgg_picture_upload_objects(p, &frame, &ranges)) != FG_OK)
        return r;
    glBindVertexArray(p->vao);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindFramebuffer(GL_FRAMEBUFFER, p->hdr_fbo);
    glViewport(0, 0, p->width, p->height);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fgg_draw_surroundings(p, &frame);
    fgg_draw_opaque(p, &frame, &ranges);
    draw_segments(p, &frame);
    fgg_draw_translucent(p, &frame, &ranges);
    bloom(p);
    composite(p);
    fgg_draw_overlay(p, &frame, &ranges);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return fgg_gl_check("fgg_picture_draw");
}

void fgg_picture_blit(fgg_picture *p, int width, int height)
{
    if (!p || width <= 0 || height <= 0)
        return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, p->ldr_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, p->width, p->height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                      GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

fg_result fgg_picture_read_rgba8(fgg_picture *p, uint8_t *rgba)
{
    if (!p || !rgba)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_read_rgba8: %s is NULL",
                        !p ? "picture" : "rgba");
    glGetError();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, p->ldr_fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, p->width, p->height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    fg_result r = fgg_gl_check("fgg_picture_read_rgba8");
    if (r != FG_OK)
        return r;
    /* GL's rows run bottom first. */
    size_t row = 4 * (size_t)p->width;
    uint8_t tmp[4 * 8192];
    for (int y = 0; y < p->height / 2; y++) {
        uint8_t *a = rgba + (size_t)y * row, *b = rgba + (size_t)(p->height - 1 - y) * row;
        memcpy(tmp, a, row);
        memcpy(a, b, row);
        memcpy(b, tmp, row);
    }
    return FG_OK;
}
