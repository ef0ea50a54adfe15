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

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fg_sound_config {
    double t0_s;          /* baseline N-wave half-duration T0, seconds */
    double r0_m;          /* baseline distance r0, metres */
    double ps0_pa;        /* peak pressure at r0, pascals */
    double sigma0;        /* stretch parameter (0.524, Wright 1983) */
    double t0_jitter;     /* per-segment T0 fluctuation, relative: T0 * (1 + u), |u| <= jitter */
    double return_stroke_speed_m_s; /* speed the return stroke climbs the channel */
    /* The line integral: a segment of half-length l radiates ps0 scaled by
     * l / ref_half_len_m, so a line sounds the same however finely it is
     * cut. The presets give their table 1 l (a segment there sounds as
     * ps0 says). 0: every segment radiates ps0 whatever its length (the
     * paper's literal form; a finer tree is louder). WM-wave model only. */
    double ref_half_len_m;
} fg_sound_config;

typedef enum fg_preset {
    FG_PRESET_SPARK_BALLS = 0, /* 2 cm gap, l = 1 mm, r0 = 5 cm, T0 = 30 us */
    FG_PRESET_PLASMA_BALL = 1, /* 20 cm filaments, l = 1 cm, r0 = 10 cm, T0 = 40 us */
    /* 5 km bolt, l = 1.5 m, r0 = 10 m, T0 = 2.5 ms: table 1's bolt
     * calibrated to measured thunder (docs/sound-model.md) */
    FG_PRESET_LIGHTNING = 2,
    FG_PRESET_LIGHTNING_TABLE1 = 3, /* the same bolt with table 1's T0 = 500 us */
    FG_PRESET_COUNT
} fg_preset;

/* The scale a preset's discharge is generated at (Matsuyama table 1; both
 * lightning presets share it). */
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

/* The preset's name ("spark_balls", "plasma_ball", "lightning",
 * "lightning_table1"), or NULL for
 * an unknown value; and the reverse lookup. [any-thread]
 * Errors (fg_preset_from_name): FG_ERR_NULL; FG_ERR_ARGUMENT unknown name. */
FG_API const char *fg_preset_name(fg_preset preset);
FG_API FG_NODISCARD fg_result fg_preset_from_name(const char *name, fg_preset *out);

/* The ranges fg_sound_config_check accepts (docs/limits.md gives the
 * reasons): T0 from a tenth of a microsecond (an N-wave shorter than that
 * has its energy above 1 MHz, beyond hearing and any output rate) to 0.1 s
 * (a 5 Hz wave); r0 up to 1 km; ps0 up to 1e7 Pa (100 atmospheres);
 * sigma0 up to 10 (Wright's 0.524 twenty times over); the return stroke
 * from 1e5 m/s (the stepped leader's pace, the slowest stage of a
 * discharge) to 3e8 m/s (light). */
#define FG_SOUND_MIN_T0_S 1e-7
#define FG_SOUND_MAX_T0_S 0.1
#define FG_SOUND_MAX_R0_M 1000.0
#define FG_SOUND_MAX_PS0_PA 1e7
#define FG_SOUND_MAX_SIGMA0 10.0
#define FG_SOUND_MIN_RETURN_STROKE_M_S 1e5
#define FG_SOUND_MAX_RETURN_STROKE_M_S 3e8

/* Checks every field: all finite; t0_s in [FG_SOUND_MIN_T0_S,
 * FG_SOUND_MAX_T0_S]; r0_m in (0, FG_SOUND_MAX_R0_M]; ps0_pa in
 * (0, FG_SOUND_MAX_PS0_PA]; sigma0 in [0, FG_SOUND_MAX_SIGMA0];
 * 0 <= t0_jitter < 1; return_stroke_speed_m_s in
 * [FG_SOUND_MIN_RETURN_STROKE_M_S, FG_SOUND_MAX_RETURN_STROKE_M_S];
 * ref_half_len_m >= 0.
 * [any-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT. */
FG_API FG_NODISCARD fg_result fg_sound_config_check(const fg_sound_config *config);

#ifdef __cplusplus
}
#endif

#endif
