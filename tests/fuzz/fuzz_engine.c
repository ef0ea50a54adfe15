/* libFuzzer target for the engine's post/render path through the public
 * API only (fulgur.h). The fuzz bytes are read in order (zeros past the
 * end) as an engine configuration, then up to 64 operations: post a
 * discharge (its tree, sound, strokes, repeats, propagation and model), move
 * the listener, render some blocks, stop a voice. Every parameter is either
 * a limit's edge or beyond it (from the table edges[]), or the preset's
 * value scaled by a power of two, so both sides of every check are reached.
 * Then every voice is stopped and the tail rendered. Asserted (abort):
 *   - every sample of every block is finite;
 *   - a refused post returns one of the documented codes, an accepted one
 *     an id; render and set_listener only their documented codes;
 *   - no voice leaks: once the tail has passed (its bound derived from the
 *     accepted posts below), every accepted voice has been collected.
 * Corpus: corpus/fulgur_fuzz_engine/ (tests/fuzz/write_seeds.py wrote it). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fulgur/fulgur.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_OPS 64
#define MAX_NODES 16
#define MAX_BLOCK 512
#define MAX_POSTS 64
/* Trees stay within +-64 m here (edges[] aside), and the head, where a pose
 * and 0.1 s along its velocity take it, within HEAD_REACH_M (else the run
 * is `far` and no tail is checked), so an accepted voice has finished this
 * long after its last emission: travel across 300 + 111 m at the slowest
 * speed of sound (100 m/s) with refraction's longer arcs, a turbulence
 * offset (< 1 s) and the longest wave stretched by the largest Doppler
 * rate: Abe's 0.83 s (to -60 dB) times 10, the rate of an ear receding at
 * 0.9 c or faster when the wave arrives (docs/sound-model.md). (At 8 s, a
 * listener jumping away as a continuous Abe voice sounded outlived the
 * bound by 0.4 s: the first input the fuzzer found past it.) */
#define HEAD_REACH_M 300.0
#define TAIL_S 14.0
/* No voice is checked whose sound could last past this engine time. */
#define MAX_CHECKED_END_S 18.0

typedef struct bytes {
    const uint8_t *at;
    size_t left;
} bytes;

static uint8_t next(bytes *b)
{
    if (b->left == 0)
        return 0;
    b->left--;
    return *b->at++;
}

static int16_t next16(bytes *b)
{
    uint16_t lo = next(b);
    return (int16_t)(lo | (uint16_t)next(b) << 8);
}

/* The values where the engine's checks change their answer, and beyond. */
static const double edges[] = {
    0.0, -0.0, NAN, INFINITY, -INFINITY, 5e-324, 1e-308, 1e-162, 1e-160, 1e-7, 0.99e-7,
    1e-6, 0.99e-6, 1e-4, 0.99e-4, 1e-3, 0.1, 0.1000001, 1.0, 10.0, 10.0000001, 100.0, 1000.0,
    1000.0001, 20e3, 200e3, 1e5, 3e8, 3.0000001e8, 1e7, 1.0000001e7, -1e7, 1e50, 1e-50,
    -1.0, 1e300, -1e300, 1.7976931348623157e308,
};
#define EDGE_COUNT (sizeof edges / sizeof edges[0])

/* One byte: below EDGE_COUNT (38) an edge, else base * 2^((b - 148) / 12)
 * (base / 512 .. base * 256), base itself at 148. */
static double value(bytes *b, double base)
{
    uint8_t v = next(b);
    if (v < EDGE_COUNT)
        return edges[v];
    return base * exp2(((int)v - 148) / 12.0);
}

/* A coordinate within +-64 m in 1/512 m steps, or (a marker byte 0xEE) an edge. */
static double coordinate(bytes *b)
{
    int16_t raw = next16(b);
    if ((raw & 0xff) == 0xee)
        return edges[(unsigned)(raw >> 8 & 0xff) % EDGE_COUNT];
    return raw / 512.0;
}

typedef struct run {
    fg_engine *engine;
    fg_engine_config cfg;
    float planes[2][MAX_BLOCK];
    uint32_t block;
    fg_voice_id ids[MAX_POSTS];
    size_t id_count;
    double latest_end_s; /* when the last accepted voice can have finished */
    int far;             /* a voice accepted, or the head taken, farther than the tail covers */
    double head_at[3];   /* the last accepted pose's position, and its time */
    double head_time_s;
} run;

static void render(run *r, uint32_t blocks)
{
    float *out[2] = {r->planes[0], r->planes[1]};
    for (uint32_t k = 0; k < blocks; k++) {
        if (fg_engine_render(r->engine, out, r->block) != FG_OK)
            abort();
        for (uint32_t ch = 0; ch < r->cfg.channels; ch++)
            for (uint32_t f = 0; f < r->block; f++)
                if (!isfinite(r->planes[ch][f]))
                    abort();
        fg_engine_collect(r->engine);
    }
}

static int post_refusal(fg_result res)
{
    return res == FG_ERR_TREE || res == FG_ERR_NOT_FINITE || res == FG_ERR_ARGUMENT ||
           res == FG_ERR_CAPACITY || res == FG_ERR_POOL_FULL || res == FG_ERR_QUEUE_FULL;
}

static void post(run *r, bytes *b)
{
    fg_node nodes[MAX_NODES];
    size_t count = 1 + next(b) % MAX_NODES; /* 1 node: too few */
    double reach = 0;
    for (size_t i = 0; i < count; i++) {
        uint8_t shape = next(b);
        nodes[i].x = coordinate(b);
        nodes[i].y = coordinate(b);
        nodes[i].z = coordinate(b);
        /* mostly a valid parent (a chain or a branch), sometimes not */
        nodes[i].parent = i == 0 ? -1 : (int32_t)(shape % 8 == 7 ? shape : shape % i);
        if (shape == 0xff)
            nodes[i].parent = -1;
        nodes[i].flags = shape & 0x40 ? FG_NODE_MAIN : 0;
        reach = fmax(reach, fmax(fabs(nodes[i].x), fmax(fabs(nodes[i].y), fabs(nodes[i].z))));
    }
    fg_discharge d = {.nodes = nodes, .node_count = count};
    fg_preset preset = (fg_preset)(next(b) % FG_PRESET_COUNT);
    if (fg_preset_sound(preset, &d.sound) != FG_OK)
        abort();
    d.sound.t0_s = value(b, d.sound.t0_s);
    d.sound.r0_m = value(b, d.sound.r0_m);
    d.sound.ps0_pa = value(b, d.sound.ps0_pa);
    d.sound.sigma0 = value(b, d.sound.sigma0);
    d.sound.t0_jitter = value(b, 0.1);
    d.sound.return_stroke_speed_m_s = value(b, d.sound.return_stroke_speed_m_s);
    d.sound.ref_half_len_m = value(b, d.sound.ref_half_len_m > 0 ? d.sound.ref_half_len_m : 1e-3);
    uint8_t emit = next(b);
    d.emit_time_s = emit == 0xff ? FG_EMIT_NOW : emit == 0xfe ? -0.5 : emit / 128.0;
    d.strokes = next(b) % (FG_MAX_STROKES + 2);
    uint8_t mode = next(b);
    d.continuous = mode & 1;
    d.repeat_min_s = value(b, 0.01);
    d.repeat_max_s = value(b, 0.03);
    d.duration_s = mode & 2 ? value(b, 0.2) : 0.0;
    d.seed = next(b);
    d.model = (fg_voice_model)(mode >> 2 & 3); /* 2, 3: unknown */
    uint8_t air = next(b);
    /* 3: unknown; ISO 9613-1 only with bit 7 as well, and no seed has it:
     * its first post designs the engine's filters (0.3 s, 5 s under ASan),
     * which would slow every run */
    d.propagation.absorption = (fg_absorption)(air & 3);
    if (d.propagation.absorption == FG_ABSORPTION_ISO9613 && !(air & 128))
        d.propagation.absorption = FG_ABSORPTION_OFF;
    if (air & 4)
        d.propagation.refraction_radius_m = value(b, FG_REFRACTION_STORM_M);
    if (air & 8) {
        d.propagation.turbulence_s = value(b, FG_TURBULENCE_DEFAULT_S);
        d.propagation.turbulence_length_m = value(b, FG_TURBULENCE_DEFAULT_LENGTH_M);
    }
    if (air & 16)
        d.propagation.abe_fir_distance_m = value(b, 1.0);
    if (air & 32)
        d.propagation.ground_reflection = value(b, FG_GROUND_DEFAULT_REFLECTION);
    d.propagation.head_shadow = air >> 6 & 1;
    fg_voice_id id = 0;
    fg_result res = fg_engine_post(r->engine, &d, &id);
    if (res != FG_OK) {
        if (!post_refusal(res))
            abort();
        return;
    }
    if (id == 0 || r->id_count == MAX_POSTS)
        abort();
    r->ids[r->id_count++] = id;
    /* the latest time this voice can sound: its emission (0 for now, the
     * engine clock otherwise), its strokes, its repeats, then the tail */
    double offsets[FG_MAX_STROKES];
    uint32_t strokes = fg_discharge_stroke_offsets(&d, offsets, FG_MAX_STROKES);
    double start = d.emit_time_s == FG_EMIT_NOW ? fg_engine_time_s(r->engine) : d.emit_time_s;
    uint32_t listed = strokes < FG_MAX_STROKES ? strokes : FG_MAX_STROKES;
    double last_stroke_s = listed ? offsets[listed - 1] : 0.0;
    /* a continuous voice's last emission falls inside its duration, or
     * (duration 0) before the stop after the operations */
    double end = fmax(start, fg_engine_time_s(r->engine)) + last_stroke_s +
                 (!d.continuous ? 0 : d.duration_s > 0 ? d.duration_s : INFINITY) + TAIL_S;
    if (reach > 64.0)
        r->far = 1;
    r->latest_end_s = fmax(r->latest_end_s, end);
}

static void move_listener(run *r, bytes *b)
{
    fg_listener pose = {0};
    for (int k = 0; k < 3; k++)
        pose.position[k] = coordinate(b);
    uint8_t look = next(b);
    pose.forward[look % 3] = look & 8 ? value(b, 1.0) : 1.0;
    pose.up[(look / 3 + 1) % 3] = look & 16 ? value(b, 1.0) : 1.0;
    if (look & 32)
        for (int k = 0; k < 3; k++)
            pose.velocity[k] = value(b, 1.0) * (next(b) & 1 ? -1 : 1);
    if (look & 64)
        pose.time_s = fg_engine_time_s(r->engine) + next(b) / 256.0;
    fg_result res = fg_engine_set_listener(r->engine, &pose);
    if (res != FG_OK && res != FG_ERR_NOT_FINITE && res != FG_ERR_ARGUMENT)
        abort();
    if (res != FG_OK)
        return;
    /* how far the head can get: the pose, then 0.1 s along its velocity
     * or, without one, the chord from the pose before (fg_engine_set_listener).
     * A post sorts its waves against that head (a jump to 100 km, found by
     * the fuzzer, scheduled a voice's waves 314 s ahead). */
    double t = pose.time_s > 0 ? pose.time_s : fg_engine_time_s(r->engine);
    double speed = 0.0, reach = 0.0, chord = 0.0;
    for (int k = 0; k < 3; k++) {
        speed += pose.velocity[k] * pose.velocity[k];
        chord += (pose.position[k] - r->head_at[k]) * (pose.position[k] - r->head_at[k]);
        reach = fmax(reach, fabs(pose.position[k]));
    }
    speed = sqrt(speed);
    if (speed == 0.0 && t > r->head_time_s) /* (else it replaces the pose before) */
        speed = sqrt(chord) / (t - r->head_time_s);
    if (reach + 0.1 * speed > HEAD_REACH_M)
        r->far = 1;
    memcpy(r->head_at, pose.position, sizeof r->head_at);
    r->head_time_s = t;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const double rates[] = {8000, 16000, 22050, 44100, 48000, 96000};
    bytes b = {data, size};
    static run r;
    memset(&r, 0, sizeof r);
    uint8_t shape = next(&b);
    r.cfg.sample_rate_hz = rates[shape % 6];
    r.block = 16u << (shape / 6 % 6); /* 16 .. 512 */
    r.cfg.max_block_frames = r.block;
    r.cfg.channels = 1 + (shape / 36 % 2);
    r.cfg.max_voices = 1 + next(&b) % 8;
    /* FG_SPEED_OF_SOUND_MIN_M_S .. _MAX_ (the old * 1000 / 256 reached 1096 m/s,
     * which create refuses: the first crash found once inputs ran fast) */
    r.cfg.speed_of_sound_m_s = 100.0 + next(&b) * 900.0 / 255;
    uint8_t sizes = next(&b);
    r.cfg.work_per_frame = sizes % 2 ? 1 : 0; /* the tightest bound, or the default */
    /* room for the largest tree here and its ground image, or (one in four)
     * less than a 16-node tree needs: both sides of the capacity check,
     * without the default's 131072 events, whose allocation and clearing
     * took most of each input's time */
    r.cfg.segment_capacity = sizes / 2 % 4 ? 2 * MAX_NODES : MAX_NODES / 2;
    /* in chunks of 1024 frames, as fulgur render renders, or a chunk a block */
    r.cfg.chunk_frames = sizes / 8 % 2 ? 1024 : 0;
    if (fg_engine_create(&r.cfg, &r.engine) != FG_OK)
        abort();
    fg_engine_get_config(r.engine, &r.cfg);
    for (int op = 0; op < MAX_OPS && b.left > 0; op++) {
        uint8_t code = next(&b);
        switch (code % 4) {
        case 0:
            post(&r, &b);
            break;
        case 1:
            move_listener(&r, &b);
            break;
        case 2:
            render(&r, 1 + code / 4 % 16);
            break;
        default:
            if (r.id_count) {
                fg_result res = fg_engine_stop(r.engine, r.ids[code / 4 % r.id_count]);
                if (res != FG_OK && res != FG_ERR_NOT_FOUND)
                    abort();
            }
            break;
        }
    }
    for (size_t i = 0; i < r.id_count; i++) {
        fg_result res = fg_engine_stop(r.engine, r.ids[i]);
        if (res != FG_OK && res != FG_ERR_NOT_FOUND)
            abort();
    }
    /* a stopped voice starts no emission after the next block */
    r.latest_end_s = fmin(r.latest_end_s, fg_engine_time_s(r.engine) + TAIL_S);
    /* the tail: every voice the bound covers must have been collected;
     * the listener is put back within reach of the trees first, at rest
     * (velocity_given: else the head would go on along the chord from the
     * last pose for 0.1 s, 2.5 km at the 25 km/s of a 48 m jump in 2 ms,
     * which the fuzzer found) */
    fg_listener home = {.position = {0, 0, 0}, .forward = {0, 1, 0}, .up = {0, 0, 1},
                        .velocity_given = 1};
    if (fg_engine_set_listener(r.engine, &home) != FG_OK)
        abort();
    if (!r.far && r.latest_end_s <= MAX_CHECKED_END_S) {
        double block_s = r.block / r.cfg.sample_rate_hz;
        while (fg_engine_time_s(r.engine) < r.latest_end_s) {
            render(&r, 1 + (uint32_t)(0.1 / block_s));
            fg_engine_report rep;
            fg_engine_get_report(r.engine, &rep);
            if (rep.collected == rep.posted)
                break;
        }
        fg_engine_report rep;
        fg_engine_get_report(r.engine, &rep);
        if (rep.collected != rep.posted || rep.posted != r.id_count)
            abort();
    }
    fg_engine_destroy(r.engine);
    return 0;
}
