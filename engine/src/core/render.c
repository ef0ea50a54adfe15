/* The audio thread's loop: adopt posted voices, render each into the
 * buses, retire the finished, filter the buses into the output. It knows
 * no model: every voice is played through its fg_source_ops. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime(CLOCK_MONOTONIC) */
#include <string.h>
#include <time.h>

#include "engine_internal.h"
#include "fp_env_internal.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void absorb(const fg_listener *pose, uint64_t number, void *trajectory)
{
    fg_trajectory_push(trajectory, pose, number);
}

/* One block of nframes <= the buses' max_frames into the zeroed out. */
static void render_block(fg_engine *e, float *const *out, uint32_t nframes)
{
    uint64_t start = atomic_load_explicit(&e->frames, memory_order_relaxed);

    double start_s = (double)start / e->cfg.sample_rate_hz;
    fg_pose_queue_drain(&e->listener, &e->poses_seen, absorb, &e->trajectory);
    fg_trajectory_forget(&e->trajectory, start_s);
    fg_head head;
    fg_trajectory_head(&e->trajectory, start_s, &head);
    fg_ears ears;
    fg_head_ears(&head, fg_layout_ears(&e->cfg), e->cfg.ear_spacing_m, &ears);
    /* a chunk of the block without chunks, or when the listener moves (its
     * waves are heard where they arrive, a block at a time); a new chunk
     * when the pose has changed since the chunk's waves were written, or
     * when a source asked */
    const uint64_t serial = fg_trajectory_serial(&e->trajectory);
    fg_chunk_start chunk = !e->cfg.chunk_frames || !e->trajectory.still    ? FG_CHUNK_BLOCK
                           : serial != e->chunk_serial || e->restart_chunk ? FG_CHUNK_NEW
                                                                           : FG_CHUNK_CARRY;
    fg_bus_set_begin(&e->buses, nframes, chunk);
    e->chunk_serial = serial;
    e->restart_chunk = false;
    const uint64_t work_bound = (uint64_t)e->cfg.work_per_frame * nframes + FG_WORK_BLOCK_FLOOR;
    uint64_t work_left = work_bound;
    fg_block_context block = {
        .cfg = &e->cfg,
        .start_frame = (double)start,
        .frames = nframes,
        .trajectory = &e->trajectory,
        .ears = &ears,
        .position = head.position,
        .serial = serial,
        .buses = &e->buses,
        .ahead = e->buses.chunk_len - e->buses.chunk_pos,
        .chunk_start = e->buses.chunk_pos == 0,
        .chunk_follows = e->buses.chunk_follows,
        .restart = &e->restart_chunk,
        .counters = &e->counters,
        .work_left = &work_left,
    };

    fg_voice *adopted;
    for (uint32_t k = 0; k < e->cfg.max_adopt_per_block && fg_ring_pop(&e->inbox, &adopted);
         k++) {
        adopted->ops->adopt(adopted->state, &block);
        e->active[e->active_count++] = adopted;
        fg_count(&e->counters.adopted, 1);
    }
    for (uint32_t i = 0; i < e->active_count;) {
        fg_voice *v = e->active[i];
        bool stopping = atomic_load_explicit(&v->stop, memory_order_acquire);
        if (v->ops->render(v->state, stopping, &block)) {
            e->active[i] = e->active[--e->active_count];
            bool pushed = fg_ring_push(&e->garbage, &v);
            (void)pushed; /* the ring holds max_voices: never full */
            fg_count(&e->counters.finished, 1);
        } else {
            i++;
        }
    }
    const uint64_t spent = work_bound - work_left;
    fg_count(&e->counters.work_units, spent);
    /* the audio thread alone writes it */
    if (spent > atomic_load_explicit(&e->counters.peak_block_work, memory_order_relaxed))
        atomic_store_explicit(&e->counters.peak_block_work, spent, memory_order_relaxed);
    uint64_t dropped;
    if (e->cfg.layout == FG_LAYOUT_BINAURAL) {
        /* the loudspeaker planes the last block wrote, over what it wrote
         * (the others are still zero: a far bolt reaches a few of 50) */
        unsigned planes = e->buses.channels;
        for (unsigned ch = 0; ch < planes; ch++)
            if (e->buses.written >> ch & 1)
                memset(e->field[ch], 0, (size_t)e->field_frames * sizeof(float));
        dropped = fg_bus_set_end(&e->buses, e->field, nframes);
        e->field_frames = nframes;
        /* the planes it did not write are zero: the convolver is told so */
        const float *speakers[FG_BUS_MAX_CHANNELS];
        for (unsigned ch = 0; ch < planes; ch++)
            speakers[ch] = e->buses.written >> ch & 1 ? e->field[ch] : NULL;
        fg_binaural_process(&e->binaural, speakers, out, nframes);
    } else {
        dropped = fg_bus_set_end(&e->buses, out, nframes);
    }
    if (dropped)
        fg_count(&e->counters.non_finite_blocks, dropped);

    atomic_store_explicit(&e->frames, start + nframes, memory_order_release);
}

fg_result fg_engine_render(fg_engine *e, float *const *out, uint32_t nframes)
{
    if (!e || !out)
        return FG_ERR_NULL;
    for (uint32_t ch = 0; ch < e->cfg.channels; ch++)
        if (!out[ch])
            return FG_ERR_NULL;
    for (uint32_t ch = 0; ch < e->cfg.channels; ch++)
        memset(out[ch], 0, (size_t)nframes * sizeof(float));
    if (nframes > e->cfg.max_block_frames)
        return FG_ERR_BLOCK_SIZE;
    if (nframes == 0)
        return FG_OK;

    double t_begin = now_s();
    fg_fp_env env = fg_fp_env_flush_denormals();
    /* a call longer than the buses' block is rendered as blocks of it */
    float *part[FG_BUS_MAX_CHANNELS];
    for (uint32_t done = 0, n; done < nframes; done += n) {
        n = nframes - done < e->buses.max_frames ? nframes - done : e->buses.max_frames;
        for (uint32_t ch = 0; ch < e->cfg.channels; ch++)
            part[ch] = out[ch] + done;
        render_block(e, part, n);
    }
    fg_count(&e->counters.blocks, 1);
    fg_fp_env_restore(env);
    if (now_s() - t_begin > nframes / e->cfg.sample_rate_hz)
        fg_count(&e->counters.blocks_over_budget, 1);
    return FG_OK;
}
