/* The kinds of source every engine holds. A new kind of source (a model
 * that is not a discharge) adds its line here; its public post function,
 * its fg_source_ops and its storage live in its own folder. */
#include "source_internal.h"
#include "aero/aero_voice_internal.h"
#include "fire/fire_voice_internal.h"
#include "sound/discharge_internal.h"

const fg_source_kind *const fg_builtin_kinds[] = {
    &fg_discharge_kind,
    &fg_aero_kind,
    &fg_fire_kind,
};

const size_t fg_builtin_kind_count = sizeof fg_builtin_kinds / sizeof fg_builtin_kinds[0];
