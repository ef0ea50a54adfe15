/* The plugin's engines: one per layout variant, and in binaural one per
 * SOFA file, made off the audio thread (instantiate, the worker, restore). */
#include <stdio.h>
#include <string.h>

#include "plugin.h"
#include "sofa_hrir.h"

/* Where the listener stands: 1.7 m up, facing +y, +x on the right. */
static const fg_listener listener = {
    .position = {0, 0, 1.7}, .forward = {0, 1, 0}, .up = {0, 0, 1}};

int engine_slot_create(plugin *p, const char *sofa, char *err, size_t err_size)
{
    uint32_t slot = 0;
    while (slot < ENGINE_SLOTS && p->slots[slot].engine)
        slot++;
    if (slot == ENGINE_SLOTS) {
        snprintf(err, err_size, "%u engines still in use (swaps still playing out)",
                 ENGINE_SLOTS);
        return -1;
    }
    const plugin_variant *v = p->variant;
    fg_engine_config config = {.sample_rate_hz = p->rate_hz, .channels = p->channels,
                               .layout = v->layout, .ambisonic_order = v->ambisonic_order};
    sofa_hrirs hrirs = {0};
    if (v->layout == FG_LAYOUT_BINAURAL) {
        if (!sofa)
            sofa = SOFA_DEFAULT_FILE;
        if (strlen(sofa) >= SOFA_PATH_BYTES) {
            snprintf(err, err_size, "a SOFA path of %zu bytes, longer than the %u taken",
                     strlen(sofa), SOFA_PATH_BYTES - 1);
            return -1;
        }
        /* the responses at the host's rate, converted at load if need be */
        if (sofa_hrirs_read(sofa, p->rate_hz, &hrirs, err, err_size) != 0)
            return -1;
        config.hrirs = &hrirs.set;
    }
    fg_engine *engine;
    fg_result r = fg_engine_create(&config, &engine);
    sofa_hrirs_free(&hrirs); /* borrowed by create only */
    if (r == FG_OK) {
        r = fg_engine_set_listener(engine, &listener);
        if (r != FG_OK)
            fg_engine_destroy(engine);
    }
    if (r != FG_OK) {
        snprintf(err, err_size, "the engine at %.0f Hz: %s", p->rate_hz, fg_result_str(r));
        return -1;
    }
    p->slots[slot].engine = engine;
    snprintf(p->slots[slot].sofa, sizeof p->slots[slot].sofa, "%s",
             v->layout == FG_LAYOUT_BINAURAL ? sofa : "");
    return (int)slot;
}

void engine_slot_destroy(plugin *p, uint32_t slot)
{
    for (size_t note = 0; note < 128; note++)
        if (p->held[note] && p->held_slot[note] == slot)
            p->held[note] = 0;
    fg_engine_destroy(p->slots[slot].engine);
    p->slots[slot].engine = NULL;
    p->slots[slot].sofa[0] = '\0';
}
