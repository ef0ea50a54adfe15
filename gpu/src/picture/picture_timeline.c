/* A discharge over time: its gains at a picture time (leader, return
 * stroke and decay, later strokes, the flicker of a continuous one), and
 * the light it and the volumes give to a frame. Constants are in
 * docs/picture.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "picture_internal.h"
#include "fg_math.h"

/* Gains on the float target, where 1 is about where the bloom starts. */
#define LEADER_GAIN 0.35     /* the growing leader, dim */
#define RETURN_GAIN 6.0      /* the first return stroke's peak */
#define RESTRIKE_GAIN 4.0    /* each later stroke's peak, main channel only */
#define CONTINUOUS_GAIN 2.5  /* a continuous discharge's mean glow */
/* The decay after a stroke: a fast flash and a slow afterglow (the
 * continuing current), peak 1. Perceptual, not the microsecond physics:
 * a 90 Hz frame must still catch the flash. */
#define DECAY_FAST_S 0.025
#define DECAY_SLOW_S 0.25
#define DECAY_SLOW_PART 0.12
/* Below this a flash is not drawn at all. */
#define GAIN_FLOOR 1e-4
/* A discharge's light: at a distance of its extent, a gain of 1 gives an
 * irradiance of LIGHT_SCALE (float-target units); softened within
 * extent / (2 * lights) of each light point. */
#define LIGHT_SCALE 0.3
/* A flame's light at a distance of its height, intensity 1. */
#define FLAME_LIGHT_SCALE 0.6
#define FLAME_LIGHT_HEIGHT 0.35 /* where on its height the light sits */

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

fgg_gains fgg_flash_gains(const fgg_flash_rec *f, double t)
{
    fgg_gains g = {.front_m = -1};
    double dt = t - f->start_s;
    if (dt < 0) {
        if (f->leader_s > 0 && -dt <= f->leader_s) {
            g.front_m = f->path_m * (1 + dt / f->leader_s);
            g.leader = LEADER_GAIN;
        }
    } else if (f->continuous) {
        if (f->duration_s == 0 || dt < f->duration_s)
            g.all = CONTINUOUS_GAIN * flicker(t, f->id);
    } else {
        g.all = RETURN_GAIN * decay(dt);
        for (size_t k = 1; k < f->stroke_count; k++)
            g.main += RESTRIKE_GAIN * decay(dt - f->strokes_s[k]);
    }
    if (g.leader == 0 && g.all < GAIN_FLOOR && g.main < GAIN_FLOOR)
        g = (fgg_gains){.front_m = 0}; /* front 0 with no leader: nothing is drawn */
    return g;
}

int fgg_gains_lit(const fgg_gains *g)
{
    return g->leader > 0 || g->all > 0 || g->main > 0;
}

size_t fgg_picture_lit_count(const fgg_picture *p, double time_s)
{
    if (!p || !isfinite(time_s))
        return 0;
    size_t n = 0;
    for (size_t i = 0; i < p->flash_count; i++) {
        fgg_gains g = fgg_flash_gains(&p->flashes[i], time_s);
        n += fgg_gains_lit(&g) != 0;
    }
    for (size_t i = 0; i < p->object_count; i++)
        n += p->objects[i].d.kind == FGG_DRAWABLE_VOLUME && p->objects[i].d.volume.intensity > 0;
    return n;
}

typedef struct light_source {
    double weight;                       /* for choosing the brightest */
    size_t count;
    double pos[FGG_FLASH_LIGHTS][3];     /* world */
    double soft_m;
    double rgb[FGG_FLASH_LIGHTS][3];
} light_source;

static void flash_light(const fgg_flash_rec *f, double t, light_source *out)
{
    fgg_gains g = fgg_flash_gains(f, t);
    out->count = 0;
    if (!fgg_gains_lit(&g) || f->light_count == 0 || !(f->extent_m > 0))
        return;
    double scale = LIGHT_SCALE * f->extent_m * f->extent_m;
    size_t lit = 0;
    for (size_t k = 0; k < f->light_count; k++)
        lit += g.front_m < 0 || f->light_path_m[k] < g.front_m;
    /* the light's colour: the white core with the halo around it */
    double tint[3];
    for (int c = 0; c < 3; c++)
        tint[c] = 0.5 + 0.5 * f->colour[c];
    out->weight = 0;
    out->soft_m = f->extent_m / (2.0 * FGG_FLASH_LIGHTS);
    for (size_t k = 0; k < f->light_count; k++) {
        double e = g.all / (double)f->light_count;
        if (f->light_main[k] && f->light_main_count)
            e += g.main / (double)f->light_main_count;
        if (g.front_m >= 0)
            e = f->light_path_m[k] < g.front_m ? g.leader / (double)(lit ? lit : 1) : 0;
        if (e <= 0)
            continue;
        size_t i = out->count++;
        for (int c = 0; c < 3; c++) {
            out->pos[i][c] = f->origin_m[c] + f->light_m[k][c];
            out->rgb[i][c] = scale * e * tint[c];
        }
        out->weight += scale * e / (f->extent_m * f->extent_m);
    }
}

static void volume_light(const fgg_object_rec *o, light_source *out)
{
    const fgg_volume *v = &o->d.volume;
    out->count = 0;
    if (v->intensity <= 0)
        return;
    double body[3] = {v->base_m[0], v->base_m[1], v->base_m[2] + FLAME_LIGHT_HEIGHT * v->height_m};
    fgg_object_to_world(o, body, out->pos[0]);
    float rgb[3];
    fgg_volume_colour(v->temperature_k, rgb);
    double scale = FLAME_LIGHT_SCALE * v->intensity * v->height_m * v->height_m;
    for (int c = 0; c < 3; c++)
        out->rgb[0][c] = scale * rgb[c];
    out->soft_m = v->radius_m;
    out->weight = FLAME_LIGHT_SCALE * v->intensity;
    out->count = 1;
}

static int by_weight_desc(const void *a, const void *b)
{
    const light_source *x = a, *y = b;
    return (x->weight < y->weight) - (x->weight > y->weight);
}

void fgg_picture_lights(const fgg_picture *p, fgg_frame *frame)
{
    frame->light_count = 0;
    size_t n = p->flash_count + p->object_count;
    light_source *src = malloc((n ? n : 1) * sizeof *src);
    if (!src)
        return; /* no light this frame: the picture still draws */
    size_t used = 0;
    for (size_t i = 0; i < p->flash_count; i++) {
        flash_light(&p->flashes[i], frame->time_s, &src[used]);
        used += src[used].count > 0;
    }
    for (size_t i = 0; i < p->object_count; i++)
        if (p->objects[i].d.kind == FGG_DRAWABLE_VOLUME) {
            volume_light(&p->objects[i], &src[used]);
            used += src[used].count > 0;
        }
    qsort(src, used, sizeof *src, by_weight_desc);
    const double *eye = frame->camera->eye_m;
    for (size_t s = 0; s < used; s++) {
        if (frame->light_count + (int)src[s].count > FGG_MAX_LIGHTS)
            break;
        for (size_t k = 0; k < src[s].count; k++) {
            int i = frame->light_count++;
            for (int c = 0; c < 3; c++) {
                frame->light_pos[i][c] = (float)(src[s].pos[k][c] - eye[c]);
                frame->light_col[i][c] = (float)src[s].rgb[k][c];
            }
            frame->light_pos[i][3] = (float)src[s].soft_m;
            frame->light_col[i][3] = 0;
        }
    }
    free(src);
}
