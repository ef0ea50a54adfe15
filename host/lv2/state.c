/* The LV2 state: the position in the seed stream.
 *
 * The control ports (preset, distance, ..., seed) are saved by the host as
 * port values with the plugin's state (lilv_state_new_from_instance asks
 * for them; every LV2 host does this), and restored before the next run().
 * What no port holds is how many discharges were triggered: each note's
 * seed is (seed port << 32 | that count), so the plugin saves the count,
 * and after a restore the same notes grow the same trees. */
#include <string.h>

#include <lv2/atom/atom.h>
#include <lv2/state/state.h>

#include "plugin.h"

static LV2_State_Status save(LV2_Handle instance, LV2_State_Store_Function store,
                             LV2_State_Handle handle, uint32_t flags,
                             const LV2_Feature *const *features)
{
    (void)flags;
    (void)features;
    const plugin *p = instance;
    int64_t count = (int64_t)p->discharge_count;
    return store(handle, p->urid_counter, &count, sizeof count, p->urid_long,
                 LV2_STATE_IS_POD | LV2_STATE_IS_PORTABLE);
}

static LV2_State_Status restore(LV2_Handle instance, LV2_State_Retrieve_Function retrieve,
                                LV2_State_Handle handle, uint32_t flags,
                                const LV2_Feature *const *features)
{
    (void)flags;
    (void)features;
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
    return LV2_STATE_SUCCESS;
}

const void *plugin_state_interface(void)
{
    static const LV2_State_Interface state = {save, restore};
    return &state;
}
