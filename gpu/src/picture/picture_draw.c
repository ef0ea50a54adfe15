/* Drawing a frame: each flash's brightness at the frame's time (the
 * timeline), the camera, the segments into the float target, the bloom
 * chain and the tonemap into the 8-bit frame. Constants are in
 * docs/picture.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "picture_internal.h"
#include "fg_vec3.h"


/* Gains on the float target, where 1 is about where the bloom starts. */
#define LEADER_GAIN 0.35     /* the growing leader, dim */
#define RETURN_GAIN 6.0      /* the first return stroke's peak */
#define RESTRIKE_GAIN 4.0    /* each later stroke's peak, main channel only */
#define CONTINUOUS_GAIN 1.5  /* a continuous discharge's mean glow */
/* The decay after a stroke: a fast flash and a slow afterglow (the
 * continuing current), peak 1. Perceptual, not the microsecond physics:
 * a 90 Hz frame must still catch the flash. */
#define DECAY_FAST_S 0.025
#define DECAY_SLOW_S 0.25
#define DECAY_SLOW_PART 0.12
/* Below this a flash is not drawn at all. */
#define GAIN_FLOOR 1e-4
/* Bloom's bright pass. */
#define BLOOM_THRESHOLD 1.0f
#define BLOOM_KNEE 0.5f
/* The narrowest half-width a segment is drawn with, in pixels. */
#define MIN_HALF_WIDTH_PX 0.75f

static double decay(double dt)
{
    if (dt < 0)
        return 0;
    return (1 - DECAY_SLOW_PART) * exp(-dt / DECAY_FAST_S) +
           DECAY_SLOW_PART * exp(-dt / DECAY_SLOW_S);
}

/* Three incommensurate sines, phases from the id: mean 1, within 0.5..1.5. */
static double flicker(double t, uint32_t id)
{
    double a = 0.37 * id, b = 1.91 * id, c = 4.03 * id;
    return 1 + 0.25 * sin(2 * FG_PI * 7.3 * t + a) + 0.15 * sin(2 * FG_PI * 13.7 * t + b) +
           0.1 * sin(2 * FG_PI * 29.9 * t + c);
}

/* gains = {leader front m (-1: whole tree), leader, all, main}. */
static void flash_gains(const fgg_flash_rec *f, double t, float gains[4])
{
    double front = -1, leader = 0, all = 0, main = 0;
    double dt = t - f->start_s;
    if (dt < 0) {
        if (f->leader_s > 0 && -dt <= f->leader_s) {
            front = f->path_m * (1 + dt / f->leader_s);
            leader = LEADER_GAIN;
        }
    } else if (f->continuous) {
        if (f->duration_s == 0 || dt < f->duration_s)
            all = CONTINUOUS_GAIN * flicker(t, f->id);
    } else {
        all = RETURN_GAIN * decay(dt);
        for (size_t k = 1; k < f->stroke_count; k++)
            main += RESTRIKE_GAIN * decay(dt - f->strokes_s[k]);
    }
    if (leader == 0 && all < GAIN_FLOOR && main < GAIN_FLOOR)
        all = main = 0, front = 0; /* front 0 with no leader: nothing is drawn */
    gains[0] = (float)front;
    gains[1] = (float)leader;
    gains[2] = (float)all;
    gains[3] = (float)main;
}

typedef struct view {
    float rot[9];    /* rows: right, up, back */
    float proj[16];  /* row-major */
    float focal;     /* 1 / tan(fov / 2) */
} view;

static fg_result make_view(const fgg_camera *c, double aspect, view *v)
{
    for (int k = 0; k < 3; k++)
        if (!isfinite(c->eye_m[k]) || !isfinite(c->target_m[k]) || !isfinite(c->up[k]))
            return fgg_fail(FG_ERR_NOT_FINITE, "fgg_picture_draw: the camera has a non-finite "
                            "coordinate");
    if (!isfinite(c->fov_y_deg))
        return fgg_fail(FG_ERR_NOT_FINITE, "fgg_picture_draw: fov_y_deg is not finite");
    double fov = c->fov_y_deg == 0 ? 45 : c->fov_y_deg;
    if (fov <= 0 || fov >= 179)
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_draw: fov_y_deg %g is outside (0, 179)",
                        fov);
    fg_vec3 fv = fg_v3_sub(fg_v3_load(c->target_m), fg_v3_load(c->eye_m)), upv = fg_v3_load(c->up);
    double fl = fg_v3_len(fv);
    if (!(fl > 0))
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_draw: the camera's eye is at its target");
    if (fg_v3_dot(upv, upv) == 0)
        upv.z = 1;
    double ul = fg_v3_len(upv);
    fg_vec3 sv = fg_v3_cross(fv, upv);
    double sl = fg_v3_len(sv);
    if (!(sl > 1e-9 * fl * ul))
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_draw: the camera's up is along its view");
    fv = fg_v3_div(fv, fl);
    sv = fg_v3_div(sv, sl);
    double f[3], s[3], u[3];
    fg_v3_store(fv, f);
    fg_v3_store(sv, s);
    fg_v3_store(fg_v3_cross(sv, fv), u);
    for (int k = 0; k < 3; k++) {
        v->rot[k] = (float)s[k];
        v->rot[3 + k] = (float)u[k];
        v->rot[6 + k] = (float)-f[k];
    }
    double focal = 1 / tan(fov * FG_PI / 360);
    double near = 1e-3 * fl; /* an infinite far plane: depth is not tested */
    memset(v->proj, 0, sizeof v->proj);
    v->proj[0] = (float)(focal / aspect);
    v->proj[5] = (float)focal;
    v->proj[10] = -1;
    v->proj[11] = (float)(-2 * near);
    v->proj[14] = -1;
    v->focal = (float)focal;
    return FG_OK;
}

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
    float state[FGG_PICTURE_MAX_FLASHES * 8];
    for (size_t i = 0; i < p->flash_count; i++) {
        const fgg_flash_rec *f = &p->flashes[i];
        for (int k = 0; k < 3; k++)
            state[8 * i + k] = (float)(f->origin_m[k] - c->eye_m[k]);
        state[8 * i + 3] = 0;
        flash_gains(f, t, &state[8 * i + 4]);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, p->flash_buf);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                    (GLsizeiptr)(p->flash_count * 8 * sizeof(float)), state);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

static void draw_segments(fgg_picture *p, const view *v)
{
    glBindFramebuffer(GL_FRAMEBUFFER, p->hdr_fbo);
    glViewport(0, 0, p->width, p->height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    if (p->segment_buf_count == 0)
        return;
    glUseProgram(p->prog_segment);
    glUniformMatrix3fv(glGetUniformLocation(p->prog_segment, "u_view"), 1, GL_TRUE, v->rot);
    glUniformMatrix4fv(glGetUniformLocation(p->prog_segment, "u_proj"), 1, GL_TRUE, v->proj);
    glUniform1f(glGetUniformLocation(p->prog_segment, "u_focal_px"),
                v->focal * 0.5f * (float)p->height);
    glUniform1f(glGetUniformLocation(p->prog_segment, "u_min_px"), MIN_HALF_WIDTH_PX);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, p->segment_buf);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, p->flash_buf);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)p->segment_buf_count);
    glDisable(GL_BLEND);
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
    view v;
    fg_result r = make_view(camera, (double)p->width / p->height, &v);
    if (r != FG_OK)
        return r;
    glGetError();
    if (p->segments_dirty && (r = upload_segments(p)) != FG_OK)
        return r;
    upload_flashes(p, camera, time_s);
    glBindVertexArray(p->vao);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    draw_segments(p, &v);
    bloom(p);
    composite(p);
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
