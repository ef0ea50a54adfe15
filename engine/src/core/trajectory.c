/* The listener's trajectory (core/trajectory_internal.h). */
#include <math.h>
#include <string.h>

#include "fg_rotation.h"
#include "fg_vec3.h"
#include "listener_internal.h"
#include "trajectory_internal.h"

static fg_trajectory_pose *at(fg_trajectory *t, unsigned i)
{
    return &t->pose[(t->first + i) % FG_TRAJECTORY_POSES];
}

static const fg_trajectory_pose *cat(const fg_trajectory *t, unsigned i)
{
    return &t->pose[(t->first + i) % FG_TRAJECTORY_POSES];
}

static bool same_place(const fg_listener *a, const fg_listener *b)
{
    return memcmp(a->position, b->position, sizeof a->position) == 0;
}

static bool same_orientation(const fg_listener *a, const fg_listener *b)
{
    return memcmp(a->forward, b->forward, sizeof a->forward) == 0 &&
           memcmp(a->up, b->up, sizeof a->up) == 0;
}

static bool zero3(const double v[3])
{
    return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

/* The pose's orthonormal frame: ahead, right, above. */
static void frame_of(const fg_listener *p, fg_vec3 f[3])
{
    f[0] = fg_v3_unit(fg_v3_load(p->forward));
    f[1] = fg_v3_unit(fg_v3_cross(f[0], fg_v3_unit(fg_v3_load(p->up))));
    f[2] = fg_v3_cross(f[1], f[0]);
}

void fg_trajectory_init(fg_trajectory *t, const fg_listener *pose, uint64_t number)
{
    t->first = 0;
    t->count = 1;
    t->pose[0] = (fg_trajectory_pose){.pose = *pose};
    t->number = number;
    t->still = fg_listener_at_rest(pose);
}

void fg_trajectory_push(fg_trajectory *t, const fg_listener *pose, uint64_t number)
{
    /* the latest value wins: a pose replaces those from its time on */
    while (t->count > 1 && cat(t, t->count - 1)->pose.time_s >= pose->time_s)
        t->count--;
    fg_trajectory_pose e = {.pose = *pose};
    fg_listener *p = &e.pose;
    const fg_listener *prev = &cat(t, t->count - 1)->pose;
    if (prev->time_s >= p->time_s) {
        t->count = 0; /* it replaces the only pose left */
    } else {
        double h = p->time_s - prev->time_s;
        /* moved without a velocity: the chord from the pose before */
        if (!pose->velocity_given && zero3(pose->velocity) && !same_place(p, prev))
            for (int k = 0; k < 3; k++)
                p->velocity[k] = (p->position[k] - prev->position[k]) / h;
        fg_vec3 fa[3], fb[3];
        frame_of(prev, fa);
        frame_of(p, fb);
        fg_vec3 turn = fg_rot_between(fa, fb);
        /* turned without an angular velocity: the turn over the time */
        if (!pose->velocity_given && zero3(pose->angular_velocity) &&
            !same_orientation(p, prev))
            fg_v3_store(fg_v3_div(turn, h), p->angular_velocity);
        fg_v3_store(turn, e.turn);
        fg_v3_store(fg_rot_jacobian_inverse(turn, fg_v3_load(p->angular_velocity)), e.turn_end);
    }
    if (t->count == FG_TRAJECTORY_POSES) {
        t->first = (t->first + 1) % FG_TRAJECTORY_POSES;
        t->count--;
    }
    *at(t, t->count++) = e;
    t->number = number;
    t->still = t->count == 1 && fg_listener_at_rest(p);
}

void fg_trajectory_forget(fg_trajectory *t, double now_s)
{
    double horizon = now_s - FG_TRAJECTORY_MEMORY_S;
    /* drop the oldest while the next one is already in force at the horizon */
    while (t->count > 1 && cat(t, 1)->pose.time_s <= horizon) {
        t->first = (t->first + 1) % FG_TRAJECTORY_POSES;
        t->count--;
    }
    /* come to rest: from now on every time sees the one pose left */
    if (t->count == 1 && fg_listener_at_rest(&cat(t, 0)->pose))
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

/* The head's orientation: frame f turned by phi, turning at w. */
static void turned(const fg_vec3 f[3], fg_vec3 phi, fg_vec3 w, fg_head *out)
{
    fg_vec3 right = fg_rot_apply(phi, f[1]);
    fg_v3_store(fg_rot_apply(phi, f[0]), out->forward);
    fg_v3_store(right, out->right);
    fg_v3_store(fg_rot_apply(phi, f[2]), out->up);
    fg_v3_store(fg_v3_cross(w, right), out->right_rate);
}

/* The head between poses a and b (b's span) at fraction u of the span h. */
static void hermite(const fg_listener *a, const fg_trajectory_pose *b, double u, double h,
                    fg_head *out)
{
    double u2 = u * u, u3 = u2 * u;
    double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = 3 * u2 - 2 * u3, h11 = u3 - u2;
    double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = 6 * u - 6 * u2, d11 = 3 * u2 - 2 * u;
    const fg_listener *q = &b->pose;
    for (int k = 0; k < 3; k++) {
        double p0 = a->position[k], p1 = q->position[k];
        double m0 = h * a->velocity[k], m1 = h * q->velocity[k];
        out->position[k] = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
        out->velocity[k] = (d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1) / h;
    }
    /* phi from 0 (a's frame) to the turn, tangents h w_a and h J^-1 w_b */
    double phi[3], rate[3];
    for (int k = 0; k < 3; k++) {
        double m0 = h * a->angular_velocity[k], m1 = h * b->turn_end[k];
        phi[k] = h10 * m0 + h01 * b->turn[k] + h11 * m1;
        rate[k] = (d10 * m0 + d01 * b->turn[k] + d11 * m1) / h;
    }
    fg_vec3 f[3], ph = fg_v3_load(phi);
    frame_of(a, f);
    turned(f, ph, fg_rot_jacobian(ph, fg_v3_load(rate)), out);
}

/* A pose carried along its velocity and angular velocity for d_s (after
 * the newest, d_s <= FG_EXTRAPOLATE_MAX_S), moving at them when `moving`,
 * else held there. */
static void carried(const fg_listener *p, double d_s, bool moving, fg_head *out)
{
    fg_vec3 w = fg_v3_load(p->angular_velocity), f[3];
    for (int k = 0; k < 3; k++) {
        out->position[k] = p->position[k] + p->velocity[k] * d_s;
        out->velocity[k] = moving ? p->velocity[k] : 0.0;
    }
    frame_of(p, f);
    turned(f, fg_v3_scale(w, d_s), moving ? w : fg_v3(0.0, 0.0, 0.0), out);
}

void fg_trajectory_head(const fg_trajectory *t, double t_s, fg_head *out)
{
    if (t->still) {
        fg_head_of_pose(&cat(t, 0)->pose, out);
        return;
    }
    const fg_listener *oldest = &cat(t, 0)->pose, *newest = &cat(t, t->count - 1)->pose;
    if (t_s >= newest->time_s) {
        double d = t_s - newest->time_s;
        carried(newest, fmin(d, FG_EXTRAPOLATE_MAX_S), d < FG_EXTRAPOLATE_MAX_S, out);
        return;
    }
    if (t_s <= oldest->time_s) {
        carried(oldest, 0.0, false, out);
        return;
    }
    /* the last pose at or before t_s: times are usually near the newest */
    unsigned lo = 0, hi = t->count - 1;
    while (hi - lo > 1) {
        unsigned mid = lo + (hi - lo) / 2;
        if (cat(t, mid)->pose.time_s <= t_s)
            lo = mid;
        else
            hi = mid;
    }
    const fg_listener *a = &cat(t, lo)->pose;
    const fg_trajectory_pose *b = cat(t, lo + 1);
    double h = b->pose.time_s - a->time_s;
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
        const fg_listener *q0 = &cat(t, i)->pose, *q1 = &cat(t, i + 1)->pose;
        if (q1->time_s <= a_s || q0->time_s >= b_s)
            continue;
        double speed = fmax(fg_v3_len(fg_v3_load(q0->velocity)), fg_v3_len(fg_v3_load(q1->velocity)));
        double far = fmax(distance(q0->position, p), distance(q1->position, p));
        double chord = distance(q0->position, q1->position);
        reach = fmax(reach, far + 0.3 * ((q1->time_s - q0->time_s) * speed + chord));
    }
    return reach;
}
