/* fulgur — the sound of fire (Chadwick & James, "Animating Fire with
 * Sound", SIGGRAPH 2011). docs/fire-sound.md gives the equations as built.
 *
 * Three objects, all of the simulation side (nothing here runs on the
 * audio thread; the fire voice, fulgur/fire_voice.h, plays the result, streamed
 * through an SPSC sample ring):
 *
 *   fg_flame_front  the flame front of one simulation step and its flux
 *                   I(t) = integral over S of u . n dS (eqs. 2-9): the burn
 *                   field reconstructed with the cubic B-spline of eqs. 7-8,
 *                   its iso-surface by marching cubes, one-point quadrature
 *                   per triangle with the velocity at the centroid.
 *   fg_fire_sound   a flux series at the simulation rate in, audio out,
 *                   streaming: p = dI/dt through the Mitchell-Netravali
 *                   filter (eqs. 10-11), the 30 Hz high-pass (section 6),
 *                   then spectral bandwidth extension (section 4,
 *                   Algorithm 1) or sound texture synthesis (section 5).
 *                   A game may feed it the flux of its own flame
 *                   simulation instead of fg_flame_front's.
 *   fg_fire_texture the training of the texture synthesis (section 5): the
 *                   Gaussian pyramid of a training clip, its dictionaries of
 *                   feature windows and their kd-trees. Read-only once made:
 *                   any number of fire sounds, on any threads, may share it.
 *
 * The fire voice (fulgur/fire_voice.h) plays it: fg_fire_feed owns one
 * fg_fire_sound on the sim thread, calls fg_fire_sound_process with each
 * frame's new flux samples and pushes the frames into the voice's SPSC
 * sample ring, which the render reads fg_fire_sound_latency_s (plus the
 * ring's lead) behind the flux (underruns counted, never waited for).
 *
 * Units: metres, seconds, m/s; the flux I in m^3/s; the sound p = dI/dt in
 * m^3/s^2. The paper drops the constant factor of eq. 3 (which a distance
 * 1/(4 pi r) and (gamma - 1)/c0^2 would turn into pascals); so do we here:
 * the fire feed scales p to pascals at 1 m (fg_fire_pascals_per_flux_rate).
 */
#ifndef FULGUR_FIRE_H
#define FULGUR_FIRE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------
 * The flame front and its flux
 * ------------------------------------------------------------------- */

#define FG_FLAME_MIN_CELLS 2
#define FG_FLAME_MAX_CELLS 512
#define FG_FLAME_MAX_SUBDIVISION 4
/* Burn values and iso levels beyond this magnitude are refused: the
 * spline's sums must not overflow. */
#define FG_FLAME_MAX_BURN 1e300
/* The default refusal limit for a front's scratch memory. */
#define FG_FLAME_DEFAULT_MAX_BYTES ((size_t)1 << 30)

typedef struct fg_flame_front fg_flame_front;

/* The simulation's grid: size[0] x size[1] x size[2] cubic cells of edge
 * cell_m, cell (0, 0, 0) having its low corner at origin_m. Scalars (the
 * burn field, a collocated velocity) live at cell centres,
 * origin_m + (i + 1/2, j + 1/2, k + 1/2) cell_m, and cell (i, j, k) is
 * element i + size[0] * (j + size[1] * k) of their arrays (x fastest). */
typedef struct fg_flame_grid {
    int size[3];        /* cells per axis, FG_FLAME_MIN_CELLS .. FG_FLAME_MAX_CELLS */
    double origin_m[3];
    double cell_m;      /* > 0 */
} fg_flame_grid;

typedef struct fg_flame_front_config {
    fg_flame_grid grid;
    double iso_level;   /* the burn value on the front; > 0, no default (the burn
                           field's units are the solver's) */
    int subdivision;    /* marching-cubes samples per cell edge, 1 .. 4: the
                           B-spline is evaluated on a lattice subdivision times
                           finer than the grid; 0 means 1 */
    size_t max_bytes;   /* refuse grids needing more scratch; 0 means
                           FG_FLAME_DEFAULT_MAX_BYTES */
} fg_flame_front_config;

typedef enum fg_velocity_layout {
    /* Staggered (MAC): u[a] lives on the faces normal to axis a, at
     * origin_m + cell_m * (the face's index on axis a, the cell centre on the
     * other two); u[0] has (size[0] + 1) * size[1] * size[2] values, element
     * i + (size[0] + 1) * (j + size[1] * k); likewise u[1], u[2] with one more
     * on their own axis. The layout of the engine's fluid core. */
    FG_VELOCITY_MAC = 0,
    /* Collocated: all three components at the cell centres, as the scalars. */
    FG_VELOCITY_COLLOCATED = 1
} fg_velocity_layout;

/* One step's velocity, borrowed for the call. Sampled by trilinear
 * interpolation; points beyond the outermost samples take the nearest
 * sample's value (the front may reach 1.5 cells past the grid, below). */
typedef struct fg_flame_velocity {
    fg_velocity_layout layout;
    const double *u_m_s[3];
} fg_flame_velocity;

typedef struct fg_flame_flux {
    double flux_m3_s;   /* I = sum over triangles of u(centroid) . (vector area) */
    double area_m2;     /* the front's area */
    size_t triangles;
} fg_flame_flux;

/* The scratch bytes a front of this configuration allocates (defaults
 * filled in; the triangle list, which grows with the surface to 72 bytes
 * a triangle, twice over, comes on top), or 0 if the grid is outside its
 * limits. [any-thread] */
FG_API size_t fg_flame_front_memory_bytes(const fg_flame_front_config *config);

/* Creates a front for one grid. *out is the caller's until
 * fg_flame_front_destroy. [main-thread] or [sim-thread]
 * Errors: FG_ERR_NULL config or out; FG_ERR_NOT_FINITE origin, cell or iso;
 * FG_ERR_ARGUMENT a size outside FG_FLAME_MIN_CELLS .. FG_FLAME_MAX_CELLS,
 * cell_m <= 0, iso_level <= 0 or > FG_FLAME_MAX_BURN, subdivision outside
 * 0 .. 4;
 * FG_ERR_CAPACITY the scratch would exceed max_bytes; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_flame_front_create(const fg_flame_front_config *config,
                                                    fg_flame_front **out);

/* Frees the front; NULL is a no-op. [main-thread] or [sim-thread] */
FG_API void fg_flame_front_destroy(fg_flame_front *front);

/* The configuration in use, defaults filled in. [sim-thread] */
FG_API void fg_flame_front_get_config(const fg_flame_front *front, fg_flame_front_config *out);

/* One step's flame front and flux. burn[] holds the burn field B (the rate
 * of fuel consumption, any units) at the cell centres; B is taken as 0
 * outside the grid. The front is the iso_level iso-surface of
 *   B~(x) = sum_ijk phi((x - x_i)/h) phi((y - y_j)/h) phi((z - z_k)/h) B_ijk
 * with phi the cubic B-spline of eq. 8, used as the paper does: the
 * samples are the spline's coefficients (not prefiltered), so B~ smooths B
 * and need not pass through it. B~ vanishes 2 cells beyond the outermost
 * centres, so the front is always a closed surface, oriented with its
 * normal pointing out of the burning region (B~ > iso_level); by the
 * divergence theorem I is then the integral of div u over that region.
 * The triangles are kept until the next successful call.
 * [sim-thread]: allocates only when a surface has more triangles than any
 * before it.
 * Errors: FG_ERR_NULL front, burn, velocity, a component pointer or out;
 * FG_ERR_ARGUMENT an unknown layout, a burn value beyond FG_FLAME_MAX_BURN;
 * FG_ERR_NOT_FINITE a burn value, a velocity sampled on the front, or a
 * flux or area that overflows (the front and *out are then unchanged: the
 * last good surface stays); FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_flame_front_flux(fg_flame_front *front, const double *burn,
                                                  const fg_flame_velocity *velocity,
                                                  fg_flame_flux *out);

/* The last surface: *xyz_m points to 9 doubles per triangle (three
 * vertices, counter-clockwise seen from outside the burning region), owned
 * by the front and valid until its next fg_flame_front_flux or destroy.
 * [sim-thread]
 * Errors: FG_ERR_NULL an argument. */
FG_API FG_NODISCARD fg_result fg_flame_front_triangles(const fg_flame_front *front,
                                                       const double **xyz_m, size_t *triangles);

/* ---------------------------------------------------------------------
 * Texture training (section 5)
 * ------------------------------------------------------------------- */

/* A training clip shorter than this is refused (the coarsest level of a
 * 6-level pyramid then holds about 1400 samples at 44.1 kHz). */
#define FG_FIRE_TRAINING_MIN_S 1.0
#define FG_FIRE_TRAINING_MAX_S 600.0
/* The default refusal limit for a texture's dictionaries and trees. */
#define FG_FIRE_TEXTURE_DEFAULT_MAX_BYTES ((size_t)1 << 30)
/* The procedural clip fg_fire_texture_create_default trains on. */
#define FG_FIRE_DEFAULT_TRAINING_S 8.0

typedef struct fg_fire_texture fg_fire_texture;

/* Zero in any field means the default in its comment (the paper's). */
typedef struct fg_fire_texture_config {
    const float *samples;     /* the training clip p_T, mono; borrowed for the call */
    size_t frames;
    double sample_rate_hz;    /* the clip's rate, which must be the synthesis rate:
                                 resample first (host/common does) */
    int levels;               /* pyramid levels L: 6; 2 .. 8 */
    int half_width;           /* window half-width h, samples: 4; 1 .. 16 */
    int feature_multiplier;   /* h_f: 3; 1 .. 8 */
    double epsilon;           /* approximate nearest neighbours within (1 + eps)
                                 of the nearest: 1; >= 0, and < 0 means 0 (exact) */
    size_t max_bytes;         /* 0 means FG_FIRE_TEXTURE_DEFAULT_MAX_BYTES */
} fg_fire_texture_config;

typedef struct fg_fire_texture_info {
    fg_fire_texture_config config;  /* as used; samples is NULL (not kept) */
    int feature_dims;               /* 46 with the defaults: see docs/fire-sound.md */
    size_t dictionary[8];           /* |D_l| for l = 1 .. L-1 (index l - 1) */
    size_t bytes;                   /* memory held */
} fg_fire_texture_info;

/* Trains a texture on a clip: builds G_T, the dictionaries D_1 .. D_{L-1}
 * and their kd-trees, and the amplitude distribution F_T of G_T(L).
 * Seconds of work for a clip of a few seconds. *out is the caller's until
 * fg_fire_texture_destroy, which must come after every fire sound using it.
 * [main-thread] or [sim-thread]
 * Errors: FG_ERR_NULL config, samples or out; FG_ERR_SAMPLE_RATE a rate
 * outside 8 kHz .. 384 kHz; FG_ERR_ARGUMENT a clip shorter than
 * FG_FIRE_TRAINING_MIN_S or longer than FG_FIRE_TRAINING_MAX_S, a
 * parameter out of range, or a clip that is silent throughout its coarsest
 * level; FG_ERR_NOT_FINITE a sample; FG_ERR_CAPACITY more than max_bytes;
 * FG_ERR_NO_MEMORY. Nothing is created on error. */
FG_API FG_NODISCARD fg_result fg_fire_texture_create(const fg_fire_texture_config *config,
                                                     fg_fire_texture **out);

/* Trains on the project's procedural clip (fg_fire_training_clip, seed 1,
 * FG_FIRE_DEFAULT_TRAINING_S long) at sample_rate_hz. We ship no recording:
 * texture-synthesised fire is then only as real as that clip.
 * [main-thread] or [sim-thread]
 * Errors: FG_ERR_NULL out; FG_ERR_SAMPLE_RATE; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_fire_texture_create_default(double sample_rate_hz,
                                                             fg_fire_texture **out);

/* Frees the texture; NULL is a no-op. [main-thread] */
FG_API void fg_fire_texture_destroy(fg_fire_texture *texture);

/* [any-thread] */
FG_API void fg_fire_texture_get_info(const fg_fire_texture *texture, fg_fire_texture_info *out);

/* The procedural training clip: frames samples at sample_rate_hz of a
 * made-up fire (power-law roar with a slow random envelope, Poisson
 * crackles with heavy-tailed amplitudes, a faint hiss; docs/fire-sound.md
 * gives the recipe), peak about 0.5. Same seed, same samples.
 * [any-thread]: allocates scratch.
 * Errors: FG_ERR_NULL out with frames > 0; FG_ERR_SAMPLE_RATE;
 * FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_fire_training_clip(double sample_rate_hz, uint64_t seed,
                                                    float *out, size_t frames);

/* ---------------------------------------------------------------------
 * Flux series in, audio out
 * ------------------------------------------------------------------- */

typedef enum fg_fire_extension {
    FG_FIRE_BANDWIDTH_EXTENSION = 0, /* section 4: power-law noise above f_cut */
    FG_FIRE_TEXTURE = 1,             /* section 5: details from a training clip */
    FG_FIRE_LOW_ONLY = 2             /* section 3 alone: p = dI/dt, high-passed */
} fg_fire_extension;

/* Spectral bandwidth extension, table 1. Zero means the default; the
 * frequency defaults are table 1's for a 360 Hz simulation and scale with
 * sim_rate_hz / 360 (f_cut is the simulation's Nyquist frequency). */
typedef struct fg_fire_bwe_config {
    double alpha;            /* power law P(f) ~ f^-alpha: 3.0 (section 6); 0.5 .. 6 */
    double f_cut_hz;         /* 180 */
    double sigma_cut_hz;     /* width of the Gaussian weight g of eq. 13: 10 */
    double blend_low_hz;     /* F_low falls linearly from 1 to 0 between these: 165 */
    double blend_high_hz;    /* 195 */
    int half_window_frames;  /* w_H: 500 at 44.1 kHz, scaled with the rate */
    int beta_half_window_frames; /* A, the half-width of the window on which eq. 13
                                    is solved for each w_H window, w_H .. 524288:
                                    sample_rate / sigma_cut (100 ms), which resolves
                                    the Gaussian g; w_H, table 1's own choice, has
                                    (A - w_H) frames less latency but puts the band
                                    power near f_cut off by up to 2 dB (measured;
                                    docs/fire-sound.md) */
    uint64_t seed;           /* the noise's random phases; any value */
} fg_fire_bwe_config;

typedef struct fg_fire_sound_config {
    double sample_rate_hz;    /* audio rate: 48000; 8 kHz .. 384 kHz */
    double sim_rate_hz;       /* flux samples per second: 360; 10 .. sample_rate_hz / 4 */
    double highpass_hz;       /* the high-pass on p (2nd-order Butterworth): 30;
                                 negative: none */
    fg_fire_extension extension;
    fg_fire_bwe_config bwe;   /* FG_FIRE_BANDWIDTH_EXTENSION */
    const fg_fire_texture *texture; /* FG_FIRE_TEXTURE: borrowed, must outlive the
                                       sound and be trained at sample_rate_hz */
    double level_history_s;   /* FG_FIRE_TEXTURE: how far back the input's amplitude
                                 distribution F_S of eq. 17 reaches: 10; at most 3600 */
} fg_fire_sound_config;

typedef struct fg_fire_sound_stats {
    uint64_t flux_steps;      /* flux samples taken */
    uint64_t frames;          /* audio frames returned */
    uint64_t windows;         /* bandwidth extension: windows blended */
    uint64_t beta_degenerate; /* windows whose noise had no power near f_cut: beta = 0 */
    uint64_t beta_no_root;    /* windows where eq. 13 had no real root >= 0: beta at
                                 the residual's least (impossible with F_low <= 1) */
    double last_beta;
    uint64_t texture_queries; /* texture: nearest-neighbour searches */
    uint64_t texture_silent;  /* texture: windows of silent input (output 0) */
} fg_fire_sound_stats;

typedef struct fg_fire_sound fg_fire_sound;

/* Flux values beyond this magnitude are refused (a fire of 10^4 m^2 at
 * 10 m/s has 10^5 m^3/s): p = dI/dt must stay far inside float's range. */
#define FG_FIRE_MAX_FLUX_M3_S 1e12

/* Creates a stream. Audio frame n is the sound at t = n / sample_rate_hz on
 * the flux's clock, where flux sample i is I at t = i / sim_rate_hz; before
 * flux sample 0 the flux is taken as constant (p = 0). *out is the
 * caller's until fg_fire_sound_destroy. [main-thread] or [sim-thread]
 * Errors: FG_ERR_NULL config or out; FG_ERR_NOT_FINITE a parameter;
 * FG_ERR_SAMPLE_RATE sample_rate_hz outside 8 kHz .. 384 kHz;
 * FG_ERR_ARGUMENT sim_rate_hz outside 10 .. sample_rate_hz / 4, an unknown
 * extension, a bandwidth-extension parameter out of range (alpha, f_cut
 * and the blend range must satisfy 0 < blend_low < f_cut < blend_high <
 * sample_rate / 2), FG_FIRE_TEXTURE without a texture or with one trained
 * at another rate, level_history_s outside (0, 3600]; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_fire_sound_create(const fg_fire_sound_config *config,
                                                   fg_fire_sound **out);

/* Frees the stream; NULL is a no-op. [main-thread] or [sim-thread] */
FG_API void fg_fire_sound_destroy(fg_fire_sound *sound);

/* The configuration in use, defaults filled in. [sim-thread] */
FG_API void fg_fire_sound_get_config(const fg_fire_sound *sound, fg_fire_sound_config *out);

/* How far the audio lags the flux: frame n is returned at the latest by
 * the call that brings the flux up to t = n / sample_rate_hz + latency_s
 * (and at most a simulation step and one extension window sooner). It is
 * the Mitchell-Netravali filter's 2 simulation steps plus the extension's
 * own: bandwidth extension M/2 + A - 1 frames (M its FFT length, 4096 at
 * 44.1 and 48 kHz; A the eq. 13 window: 146 ms at 44.1 kHz with the
 * default A, 58 ms with A = w_H), texture synthesis 869 frames at the
 * paper's parameters (19.7 ms at 44.1 kHz). [any-thread] */
FG_API double fg_fire_sound_latency_s(const fg_fire_sound *sound);

/* The most audio frames fg_fire_sound_process can return for `steps` flux
 * samples (a bound; SIZE_MAX where it would overflow). [any-thread] */
FG_API size_t fg_fire_sound_max_frames(const fg_fire_sound *sound, size_t steps);

/* Takes flux[0 .. steps) (I at the simulation rate, m^3/s, the steps that
 * follow those already taken) and writes the audio frames they complete to
 * out[0 .. *frames) (p, m^3/s^2, float). A stream split into calls
 * anywhere gives the same frames as one call. [sim-thread]: never
 * allocates; the cost is the extension's (docs/fire-sound.md has figures).
 * Errors: FG_ERR_NULL sound or frames, flux with steps > 0, out with
 * capacity > 0; FG_ERR_NOT_FINITE a flux value; FG_ERR_ARGUMENT a flux
 * beyond FG_FIRE_MAX_FLUX_M3_S, or the stream was drained; FG_ERR_CAPACITY
 * capacity below fg_fire_sound_max_frames(steps). On error nothing is
 * taken and *frames is 0. */
FG_API FG_NODISCARD fg_result fg_fire_sound_process(fg_fire_sound *sound, const double *flux_m3_s,
                                                    size_t steps, float *out, size_t capacity,
                                                    size_t *frames);

/* The frames fg_fire_sound_drain may need room for. [any-thread] */
FG_API size_t fg_fire_sound_drain_frames(const fg_fire_sound *sound);

/* Ends the stream: holds the flux at its last value long enough to return
 * every frame up to the time of the last flux sample taken, writing them
 * to out[0 .. *frames). The stream then takes nothing more (process and
 * drain answer FG_ERR_ARGUMENT) until fg_fire_sound_reset. [sim-thread]
 * Errors: FG_ERR_NULL sound or frames, out with capacity > 0;
 * FG_ERR_CAPACITY capacity below fg_fire_sound_drain_frames (nothing
 * done); FG_ERR_ARGUMENT already drained. */
FG_API FG_NODISCARD fg_result fg_fire_sound_drain(fg_fire_sound *sound, float *out,
                                                  size_t capacity, size_t *frames);

/* Back to the state just after create (same seed, same noise). [sim-thread] */
FG_API void fg_fire_sound_reset(fg_fire_sound *sound);

/* [sim-thread] */
FG_API void fg_fire_sound_get_stats(const fg_fire_sound *sound, fg_fire_sound_stats *out);

#ifdef __cplusplus
}
#endif

#endif
