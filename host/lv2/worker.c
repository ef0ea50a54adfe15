/* The LV2 worker: notes become discharges off the audio thread, a SOFA
 * file becomes a new engine, and engines let go of are destroyed. */
#include <stdatomic.h>
#include <stddef.h>
#include <string.h>

#include "plugin.h"

static LV2_Worker_Status note(plugin *p, LV2_Worker_Respond_Function respond,
                              LV2_Worker_Respond_Handle handle, const work_request *rq)
{
    fg_engine *engine = p->slots[p->posting].engine;
    /* Every request reclaims the voices the audio thread has finished, so a
     * voice's slot is free again by the next note. */
    fg_engine_collect(engine);
    fg_voice_id *held = &p->held[rq->note & 127];
    /* a held note ends in the engine it was played on (a swap may be
     * playing it out) */
    fg_engine *held_in = p->slots[p->held_slot[rq->note & 127]].engine;
    work_reply reply = {.kind = rq->kind, .result = FG_OK};
    if (rq->kind == REQUEST_NOTE_ON) {
        if (*held) {
            /* the same note again before its note-off: the old voice ends
             * (FG_ERR_NOT_FOUND would only mean it already has) */
            fg_result ended = fg_engine_stop(held_in, *held);
            (void)ended;
            *held = 0;
        }
        fg_voice_id id;
        reply.result = note_post(p, rq, &id);
        if (reply.result == FG_OK && rq->controls.preset == FG_PRESET_PLASMA_BALL) {
            *held = id;
            p->held_slot[rq->note & 127] = p->posting;
        }
    } else {
        if (!*held)
            return LV2_WORKER_SUCCESS;  /* a one-shot discharge: nothing to end */
        reply.result = fg_engine_stop(held_in, *held);
        *held = 0;
    }
    return respond(handle, sizeof reply, &reply);
}

/* A new engine from the SOFA file named; a file that cannot be played is
 * refused with a message through the host's log, and the engine playing
 * goes on. */
static LV2_Worker_Status sofa(plugin *p, LV2_Worker_Respond_Function respond,
                              LV2_Worker_Respond_Handle handle, const sofa_request *rq)
{
    work_reply reply = {.kind = REQUEST_SOFA, .result = FG_ERR_ARGUMENT,
                        .generation = p->generation};
    char err[600];
    int slot = -1;
    if (rq->length >= SOFA_PATH_BYTES)
        snprintf(err, sizeof err, "a path of %u bytes, longer than the %u taken", rq->length,
                 SOFA_PATH_BYTES - 1);
    else if (rq->length == 0)
        snprintf(err, sizeof err, "an empty path");
    else
        slot = engine_slot_create(p, rq->path, err, sizeof err);
    if (slot < 0) {
        lv2_log_error(&p->logger, "fulgur.lv2: sofa: %s; the previous file plays on\n", err);
    } else {
        reply.result = FG_OK;
        reply.slot = (uint32_t)slot;
        p->posting = (uint32_t)slot; /* the next notes go to it */
    }
    return respond(handle, sizeof reply, &reply);
}

LV2_Worker_Status plugin_work(LV2_Handle instance, LV2_Worker_Respond_Function respond,
                              LV2_Worker_Respond_Handle handle, uint32_t size, const void *data)
{
    plugin *p = instance;
    request_kind kind;
    if (size < sizeof kind)
        return LV2_WORKER_ERR_UNKNOWN;
    memcpy(&kind, data, sizeof kind);
    if ((kind == REQUEST_NOTE_ON || kind == REQUEST_NOTE_OFF) && size == sizeof(work_request)) {
        work_request rq;
        memcpy(&rq, data, sizeof rq);
        return note(p, respond, handle, &rq);
    }
    if (kind == REQUEST_SOFA && size > offsetof(sofa_request, path) &&
        size <= sizeof(sofa_request)) {
        sofa_request rq;
        memcpy(&rq, data, size);
        rq.path[size - offsetof(sofa_request, path) - 1] = '\0';
        return sofa(p, respond, handle, &rq);
    }
    if (kind == REQUEST_RETIRE && size == sizeof(retire_request)) {
        retire_request rq;
        memcpy(&rq, data, sizeof rq);
        if (rq.generation != p->generation)
            return LV2_WORKER_SUCCESS; /* restore has destroyed it already */
        if (rq.slot >= ENGINE_SLOTS || rq.slot == p->posting)
            return LV2_WORKER_ERR_UNKNOWN;
        engine_slot_destroy(p, rq.slot);
        return LV2_WORKER_SUCCESS;
    }
    return LV2_WORKER_ERR_UNKNOWN;
}

LV2_Worker_Status plugin_work_response(LV2_Handle instance, uint32_t size, const void *body)
{
    plugin *p = instance;
    work_reply reply;
    if (size != sizeof reply)
        return LV2_WORKER_ERR_UNKNOWN;
    memcpy(&reply, body, sizeof reply);
    if (reply.kind == REQUEST_SOFA) {
        if (reply.generation != p->generation)
            return LV2_WORKER_SUCCESS; /* an engine restore has destroyed */
        if (reply.result == FG_OK)
            p->swap_to = (int32_t)reply.slot; /* run() swaps it in */
        p->notify_pending = 1; /* the file now playing, new or not */
    } else if (reply.result != FG_OK) {
        p->failures++;
    } else if (reply.kind == REQUEST_NOTE_ON) {
        p->discharges++;
    }
    return LV2_WORKER_SUCCESS;
}
