/* A frame's camera (the view rotation, an infinite-far projection) and
 * light, and the uniforms the scene shaders share. */
#include <math.h>
#include <string.h>

#include "picture_internal.h"
#include "fg_vec3.h"

static fg_result make_view(const fgg_camera *c, double aspect, fgg_frame *v)
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
    v->aspect = (float)aspect;
    return FG_OK;
}

fg_result fgg_frame_begin(const fgg_picture *p, const fgg_camera *camera, double time_s,
                          fgg_frame *frame)
{
    *frame = (fgg_frame){.camera = camera, .time_s = time_s};
    fg_result r = make_view(camera, (double)p->width / p->height, frame);
    if (r != FG_OK)
        return r;
    fgg_picture_lights(p, frame);
    frame->ground = fgg_picture_ground(p);
    return FG_OK;
}

void fgg_frame_uniforms(const fgg_picture *p, const fgg_frame *f, GLuint prog)
{
    glUniformMatrix3fv(glGetUniformLocation(prog, "u_view"), 1, GL_TRUE, f->rot);
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_proj"), 1, GL_TRUE, f->proj);
    glUniform2f(glGetUniformLocation(prog, "u_lens"), f->focal / f->aspect, f->focal);
    glUniform2f(glGetUniformLocation(prog, "u_viewport"), (float)p->width, (float)p->height);
    glUniform1i(glGetUniformLocation(prog, "u_light_count"), f->light_count);
    if (f->light_count > 0) {
        glUniform4fv(glGetUniformLocation(prog, "u_light_pos"), f->light_count,
                     &f->light_pos[0][0]);
        glUniform4fv(glGetUniformLocation(prog, "u_light_col"), f->light_count,
                     &f->light_col[0][0]);
    }
    glUniform3f(glGetUniformLocation(prog, "u_ambient"), p->ambient[0], p->ambient[1],
                p->ambient[2]);
    glUniform1i(glGetUniformLocation(prog, "u_outdoor"), f->ground != NULL);
}
