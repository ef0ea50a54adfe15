/* The viewer's camera (an orbit about a target) and the scene's own
 * discharges, played from the start as the scene times them (each asked
 * of the sim thread VIEW_TIMELINE_AHEAD_S before its emit time, so its
 * leader shows whole), again from now on R; and the camera that follows
 * them: it eases to each one's framing as it comes, until you orbit, zoom
 * or place a charge; F frames the latest again and follows. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fg_vec3.h"
#include "view.h"

/* The camera turns to a discharge this long before its emit time, and
 * reaches it with this time constant (95 % in three). */
#define FOLLOW_LEAD_S 0.15
#define FOLLOW_TAU_S 0.05

void view_camera_set(view_camera *c, const scene_camera *sc)
{
    fg_vec3 d = fg_v3_sub(fg_v3_load(sc->eye_m), fg_v3_load(sc->target_m));
    memcpy(c->target_m, sc->target_m, sizeof c->target_m);
    c->distance_m = fg_v3_len(d);
    c->azimuth_rad = atan2(d.y, d.x);
    c->elevation_rad = asin(d.z / c->distance_m);
    c->fov_y_deg = sc->fov_y_deg;
}

void view_camera_get(const view_camera *c, fgg_camera *out)
{
    double ce = cos(c->elevation_rad), se = sin(c->elevation_rad);
    double dir[3] = {ce * cos(c->azimuth_rad), ce * sin(c->azimuth_rad), se};
    *out = (fgg_camera){.up = {0, 0, 1}, .fov_y_deg = c->fov_y_deg};
    for (int k = 0; k < 3; k++) {
        out->target_m[k] = c->target_m[k];
        out->eye_m[k] = c->target_m[k] + c->distance_m * dir[k];
    }
}

int view_timeline_init(view *v)
{
    size_t n = v->s->discharge_count;
    v->order = scene_post_order(v->s);
    v->framing = malloc((n ? n : 1) * sizeof *v->framing);
    if (!v->order || !v->framing)
        return -1;
    double aspect = (double)v->opt.size.width / v->opt.size.height;
    for (size_t i = 0; i < (n ? n : 1); i++) { /* none: the fires and objects' framing */
        scene_camera sc;
        scene_camera_framing(v->s, i, aspect, &sc);
        view_camera_set(&v->framing[i], &sc);
    }
    v->next = v->next_framed = 0;
    v->timeline_start_s = 0;
    v->follow = true;
    v->framed = n ? v->order[0] : 0;
    v->cam = v->goal = v->framing[v->framed];
    return 0;
}

void view_timeline_deinit(view *v)
{
    free(v->order);
    free(v->framing);
    v->order = NULL;
    v->framing = NULL;
}

/* The shorter way round from angle a to b. */
static double angle_step(double a, double b)
{
    double d = fmod(b - a + FG_PI, 2 * FG_PI);
    return (d < 0 ? d + 2 * FG_PI : d) - FG_PI;
}

static void ease(view *v, double dt_s)
{
    double k = 1 - exp(-dt_s / FOLLOW_TAU_S);
    view_camera *c = &v->cam;
    const view_camera *g = &v->goal;
    for (int i = 0; i < 3; i++)
        c->target_m[i] += k * (g->target_m[i] - c->target_m[i]);
    c->distance_m *= exp(k * log(g->distance_m / c->distance_m)); /* evenly in scale */
    c->azimuth_rad += k * angle_step(c->azimuth_rad, g->azimuth_rad);
    c->elevation_rad += k * (g->elevation_rad - c->elevation_rad);
    c->fov_y_deg += k * (g->fov_y_deg - c->fov_y_deg);
}

/* The emit time of the k-th discharge of the timeline, on the engine clock. */
static double emit_at(const view *v, size_t k)
{
    return v->timeline_start_s + v->s->discharges[v->order[k]].post.emit_time_s;
}

void view_timeline_step(view *v, double dt_s)
{
    size_t n = v->s->discharge_count;
    for (; v->next < n && emit_at(v, v->next) - VIEW_TIMELINE_AHEAD_S <= v->now_s; v->next++)
        view_request_discharge(v, VIEW_REQ_SCENE, v->order[v->next], emit_at(v, v->next));
    for (; v->next_framed < n && emit_at(v, v->next_framed) - FOLLOW_LEAD_S <= v->now_s;
         v->next_framed++) {
        v->framed = v->order[v->next_framed];
        if (v->follow)
            v->goal = v->framing[v->framed];
    }
    if (v->follow)
        ease(v, dt_s);
}

void view_timeline_replay(view *v)
{
    v->timeline_start_s = v->now_s + VIEW_LEAD_S;
    v->next = v->next_framed = 0;
}

void view_timeline_frame(view *v)
{
    v->follow = true;
    v->goal = v->framing[v->framed];
}
