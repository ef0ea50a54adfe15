/* What goes over the finished 8-bit frame, after the tonemap, so that it
 * keeps its colours and never blooms: the charges' markers, then the
 * overlay image (a legend, the viewer's counters). */
#include <stdlib.h>

#include "picture_internal.h"

fg_result fgg_picture_set_overlay(fgg_picture *p, const uint8_t *rgba, int width, int height,
                                  int x, int y)
{
    if (!p)
        return fgg_fail(FG_ERR_NULL, "fgg_picture_set_overlay: picture is NULL");
    if (!rgba) {
        p->overlay_w = p->overlay_h = 0;
        return FG_OK;
    }
    if (width < 1 || width > 8192 || height < 1 || height > 8192)
        return fgg_fail(FG_ERR_ARGUMENT, "fgg_picture_set_overlay: size %d x %d is outside "
                        "1..8192", width, height);
    glGetError();
    glBindTexture(GL_TEXTURE_2D, p->overlay_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    fg_result r = fgg_gl_check("fgg_picture_set_overlay");
    if (r != FG_OK) {
        p->overlay_w = p->overlay_h = 0;
        return r;
    }
    p->overlay_w = width;
    p->overlay_h = height;
    p->overlay_x = x;
    p->overlay_y = y;
    return FG_OK;
}

void fgg_draw_overlay(fgg_picture *p, const fgg_frame *f, const fgg_object_ranges *r)
{
    size_t markers = r->total - r->marker;
    if (markers == 0 && p->overlay_w == 0)
        return;
    glBindFramebuffer(GL_FRAMEBUFFER, p->ldr_fbo);
    glViewport(0, 0, p->width, p->height);
    glEnable(GL_BLEND);
    /* the colour over the frame's by alpha; the frame stays opaque */
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    if (markers > 0) {
        glUseProgram(p->prog_marker);
        fgg_frame_uniforms(p, f, p->prog_marker);
        glUniform1i(glGetUniformLocation(p->prog_marker, "u_first"), (GLint)r->marker);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, p->object_buf);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)markers);
    }
    if (p->overlay_w > 0) {
        GLuint prog = p->prog_overlay;
        glUseProgram(prog);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, p->overlay_tex);
        glUniform1i(glGetUniformLocation(prog, "u_image"), 0);
        glUniform4f(glGetUniformLocation(prog, "u_rect"), (float)p->overlay_x,
                    (float)p->overlay_y, (float)p->overlay_w, (float)p->overlay_h);
        glUniform2f(glGetUniformLocation(prog, "u_viewport"), (float)p->width,
                    (float)p->height);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glDisable(GL_BLEND);
}
