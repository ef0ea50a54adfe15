/* The viewer's one input path: events from the window or the script,
 * applied to the camera, the charges and the sim thread's requests. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view.h"
#include "fg_vec3.h"
#include "fg_array.h"


bool view_ring_push(fg_ring *r, void *item)
{
    return fg_ring_push(r, &item);
}

void *view_ring_pop(fg_ring *r)
{
    void *item;
    return fg_ring_pop(r, &item) ? item : NULL;
}

static int parse_line(char *line, view_event *e)
{
    char what[16] = "", a[32] = "", b[32] = "", c[32] = "";
    unsigned frame;
    int n = sscanf(line, " frame %u %15s %31s %31s %31s", &frame, what, a, b, c);
    if (n < 2)
        return -1;
    *e = (view_event){.frame = frame};
    char *end;
    if (strcmp(what, "key") == 0 && n == 3) {
        static const struct {
            const char *name;
            view_event_kind kind;
        } keys[] = {{"space", VIEW_EV_DISCHARGE}, {"h", VIEW_EV_HOLD}, {"c", VIEW_EV_CLEAR},
                    {"escape", VIEW_EV_QUIT}};
        for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
            if (strcmp(a, keys[i].name) == 0) {
                e->kind = keys[i].kind;
                return 0;
            }
        return -1;
    }
    if (strcmp(what, "click") == 0 && n == 5) {
        e->kind = VIEW_EV_CLICK;
        e->x = strtod(a, &end);
        if (*end)
            return -1;
        e->y = strtod(b, &end);
        if (*end || !(e->x >= 0 && e->x <= 1 && e->y >= 0 && e->y <= 1))
            return -1;
        e->sign = strcmp(c, "left") == 0 ? 1 : strcmp(c, "right") == 0 ? -1 : 0;
        return e->sign ? 0 : -1;
    }
    if ((strcmp(what, "drag") == 0 && n == 4) || (strcmp(what, "scroll") == 0 && n == 3)) {
        e->kind = what[0] == 'd' ? VIEW_EV_ORBIT : VIEW_EV_ZOOM;
        double *first = e->kind == VIEW_EV_ORBIT ? &e->x : &e->y;
        *first = strtod(a, &end);
        if (*end || !isfinite(*first))
            return -1;
        if (e->kind == VIEW_EV_ORBIT) {
            e->y = strtod(b, &end);
            if (*end || !isfinite(e->y))
                return -1;
        }
        return 0;
    }
    return -1;
}

/* Insertion sort by frame: stable, so events of one frame keep file order. */
static void sort_by_frame(view_event *list, size_t n)
{
    for (size_t i = 1; i < n; i++) {
        view_event e = list[i];
        size_t j = i;
        for (; j > 0 && list[j - 1].frame > e.frame; j--)
            list[j] = list[j - 1];
        list[j] = e;
    }
}

int view_script_load(const char *path, view_event **events, size_t *count, char *err,
                     size_t err_size)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, err_size, "%s: cannot open", path);
        return -1;
    }
    view_event *list = NULL;
    size_t n = 0, cap = 0;
    char line[256];
    int rc = 0;
    for (unsigned number = 1; fgets(line, sizeof line, f); number++) {
        line[strcspn(line, "#\r\n")] = '\0';
        if (line[strspn(line, " \t")] == '\0')
            continue;
        if (n == cap) {
            view_event *grown = fg_array_grow(list, &cap, n + 1, sizeof *grown, 16);
            if (!grown) {
                snprintf(err, err_size, "out of memory");
                rc = -1;
                break;
            }
            list = grown;
        }
        if (parse_line(line, &list[n]) != 0) {
            snprintf(err, err_size,
                     "%s:%u: expected \"frame N key space|h|c|escape\", \"frame N click X Y "
                     "left|right\" (X, Y in 0..1), \"frame N drag DX DY\" or \"frame N scroll S\"",
                     path, number);
            rc = -1;
            break;
        }
        n++;
    }
    fclose(f);
    if (rc != 0) {
        free(list);
        return -1;
    }
    sort_by_frame(list, n);
    *events = list;
    *count = n;
    return 0;
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

/* The point under (x, y) on the plane through the target facing the eye. */
static void unproject(const view *v, double x, double y, double out[3])
{
    fgg_camera cam;
    view_camera_get(&v->cam, &cam);
    fg_vec3 fv = fg_v3_div(fg_v3_sub(fg_v3_load(cam.target_m), fg_v3_load(cam.eye_m)),
                           v->cam.distance_m);
    fg_vec3 rv = fg_v3(fv.y, -fv.x, 0); /* f x up(+z) */
    rv = fg_v3_div(rv, hypot(rv.x, rv.y));
    double r[3], u[3];
    fg_v3_store(rv, r);
    fg_v3_store(fg_v3_cross(rv, fv), u);
    double half_h = v->cam.distance_m * tan(v->cam.fov_y_deg * FG_PI / 360.0);
    double aspect = (double)v->opt.width / v->opt.height;
    for (int k = 0; k < 3; k++)
        out[k] = cam.target_m[k] + (2 * x - 1) * half_h * aspect * r[k] + (1 - 2 * y) * half_h * u[k];
}

static void request(view *v, view_request_kind kind)
{
    view_request *q = calloc(1, sizeof *q);
    if (!q)
        return;
    q->kind = kind;
    q->emit_s = v->now_s + VIEW_LEAD_S;
    q->seed = scene_discharge_seed(v->s->seed, (size_t)v->seed_counter++);
    q->charge_count = v->charge_count;
    memcpy(q->charges, v->charges, v->charge_count * sizeof *q->charges);
    /* the leader's step: a fiftieth of the view's height at the target */
    q->step_m = 2 * v->cam.distance_m * tan(v->cam.fov_y_deg * FG_PI / 360.0) / 50;
    if (view_ring_push(&v->to_sim, q))
        v->requests++;
    else
        free(q);
}

void view_apply(view *v, const view_event *e)
{
    switch (e->kind) {
    case VIEW_EV_DISCHARGE:
        request(v, VIEW_REQ_ONE);
        break;
    case VIEW_EV_HOLD:
        v->holding = !v->holding;
        request(v, v->holding ? VIEW_REQ_HOLD : VIEW_REQ_STOP);
        break;
    case VIEW_EV_CLEAR:
        v->charge_count = 0;
        break;
    case VIEW_EV_QUIT:
        v->quit = true;
        break;
    case VIEW_EV_CLICK:
        if (v->charge_count < VIEW_MAX_CHARGES) {
            fg_point_charge *q = &v->charges[v->charge_count++];
            unproject(v, e->x, e->y, q->position_m);
            q->charge_c = e->sign;
        }
        break;
    case VIEW_EV_ORBIT:
        v->cam.azimuth_rad -= e->x * FG_PI;
        v->cam.elevation_rad += e->y * FG_PI / 2;
        v->cam.elevation_rad = fmax(-1.4, fmin(1.4, v->cam.elevation_rad));
        break;
    case VIEW_EV_ZOOM:
        v->cam.distance_m *= pow(0.9, e->y);
        break;
    }
}
