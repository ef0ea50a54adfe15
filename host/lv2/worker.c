/* The LV2 worker: notes become discharges off the audio thread. */
#include <string.h>

#include "plugin.h"

LV2_Worker_Status plugin_work(LV2_Handle instance, LV2_Worker_Respond_Function respond,
                              LV2_Worker_Respond_Handle handle, uint32_t size, const void *data)
{
    plugin *p = instance;
    work_request rq;
    if (size != sizeof rq)
        return LV2_WORKER_ERR_UNKNOWN;
    memcpy(&rq, data, sizeof rq);
    /* Every request reclaims the voices the audio thread has finished, so a
     * voice's slot is free again by the next note. */
    fg_engine_collect(p->engine);
    fg_voice_id *held = &p->held[rq.note & 127];
    work_reply reply = {.kind = rq.kind, .result = FG_OK};
    if (rq.kind == REQUEST_NOTE_ON) {
        if (*held) {
            /* the same note again before its note-off: the old voice ends
             * (FG_ERR_NOT_FOUND would only mean it already has) */
            fg_result ended = fg_engine_stop(p->engine, *held);
            (void)ended;
            *held = 0;
        }
        fg_voice_id id;
        reply.result = note_post(p, &rq, &id);
        if (reply.result == FG_OK && rq.controls.preset == FG_PRESET_PLASMA_BALL)
            *held = id;
    } else if (rq.kind == REQUEST_NOTE_OFF) {
        if (!*held)
            return LV2_WORKER_SUCCESS;  /* a one-shot discharge: nothing to end */
        reply.result = fg_engine_stop(p->engine, *held);
        *held = 0;
    } else {
        return LV2_WORKER_ERR_UNKNOWN;
    }
    return respond(handle, sizeof reply, &reply);
}

LV2_Worker_Status plugin_work_response(LV2_Handle instance, uint32_t size, const void *body)
{
    plugin *p = instance;
    work_reply reply;
    if (size != sizeof reply)
        return LV2_WORKER_ERR_UNKNOWN;
    memcpy(&reply, body, sizeof reply);
    if (reply.result != FG_OK)
        p->failures++;
    else if (reply.kind == REQUEST_NOTE_ON)
        p->discharges++;
    return LV2_WORKER_SUCCESS;
}
