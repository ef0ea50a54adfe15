/* fulgur — what the air does between a discharge and the ear.
 *
 * Every effect is off in a zeroed struct (a "pure" render in free, still
 * air), and each has a physical parameter whose zero means its default once
 * the effect is switched on. They apply per discharge, at post time where
 * they can (travel times, the shadow zone, the ground image) and on the audio
 * thread only in bounded form (a few filter buses shared by all voices,
 * whatever their segment count).
 */
#ifndef FULGUR_PROPAGATION_H
#define FULGUR_PROPAGATION_H

#include "fulgur/defs.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fg_absorption {
    FG_ABSORPTION_OFF = 0,
    /* ISO 9613-1 for the engine's air: each ear's signal passes through
     * FG_ABSORPTION_BANDS distance-band buses, whose minimum-phase IIRs
     * are fitted to their centre distances (10 m to 30 km, 1.2 apart);
     * each source is split between the two bands around its distance, so
     * the attenuation follows alpha(f) d within 1 dB for 63 Hz - 4 kHz at
     * 100 m - 20 km, and stays at least 80 dB down where the standard's is
     * deeper. The first discharge posted with it designs the filters on
     * the sim thread, once per engine (about 1 s). */
    FG_ABSORPTION_ISO9613 = 1,
    /* Abe et al.'s fixed alternative: a 200 Hz low-pass FIR of order 51 on
     * every source farther than abe_fir_distance_m. */
    FG_ABSORPTION_ABE_FIR = 2
} fg_absorption;

#define FG_ABSORPTION_BANDS 45

typedef struct fg_propagation_config {
    /* Refraction (Glassner): sound travels on circular arcs of this radius;
     * an ear z_e high at horizontal distance D sees no source below the
     * tangent ray (D - sqrt(2 R z_e))^2 / 2R, and hears those below it
     * through the creeping wave of the shadow zone, weaker by 4.1 dB per
     * km of shadow at R = 55 km. 0 = straight rays; else 20 km .. 200 km
     * (a storm: 55 km). */
    double refraction_radius_m;
    /* Turbulence: a smooth, seeded travel-time offset along the channel of
     * at most this many seconds (0 = off; 2 ms is a windy storm's), varying
     * over the correlation length (0 = 50 m; else at least
     * FG_TURBULENCE_MIN_LENGTH_M). */
    double turbulence_s;
    double turbulence_length_m;
    fg_absorption absorption;
    double abe_fir_distance_m;  /* FG_ABSORPTION_ABE_FIR: 0 = 1000 m */
    /* Ground reflection: an image source below z = 0 with this pressure
     * reflection coefficient, (0, 1]; 0 = off. Doubles the events a
     * discharge holds. */
    double ground_reflection;
    /* Head shadow: non-zero adds an interaural level difference at high
     * frequencies, up to -10 dB for a source straight behind the head on
     * the far side, on top of the per-ear delays. */
    int head_shadow;
} fg_propagation_config;

/* Refraction radii accepted when refraction is on, and a storm's. */
#define FG_REFRACTION_MIN_M 20e3
#define FG_REFRACTION_MAX_M 200e3
#define FG_REFRACTION_STORM_M 55e3

/* Defaults a host can offer when an effect is switched on. */
#define FG_TURBULENCE_DEFAULT_S 0.002
#define FG_TURBULENCE_DEFAULT_LENGTH_M 50.0
/* The shortest correlation length: the atmosphere's smallest eddies (the
 * Kolmogorov scale) are about a millimetre; it also keeps every lattice
 * coordinate of the noise (position / length) within an int64_t. */
#define FG_TURBULENCE_MIN_LENGTH_M 1e-3
#define FG_ABE_FIR_DEFAULT_DISTANCE_M 1000.0
#define FG_GROUND_DEFAULT_REFLECTION 0.9

/* Checks every field (finite; radius 0 or within the range above;
 * turbulence >= 0 and < 1 s, length 0 or >= FG_TURBULENCE_MIN_LENGTH_M; a
 * known absorption mode; Abe distance >= 0; reflection in [0, 1]) and
 * writes to *out the values a discharge posted with *in is rendered with:
 * the parameters of the effects that are on, with their zeros replaced by
 * the defaults above.
 * *out is written only on success and may be in. [any-thread]
 * Errors: FG_ERR_NULL; FG_ERR_NOT_FINITE; FG_ERR_ARGUMENT. */
FG_API FG_NODISCARD fg_result fg_propagation_config_resolve(const fg_propagation_config *in,
                                                            fg_propagation_config *out);

#ifdef __cplusplus
}
#endif

#endif
