/* The aero object's voice on the audio thread: adopt and render.
 *
 * For each source and ear, at every control frame (FG_CONTROL_FRAMES
 * of the engine clock) the sample there is heard from the emission time
 * tau solving tau = t - |q(t) - o(tau)| / c (q the ear on the listener's
 * path, o the source on the object's); two fixed-point steps from the
 * previous control frame's tau advanced by the interval (off by at most
 * speed / c of it) leave (speed / c)^3 of the interval, 20 us at Mach 0.1
 * for 256 frames at 48 kHz: under a sample. There the source's flow, its
 * texture rate u / v0 and the dipole's projection on the ear are
 * evaluated; the texture position is the integral of the rate over
 * emission time (trapezoids, exact at a steady speed). The samples between
 * two control frames interpolate tau, the position and the projections
 * linearly, so the pitch follows the Doppler rate d tau / dt and the
 * texture is read at a fractional position. A block plays the control
 * intervals it overlaps, each sample as every other block size would: the
 * sound does not depend on the host's block. The layout
 * (spatial/layout_internal.h) sends each ear's samples to its channel in
 * stereo; in ambisonics the one ear at the head's centre is encoded from
 * the direction the source is heard from, in the head's frame at the
 * interval's two ends, the gains interpolated between them, so a moving
 * source or a turning head pans smoothly.
 * Wait-free and bounded: a fixed number of steps per source, ear and
 * control frame, the per-block work bound, no allocation. */
#include <math.h>
#include <string.h>

#include "aero_voice_internal.h"
#include "fg_math.h"
#include "fg_vec3.h"
#include "spatial/layout_internal.h"

#define RETARDED_STEPS 2
#define WORK_SAMPLES 32 /* one work unit per this many samples of a source, ear and output channel */

static void absorb(const fg_listener *pose, uint64_t number, void *arg)
{
    fg_trajectory_push(arg, pose, number);
}

static fg_vec3 source_at(const fg_head *h, double along_m)
{
    return fg_v3_add(fg_v3_load(h->position), fg_v3_scale(fg_v3_load(h->right), along_m));
}

/* The unit direction from q towards o in the head frame of ears (x
 * ahead, y left, z up); ahead when the two coincide. */
static void head_direction(const fg_ears *ears, fg_vec3 q, fg_vec3 o, double dir[3])
{
    fg_vec3 from = fg_v3_sub(o, q);
    double len = fg_v3_len(from);
    if (!(len > 0.0)) {
        dir[0] = 1.0, dir[1] = 0.0, dir[2] = 0.0;
        return;
    }
    from = fg_v3_scale(from, 1.0 / len);
    dir[0] = fg_v3_dot(from, fg_v3_load(ears->ahead));
    dir[1] = -fg_v3_dot(from, fg_v3_load(ears->right));
    dir[2] = fg_v3_dot(from, fg_v3_load(ears->above));
}

/* The flow over source s at emission time tau and what ear q of ears
 * hears of it: fills *out (tau, lookup, coef, dir, the cross-flow speed;
 * position from prev, advanced by the rate) and *rate_out. */
static void evaluate(const fg_aero_voice *v, const fg_aero_source_state *s, const fg_ears *ears,
                     unsigned ear, double t_s, double tau_guess, const fg_aero_end *prev,
                     double prev_rate, double c, fg_aero_end *out, double *rate_out)
{
    const fg_vec3 q = fg_v3_load(ears->pos[ear]);
    fg_head h;
    double tau = tau_guess;
    for (int i = 0; i < RETARDED_STEPS; i++) {
        fg_trajectory_head(&v->path, tau, &h);
        tau = t_s - fg_v3_len(fg_v3_sub(q, source_at(&h, s->along_m))) / c;
    }
    fg_trajectory_head(&v->path, tau, &h);
    fg_vec3 o = source_at(&h, s->along_m), d = fg_v3_sub(q, o);
    double r = fg_v3_len(d);
    head_direction(ears, q, o, out->dir);
    fg_vec3 axis = fg_v3_load(h.right);
    fg_vec3 vel = fg_v3_add(fg_v3_load(h.velocity), fg_v3_scale(fg_v3_load(h.right_rate), s->along_m));
    double w[3];
    fg_aero_voice_wind_at(v, tau, w);
    fg_vec3 u = fg_v3_sub(fg_v3_load(w), vel); /* the air, as the source sees it */
    const fg_aero_texture_desc *t = v->tex;
    if (t->dims == 2 || t->shape == FG_AERO_CLUB)
        u = fg_v3_sub(u, fg_v3_scale(axis, fg_v3_dot(u, axis))); /* the cross-flow */
    double speed = fg_v3_len(u);
    out->tau_s = tau;
    memset(out->coef, 0, sizeof out->coef);
    out->lookup = prev->lookup;
    double rate = speed / t->speed_m_s * t->sample_rate_hz;
    /* below the onset of shedding the body sheds no tone: silent (the
     * level law has it 120 dB below v0's there already for Re0 ~ 10^4) */
    if (speed * t->reference_m / t->viscosity_m2_s >= FG_AERO_RE_MIN) {
        fg_vec3 drag = fg_v3_scale(u, 1.0 / speed), lift, axial = fg_v3(0, 0, 0);
        if (t->dims == 2) {
            double a = atan2(fg_v3_dot(drag, fg_v3_load(h.up)), fg_v3_dot(drag, fg_v3_load(h.forward)));
            fg_aero_texture_lookup(v->texture, a, &out->lookup);
            lift = fg_v3_cross(axis, drag);
        } else {
            fg_aero_texture_lookup(v->texture, 0.0, &out->lookup);
            fg_vec3 z = fg_v3_sub(axis, fg_v3_scale(drag, fg_v3_dot(axis, drag)));
            if (fg_v3_len(z) < 1e-6) /* a sphere's flow along its axis */
                z = fg_v3_load(h.forward);
            axial = fg_v3_unit(fg_v3_sub(z, fg_v3_scale(drag, fg_v3_dot(z, drag))));
            lift = fg_v3_cross(axial, drag);
        }
        double k = fg_aero_pressure_scale(v->texture, speed) * s->span_m * v->gain /
                   (4.0 * FG_PI * c * r * r);
        out->coef[0] = k * fg_v3_dot(d, drag);
        out->coef[1] = k * fg_v3_dot(d, lift) * out->lookup.lift_sign;
        out->coef[2] = k * fg_v3_dot(d, axial);
    }
    out->position = prev->position + 0.5 * (prev_rate + rate) * (tau - prev->tau_s);
    out->speed_m_s = speed;
    *rate_out = rate;
}

static double unit_clamp(double x)
{
    return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
}

/* The emission's envelope at emission time tau. */
static double envelope(const fg_aero_voice *v, double tau)
{
    double in = (tau - v->emit_s) / FG_AERO_FADE_S, out = (v->end_s + FG_AERO_FADE_S - tau) / FG_AERO_FADE_S;
    return unit_clamp(in) * unit_clamp(out);
}

static void adopt(void *voice, const fg_block_context *block)
{
    fg_aero_voice *v = voice;
    const double fs = block->cfg->sample_rate_hz;
    fg_pose_queue_drain(&v->queue, &v->poses_seen, absorb, &v->path);
    if (v->emit_s < 0.0)
        v->emit_s = block->start_frame / fs;
    v->end_s = v->duration_s > 0.0 ? v->emit_s + v->duration_s : INFINITY;
    /* nothing is heard before the emission: the sources start at the
     * control frame at or before it, or before the adoption when that is
     * later (a voice adopted late); an emission beyond 2^52 frames (3 000
     * years at 48 kHz) waits there */
    double from = fmin(fmax(block->start_frame, v->emit_s * fs), 0x1p52);
    v->control_frame = (uint64_t)(from / FG_CONTROL_FRAMES) * FG_CONTROL_FRAMES;
    v->started = v->next_ready = false;
}

/* The ears at control frame `frame`. */
static void ears_at(const fg_block_context *block, uint64_t frame, fg_ears *out)
{
    fg_head head;
    fg_trajectory_head(block->trajectory, (double)frame / block->cfg->sample_rate_hz, &head);
    fg_head_ears(&head, block->ears->count, block->cfg->ear_spacing_m, out);
}

/* The sources' end[] at the voice's first control frame, the texture at
 * its start. */
static void start(fg_aero_voice *v, const fg_block_context *block)
{
    const double c = block->cfg->speed_of_sound_m_s;
    const double t = (double)v->control_frame / block->cfg->sample_rate_hz;
    fg_ears ears;
    ears_at(block, v->control_frame, &ears);
    for (uint32_t i = 0; i < v->source_count; i++) {
        fg_aero_source_state *s = &v->source[i];
        for (unsigned ch = 0; ch < ears.count; ch++) {
            fg_aero_end from = {.tau_s = t, .lookup = {.weight = {1.0f, 0.0f}, .lift_sign = 1.0f}};
            evaluate(v, s, &ears, ch, t, t, &from, 0.0, c, &s->end[ch], &s->rate[ch]);
            s->end[ch].position = 0.0;
        }
    }
    v->started = true;
}

static bool end_finite(const fg_aero_end *e)
{
    return isfinite(e->tau_s) && isfinite(e->position) && isfinite(e->coef[0]) &&
           isfinite(e->coef[1]) && isfinite(e->coef[2]);
}

/* The sources' next[], at the control frame after end[]'s; false when one
 * of either is not finite (end[] the first time: the start's). */
static bool evaluate_next(fg_aero_voice *v, const fg_block_context *block)
{
    const double fs = block->cfg->sample_rate_hz, c = block->cfg->speed_of_sound_m_s;
    const uint64_t frame = v->control_frame + FG_CONTROL_FRAMES;
    const double t0 = (double)v->control_frame / fs, t1 = (double)frame / fs;
    fg_ears ears;
    ears_at(block, frame, &ears);
    for (uint32_t i = 0; i < v->source_count; i++) {
        fg_aero_source_state *s = &v->source[i];
        for (unsigned ch = 0; ch < ears.count; ch++) {
            evaluate(v, s, &ears, ch, t1, s->end[ch].tau_s + (t1 - t0), &s->end[ch], s->rate[ch], c,
                     &s->next[ch], &s->next_rate[ch]);
            if (!end_finite(&s->end[ch]) || !end_finite(&s->next[ch]))
                return false;
        }
    }
    v->next_ready = true;
    return true;
}

/* Moves the sources on to the next control frame (next_ready). */
static void step(fg_aero_voice *v, unsigned ears)
{
    for (uint32_t i = 0; i < v->source_count; i++) {
        fg_aero_source_state *s = &v->source[i];
        for (unsigned ch = 0; ch < ears; ch++) {
            s->end[ch] = s->next[ch];
            s->rate[ch] = s->next_rate[ch];
        }
    }
    v->control_frame += FG_CONTROL_FRAMES;
    v->next_ready = false;
}

/* Weight per distinct texture direction of the two ends' lookups. */
typedef struct direction_mix {
    uint32_t index[4];
    double a0[4][3], a1[4][3]; /* weight times coef at the block's start and end */
    unsigned count;
} direction_mix;

static void mix_add(direction_mix *m, uint32_t index, float weight, const double coef[3], int end)
{
    if (weight == 0.0f)
        return;
    unsigned k = 0;
    while (k < m->count && m->index[k] != index)
        k++;
    if (k == m->count) {
        m->index[k] = index;
        memset(m->a0[k], 0, sizeof m->a0[k]);
        memset(m->a1[k], 0, sizeof m->a1[k]);
        m->count++;
    }
    for (int c = 0; c < 3; c++)
        (end ? m->a1 : m->a0)[k][c] += weight * coef[c];
}

/* Where one source and ear's samples go: count output channels, each
 * into its band's bus `near[c]` and, split by the voice's next_share, the
 * next band's `far[c]` (NULL when unshared), from the sample the block
 * plays first, with the layout's gain moving linearly from g0[c] at the
 * interval's start to g1[c] at its end. */
typedef struct aero_outputs {
    unsigned count;
    float *near[FG_LAYOUT_CHANNELS_MAX], *far[FG_LAYOUT_CHANNELS_MAX];
    double g0[FG_LAYOUT_CHANNELS_MAX], g1[FG_LAYOUT_CHANNELS_MAX];
} aero_outputs;

/* The outputs of ear ch between ends e0 and e1, from frame `at` of the
 * block: in stereo its own channel with gain 1; in ambisonics every
 * channel, with the harmonics of the directions at the two ends (a
 * channel that is 0 at both is left out). */
static void outputs_for(const fg_aero_voice *v, const fg_block_context *block, unsigned ch,
                        const fg_aero_end *e0, const fg_aero_end *e1, uint32_t at,
                        aero_outputs *out)
{
    double g0[FG_LAYOUT_CHANNELS_MAX], g1[FG_LAYOUT_CHANNELS_MAX];
    unsigned first0, first1;
    const unsigned count = fg_layout_gains(block->cfg, ch, e0->dir, &first0, g0);
    (void)fg_layout_gains(block->cfg, ch, e1->dir, &first1, g1);
    out->count = 0;
    for (unsigned c = 0; c < count; c++) {
        if (g0[c] == 0.0 && g1[c] == 0.0)
            continue;
        unsigned k = out->count++;
        out->near[k] = fg_bus_pre(block->buses, v->bus, first0 + c) + at;
        out->far[k] =
            v->next_share > 0.0 ? fg_bus_pre(block->buses, v->bus + 1, first0 + c) + at : NULL;
        out->g0[k] = g0[c];
        out->g1[k] = g1[c];
    }
}

/* Adds samples from .. from + count - 1 of the interval between ends e0
 * and e1 of source s into out. */
static void play(const fg_aero_voice *v, const fg_aero_source_state *s, const fg_aero_end *e0,
                 const fg_aero_end *e1, uint32_t from, uint32_t count, const aero_outputs *out)
{
    const double w_far = v->next_share, w_near = 1.0 - w_far;
    direction_mix m = {.count = 0};
    for (int j = 0; j < 2; j++) {
        mix_add(&m, e0->lookup.index[j], e0->lookup.weight[j], e0->coef, 0);
        mix_add(&m, e1->lookup.index[j], e1->lookup.weight[j], e1->coef, 1);
    }
    const fg_aero_texture_desc *t = v->tex;
    const uint32_t comps = t->components;
    const double inv = 1.0 / FG_CONTROL_FRAMES;
    /* tau runs monotonically from e0 to e1: inside the steady part at both
     * ends, it is inside between */
    const bool steady = envelope(v, e0->tau_s) == 1.0 && envelope(v, e1->tau_s) == 1.0;
    for (unsigned k = 0; k < m.count; k++) {
        const fg_aero_direction *dir = &t->direction[m.index[k]];
        const uint32_t f = dir->frames;
        const float *g = dir->samples + (size_t)s->texture_source * f * comps;
        double base = floor(e0->position / f) * f;
        for (uint32_t j = 0; j < count; j++) {
            double u = (from + j) * inv;
            double tau = e0->tau_s + (e1->tau_s - e0->tau_s) * u;
            double env = steady ? 1.0 : envelope(v, tau);
            if (env <= 0.0)
                continue;
            double x = e0->position + (e1->position - e0->position) * u - base;
            if (x >= f)
                x = fmod(x, f);
            uint32_t i = (uint32_t)x;
            if (i >= f)
                i = f - 1;
            double frac = x - i;
            uint32_t i1 = i + 1 == f ? 0 : i + 1;
            double p = 0.0;
            for (uint32_t c = 0; c < comps; c++) {
                double a = m.a0[k][c] + (m.a1[k][c] - m.a0[k][c]) * u;
                double sample = (1.0 - frac) * g[(size_t)i * comps + c] + frac * g[(size_t)i1 * comps + c];
                p += a * sample;
            }
            for (unsigned c = 0; c < out->count; c++) {
                double gain = out->g0[c] + (out->g1[c] - out->g0[c]) * u;
                if (out->far[c])
                    out->far[c][j] += (float)(gain * w_far * env * p);
                out->near[c][j] += (float)(gain * w_near * env * p);
            }
        }
    }
}

/* Plays frames at .. at + count - 1 of the block, which lie in the
 * interval from the voice's control frame: each source and ear that sounds
 * there, as the work bound allows. Notes the speeds heard. */
static void play_interval(fg_aero_voice *v, const fg_block_context *block, uint32_t at,
                          uint32_t count, double *fastest, bool *beyond)
{
    const fg_aero_texture_desc *t = v->tex;
    const uint32_t from = (uint32_t)((uint64_t)block->start_frame + at - v->control_frame);
    const uint64_t units = 1 + count / WORK_SAMPLES;
    for (uint32_t i = 0; i < v->source_count; i++) {
        const fg_aero_source_state *s = &v->source[i];
        for (unsigned ch = 0; ch < block->ears->count; ch++) {
            const fg_aero_end *e0 = &s->end[ch], *e1 = &s->next[ch];
            if (!(envelope(v, e1->tau_s) > 0.0 || envelope(v, e0->tau_s) > 0.0))
                continue;
            if (e1->speed_m_s * t->reference_m / t->viscosity_m2_s > FG_AERO_RE_MAX)
                *beyond = true;
            *fastest = fmax(*fastest, e1->speed_m_s);
            aero_outputs out;
            outputs_for(v, block, ch, e0, e1, at, &out);
            const uint64_t cost = units * (out.count > 0 ? out.count : 1);
            if (*block->work_left >= cost) {
                *block->work_left -= cost;
                play(v, s, e0, e1, from, count, &out);
            } else {
                fg_count(&block->counters->skipped_work, cost);
            }
        }
    }
}

/* Whether every source and ear is past the fade out at the last control
 * frame the block reached: next[] (at_next: the block ends on it), else
 * end[]. Emission time only grows, so nothing after it sounds. */
static bool all_past(const fg_aero_voice *v, unsigned ears, bool at_next)
{
    for (uint32_t i = 0; i < v->source_count; i++)
        for (unsigned ch = 0; ch < ears; ch++) {
            const fg_aero_end *e = at_next ? &v->source[i].next[ch] : &v->source[i].end[ch];
            if (!(e->tau_s >= v->end_s + FG_AERO_FADE_S))
                return false;
        }
    return true;
}

static bool render(void *voice, bool stopping, const fg_block_context *block)
{
    fg_aero_voice *v = voice;
    const double t0 = block->start_frame / block->cfg->sample_rate_hz;
    const unsigned ears = block->ears->count;
    const uint64_t first = (uint64_t)block->start_frame, last = first + block->frames;
    fg_pose_queue_drain(&v->queue, &v->poses_seen, absorb, &v->path);
    fg_trajectory_forget(&v->path, t0);
    if (stopping && !(v->end_s < INFINITY))
        v->end_s = fmax(t0, v->emit_s);
    if (!v->started) {
        if (last <= v->control_frame) {
            fg_count(&v->blocks, 1);
            return false; /* before the emission */
        }
        start(v, block);
    }
    if (v->next_ready && first >= v->control_frame + FG_CONTROL_FRAMES)
        step(v, ears);
    double oldest_tau = INFINITY;
    for (uint32_t i = 0; i < v->source_count; i++)
        for (unsigned ch = 0; ch < ears; ch++)
            oldest_tau = fmin(oldest_tau, v->source[i].end[ch].tau_s);
    fg_aero_voice_take_wind(v, oldest_tau, t0);

    double fastest = 0.0;
    bool beyond = false;
    /* frames before the first control frame hear nothing yet */
    uint64_t at = first > v->control_frame ? first : v->control_frame;
    while (at < last) {
        if (at >= v->control_frame + FG_CONTROL_FRAMES)
            step(v, ears);
        if (!v->next_ready && !evaluate_next(v, block)) {
            fg_count(&block->counters->non_finite_voices, 1);
            return true;
        }
        uint64_t to = v->control_frame + FG_CONTROL_FRAMES;
        to = to < last ? to : last;
        play_interval(v, block, (uint32_t)(at - first), (uint32_t)(to - at), &fastest, &beyond);
        at = to;
    }
    fg_count(&v->blocks, 1);
    if (beyond)
        fg_count(&v->beyond_range_blocks, 1);
    uint64_t um = (uint64_t)(fmin(fastest, 1e9) * 1e6);
    if (um > atomic_load_explicit(&v->max_speed_um_s, memory_order_relaxed))
        atomic_store_explicit(&v->max_speed_um_s, um, memory_order_relaxed);
    return v->next_ready && all_past(v, ears, last == v->control_frame + FG_CONTROL_FRAMES);
}

const fg_source_ops fg_aero_ops = {
    .name = "aero object",
    .kind = &fg_aero_kind,
    .prepare = fg_aero_prepare,
    .adopt = adopt,
    .render = render,
};
