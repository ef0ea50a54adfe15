/* fulgur — the sound of electric discharges. One include for the engine. */
#ifndef FULGUR_FULGUR_H
#define FULGUR_FULGUR_H

#include "fulgur/aero.h"
#include "fulgur/aero_object.h"
#include "fulgur/charges.h"
#include "fulgur/defs.h"
#include "fulgur/field_scene.h"
#include "fulgur/engine.h"
#include "fulgur/field.h"
#include "fulgur/fire.h"
#include "fulgur/fire_voice.h"
#include "fulgur/flame.h"
#include "fulgur/growth.h"
#include "fulgur/lightning.h"
#include "fulgur/propagation.h"
#include "fulgur/result.h"
#include "fulgur/sound.h"
#include "fulgur/tree.h"
#include "fulgur/version.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifdef __cplusplus
}
#endif

#endif
