/* The fire voice on the audio thread: adopt and render.
 *
 * For each ear the sample at every control frame (FG_CONTROL_FRAMES of
 * the engine clock) is heard from the emission time tau solving tau = t -
 * (|q(t) - o(tau)| + e) / c, q the ear on the listener's path, o the fire
 * on its own, e the way around the head
 * (spatial/spherical_head_internal.h): two fixed-point steps from the
 * previous control frame's tau advanced by the interval leave (speed /
 * c)^3 of the interval's error. The samples between interpolate tau, the
 * gain g / r and the layout's gains linearly and read the ring at the
 * stream frame (tau - emit) fs by a Catmull-Rom cubic, so the pitch
 * follows d tau / dt (Doppler) and a moving fire is click-free. A block
 * plays the intervals it overlaps, each piece as a block of its own: what
 * is heard does not depend on the host's block.
 *
 * The ring: a piece's frames must be pushed, and the look-ahead beyond
 * them, or the voice fades out (FG_FIRE_FADE_S) and stays silent until
 * they are; the frames of emission time that pass unpushed are counted.
 * Wait-free and bounded: a fixed number of steps per ear and control
 * frame, one pass over the block per ear and output channel, the
 * per-block work bound, no allocation. */
#include <math.h>
#include <string.h>

#include "fg_math.h"
#include "fg_vec3.h"
#include "fire_voice_internal.h"
#include "spatial/layout_internal.h"
#include "spatial/spherical_head_internal.h"

#define RETARDED_STEPS 2
#define ADOPT_STEPS 8
#define WORK_SAMPLES 32   /* one work unit per this many samples of an ear */
#define MIN_DISTANCE_M 0.1 /* nearer counts as this near: the fire is not a point there */

static void absorb(const fg_listener *pose, uint64_t number, void *arg)
{
    fg_trajectory_push(arg, pose, number);
}

static fg_vec3 fire_at(const fg_fire_voice_state *v, double tau)
{
    fg_head h;
    fg_trajectory_head(&v->path, tau, &h);
    return fg_v3_load(h.position);
}

/* The travel time from o to ear k of ears, around the head. */
static double travel_s(const fg_ears *ears, unsigned k, fg_vec3 o, double c)
{
    double r = fg_v3_len(fg_v3_sub(fg_v3_load(ears->pos[k]), o));
    if (ears->radius_m > 0.0) {
        double u[3], u_rate[3], src[3];
        for (int j = 0; j < 3; j++) {
            u[j] = k == 0 ? -ears->right[j] : ears->right[j];
            u_rate[j] = k == 0 ? -ears->right_rate[j] : ears->right_rate[j];
        }
        fg_v3_store(o, src);
        r += fg_head_excess_m(src, ears->centre, u, ears->radius_m, ears->centre_vel, u_rate, NULL);
    }
    return r / c;
}

/* Ear k at time t_s: tau from the guess, the gain, the layout's gains. */
static void evaluate(const fg_fire_voice_state *v, const fg_engine_config *cfg,
                     const fg_ears *ears, unsigned k, double t_s, double tau, int steps,
                     fg_fire_end *out)
{
    const double c = cfg->speed_of_sound_m_s;
    for (int i = 0; i < steps; i++)
        tau = t_s - travel_s(ears, k, fire_at(v, tau), c);
    fg_vec3 o = fire_at(v, tau);
    double r = fg_v3_len(fg_v3_sub(fg_v3_load(ears->pos[k]), o));
    out->tau_s = tau;
    out->gain = v->gain / fmax(r, MIN_DISTANCE_M);
    fg_vec3 from = fg_v3_sub(o, fg_v3_load(ears->centre));
    double len = fg_v3_len(from);
    double dir[3] = {1.0, 0.0, 0.0}; /* a fire at the centre is heard from ahead */
    if (len > 0.0) {
        dir[0] = fg_v3_dot(from, fg_v3_load(ears->ahead)) / len;
        dir[1] = -fg_v3_dot(from, fg_v3_load(ears->right)) / len;
        dir[2] = fg_v3_dot(from, fg_v3_load(ears->above)) / len;
    }
    memset(out->layout, 0, sizeof out->layout);
    out->count = fg_layout_gains(cfg, k, dir, &out->first, out->layout);
}

static void ears_at(const fg_block_context *block, unsigned count, double t_s, fg_ears *out)
{
    fg_head head;
    fg_trajectory_head(block->trajectory, t_s, &head);
    fg_head_ears(&head, count, block->cfg->ear_spacing_m, out);
}

static void adopt(void *voice, const fg_block_context *block)
{
    fg_fire_voice_state *v = voice;
    const double fs = block->cfg->sample_rate_hz, c = block->cfg->speed_of_sound_m_s;
    fg_pose_queue_drain(&v->queue, &v->poses_seen, absorb, &v->path);
    if (v->emit_s < 0.0)
        v->emit_s = block->start_frame / fs;
    /* from the control frame at or before the block (one no block
     * reaches beyond 2^52 frames, 3 000 years at 48 kHz) */
    double from = fmin(block->start_frame, 0x1p52);
    v->control_frame = (uint64_t)(from / FG_CONTROL_FRAMES) * FG_CONTROL_FRAMES;
    v->next_ready = false;
    const double t0 = (double)v->control_frame / fs;
    fg_ears ears;
    ears_at(block, v->ears, t0, &ears);
    for (unsigned k = 0; k < v->ears; k++) {
        double guess = t0 - travel_s(&ears, k, fire_at(v, t0), c);
        evaluate(v, block->cfg, &ears, k, t0, guess, ADOPT_STEPS, &v->end[k]);
    }
}

static double unit_clamp(double x)
{
    return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
}

/* The ring's frame n as the voice hears it: 0 outside [released, head). */
static double frame(const fg_fire_voice_state *v, int64_t n, uint64_t head)
{
    if (n < 0 || (uint64_t)n < v->released || (uint64_t)n >= head)
        return 0.0;
    return fg_sample_ring_at(v->ring, (uint64_t)n);
}

/* The stream at fractional frame x: Catmull-Rom through its 4 neighbours;
 * taper_end (a closed stream's last frame + 1, else 0) fades its last
 * fade frames. */
static double stream_at(const fg_fire_voice_state *v, double x, uint64_t head,
                        double taper_end, double fade)
{
    double fl = floor(x);
    int64_t i = (int64_t)fl;
    double f = x - fl;
    double p0 = frame(v, i - 1, head), p1 = frame(v, i, head), p2 = frame(v, i + 1, head),
           p3 = frame(v, i + 2, head);
    double y = p1 + 0.5 * f * (p2 - p0 + f * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 +
                                               f * (3.0 * (p1 - p2) + p3 - p0)));
    if (taper_end > 0.0)
        y *= unit_clamp((taper_end - 1.0 - x) / fade);
    return y;
}

static bool end_finite(const fg_fire_end *e)
{
    if (!isfinite(e->tau_s) || !isfinite(e->gain))
        return false;
    for (unsigned j = 0; j < e->count; j++)
        if (!isfinite(e->layout[j]))
            return false;
    return true;
}

/* Each ear at the control frame after end[]'s; false when one of either
 * is not finite (end[] the first time: the adoption's). */
static bool evaluate_next(fg_fire_voice_state *v, const fg_block_context *block)
{
    const double fs = block->cfg->sample_rate_hz;
    const double t0 = (double)v->control_frame / fs;
    const double t1 = (double)(v->control_frame + FG_CONTROL_FRAMES) / fs;
    fg_ears ears;
    ears_at(block, v->ears, t1, &ears);
    for (unsigned k = 0; k < v->ears; k++) {
        evaluate(v, block->cfg, &ears, k, t1, v->end[k].tau_s + (t1 - t0), RETARDED_STEPS,
                 &v->next[k]);
        if (!end_finite(&v->end[k]) || !end_finite(&v->next[k]))
            return false;
    }
    v->next_ready = true;
    return true;
}

/* On to the next control frame (next_ready). */
static void step(fg_fire_voice_state *v)
{
    for (unsigned k = 0; k < v->ears; k++)
        v->end[k] = v->next[k];
    v->control_frame += FG_CONTROL_FRAMES;
    v->next_ready = false;
}

/* Plays frames at .. at + count - 1 of the block, which lie in the
 * interval from the control frame, as a block of their own: the ring's
 * frames they need, the fade, the samples, the frames let go. Returns
 * true once the voice is done. */
static bool play_piece(fg_fire_voice_state *v, bool stopping, const fg_block_context *block,
                       uint32_t at, uint32_t count)
{
    const double fs = block->cfg->sample_rate_hz;
    const double inv = 1.0 / FG_CONTROL_FRAMES;
    const uint32_t from = (uint32_t)((uint64_t)block->start_frame + at - v->control_frame);
    const bool to_next = from + count == FG_CONTROL_FRAMES;
    /* the stream frame each ear reads at the interval's two ends, and at
     * the piece's (the interval's own where they meet) */
    double x0[2], x1[2], x_end[2], hi = -INFINITY;
    for (unsigned k = 0; k < v->ears; k++) {
        x0[k] = (v->end[k].tau_s - v->emit_s) * fs;
        x1[k] = (v->next[k].tau_s - v->emit_s) * fs;
        double x_start = x0[k] + (x1[k] - x0[k]) * (from * inv);
        x_end[k] = to_next ? x1[k] : x0[k] + (x1[k] - x0[k]) * ((from + count) * inv);
        hi = fmax(hi, fmax(x_start, x_end[k]));
    }
    /* the close is read before the head: once closed, the head is final */
    const bool closed = atomic_load_explicit(&v->closed, memory_order_acquire);
    const uint64_t head = fg_sample_ring_head(v->ring);
    const double fade = fmax(1.0, FG_FIRE_FADE_S * fs);

    /* the frames whose emission time has now passed: [covered, need) */
    uint64_t need = hi >= 0.0 ? (uint64_t)floor(hi) + 1 : 0;
    if (need > v->covered) {
        uint64_t first = v->covered > head ? v->covered : head;
        if (!closed && need > first) {
            fg_count(&v->underrun_frames, need - first);
            if (!v->dry)
                fg_count(&v->underruns, 1);
            v->dry = true;
        } else {
            v->dry = false;
        }
        v->covered = need;
    }
    /* play on only while the piece's frames and the fade's look-ahead are
     * there (a fade down needs at most 2 fade lengths of frames at the
     * fastest Doppler rate, 1 / (1 - 0.29)) */
    const double look = hi + 2.0 + 2.0 * fade + 4.0;
    const bool ok = closed || (double)head >= look;
    const bool up = !stopping && ok; /* the fade's way */
    const double env0 = v->envelope;
    const double taper_end = closed ? (double)head : 0.0;

    const uint64_t units = 1 + count / WORK_SAMPLES;
    const double w_far = v->next_share, w_near = 1.0 - w_far;
    for (unsigned k = 0; k < v->ears; k++) {
        const fg_fire_end *a = &v->end[k], *b = &v->next[k];
        if (env0 == 0.0 && !up)
            break;
        if (*block->work_left < units) {
            fg_count(&block->counters->skipped_work, units);
            continue;
        }
        *block->work_left -= units;
        for (unsigned j = 0; j < b->count; j++) {
            if (a->layout[j] == 0.0 && b->layout[j] == 0.0)
                continue;
            float *near = fg_bus_pre(block->buses, v->bus, b->first + j) + at;
            float *far =
                w_far > 0.0 ? fg_bus_pre(block->buses, v->bus + 1, b->first + j) + at : NULL;
            for (uint32_t n = 0; n < count; n++) {
                double u = (from + n) * inv;
                double env = up ? fmin(1.0, env0 + n / fade) : fmax(0.0, env0 - n / fade);
                if (env == 0.0)
                    continue;
                double x = x0[k] + (x1[k] - x0[k]) * u;
                double g = (a->gain + (b->gain - a->gain) * u) *
                           (a->layout[j] + (b->layout[j] - a->layout[j]) * u);
                double p = env * g * stream_at(v, x, head, taper_end, fade);
                near[n] += (float)(w_near * p);
                if (far)
                    far[n] += (float)(w_far * p);
            }
        }
    }
    v->envelope = up ? fmin(1.0, env0 + count / fade) : fmax(0.0, env0 - count / fade);
    /* let go of what no ear reads again (the cubic's frame before) */
    double low_end = INFINITY;
    for (unsigned k = 0; k < v->ears; k++)
        low_end = fmin(low_end, x_end[k]);
    double keep = floor(low_end) - 2.0;
    if (keep > 0.0) {
        uint64_t n = (uint64_t)keep;
        if (n > head)
            n = head;
        if (n > v->released) {
            v->released = n;
            fg_sample_ring_release_before(v->ring, n);
        }
    }
    atomic_store_explicit(&v->read_frame, (int64_t)floor(fmax(low_end, -9e18)),
                          memory_order_relaxed);
    if (stopping && v->envelope == 0.0)
        return true;
    return closed && low_end >= (double)head + 2.0;
}

static bool render(void *voice, bool stopping, const fg_block_context *block)
{
    fg_fire_voice_state *v = voice;
    const uint64_t first = (uint64_t)block->start_frame, last = first + block->frames;
    fg_pose_queue_drain(&v->queue, &v->poses_seen, absorb, &v->path);
    if (v->next_ready && first >= v->control_frame + FG_CONTROL_FRAMES)
        step(v);
    double heard = INFINITY; /* the earliest emission time an ear still hears */
    for (unsigned k = 0; k < v->ears; k++)
        heard = fmin(heard, v->end[k].tau_s);
    fg_trajectory_forget(&v->path, heard);
    bool done = false;
    for (uint64_t at = first; at < last && !done;) {
        if (at >= v->control_frame + FG_CONTROL_FRAMES)
            step(v);
        if (!v->next_ready && !evaluate_next(v, block)) {
            fg_count(&block->counters->non_finite_voices, 1);
            return true;
        }
        uint64_t to = v->control_frame + FG_CONTROL_FRAMES;
        to = to < last ? to : last;
        done = play_piece(v, stopping, block, (uint32_t)(at - first), (uint32_t)(to - at));
        at = to;
    }
    fg_count(&v->blocks, 1);
    return done;
}

const fg_source_ops fg_fire_ops = {
    .name = "fire",
    .kind = &fg_fire_kind,
    .prepare = fg_fire_prepare,
    .adopt = adopt,
    .render = render,
    .release = fg_fire_release,
};
