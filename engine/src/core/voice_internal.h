/* A voice: one posted source, from its post until it is collected.
 *
 * Ownership moves with the rings: the sim thread fills a free voice and
 * pushes it to the inbox; from then on only the audio thread touches its
 * state (the model's playback state and caches); once retired onto the
 * garbage ring it belongs to the sim thread again. */
#ifndef FULGUR_VOICE_INTERNAL_H
#define FULGUR_VOICE_INTERNAL_H

#include <stdatomic.h>
#include <stdint.h>

#include "source_internal.h"

typedef struct fg_voice {
    const fg_source_ops *ops;  /* its model: set by the post */
    void *state;               /* the model's state: this slot's in its kind's pool */
    void *storage;             /* the kind's shared storage */
    uint32_t slot, generation;
    atomic_bool stop;          /* set by fg_engine_stop */
} fg_voice;

#endif
