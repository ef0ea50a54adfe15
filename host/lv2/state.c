/* The LV2 state: the position in the seed stream, and the binaural
 * plugin's SOFA file.
 *
 * The control ports (preset, distance, ..., seed) are saved by the host as
 * port values with the plugin's state (lilv_state_new_from_instance asks
 * for them; every LV2 host does this), and restored before the next run().
 * What no port holds is how many discharges were triggered: each note's
 * seed is (seed port << 32 | that count), so the plugin saves the count,
 * and after a restore the same notes grow the same trees. The binaural
 * plugin saves the SOFA file it plays as an atom:Path (through the host's
 * state:mapPath when it has one, so a session can move).
 *
 * save() may run while run() does (LV2 state): it reads the count and the
 * playing slot's path, which the worker writes only while the slot is free,
 * and a slot is freed RETIRE_TAIL_S after the audio thread let it go.
 * restore() runs alone (LV2's instantiation class): it makes the engine of
 * the saved file directly and destroys the others (a swap's held notes end
 * there); the swaps' replies and retire requests still on their way then
 * name destroyed slots and are dropped (plugin.generation). */
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include <lv2/atom/atom.h>
#include <lv2/state/state.h>

#include "plugin.h"
#include "sofa_hrir.h"

static const LV2_State_Map_Path *map_path(const LV2_Feature *const *features)
{
    for (size_t i = 0; features && features[i]; i++)
        if (features[i]->URI && !strcmp(features[i]->URI, LV2_STATE__mapPath))
            return features[i]->data;
    return NULL;
}

static LV2_State_Status save(LV2_Handle instance, LV2_State_Store_Function store,
                             LV2_State_Handle handle, uint32_t flags,
                             const LV2_Feature *const *features)
{
    (void)flags;
    const plugin *p = instance;
    int64_t count = (int64_t)p->discharge_count;
    LV2_State_Status s = store(handle, p->urid_counter, &count, sizeof count, p->urid_long,
                               LV2_STATE_IS_POD | LV2_STATE_IS_PORTABLE);
    if (s != LV2_STATE_SUCCESS || p->variant->layout != FG_LAYOUT_BINAURAL)
        return s;
    const char *sofa = p->slots[atomic_load_explicit(&p->playing, memory_order_relaxed)].sofa;
    const LV2_State_Map_Path *paths = map_path(features);
    char *abstract = paths ? paths->abstract_path(paths->handle, sofa) : NULL;
    const char *kept = abstract ? abstract : sofa;
    s = store(handle, p->urid_sofa, kept, strlen(kept) + 1, p->urid_path,
              LV2_STATE_IS_POD | LV2_STATE_IS_PORTABLE);
    free(abstract); /* the host's malloc (state:mapPath) */
    return s;
}

/* The binaural plugin's engine for the saved file (missing: the default
 * one), unless it plays that file already. */
static LV2_State_Status restore_sofa(plugin *p, LV2_State_Retrieve_Function retrieve,
                                     LV2_State_Handle handle, const LV2_Feature *const *features)
{
    size_t size;
    uint32_t type, value_flags;
    const char *value = retrieve(handle, p->urid_sofa, &size, &type, &value_flags);
    if (value && (type != p->urid_path || size == 0 || memchr(value, 0, size) == NULL)) {
        lv2_log_error(&p->logger, "fulgur.lv2: state: the SOFA file is not a path; the "
                                  "previous file plays on\n");
        return LV2_STATE_ERR_BAD_TYPE;
    }
    const LV2_State_Map_Path *paths = map_path(features);
    char *absolute = value && paths ? paths->absolute_path(paths->handle, value) : NULL;
    const char *sofa = absolute ? absolute : value ? value : SOFA_DEFAULT_FILE;
    uint32_t playing = atomic_load_explicit(&p->playing, memory_order_relaxed);
    int changes = strcmp(sofa, p->slots[playing].sofa) != 0;
    char err[600];
    int slot = changes ? engine_slot_create(p, sofa, err, sizeof err) : 0;
    if (slot < 0)
        lv2_log_error(&p->logger, "fulgur.lv2: state: sofa: %s; the previous file plays on\n",
                      err);
    free(absolute);
    if (slot < 0)
        return LV2_STATE_ERR_UNKNOWN;
    if (changes) {
        /* restore runs alone: every other engine goes now */
        for (uint32_t s = 0; s < ENGINE_SLOTS; s++)
            if (s != (uint32_t)slot)
                engine_slot_destroy(p, s);
        atomic_store_explicit(&p->playing, (uint32_t)slot, memory_order_relaxed);
        p->posting = (uint32_t)slot;
        p->generation++; /* replies and retire requests on their way are stale */
        p->retiring = -1;
        p->swap_to = -1;
        p->notify_pending = 1;
    }
    return LV2_STATE_SUCCESS;
}

static LV2_State_Status restore(LV2_Handle instance, LV2_State_Retrieve_Function retrieve,
                                LV2_State_Handle handle, uint32_t flags,
                                const LV2_Feature *const *features)
{
    (void)flags;
    plugin *p = instance;
    size_t size;
    uint32_t type, value_flags;
    const void *value = retrieve(handle, p->urid_counter, &size, &type, &value_flags);
    int64_t count = 0;   /* missing: the stream's start */
    if (value && (type != p->urid_long || size != sizeof count))
        return LV2_STATE_ERR_BAD_TYPE;
    if (value)
        memcpy(&count, value, sizeof count);
    if (count < 0)
        return LV2_STATE_ERR_UNKNOWN;
    p->discharge_count = (uint64_t)count;
    if (p->variant->layout == FG_LAYOUT_BINAURAL)
        return restore_sofa(p, retrieve, handle, features);
    return LV2_STATE_SUCCESS;
}

const void *plugin_state_interface(void)
{
    static const LV2_State_Interface state = {save, restore};
    return &state;
}
