#include <math.h>
#include <string.h>

#include "fg_vec3.h"
#include "listener_internal.h"

#define FG_LISTENER_MIN_LENGTH 1e-50
#define FG_LISTENER_MAX_LENGTH 1e50

static void pack(const fg_listener *p, uint64_t w[FG_POSE_WORDS])
{
    const double *v[5] = {p->position, p->forward, p->up, p->velocity, p->angular_velocity};
    for (int i = 0; i < 5; i++)
        memcpy(&w[3 * i], v[i], 3 * sizeof(double));
    memcpy(&w[15], &p->time_s, sizeof(double));
    w[16] = p->velocity_given != 0;
}

static void unpack(const uint64_t w[FG_POSE_WORDS], fg_listener *p)
{
    double *v[5] = {p->position, p->forward, p->up, p->velocity, p->angular_velocity};
    for (int i = 0; i < 5; i++)
        memcpy(v[i], &w[3 * i], 3 * sizeof(double));
    memcpy(&p->time_s, &w[15], sizeof(double));
    p->velocity_given = (int)w[16];
}

void fg_listener_cell_init(fg_listener_cell *cell, const fg_listener *pose)
{
    uint64_t w[FG_POSE_WORDS];
    pack(pose, w);
    atomic_init(&cell->seq, 0);
    for (int i = 0; i < FG_POSE_WORDS; i++)
        atomic_init(&cell->words[i], w[i]);
}

fg_result fg_listener_check(const fg_listener *p)
{
    if (!p)
        return FG_ERR_NULL;
    uint64_t w[FG_POSE_WORDS];
    pack(p, w);
    for (int i = 0; i < FG_POSE_DOUBLES; i++) {
        double d;
        memcpy(&d, &w[i], sizeof d);
        if (!isfinite(d))
            return FG_ERR_NOT_FINITE;
    }
    if (p->time_s < 0 ||
        fg_v3_len(fg_v3_load(p->angular_velocity)) > FG_MAX_ANGULAR_SPEED_RAD_S)
        return FG_ERR_ARGUMENT;
    for (int k = 0; k < 3; k++)
        if (fabs(p->position[k]) > FG_TREE_MAX_COORDINATE_M)
            return FG_ERR_ARGUMENT;
    fg_vec3 forward = fg_v3_load(p->forward), up = fg_v3_load(p->up);
    double f = fg_v3_len(forward), u = fg_v3_len(up);
    /* lengths whose squares are normal numbers: the audio thread flushes
     * denormals, and the ears are a cross product of the two (its square
     * stays within 1e-206 .. 1e200) */
    if (!(f >= FG_LISTENER_MIN_LENGTH && f <= FG_LISTENER_MAX_LENGTH) ||
        !(u >= FG_LISTENER_MIN_LENGTH && u <= FG_LISTENER_MAX_LENGTH))
        return FG_ERR_ARGUMENT;
    /* parallel within about 0.06 degrees */
    if (fg_v3_len(fg_v3_cross(fg_v3_scale(forward, 1 / f), fg_v3_scale(up, 1 / u))) < 1e-3)
        return FG_ERR_ARGUMENT;
    return FG_OK;
}

void fg_listener_cell_write(fg_listener_cell *cell, const fg_listener *pose)
{
    uint64_t w[FG_POSE_WORDS];
    pack(pose, w);
    unsigned s = atomic_load_explicit(&cell->seq, memory_order_relaxed);
    for (;;) {
        if (!(s & 1u) && atomic_compare_exchange_weak_explicit(&cell->seq, &s, s + 1u,
                                                               memory_order_acq_rel,
                                                               memory_order_relaxed))
            break;
        s = atomic_load_explicit(&cell->seq, memory_order_relaxed);
    }
    atomic_thread_fence(memory_order_release);
    for (int i = 0; i < FG_POSE_WORDS; i++)
        atomic_store_explicit(&cell->words[i], w[i], memory_order_relaxed);
    atomic_store_explicit(&cell->seq, s + 2u, memory_order_release);
}

bool fg_listener_cell_try_read(const fg_listener_cell *cell, fg_listener *pose, unsigned *serial)
{
    fg_listener_cell *c = (fg_listener_cell *)cell;
    unsigned s1 = atomic_load_explicit(&c->seq, memory_order_acquire);
    if (s1 & 1u)
        return false;
    uint64_t w[FG_POSE_WORDS];
    for (int i = 0; i < FG_POSE_WORDS; i++)
        w[i] = atomic_load_explicit(&c->words[i], memory_order_relaxed);
    atomic_thread_fence(memory_order_acquire);
    if (atomic_load_explicit(&c->seq, memory_order_relaxed) != s1)
        return false;
    unpack(w, pose);
    *serial = s1;
    return true;
}

void fg_listener_cell_read(const fg_listener_cell *cell, fg_listener *pose, unsigned *serial)
{
    while (!fg_listener_cell_try_read(cell, pose, serial))
        ;
}

void fg_pose_queue_init(fg_pose_queue *q, const fg_listener *pose)
{
    for (unsigned i = 0; i < FG_POSE_QUEUE; i++)
        fg_listener_cell_init(&q->slot[i], pose);
    /* pose number 1 sits in slot 0, written once */
    atomic_init(&q->slot[0].seq, 2u);
    atomic_init(&q->published, 1);
    atomic_init(&q->writing, 0);
    q->resting = false;
}

bool fg_listener_at_rest(const fg_listener *p)
{
    for (int k = 0; k < 3; k++)
        if (p->velocity[k] != 0.0 || p->angular_velocity[k] != 0.0)
            return false;
    return true;
}

/* Are p and q both at rest, in the same place (bit for bit)? */
static bool rests_where(const fg_listener *p, const fg_listener *q)
{
    return fg_listener_at_rest(p) && fg_listener_at_rest(q) &&
           memcmp(p->position, q->position, sizeof p->position) == 0 &&
           memcmp(p->forward, q->forward, sizeof p->forward) == 0 &&
           memcmp(p->up, q->up, sizeof p->up) == 0;
}

/* Pose number n (from 1, among the last FG_POSE_QUEUE), as its writer
 * (holding the turn) sees it. */
static void written(const fg_pose_queue *q, uint64_t n, fg_listener *pose)
{
    const fg_listener_cell *c = &q->slot[(n - 1) % FG_POSE_QUEUE];
    uint64_t w[FG_POSE_WORDS];
    for (int i = 0; i < FG_POSE_WORDS; i++)
        w[i] = atomic_load_explicit(&((fg_listener_cell *)c)->words[i], memory_order_relaxed);
    unpack(w, pose);
}

/* Does the trajectory (core/trajectory_internal.h) hold pose n, last, at
 * rest? At rest as given (velocity_given): yes. Else it joins last to
 * the newest pose published before it with an earlier time (those at its
 * time or later it replaced), and gives last the chord's velocity and the
 * turn's angular velocity from there when that pose is elsewhere,
 * carrying the body on along them past last. At rest: last is alone (the
 * first pose, or it replaced every one before it), or that pose rests in
 * the same place. Not known (beyond the queue's memory): false. */
static bool known_to_rest(const fg_pose_queue *q, uint64_t n, const fg_listener *last)
{
    if (last->velocity_given)
        return true;
    for (uint64_t k = n - 1; k >= 1 && n - k < FG_POSE_QUEUE; k--) {
        fg_listener p;
        written(q, k, &p);
        if (p.time_s < last->time_s)
            return rests_where(last, &p);
    }
    return n <= FG_POSE_QUEUE;
}

/* Writes pose number n + 1 (the writer holding the turn). */
static void publish(fg_pose_queue *q, uint64_t n, const fg_listener *pose)
{
    fg_listener_cell_write(&q->slot[n % FG_POSE_QUEUE], pose);
    atomic_store_explicit(&q->published, n + 1, memory_order_release);
}

bool fg_pose_queue_push(fg_pose_queue *q, const fg_listener *pose)
{
    unsigned idle = 0;
    while (!atomic_compare_exchange_weak_explicit(&q->writing, &idle, 1u, memory_order_acquire,
                                                  memory_order_relaxed))
        idle = 0;
    uint64_t n = atomic_load_explicit(&q->published, memory_order_relaxed);
    fg_listener last;
    written(q, n, &last);
    bool same = rests_where(pose, &last) && known_to_rest(q, n, &last);
    if (same && pose->time_s > last.time_s) {
        q->rest = *pose;
        q->resting = true;
    } else if (!same) {
        if (q->resting && q->rest.time_s < pose->time_s)
            publish(q, n++, &q->rest);
        q->resting = false;
        publish(q, n, pose);
    }
    atomic_store_explicit(&q->writing, 0u, memory_order_release);
    return !same;
}

/* Pose number n (from 1) lives in slot (n - 1) % FG_POSE_QUEUE, whose
 * sequence word then reads twice the times it has been written. */
static unsigned seq_of(uint64_t n)
{
    return 2u * (unsigned)((n - 1) / FG_POSE_QUEUE + 1);
}

uint64_t fg_pose_queue_latest(const fg_pose_queue *q, fg_listener *pose)
{
    for (;;) {
        uint64_t n = atomic_load_explicit(&q->published, memory_order_acquire);
        unsigned seq;
        fg_listener_cell_read(&q->slot[(n - 1) % FG_POSE_QUEUE], pose, &seq);
        if (seq == seq_of(n))
            return n;
    }
}

void fg_pose_queue_drain(const fg_pose_queue *q, uint64_t *seen,
                         void (*take)(const fg_listener *pose, uint64_t number, void *arg),
                         void *arg)
{
    uint64_t n = atomic_load_explicit(&q->published, memory_order_acquire);
    uint64_t from = *seen + 1;
    if (n >= FG_POSE_QUEUE && from < n - FG_POSE_QUEUE + 1)
        from = n - FG_POSE_QUEUE + 1;
    for (uint64_t k = from; k <= n; k++) {
        fg_listener pose;
        unsigned seq;
        if (fg_listener_cell_try_read(&q->slot[(k - 1) % FG_POSE_QUEUE], &pose, &seq) &&
            seq == seq_of(k))
            take(&pose, k, arg);
    }
    if (n > *seen)
        *seen = n;
}
