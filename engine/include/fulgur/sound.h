/* fulgur — the parameters of the WM-wave sound model and the presets.
 *
 * One segment of half-length l radiates one WM-wave (Matsuyama eq. 5): the
 * N-wave of a point source integrated along a line. At distance r from the
 * segment (clamped to r >= r0) the N-wave has half-duration
 *   T  = T0 * sqrt(1 + sigma0 ln(r/r0))                       (eq. 4)
 * and peak pressure
 *   ps = r0 * ps0 / (r * sqrt(1 + sigma0 ln(r/r0)))           (eq. 3)
 * A segment seen broadside gives an N-wave of peak ps (our amplitude
 * convention; the paper leaves it arbitrary).
 */
#ifndef FULGUR_SOUND_H
#define FULGUR_SOUND_H

#include "fulgur/defs.h"
#include "fulgur/result.h"

typedef struct fg_sound_config {
    double t0_s;          /* baseline N-wave half-duration T0, seconds */
    double r0_m;          /* baseline distance r0, metres */
    double ps0_pa;        /* peak pressure at r0, pascals */
    double sigma0;        /* stretch parameter (0.524, Wright 1983) */
    double t0_jitter;     /* per-segment T0 fluctuation, relative: T0 * (1 + u), |u| <= jitter */
    double return_stroke_speed_m_s; /* speed the return stroke climbs the channel */
} fg_sound_config;

typedef enum fg_preset {
    FG_PRESET_SPARK_BALLS = 0, /* 2 cm gap, l = 1 mm, r0 = 5 cm, T0 = 30 us */
    FG_PRESET_PLASMA_BALL = 1, /* 20 cm filaments, l = 1 cm, r0 = 10 cm, T0 = 40 us */
    FG_PRESET_LIGHTNING = 2,   /* 5 km bolt, l = 1.5 m, r0 = 10 m, T0 = 500 us */
    FG_PRESET_COUNT
} fg_preset;

/* The scale a preset's discharge is generated at (Matsuyama table 1). */
typedef struct fg_preset_scale {
    double path_m;       /* typical length of the discharge path */
    double half_step_m;  /* segment half-length l */
} fg_preset_scale;

/* Fills *out with the sound parameters of a preset. [any-thread]
 * Errors: FG_ERR_NULL out; FG_ERR_ARGUMENT unknown preset. */
FG_API FG_NODISCARD fg_result fg_preset_sound(fg_preset preset, fg_sound_config *out);

/* Fills *out with the geometric scale of a preset. [any-thread]
 * Errors: FG_ERR_NULL out; FG_ERR_ARGUMENT unknown preset. */
FG_API FG_NODISCARD fg_result fg_preset_get_scale(fg_preset preset, fg_preset_scale *out);

/* The preset's name ("spark_balls", "plasma_ball", "lightning"), or NULL for
 * an unknown value; and the reverse lookup. [any-thread]
 * Errors (fg_preset_from_name): FG_ERR_NULL; FG_ERR_ARGUMENT unknown name. */
FG_API const char *fg_preset_name(fg_preset preset);
FG_API FG_NODISCARD fg_result fg_preset_from_name(const char *name, fg_preset *out);

/* Checks every field: all finite; t0_s, r0_m, ps0_pa > 0; sigma0 >= 0;
 * 0 <= t0_jitter < 1; return_stroke_speed_m_s > 0. [any-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT. */
FG_API FG_NODISCARD fg_result fg_sound_config_check(const fg_sound_config *config);

#endif
