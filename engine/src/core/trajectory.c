/* The listener's trajectory (core/trajectory_internal.h). */
#include <math.h>
#include <string.h>

#include "fg_vec3.h"
#include "trajectory_internal.h"

static fg_listener *at(fg_trajectory *t, unsigned i)
{
    return &t->pose[(t->first + i) % FG_TRAJECTORY_POSES];
}

static const fg_listener *cat(const fg_trajectory *t, unsigned i)
{
    return &t->pose[(t->first + i) % FG_TRAJECTORY_POSES];
}

static bool at_rest(const fg_listener *p)
{
    return p->velocity[0] == 0.0 && p->velocity[1] == 0.0 && p->velocity[2] == 0.0;
}

static bool same_place(const fg_listener *a, const fg_listener *b)
{
    return memcmp(a->position, b->position, sizeof a->position) == 0 &&
           memcmp(a->forward, b->forward, sizeof a->forward) == 0 &&
           memcmp(a->up, b->up, sizeof a->up) == 0;
}

void fg_trajectory_init(fg_trajectory *t, const fg_listener *pose, uint64_t number)
{
    t->first = 0;
    t->count = 1;
    t->pose[0] = *pose;
    t->number = number;
    t->still = at_rest(pose);
}

void fg_trajectory_push(fg_trajectory *t, const fg_listener *pose, uint64_t number)
{
    /* the latest value wins: a pose replaces those from its time on */
    while (t->count > 1 && cat(t, t->count - 1)->time_s >= pose->time_s)
        t->count--;
    fg_listener p = *pose;
    const fg_listener *prev = cat(t, t->count - 1);
    if (prev->time_s >= p.time_s) {
        t->count = 0; /* it replaces the only pose left */
    } else if (at_rest(&p) && !same_place(&p, prev)) {
        /* moved without a velocity: the chord from the pose before */
        double h = p.time_s - prev->time_s;
        for (int k = 0; k < 3; k++)
            p.velocity[k] = (p.position[k] - prev->position[k]) / h;
    }
    if (t->count == FG_TRAJECTORY_POSES) {
        t->first = (t->first + 1) % FG_TRAJECTORY_POSES;
        t->count--;
    }
    *at(t, t->count++) = p;
    t->number = number;
    t->still = t->count == 1 && at_rest(&p);
}

void fg_trajectory_forget(fg_trajectory *t, double now_s)
{
    double horizon = now_s - FG_TRAJECTORY_MEMORY_S;
    /* drop the oldest while the next one is already in force at the horizon */
    while (t->count > 1 && cat(t, 1)->time_s <= horizon) {
        t->first = (t->first + 1) % FG_TRAJECTORY_POSES;
        t->count--;
    }
    /* come to rest: from now on every time sees the one pose left */
    if (t->count == 1 && at_rest(cat(t, 0)))
        t->still = true;
}

void fg_head_of_pose(const fg_listener *pose, fg_head *out)
{
    memcpy(out->position, pose->position, sizeof out->position);
    memset(out->velocity, 0, sizeof out->velocity);
    memcpy(out->forward, pose->forward, sizeof out->forward);
    memcpy(out->up, pose->up, sizeof out->up);
    fg_vec3 r = fg_v3_cross(fg_v3_load(pose->forward), fg_v3_load(pose->up));
    double norm = fg_v3_len(r);
    fg_v3_store(fg_v3(r.x / norm, r.y / norm, r.z / norm), out->right);
    memset(out->right_rate, 0, sizeof out->right_rate);
}

static fg_vec3 unit_blend(const double a[3], const double b[3], double u)
{
    fg_vec3 x = fg_v3_unit(fg_v3_load(a)), y = fg_v3_unit(fg_v3_load(b));
    return fg_v3_unit(fg_v3_add(fg_v3_scale(x, 1.0 - u), fg_v3_scale(y, u)));
}

static fg_vec3 right_of(fg_vec3 forward, fg_vec3 up)
{
    return fg_v3_unit(fg_v3_cross(forward, up));
}

/* The head between poses a and b at fraction u of the span h. */
static void hermite(const fg_listener *a, const fg_listener *b, double u, double h, fg_head *out)
{
    double u2 = u * u, u3 = u2 * u;
    double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = 3 * u2 - 2 * u3, h11 = u3 - u2;
    double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = 6 * u - 6 * u2, d11 = 3 * u2 - 2 * u;
    for (int k = 0; k < 3; k++) {
        double p0 = a->position[k], p1 = b->position[k];
        double m0 = h * a->velocity[k], m1 = h * b->velocity[k];
        out->position[k] = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
        out->velocity[k] = (d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1) / h;
    }
    fg_vec3 f = unit_blend(a->forward, b->forward, u), up = unit_blend(a->up, b->up, u);
    fg_v3_store(f, out->forward);
    fg_v3_store(up, out->up);
    fg_v3_store(right_of(f, up), out->right);
    fg_vec3 r0 = right_of(fg_v3_unit(fg_v3_load(a->forward)), fg_v3_unit(fg_v3_load(a->up)));
    fg_vec3 r1 = right_of(fg_v3_unit(fg_v3_load(b->forward)), fg_v3_unit(fg_v3_load(b->up)));
    fg_v3_store(fg_v3_scale(fg_v3_sub(r1, r0), 1.0 / h), out->right_rate);
}

/* A pose held (before the oldest) or carried along its velocity for
 * dt_s (after the newest, dt_s >= 0). */
static void carried(const fg_listener *p, double dt_s, fg_head *out)
{
    double d = dt_s < FG_EXTRAPOLATE_MAX_S ? dt_s : FG_EXTRAPOLATE_MAX_S;
    bool moving = dt_s < FG_EXTRAPOLATE_MAX_S;
    for (int k = 0; k < 3; k++) {
        out->position[k] = p->position[k] + p->velocity[k] * d;
        out->velocity[k] = moving ? p->velocity[k] : 0.0;
    }
    fg_vec3 f = fg_v3_unit(fg_v3_load(p->forward)), up = fg_v3_unit(fg_v3_load(p->up));
    fg_v3_store(f, out->forward);
    fg_v3_store(up, out->up);
    fg_v3_store(right_of(f, up), out->right);
    memset(out->right_rate, 0, sizeof out->right_rate);
}

void fg_trajectory_head(const fg_trajectory *t, double t_s, fg_head *out)
{
    if (t->still) {
        fg_head_of_pose(cat(t, 0), out);
        return;
    }
    const fg_listener *oldest = cat(t, 0), *newest = cat(t, t->count - 1);
    if (t_s >= newest->time_s) {
        carried(newest, t_s - newest->time_s, out);
        return;
    }
    if (t_s <= oldest->time_s) {
        carried(oldest, 0.0, out);
        memset(out->velocity, 0, sizeof out->velocity);
        return;
    }
    /* the last pose at or before t_s: times are usually near the newest */
    unsigned lo = 0, hi = t->count - 1;
    while (hi - lo > 1) {
        unsigned mid = lo + (hi - lo) / 2;
        if (cat(t, mid)->time_s <= t_s)
            lo = mid;
        else
            hi = mid;
    }
    const fg_listener *a = cat(t, lo), *b = cat(t, lo + 1);
    double h = b->time_s - a->time_s;
    hermite(a, b, (t_s - a->time_s) / h, h, out);
}

void fg_head_ears(const fg_head *head, unsigned channels, double spacing_m, fg_ears *out)
{
    out->count = channels;
    memcpy(out->right, head->right, sizeof out->right);
    memcpy(out->right_rate, head->right_rate, sizeof out->right_rate);
    fg_vec3 right = fg_v3_load(head->right), ahead = fg_v3_unit(fg_v3_load(head->forward));
    fg_v3_store(ahead, out->ahead);
    fg_v3_store(fg_v3_unit(fg_v3_cross(right, ahead)), out->above);
    memcpy(out->centre, head->position, sizeof out->centre);
    memcpy(out->centre_vel, head->velocity, sizeof out->centre_vel);
    out->radius_m = channels == 1 ? 0.0 : 0.5 * spacing_m;
    if (channels == 1) {
        memcpy(out->pos[0], head->position, sizeof out->pos[0]);
        memcpy(out->vel[0], head->velocity, sizeof out->vel[0]);
        return;
    }
    for (int k = 0; k < 3; k++) {
        double side = 0.5 * spacing_m * head->right[k], turn = 0.5 * spacing_m * head->right_rate[k];
        out->pos[0][k] = head->position[k] - side;
        out->pos[1][k] = head->position[k] + side;
        out->vel[0][k] = head->velocity[k] - turn;
        out->vel[1][k] = head->velocity[k] + turn;
    }
}

static double distance(const double a[3], const double b[3])
{
    return fg_v3_len(fg_v3_sub(fg_v3_load(a), fg_v3_load(b)));
}

double fg_trajectory_reach_m(const fg_trajectory *t, const double p[3], double a_s, double b_s)
{
    fg_head h;
    fg_trajectory_head(t, a_s, &h);
    double reach = distance(h.position, p);
    fg_trajectory_head(t, b_s, &h);
    reach = fmax(reach, distance(h.position, p));
    /* between two poses the curve is their chord plus h10 (h v0 - dp) +
     * h11 (h v1 - dp), |h10|, |h11| <= 4/27: it strays from the farther
     * pose by at most 0.3 (h max|v| + |dp|) */
    for (unsigned i = 0; !t->still && i + 1 < t->count; i++) {
        const fg_listener *q0 = cat(t, i), *q1 = cat(t, i + 1);
        if (q1->time_s <= a_s || q0->time_s >= b_s)
            continue;
        double speed = fmax(fg_v3_len(fg_v3_load(q0->velocity)), fg_v3_len(fg_v3_load(q1->velocity)));
        double far = fmax(distance(q0->position, p), distance(q1->position, p));
        double chord = distance(q0->position, q1->position);
        reach = fmax(reach, far + 0.3 * ((q1->time_s - q0->time_s) * speed + chord));
    }
    return reach;
}
