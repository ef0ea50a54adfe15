/* One flow past the still body: the paper's set-up (section 5.2.2) on the
 * fluid core, run from rest until shedding has settled, then recorded.
 *
 * The box: the inflow v0 on the upstream face, an open face downstream
 * (p = 0, zero normal gradient: the paper's natural condition), free-slip
 * lateral faces. The paper leaves its lateral faces natural too; an open
 * lateral face (p = 0) lets the inflow leak out sideways before it reaches
 * the body, and then the answer depends on the upstream length: at Re 100
 * the Strouhal number fell from 0.168 to 0.157 as the inflow moved from 5
 * to 15 diameters upstream. Free-slip faces do not leak; their blockage
 * (D / width) raises St by about 2 % at 6 diameters either side.
 *
 * A body that does not shed (streamlined, or below Re 47) gets a quiet
 * direction: the record of its steady force, looped over the periods a
 * shedding body would have had, with frequency 0.
 *
 * Start-up: from rest; for the first 2 D / v0 the body's surface turns
 * (surface speed v0 / 2) to break the symmetry that would otherwise delay
 * shedding for hundreds of D / v0 on a symmetric grid. That part, and the
 * growth of the shedding, is discarded: the transient ends once at least
 * transient_s has passed and the lift's rms over its last three periods is
 * within 5 % of the three before. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aero_internal.h"
#include "fg_array.h"
#include "fluid/fluid_internal.h"

#define SPIN_TIME 2.0       /* in D / v0 */
#define SETTLE_PERIODS 3
#define SETTLE_TOLERANCE 0.05

/* A growing record of samples of sources * dims values. */
typedef struct series {
    double *v;
    size_t n, cap, width;
} series;

static int series_push(series *s, const double *values)
{
    double *grown = fg_array_grow(s->v, &s->cap, s->n + 1, s->width * sizeof(double), 1024);
    if (!grown)
        return -1;
    s->v = grown;
    memcpy(&s->v[s->n * s->width], values, s->width * sizeof(double));
    s->n++;
    return 0;
}

double fg_aero_box(const fg_aero_plan *p, const fg_aero_body *b, int cells[3], double origin[3])
{
    double h = p->cell_m, r = fg_aero_body_radius(b), d = p->reference_m;
    /* at least 2 D of clearance on the sides and upstream, 4 D downstream */
    double up = fmax(p->domain_m[0], r + 2.0 * d), down = fmax(p->domain_m[1], r + 4.0 * d);
    double lat = fmax(p->domain_m[2], r + 2.0 * d);
    double lo_z = -lat, hi_z = b->shape == FG_AERO_CLUB ? b->length_m + lat : lat;
    double n[3] = {ceil((up + down) / h), ceil(2.0 * lat / h),
                   p->dims == 3 ? ceil((hi_z - lo_z) / h) : 1.0};
    for (int a = 0; a < 3; a++)
        cells[a] = n[a] < 1 << 30 ? (int)n[a] : 1 << 30;
    origin[0] = -up;
    origin[1] = -lat;
    origin[2] = p->dims == 3 ? lo_z : 0.0;
    return n[0] * n[1] * n[2];
}

static fg_result make_fluid(const fg_aero_plan *p, fg_aero_body *b, fg_fluid **out)
{
    fg_fluid_config c = {
        .dims = p->dims,
        .cell_m = p->cell_m,
        .viscosity_m2_s = p->viscosity_m2_s,
        .density_kg_m3 = p->density_kg_m3,
        .boundary = {{FG_FLUID_INFLOW, FG_FLUID_OPEN},
                     {FG_FLUID_SLIP, FG_FLUID_SLIP},
                     {FG_FLUID_SLIP, FG_FLUID_SLIP}},
        .inflow_m_s = {p->speed_m_s, 0.0, 0.0},
        /* at Re 100 the texture (St, lift, drag, its spectrum to 0.1 dB) was
         * the same at 1e-6 and 1e-4, and 16 % faster at 1e-4 */
        .tolerance = 1e-4,
    };
    if (fg_aero_box(p, b, c.cells, c.origin_m) > FG_AERO_MAX_CELLS)
        return FG_ERR_ARGUMENT;
    fg_fluid *f;
    fg_result res = fg_fluid_create(&c, &f);
    if (res != FG_OK)
        return res;
    res = fg_fluid_set_solid(f, fg_aero_body_sdf, b);
    if (res != FG_OK) {
        fg_fluid_destroy(f);
        return res;
    }
    *out = f;
    return FG_OK;
}

/* The force on each source's part of the body: [sources][dims]. */
static void source_forces(const fg_aero_plan *p, const fg_aero_body *b, const fg_fluid *f,
                          double *out)
{
    for (uint32_t s = 0; s < p->sources; s++) {
        double lo[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, hi[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
        if (b->shape == FG_AERO_CLUB && p->sources > 1) {
            double span = b->length_m / p->sources;
            if (s > 0)
                lo[2] = s * span;
            if (s + 1 < p->sources)
                hi[2] = (s + 1) * span;
        }
        fg_fluid_force F;
        fg_fluid_solid_force(f, lo, hi, &F);
        for (int a = 0; a < p->dims; a++)
            out[(size_t)s * p->dims + a] = F.pressure_n[a] + F.viscous_n[a];
    }
}

/* The total lift of sample i of a series. */
static double lift_of(const fg_aero_plan *p, const series *s, size_t i)
{
    double l = 0.0;
    for (uint32_t k = 0; k < p->sources; k++)
        l += s->v[i * s->width + (size_t)k * p->dims + 1];
    return l;
}

static double rms_window(const double *x, size_t n)
{
    double m = 0.0, q = 0.0;
    for (size_t i = 0; i < n; i++)
        m += x[i];
    m /= (double)n;
    for (size_t i = 0; i < n; i++)
        q += (x[i] - m) * (x[i] - m);
    return sqrt(q / (double)n);
}

/* Has the lift settled? *period_s gets the period of the recent lift (0: no
 * shedding). */
static int settled(const fg_aero_plan *p, const series *s, double *lift, double *period_s,
                   double *rms)
{
    size_t n = s->n, tail = n / 2;
    for (size_t i = 0; i < n; i++)
        lift[i] = lift_of(p, s, i);
    /* the period of the recent half; the two windows at the very end */
    *period_s = fg_aero_dominant_period(lift + n - tail, tail, p->rate_hz, p->band_hz[0],
                                        p->band_hz[1]);
    *rms = 0.0;
    if (!(*period_s > 0.0))
        return 0;
    size_t w = (size_t)lround(SETTLE_PERIODS * *period_s * p->rate_hz);
    if (w < 8 || 2 * w > n)
        return 0;
    double r1 = rms_window(lift + n - w, w), r0 = rms_window(lift + n - 2 * w, w);
    *rms = r1;
    return fabs(r1 - r0) <= SETTLE_TOLERANCE * fmax(r0, r1);
}

static fg_result step(fg_fluid *f, const fg_aero_plan *p, fg_aero_watch *w)
{
    fg_result r = fg_fluid_step(f, p->dt_s, NULL);
    atomic_fetch_add_explicit(&w->steps, 1, memory_order_relaxed);
    /* an unconverged projection still takes the step; a blow-up ends the run */
    return r == FG_ERR_NOT_FINITE ? FG_ERR_NOT_CONVERGED : FG_OK;
}

/* From rest to settled shedding. On success *period_s is the shedding
 * period, or 0 when there is none. */
static fg_result transient(fg_fluid *f, const fg_aero_plan *p, const fg_aero_body *b,
                           fg_aero_watch *w, double *period_s)
{
    series s = {.width = (size_t)p->sources * p->dims};
    double *sample = malloc(s.width * sizeof(double));
    size_t most = (size_t)ceil(p->max_transient_s * p->rate_hz) + 4;
    double *lift = malloc(most * sizeof(double));
    fg_result r = sample && lift ? FG_OK : FG_ERR_NO_MEMORY;
    double spin_until = SPIN_TIME * p->reference_m / p->speed_m_s;
    double omega[3] = {0.0, 0.0, p->speed_m_s / p->reference_m};
    int spinning = 0;
    double next_check = p->transient_s, rms = 0.0, quiet = 1e-4 * 0.5 * p->density_kg_m3 *
                                                       p->speed_m_s * p->speed_m_s * p->area_m2;
    *period_s = 0.0;
    while (r == FG_OK) {
        double t = fg_fluid_time_s(f);
        int spin = t < spin_until;
        if (spin != spinning) {
            r = fg_fluid_set_solid_motion(f, NULL, spin ? omega : NULL, NULL);
            spinning = spin;
        }
        for (uint32_t k = 0; k < p->substeps && r == FG_OK; k++)
            r = step(f, p, w);
        if (r != FG_OK)
            break;
        source_forces(p, b, f, sample);
        if (s.n == most || series_push(&s, sample) != 0) {
            r = FG_ERR_NO_MEMORY; /* (most outlasts max_transient_s) */
            break;
        }
        t = fg_fluid_time_s(f);
        if (t < next_check && t < p->max_transient_s)
            continue;
        int done = settled(p, &s, lift, period_s, &rms);
        if (done)
            break;
        if (t >= p->max_transient_s) {
            /* unsettled but shedding (a chaotic wake): go on; no shedding
             * (a streamlined body, Re below 47): a quiet direction */
            if (!(rms > quiet))
                *period_s = 0.0;
            break;
        }
        next_check = t + (*period_s > 0.0 ? *period_s : p->reference_m / p->speed_m_s);
    }
    free(s.v);
    free(sample);
    free(lift);
    return r;
}

fg_result fg_aero_run(const fg_aero_plan *p, fg_aero_body *b, fg_aero_watch *w,
                      fg_aero_record *out)
{
    memset(out, 0, sizeof *out);
    fg_fluid *f;
    fg_result r = make_fluid(p, b, &f);
    if (r != FG_OK)
        return r;
    const fg_fluid_config *fc = fg_fluid_get_config(f);
    atomic_store_explicit(&w->cells,
                          (long long)fc->cells[0] * fc->cells[1] * (p->dims == 3 ? fc->cells[2] : 1),
                          memory_order_relaxed);
    double period = 0.0;
    r = transient(f, p, b, w, &period);
    if (r != FG_OK) {
        fg_fluid_destroy(f);
        return r;
    }
    out->transient_s = fg_fluid_time_s(f);
    out->shedding = period > 0.0;
    if (!out->shedding)
        period = p->reference_m / (FG_AERO_GUESSED_STROUHAL * p->speed_m_s);
    /* the loop's periods, one more for the cross-fade, half a period of slack */
    double periods = p->seconds > 0.0 ? fmax(2.0, round(p->seconds / period)) : p->periods;
    size_t samples = (size_t)ceil((periods + 1.5) * period * p->rate_hz);
    size_t width = (size_t)p->sources * p->dims;
    out->force = malloc(samples * width * sizeof(double));
    if (!out->force) {
        fg_fluid_destroy(f);
        return FG_ERR_NO_MEMORY;
    }
    atomic_store_explicit(&w->planned,
                          atomic_load_explicit(&w->steps, memory_order_relaxed) +
                              (long long)(samples * p->substeps),
                          memory_order_relaxed);
    atomic_store_explicit(&w->phase, FG_AERO_RECORDING, memory_order_relaxed);
    for (size_t i = 0; i < samples && r == FG_OK; i++) {
        for (uint32_t k = 0; k < p->substeps && r == FG_OK; k++)
            r = step(f, p, w);
        source_forces(p, b, f, &out->force[i * width]);
    }
    out->samples = samples;
    fg_fluid_destroy(f);
    if (r != FG_OK)
        fg_aero_record_free(out);
    return r;
}

void fg_aero_record_free(fg_aero_record *r)
{
    free(r->force);
    r->force = NULL;
    r->samples = 0;
}
