/* fulgur — aerodynamic sound textures (Dobashi, Yamamoto & Nishita 2003).
 *
 * An object in a flow sheds vortices; the force they leave on it radiates
 * as a compact dipole, p(q, t) = (q - o) . g(t - r/c) / (4 pi c r^2) with
 * g = dF/dt (the paper's eqs. 1-2). A texture is g for one shape, computed
 * once by CFD at a base speed v0, as a seamless loop, for each sampled flow
 * direction (2-D cross-sections) or each source along the object (3-D). At
 * run time a source at speed v replays it with texture time advancing at
 * v / v0 and the pressure scaled by fg_aero_pressure_scale.
 *
 * Frames. 2-D: the cross-section lies in its own (x, y) plane; a flow at
 * angle a comes from direction (cos a, sin a) (the free stream moves along
 * it). Component 0 is the drag, along the flow; component 1 the lift, along
 * the flow turned +90 degrees about +z. 3-D: the object's axis is +z (the
 * club runs from its handle end at z = 0 to its tip); the flow is along +x;
 * components are drag (x), lift (y) and axial (z).
 *
 * Units: SI. Samples are g in N/s: per metre of span for 2-D textures (a
 * source of span L multiplies by L), for the whole source in 3-D.
 *
 * Threads: generation is [sim-thread] work (minutes to hours; it may
 * allocate, and start threads of its own); a finished texture is immutable
 * and its getters are [any-thread]. */
#ifndef FULGUR_AERO_H
#define FULGUR_AERO_H

#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FG_AERO_MAX_DIRECTIONS 720
#define FG_AERO_MAX_SOURCES 256
#define FG_AERO_MAX_POLYGON 4096
#define FG_AERO_MAX_FRAMES (1u << 24) /* per direction and source */

typedef enum fg_aero_shape {
    FG_AERO_CIRCLE = 1,    /* 2-D: a circular cylinder, diameter length_m */
    FG_AERO_RECTANGLE = 2, /* 2-D: length_m along x by height_m along y (a square prism) */
    FG_AERO_POLYGON = 3,   /* 2-D: any simple polygon, e.g. a blade's cross-section */
    FG_AERO_SPHERE = 4,    /* 3-D: diameter length_m */
    FG_AERO_CLUB = 5       /* 3-D: a tapered body of revolution with round ends, length_m
                              long, diameters diameter_m[0] (handle, z = 0) to [1] (tip) */
} fg_aero_shape;

/* Which level law the texture is played with (fg_aero_pressure_scale). */
typedef enum fg_aero_tone {
    FG_AERO_AEOLIAN = 0, /* vortex shedding from a body: pressure ∝ (v/v0)^3 */
    FG_AERO_CAVITY = 1   /* a flow over a hollow: pressure ∝ (v/v0)^2 */
} fg_aero_tone;

/* One sampled flow direction of a texture. */
typedef struct fg_aero_direction {
    double angle_rad;      /* the flow's angle in the body frame (2-D; 0 in 3-D) */
    double frontal_m;      /* the body's width across this flow (3-D: across x in y) */
    double frequency_hz;   /* the shedding frequency found in the lift, at v0; 0 when
                              the body does not shed (a quiet direction) */
    double strouhal;       /* frequency_hz * reference_m / speed_m_s */
    double lift_amplitude; /* half the peak-to-peak lift coefficient over the loop */
    double drag_mean;      /* mean drag coefficient (the coefficients are of
                              rho v0^2 / 2 times reference_m in 2-D, times the
                              frontal area in 3-D) */
    double transient_s;    /* start-up simulated and discarded before the loop */
    uint32_t periods;      /* whole shedding periods the loop holds (0 when quiet) */
    uint32_t frames;       /* loop length, samples */
    const float *samples;  /* [sources][frames][components], N/s */
} fg_aero_direction;

/* One source along a 3-D object (2-D textures have one, of unit span). */
typedef struct fg_aero_source {
    double position_m; /* along the axis, the middle of the source's span */
    double span_m;     /* the length of object it covers */
} fg_aero_source;

/* A texture as plain data: what fg_aero_texture_create validates and
 * copies, and what fg_aero_texture_get shows of its own copy. */
typedef struct fg_aero_texture_desc {
    fg_aero_shape shape;
    fg_aero_tone tone;
    uint32_t dims;            /* 2 or 3, as the shape implies */
    uint32_t components;      /* = dims */
    double length_m;          /* the shape's parameters, as in fg_aero_config */
    double height_m;
    double diameter_m[2];
    uint32_t polygon_vertices;
    const double *polygon_xy; /* [2 * polygon_vertices], counter-clockwise, centred on the
                                 area centroid */
    double reference_m;       /* D of Re and St */
    double speed_m_s;         /* v0 */
    double viscosity_m2_s;
    double density_kg_m3;
    double reynolds;          /* reference_m * speed_m_s / viscosity_m2_s */
    double sample_rate_hz;
    double cells_per_length;  /* grid resolution the texture was computed at */
    /* Symmetry of the cross-section, which maps any flow angle onto the
     * sampled ones: rotation_order n means turning the shape by 2 pi / n
     * leaves it unchanged (0: by any angle — circle, sphere, club); mirror
     * means it is symmetric about the line through its centre at
     * mirror_angle_rad. */
    uint32_t rotation_order;
    uint32_t mirror;
    double mirror_angle_rad;
    uint32_t sources;
    const fg_aero_source *source;       /* [sources] */
    uint32_t directions;
    const fg_aero_direction *direction; /* [directions], angles increasing */
} fg_aero_texture_desc;

typedef struct fg_aero_texture fg_aero_texture;

/* Validates d and makes a texture holding a copy of everything it points
 * to; d is not referenced afterwards. [sim-thread]
 * Errors: NULL (d, out, or an array d needs), ARGUMENT (an unknown shape or
 * tone; dims or components not the shape's; counts out of range — no
 * direction, more than FG_AERO_MAX_DIRECTIONS, sources not 1 in 2-D or
 * above FG_AERO_MAX_SOURCES, a polygon outside 3..FG_AERO_MAX_POLYGON,
 * frames 0 or above FG_AERO_MAX_FRAMES, periods 0 with a frequency;
 * non-positive lengths, speed,
 * viscosity, density or rate; reynolds not reference * speed / viscosity
 * within 1e-6; angles not increasing or outside the fundamental range of
 * the symmetry; spans not positive), NOT_FINITE (a NaN or infinite value
 * anywhere, samples included), NO_MEMORY. *out is written only on success. */
FG_API FG_NODISCARD fg_result fg_aero_texture_create(const fg_aero_texture_desc *d,
                                                     fg_aero_texture **out);

/* NULL is a no-op. [sim-thread] (no other call on t may be running) */
FG_API void fg_aero_texture_destroy(fg_aero_texture *t);

/* The texture's own description; every pointer in it is valid until
 * fg_aero_texture_destroy(t). [any-thread] */
FG_API const fg_aero_texture_desc *fg_aero_texture_get(const fg_aero_texture *t);

/* Where a flow at angle_rad (any value, body frame) reads the texture:
 * the two sampled directions around it after the symmetry maps the angle
 * into the sampled range, their weights (summing to 1), and the sign the
 * lift component takes (-1 when the mapping mirrored the flow). Sources
 * and components stay as stored. [any-thread], wait-free: it may be called
 * from the audio thread. */
typedef struct fg_aero_lookup {
    uint32_t index[2];
    float weight[2];
    float lift_sign;
} fg_aero_lookup;
FG_API void fg_aero_texture_lookup(const fg_aero_texture *t, double angle_rad,
                                   fg_aero_lookup *out);

/* The factor on the texture's samples for a source at speed v (m/s):
 * (v / v0)^3 for aeolian tones, (v / v0)^2 for cavity tones. The paper's
 * eq. 3 writes v^6 and v^4: those are the intensity laws (Phillips 1956);
 * the force is rho v^2 D L C(t v / D) / 2, so g = dF/dt goes as v^3. 0 for
 * v <= 0 or not finite. [any-thread], wait-free. */
FG_API double fg_aero_pressure_scale(const fg_aero_texture *t, double speed_m_s);

/* What to compute. Zero means the default for every field. */
typedef struct fg_aero_config {
    fg_aero_shape shape;
    fg_aero_tone tone;
    double length_m;          /* circle, sphere: diameter; rectangle: along x; club: length */
    double height_m;          /* rectangle: along y (0: a square) */
    double diameter_m[2];     /* club: at the handle and at the tip */
    const double *polygon_xy; /* polygon: [2 * polygon_vertices] (x, y) in metres, either
                                 winding, any placement (it is centred on its centroid) */
    uint32_t polygon_vertices;
    double reference_m;       /* D of Re, St and the grid; 0: the diameter (circle, sphere),
                                 the width across the flow at angle 0 (rectangle, polygon),
                                 the larger diameter (club) */
    double speed_m_s;         /* v0, required */
    double viscosity_m2_s;    /* 0: air, 1.5e-5 */
    double density_kg_m3;     /* 0: air, 1.204 */
    double cells_per_length;  /* cells across reference_m; 0: 32 in 2-D, 12 in 3-D */
    double sample_rate_hz;    /* 0: 16 samples per reference_m / speed_m_s (16 kHz for
                                 1 cm at 10 m/s) */
    double seconds;           /* loop length at v0; 0: 24 shedding periods */
    double transient_s;       /* least start-up to discard; 0: 60 reference_m / speed_m_s
                                 (2-D; 30 in 3-D), longer until the lift amplitude settles */
    double max_transient_s;   /* give up when shedding has not settled by then; 0: 5x
                                 the least transient */
    const double *directions_rad; /* the flow angles to sample; NULL: every
                                     direction_step_rad over the symmetry's range */
    uint32_t direction_count;
    double direction_step_rad;    /* 0: 5 degrees */
    uint32_t sources;         /* club: sources along the axis; 0: one per 3 mean diameters
                                 (the correlation length); 1 for the other shapes */
    uint32_t threads;         /* directions computed at once; 0: 1 */
    double domain[3];         /* upstream, downstream and lateral half-width of the box,
                                 in reference_m; 0: 10, 15, 6 (2-D) and 4, 8, 3 (3-D) */
    double cfl;               /* free-stream Courant number of the flow steps; 0: 0.5 */
} fg_aero_config;

/* What fg_aero_config_check found wrong: which field, and for a polygon
 * which vertices; for a message that names it. */
typedef enum fg_aero_field {
    FG_AERO_FIELD_NONE = 0,
    FG_AERO_FIELD_SHAPE,
    FG_AERO_FIELD_TONE,
    FG_AERO_FIELD_SIZE,          /* length_m, height_m or diameter_m for the shape */
    FG_AERO_FIELD_POLYGON,       /* see fg_aero_check.polygon */
    FG_AERO_FIELD_REFERENCE,
    FG_AERO_FIELD_SPEED,
    FG_AERO_FIELD_VISCOSITY,
    FG_AERO_FIELD_DENSITY,
    FG_AERO_FIELD_CELLS,         /* cells_per_length: 4..1024 */
    FG_AERO_FIELD_RATE,          /* below limit: 8 samples a period at St 0.2, or above 1e7 */
    FG_AERO_FIELD_SECONDS,
    FG_AERO_FIELD_TRANSIENT,
    FG_AERO_FIELD_MAX_TRANSIENT, /* below transient_s */
    FG_AERO_FIELD_DIRECTIONS,    /* index: the direction */
    FG_AERO_FIELD_STEP,          /* below 0.1 degree */
    FG_AERO_FIELD_SOURCES,       /* above FG_AERO_MAX_SOURCES, or not a club */
    FG_AERO_FIELD_THREADS,       /* above 64 */
    FG_AERO_FIELD_DOMAIN,
    FG_AERO_FIELD_CFL,           /* above 4 */
    FG_AERO_FIELD_GRID           /* the box would have limit cells, above 2^27 */
} fg_aero_field;

typedef enum fg_aero_polygon_fault {
    FG_AERO_POLYGON_OK = 0,
    FG_AERO_POLYGON_COUNT,      /* fewer than 3 or more than FG_AERO_MAX_POLYGON vertices */
    FG_AERO_POLYGON_NOT_FINITE, /* vertex index */
    FG_AERO_POLYGON_REPEATED,   /* vertex index is vertex index - 1 (or the last) again */
    FG_AERO_POLYGON_CROSSING,   /* edges index and other (from vertex i to i + 1) meet */
    FG_AERO_POLYGON_NO_AREA     /* all on a line */
} fg_aero_polygon_fault;

typedef struct fg_aero_check {
    fg_aero_field field;
    fg_aero_polygon_fault polygon;
    uint32_t index, other;
    double limit;
} fg_aero_check;

/* Checks c as fg_aero_generate would, without computing anything, and
 * says which field is wrong in *why (may be NULL). [any-thread]
 * Errors: as fg_aero_generate's NULL, ARGUMENT and NOT_FINITE. */
FG_API FG_NODISCARD fg_result fg_aero_config_check(const fg_aero_config *c, fg_aero_check *why);

typedef enum fg_aero_phase {
    FG_AERO_TRANSIENT = 0, /* starting the flow, to be discarded */
    FG_AERO_RECORDING = 1, /* the loop's force being recorded */
    FG_AERO_DONE = 2
} fg_aero_phase;

typedef struct fg_aero_progress {
    uint32_t directions;      /* to compute */
    uint32_t directions_done;
    uint32_t direction;       /* the one most recently advanced */
    fg_aero_phase phase;      /* of that direction */
    double simulated_s;       /* flow time that direction has simulated */
    double fraction;          /* of the whole job, 0..1 (an estimate while transients run) */
    double cells;             /* grid cells per flow */
} fg_aero_progress;

/* Called about ten times a second from the thread that called
 * fg_aero_generate; must not call back into fulgur. */
typedef void (*fg_aero_progress_fn)(const fg_aero_progress *p, void *user);

/* Computes a texture: for each direction (2-D) or once (3-D), an
 * incompressible flow past the still body from rest, the inflow v0 on the
 * upstream face, the start-up discarded, then the force on the body (on
 * each source's part in 3-D) recorded at the texture rate, a loop of a
 * whole number of shedding periods cut and cross-faded, and g = dF/dt.
 * [sim-thread]; blocks until done (seconds to hours: see bench/results/
 * aero_precompute.md); progress may be NULL.
 * A direction in which the body does not shed by max_transient_s (a
 * streamlined section, Re below 47) is quiet: frequency 0, the steady
 * force's small fluctuation looped.
 * Errors: NULL (c, out, or the polygon), ARGUMENT (an unknown shape or
 * tone; a length, diameter, speed, rate, duration or count out of range; a
 * polygon with fewer than 3 or more than FG_AERO_MAX_POLYGON vertices,
 * repeated vertices, crossing edges or no area; a club whose diameters
 * exceed its length; a grid above 2^27 cells: fg_aero_config_check says
 * which), NOT_FINITE (a NaN or infinite value), NOT_CONVERGED (the flow
 * blew up), NO_MEMORY. *out is written only on success. */
FG_API FG_NODISCARD fg_result fg_aero_generate(const fg_aero_config *c,
                                               fg_aero_progress_fn progress, void *user,
                                               fg_aero_texture **out);

#ifdef __cplusplus
}
#endif

#endif
