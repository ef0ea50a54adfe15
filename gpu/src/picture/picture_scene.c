/* The passes of what the discharges happen among, into the float target:
 * the outdoors behind everything (sky_fs), the opaque objects with depth
 * (round_fs ray-traces spheres and rods, box_fs shades boxes and planes),
 * and after the segments the glass (added, as light it reflects and
 * scatters) and the flames (added, marched through their boxes). */
#include <math.h>

#include "picture_internal.h"

/* The storm cell's radius when the ground gives none, and the scale of
 * the outdoors' textures when there is no cloud deck to measure it by. */
#define DEFAULT_CELL_M 12000.0
#define DEFAULT_SCALE_M 3000.0
#define DEFAULT_HAZE_PER_M 4e-6
#define BOX_VERTICES 36

void fgg_draw_surroundings(fgg_picture *p, const fgg_frame *f)
{
    const fgg_ground *g = f->ground;
    if (!g)
        return;
    GLuint prog = p->prog_sky;
    glUseProgram(prog);
    fgg_frame_uniforms(p, f, prog);
    const double *eye = f->camera->eye_m;
    int clouds = g->cloud_base_m != 0;
    double scale = clouds ? g->cloud_base_m - g->height_m : DEFAULT_SCALE_M;
    glUniform4f(glGetUniformLocation(prog, "u_ground"), (float)(g->height_m - eye[2]),
                (float)(clouds ? g->cloud_base_m - eye[2] : 0),
                (float)(g->haze_per_m == 0 ? DEFAULT_HAZE_PER_M : g->haze_per_m),
                clouds ? 1.0f : 0.0f);
    glUniform4f(glGetUniformLocation(prog, "u_cell"), (float)(g->cloud_centre_m[0] - eye[0]),
                (float)(g->cloud_centre_m[1] - eye[1]),
                (float)(g->cloud_radius_m == 0 ? DEFAULT_CELL_M : g->cloud_radius_m),
                (float)scale);
    /* the textures' world coordinates, kept small: they repeat far beyond
     * any view, so the eye is taken modulo a large period */
    double period = 4096 * scale;
    glUniform3f(glGetUniformLocation(prog, "u_eye"), (float)fmod(eye[0], period),
                (float)fmod(eye[1], period), (float)eye[2]);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
}

static void draw_round(fgg_picture *p, const fgg_frame *f, size_t first, size_t count)
{
    if (count == 0)
        return;
    glUseProgram(p->prog_round);
    fgg_frame_uniforms(p, f, p->prog_round);
    glUniform1i(glGetUniformLocation(p->prog_round, "u_first"), (GLint)first);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, p->object_buf);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)count);
}

static void draw_boxes(fgg_picture *p, GLuint prog, const fgg_frame *f, size_t first,
                       size_t count)
{
    if (count == 0)
        return;
    glUseProgram(prog);
    fgg_frame_uniforms(p, f, prog);
    glUniform1i(glGetUniformLocation(prog, "u_first"), (GLint)first);
    glUniform1f(glGetUniformLocation(prog, "u_time"), (float)fmod(f->time_s, 1000.0));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, p->object_buf);
    glDrawArraysInstanced(GL_TRIANGLES, 0, BOX_VERTICES, (GLsizei)count);
}

void fgg_draw_opaque(fgg_picture *p, const fgg_frame *f, const fgg_object_ranges *r)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    draw_round(p, f, r->round_opaque, r->round_glass - r->round_opaque);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    draw_boxes(p, p->prog_box, f, r->box_opaque, r->box_glass - r->box_opaque);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
}

void fgg_draw_translucent(fgg_picture *p, const fgg_frame *f, const fgg_object_ranges *r)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    draw_round(p, f, r->round_glass, r->box_opaque - r->round_glass);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    draw_boxes(p, p->prog_box, f, r->box_glass, r->volume - r->box_glass);
    glCullFace(GL_FRONT); /* a flame's back faces: it shows from inside its box too */
    draw_boxes(p, p->prog_volume, f, r->volume, r->marker - r->volume);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}
