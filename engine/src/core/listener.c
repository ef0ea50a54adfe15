#include <math.h>
#include <string.h>

#include "fg_vec3.h"
#include "listener_internal.h"

#define FG_LISTENER_MIN_LENGTH 1e-50
#define FG_LISTENER_MAX_LENGTH 1e50

static void pack(const fg_listener *p, uint64_t w[FG_POSE_WORDS])
{
    const double *v[4] = {p->position, p->forward, p->up, p->velocity};
    for (int i = 0; i < 4; i++)
        memcpy(&w[3 * i], v[i], 3 * sizeof(double));
}

static void unpack(const uint64_t w[FG_POSE_WORDS], fg_listener *p)
{
    double *v[4] = {p->position, p->forward, p->up, p->velocity};
    for (int i = 0; i < 4; i++)
        memcpy(v[i], &w[3 * i], 3 * sizeof(double));
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
    for (int i = 0; i < FG_POSE_WORDS; i++) {
        double d;
        memcpy(&d, &w[i], sizeof d);
        if (!isfinite(d))
            return FG_ERR_NOT_FINITE;
    }
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

void fg_listener_ears(const fg_listener *p, unsigned channels, double spacing_m, fg_ears *out)
{
    out->count = channels;
    fg_vec3 r = fg_v3_cross(fg_v3_load(p->forward), fg_v3_load(p->up));
    double norm = fg_v3_len(r);
    fg_v3_store(fg_v3(r.x / norm, r.y / norm, r.z / norm), out->right);
    if (channels == 1) {
        memcpy(out->pos[0], p->position, sizeof out->pos[0]);
        return;
    }
    for (int k = 0; k < 3; k++) {
        out->pos[0][k] = p->position[k] - 0.5 * spacing_m * out->right[k];
        out->pos[1][k] = p->position[k] + 0.5 * spacing_m * out->right[k];
    }
}
