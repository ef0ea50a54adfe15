/* The viewer's one input path: events from the window or the script,
 * applied to the camera, the charges and the sim thread's requests. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view.h"
#include "fg_vec3.h"
#include "fg_array.h"


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
                    {"r", VIEW_EV_REPLAY},      {"f", VIEW_EV_FRAME}, {"f1", VIEW_EV_OVERLAY},
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
                     "%s:%u: expected \"frame N key space|h|c|r|f|f1|escape\", \"frame N click X Y "
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
    double aspect = (double)v->opt.size.width / v->opt.size.height;
    for (int k = 0; k < 3; k++)
        out[k] = cam.target_m[k] + (2 * x - 1) * half_h * aspect * r[k] + (1 - 2 * y) * half_h * u[k];
}

/* A charge where the click lands, and its marker on the picture. */
static void place_charge(view *v, const view_event *e)
{
    if (v->charge_count == VIEW_MAX_CHARGES)
        return;
    fg_point_charge *q = &v->charges[v->charge_count];
    unproject(v, e->x, e->y, q->position_m);
    q->charge_c = e->sign;
    fgg_drawable m = {.kind = FGG_DRAWABLE_MARKER, .marker = {.sign = e->sign}};
    memcpy(m.marker.position_m, q->position_m, sizeof m.marker.position_m);
    v->markers[v->charge_count] = 0;
    if (v->pic && fgg_picture_add_drawable(v->pic, &m, &v->markers[v->charge_count]) != FG_OK)
        fprintf(stderr, "fulgur view: the charge's marker: %s\n", fgg_error_message());
    v->charge_count++;
}

static void clear_charges(view *v)
{
    for (size_t i = 0; i < v->charge_count; i++)
        if (v->markers[i])
            fgg_picture_remove(v->pic, v->markers[i]);
    v->charge_count = 0;
}

void view_apply(view *v, const view_event *e)
{
    double soon = v->now_s + VIEW_LEAD_S;
    bool triggers = v->s->discharge_count > 0; /* space and H play its first discharge */
    switch (e->kind) {
    case VIEW_EV_DISCHARGE:
        if (triggers)
            view_request_discharge(v, VIEW_REQ_ONE, 0, soon);
        break;
    case VIEW_EV_HOLD:
        if (!triggers)
            break;
        v->holding = !v->holding;
        view_request_discharge(v, v->holding ? VIEW_REQ_HOLD : VIEW_REQ_STOP, 0, soon);
        break;
    case VIEW_EV_CLEAR:
        clear_charges(v);
        break;
    case VIEW_EV_REPLAY:
        view_timeline_replay(v);
        break;
    case VIEW_EV_FRAME:
        view_timeline_frame(v);
        break;
    case VIEW_EV_OVERLAY:
        v->overlay_on = !v->overlay_on;
        if (!v->overlay)
            fprintf(stderr, "fulgur view: no overlay: this fulgur has no font for it (it "
                            "needs FreeType, fontconfig and a monospace font)\n");
        break;
    case VIEW_EV_QUIT:
        v->quit = true;
        break;
    case VIEW_EV_CLICK:
        v->follow = false; /* the charges stay where they were placed in the view */
        place_charge(v, e);
        break;
    case VIEW_EV_ORBIT:
        v->follow = false;
        v->cam.azimuth_rad -= e->x * FG_PI;
        v->cam.elevation_rad += e->y * FG_PI / 2;
        v->cam.elevation_rad = fmax(-1.4, fmin(1.4, v->cam.elevation_rad));
        break;
    case VIEW_EV_ZOOM:
        v->follow = false;
        v->cam.distance_m *= pow(0.9, e->y);
        break;
    }
}
