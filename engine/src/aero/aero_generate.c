/* fg_aero_generate: the configuration checked and resolved, one flow per
 * direction on worker threads, each record made into a loop of g, and the
 * texture assembled. The calling thread only reports progress. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <pthread.h>
#include <threads.h> /* thrd_sleep */
#include <time.h>

#include "aero_internal.h"
#include "fluid/fluid_internal.h"
#include "fg_math.h"

#define MAX_THREADS 64
#define DEFAULT_PERIODS 24
#define DEFAULT_CFL 0.5
#define SAMPLES_PER_CONVECTIVE_TIME 16.0

static fg_result fault(fg_aero_check *why, fg_aero_field field, fg_result r, double limit)
{
    why->field = field;
    why->limit = limit;
    return r;
}

/* A finite value, >= 0 (0 meaning the default), at most most. */
static fg_result in_range(double v, double most, fg_aero_field field, fg_aero_check *why)
{
    if (!isfinite(v))
        return fault(why, field, FG_ERR_NOT_FINITE, most);
    if (v < 0.0 || v > most)
        return fault(why, field, FG_ERR_ARGUMENT, most);
    return FG_OK;
}

static fg_result check_fields(const fg_aero_config *c, fg_aero_check *why)
{
    if (!isfinite(c->speed_m_s))
        return fault(why, FG_AERO_FIELD_SPEED, FG_ERR_NOT_FINITE, 0);
    if (!(c->speed_m_s > 0.0))
        return fault(why, FG_AERO_FIELD_SPEED, FG_ERR_ARGUMENT, 0);
    if ((unsigned)c->tone > FG_AERO_CAVITY)
        return fault(why, FG_AERO_FIELD_TONE, FG_ERR_ARGUMENT, 0);
    static const struct {
        size_t offset;
        double most;
        fg_aero_field field;
    } reals[] = {
        {offsetof(fg_aero_config, viscosity_m2_s), HUGE_VAL, FG_AERO_FIELD_VISCOSITY},
        {offsetof(fg_aero_config, density_kg_m3), HUGE_VAL, FG_AERO_FIELD_DENSITY},
        {offsetof(fg_aero_config, cells_per_length), 1024.0, FG_AERO_FIELD_CELLS},
        {offsetof(fg_aero_config, sample_rate_hz), 1e7, FG_AERO_FIELD_RATE},
        {offsetof(fg_aero_config, seconds), HUGE_VAL, FG_AERO_FIELD_SECONDS},
        {offsetof(fg_aero_config, transient_s), HUGE_VAL, FG_AERO_FIELD_TRANSIENT},
        {offsetof(fg_aero_config, max_transient_s), HUGE_VAL, FG_AERO_FIELD_MAX_TRANSIENT},
        {offsetof(fg_aero_config, direction_step_rad), 2.0 * FG_PI, FG_AERO_FIELD_STEP},
        {offsetof(fg_aero_config, domain[0]), HUGE_VAL, FG_AERO_FIELD_DOMAIN},
        {offsetof(fg_aero_config, domain[1]), HUGE_VAL, FG_AERO_FIELD_DOMAIN},
        {offsetof(fg_aero_config, domain[2]), HUGE_VAL, FG_AERO_FIELD_DOMAIN},
        {offsetof(fg_aero_config, cfl), 4.0, FG_AERO_FIELD_CFL},
    };
    for (size_t i = 0; i < sizeof reals / sizeof reals[0]; i++) {
        double v;
        memcpy(&v, (const char *)c + reals[i].offset, sizeof v);
        fg_result r = in_range(v, reals[i].most, reals[i].field, why);
        if (r != FG_OK)
            return r;
    }
    if (c->cells_per_length != 0.0 && c->cells_per_length < 4.0)
        return fault(why, FG_AERO_FIELD_CELLS, FG_ERR_ARGUMENT, 4.0);
    if (c->threads > MAX_THREADS)
        return fault(why, FG_AERO_FIELD_THREADS, FG_ERR_ARGUMENT, MAX_THREADS);
    if (c->sources > FG_AERO_MAX_SOURCES || (c->sources > 1 && c->shape != FG_AERO_CLUB))
        return fault(why, FG_AERO_FIELD_SOURCES, FG_ERR_ARGUMENT, FG_AERO_MAX_SOURCES);
    if (c->max_transient_s > 0.0 && c->max_transient_s < c->transient_s)
        return fault(why, FG_AERO_FIELD_MAX_TRANSIENT, FG_ERR_ARGUMENT, c->transient_s);
    if (c->direction_step_rad != 0.0 && c->direction_step_rad < FG_PI / 1800.0)
        return fault(why, FG_AERO_FIELD_STEP, FG_ERR_ARGUMENT, FG_PI / 1800.0);
    if (c->direction_count > 0) {
        if (!c->directions_rad)
            return fault(why, FG_AERO_FIELD_DIRECTIONS, FG_ERR_NULL, 0);
        if (c->direction_count > FG_AERO_MAX_DIRECTIONS)
            return fault(why, FG_AERO_FIELD_DIRECTIONS, FG_ERR_ARGUMENT, FG_AERO_MAX_DIRECTIONS);
        for (uint32_t i = 0; i < c->direction_count; i++)
            if (!isfinite(c->directions_rad[i])) {
                why->index = i;
                return fault(why, FG_AERO_FIELD_DIRECTIONS, FG_ERR_NOT_FINITE, 0);
            }
    }
    return FG_OK;
}

static fg_result make_plan(const fg_aero_config *c, const fg_aero_body *b, fg_aero_plan *p,
                           fg_aero_check *why)
{
    memset(p, 0, sizeof *p);
    p->dims = b->dims;
    p->reference_m = b->reference_m;
    p->speed_m_s = c->speed_m_s;
    p->viscosity_m2_s = c->viscosity_m2_s > 0.0 ? c->viscosity_m2_s : FG_AIR_KINEMATIC_VISCOSITY;
    p->density_kg_m3 = c->density_kg_m3 > 0.0 ? c->density_kg_m3 : FG_AIR_DENSITY;
    double cells = c->cells_per_length > 0.0 ? c->cells_per_length : (b->dims == 2 ? 32.0 : 12.0);
    p->cell_m = p->reference_m / cells;
    double convective = p->reference_m / p->speed_m_s;
    p->rate_hz = c->sample_rate_hz > 0.0 ? c->sample_rate_hz
                                         : SAMPLES_PER_CONVECTIVE_TIME / convective;
    /* the texture must resolve the shedding: at least 8 samples a period */
    double least = 8.0 * FG_AERO_GUESSED_STROUHAL / convective;
    if (p->rate_hz < least)
        return fault(why, FG_AERO_FIELD_RATE, FG_ERR_ARGUMENT, least);
    double cfl = c->cfl > 0.0 ? c->cfl : DEFAULT_CFL;
    double dt_most = cfl * p->cell_m / p->speed_m_s, dt_sample = 1.0 / p->rate_hz;
    p->substeps = (uint32_t)ceil(dt_sample / dt_most * (1.0 - 1e-12));
    if (p->substeps < 1)
        p->substeps = 1;
    p->dt_s = dt_sample / p->substeps;
    static const double defaults[2][3] = {{10.0, 15.0, 6.0}, {4.0, 8.0, 3.0}};
    for (int a = 0; a < 3; a++)
        p->domain_m[a] = (c->domain[a] > 0.0 ? c->domain[a] : defaults[b->dims - 2][a]) *
                         p->reference_m;
    p->transient_s = c->transient_s > 0.0 ? c->transient_s
                                          : (b->dims == 2 ? 60.0 : 30.0) * convective;
    p->max_transient_s = c->max_transient_s > 0.0 ? c->max_transient_s : 5.0 * p->transient_s;
    p->seconds = c->seconds;
    p->periods = DEFAULT_PERIODS;
    if (b->shape == FG_AERO_CLUB) {
        double mean_d = b->club_r[0] + b->club_r[1];
        p->sources = c->sources > 0 ? c->sources
                                    : (uint32_t)fmax(1.0, round(b->length_m / (3.0 * mean_d)));
    } else {
        p->sources = 1;
    }
    p->area_m2 = fg_aero_body_area(b);
    p->band_hz[0] = 0.02 / convective;
    p->band_hz[1] = 1.0 / convective;
    int n[3];
    double origin[3], total = fg_aero_box(p, b, n, origin);
    if (total > FG_AERO_MAX_CELLS)
        return fault(why, FG_AERO_FIELD_GRID, FG_ERR_ARGUMENT, total);
    return FG_OK;
}

/* The whole check: fields, shape, plan. On success b holds the body. */
static fg_result check(const fg_aero_config *c, fg_aero_body *b, fg_aero_plan *p,
                       fg_aero_check *why)
{
    memset(why, 0, sizeof *why);
    fg_result r = check_fields(c, why);
    if (r != FG_OK)
        return r;
    r = fg_aero_body_init(b, c, why);
    if (r != FG_OK)
        return r;
    r = make_plan(c, b, p, why);
    if (r != FG_OK)
        fg_aero_body_deinit(b);
    return r;
}

fg_result fg_aero_config_check(const fg_aero_config *c, fg_aero_check *why)
{
    fg_aero_check ignored;
    why = why ? why : &ignored;
    if (!c)
        return FG_ERR_NULL;
    fg_aero_body b;
    fg_aero_plan p;
    fg_result r = check(c, &b, &p, why);
    if (r == FG_OK)
        fg_aero_body_deinit(&b);
    return r;
}

/* What one direction's flow leaves for the texture. */
typedef struct direction_result {
    fg_aero_direction info;
    float *samples;
    fg_result status;
} direction_result;

typedef struct job {
    const fg_aero_plan *plan;
    const fg_aero_body *body;
    const double *angles;
    uint32_t count;
    atomic_uint next;
    atomic_uint done;
    atomic_int failed;
    direction_result *result;
    fg_aero_watch *watch;   /* one per direction */
} job;

static void stats(const fg_aero_plan *p, const double *lift, const double *drag, uint32_t n,
                  fg_aero_direction *d)
{
    double q = 0.5 * p->density_kg_m3 * p->speed_m_s * p->speed_m_s * p->area_m2;
    double lo = lift[0], hi = lift[0], mean = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        lo = fmin(lo, lift[i]);
        hi = fmax(hi, lift[i]);
        mean += drag[i];
    }
    d->lift_amplitude = 0.5 * (hi - lo) / q;
    d->drag_mean = mean / n / q;
}

/* A loop for a body that does not shed: as many nominal periods (St 0.2)
 * as a shedding one would get, faded over one. */
static void quiet_loop(const fg_aero_plan *p, size_t n, uint32_t want, fg_aero_loop *loop)
{
    double period = p->reference_m / (FG_AERO_GUESSED_STROUHAL * p->speed_m_s);
    double samples = period * p->rate_hz;
    loop->period_s = period;
    loop->fade = (uint32_t)lround(samples);
    uint32_t fit = (uint32_t)floor(((double)n - loop->fade) / samples);
    loop->periods = 0; /* no shedding: none */
    loop->frames = (uint32_t)lround((want > 0 && want < fit ? want : fit) * samples);
}

/* The record of one direction made into its loop of g. */
static fg_result build_direction(const fg_aero_plan *p, const fg_aero_record *rec,
                                 direction_result *out)
{
    size_t n = rec->samples, width = (size_t)p->sources * p->dims;
    double *x = malloc(n * sizeof(double)), *loop_x = malloc(n * sizeof(double));
    double *lift = malloc(n * sizeof(double)), *drag = malloc(n * sizeof(double));
    fg_result r = x && loop_x && lift && drag ? FG_OK : FG_ERR_NO_MEMORY;
    fg_aero_loop loop;
    if (r == FG_OK) {
        for (size_t i = 0; i < n; i++) {
            double l = 0.0;
            for (uint32_t s = 0; s < p->sources; s++)
                l += rec->force[i * width + (size_t)s * p->dims + 1];
            lift[i] = l;
        }
        uint32_t want = p->seconds > 0.0 ? 0 : p->periods;
        if (!rec->shedding)
            quiet_loop(p, n, want, &loop);
        else if (fg_aero_loop_plan(lift, n, p->rate_hz, p->band_hz[0], p->band_hz[1], want,
                                   &loop) != 0)
            r = FG_ERR_NOT_CONVERGED;
    }
    if (r == FG_OK && !(out->samples = malloc((size_t)loop.frames * width * sizeof(float))))
        r = FG_ERR_NO_MEMORY;
    if (r == FG_OK) {
        /* loops of the totals, for the coefficients */
        for (int which = 0; which < 2; which++) {
            for (size_t i = 0; i < n; i++) {
                double v = 0.0;
                for (uint32_t s = 0; s < p->sources; s++)
                    v += rec->force[i * width + (size_t)s * p->dims + (which ? 1 : 0)];
                x[i] = v;
            }
            fg_aero_loop_crossfade(x, &loop, which ? lift : drag);
        }
        stats(p, lift, drag, loop.frames, &out->info);
        for (uint32_t s = 0; s < p->sources; s++)
            for (int a = 0; a < p->dims; a++) {
                for (size_t i = 0; i < n; i++)
                    x[i] = rec->force[i * width + (size_t)s * p->dims + a];
                fg_aero_loop_crossfade(x, &loop, loop_x);
                fg_aero_loop_derivative(loop_x, loop.frames, p->rate_hz,
                                        &out->samples[(size_t)s * loop.frames * p->dims + a],
                                        (size_t)p->dims);
            }
        out->info.frequency_hz = rec->shedding ? 1.0 / loop.period_s : 0.0;
        out->info.strouhal = out->info.frequency_hz * p->reference_m / p->speed_m_s;
        out->info.periods = loop.periods;
        out->info.frames = loop.frames;
        out->info.transient_s = rec->transient_s;
    }
    free(x);
    free(loop_x);
    free(lift);
    free(drag);
    return r;
}

static void *worker(void *arg)
{
    job *j = arg;
    fg_aero_body body;
    if (fg_aero_body_copy(j->body, &body) != FG_OK) {
        atomic_store(&j->failed, FG_ERR_NO_MEMORY);
        return NULL;
    }
    for (;;) {
        unsigned i = atomic_fetch_add(&j->next, 1);
        if (i >= j->count || atomic_load(&j->failed) != FG_OK)
            break;
        direction_result *out = &j->result[i];
        fg_aero_body_place(&body, j->angles[i]);
        out->info.angle_rad = j->angles[i];
        out->info.frontal_m = fg_aero_body_frontal(&body, j->angles[i]);
        fg_aero_record rec;
        fg_result r = fg_aero_run(j->plan, &body, &j->watch[i], &rec);
        if (r == FG_OK)
            r = build_direction(j->plan, &rec, out);
        fg_aero_record_free(&rec);
        out->status = r;
        atomic_store_explicit(&j->watch[i].phase, FG_AERO_DONE, memory_order_relaxed);
        if (r != FG_OK)
            atomic_store(&j->failed, r);
        atomic_fetch_add(&j->done, 1);
    }
    fg_aero_body_deinit(&body);
    return NULL;
}

static void report(job *j, fg_aero_progress_fn progress, void *user)
{
    fg_aero_progress p = {.directions = j->count};
    p.directions_done = atomic_load(&j->done);
    double sum = 0.0;
    long long most_recent = -1;
    for (uint32_t i = 0; i < j->count; i++) {
        fg_aero_watch *w = &j->watch[i];
        int phase = atomic_load_explicit(&w->phase, memory_order_relaxed);
        long long steps = atomic_load_explicit(&w->steps, memory_order_relaxed);
        long long planned = atomic_load_explicit(&w->planned, memory_order_relaxed);
        double cells = (double)atomic_load_explicit(&w->cells, memory_order_relaxed);
        p.cells = cells > p.cells ? cells : p.cells;
        double part = phase == FG_AERO_DONE ? 1.0 : (planned > 0 ? (double)steps / planned : 0.0);
        sum += part > 0.99 && phase != FG_AERO_DONE ? 0.99 : part;
        if (steps > 0 && phase != FG_AERO_DONE && (long long)i > most_recent) {
            most_recent = i;
            p.direction = i;
            p.phase = (fg_aero_phase)phase;
            p.simulated_s = (double)steps * j->plan->dt_s;
        }
    }
    if (most_recent < 0)
        p.phase = p.directions_done == j->count ? FG_AERO_DONE : FG_AERO_TRANSIENT;
    p.fraction = sum / j->count;
    progress(&p, user);
}

static fg_result assemble(const fg_aero_config *c, const fg_aero_body *b, const fg_aero_plan *p,
                          job *j, fg_aero_texture **out)
{
    fg_aero_source *src = malloc(p->sources * sizeof *src);
    fg_aero_direction *dir = malloc(j->count * sizeof *dir);
    if (!src || !dir) {
        free(src);
        free(dir);
        return FG_ERR_NO_MEMORY;
    }
    for (uint32_t s = 0; s < p->sources; s++) {
        if (b->shape == FG_AERO_CLUB) {
            src[s].span_m = b->length_m / p->sources;
            src[s].position_m = (s + 0.5) * src[s].span_m;
        } else {
            src[s].span_m = b->dims == 2 ? 1.0 : p->reference_m;
            src[s].position_m = 0.0;
        }
    }
    for (uint32_t i = 0; i < j->count; i++) {
        dir[i] = j->result[i].info;
        dir[i].samples = j->result[i].samples;
    }
    fg_aero_texture_desc d = {
        .shape = b->shape,
        .tone = c->tone,
        .dims = (uint32_t)b->dims,
        .components = (uint32_t)b->dims,
        .length_m = c->length_m,
        .height_m = b->shape == FG_AERO_RECTANGLE ? (c->height_m > 0.0 ? c->height_m : c->length_m)
                                                  : 0.0,
        .diameter_m = {b->shape == FG_AERO_CLUB ? c->diameter_m[0] : 0.0,
                       b->shape == FG_AERO_CLUB ? c->diameter_m[1] : 0.0},
        .polygon_vertices = b->shape == FG_AERO_POLYGON ? b->vertices : 0,
        .polygon_xy = b->shape == FG_AERO_POLYGON ? b->polygon : NULL,
        .reference_m = p->reference_m,
        .speed_m_s = p->speed_m_s,
        .viscosity_m2_s = p->viscosity_m2_s,
        .density_kg_m3 = p->density_kg_m3,
        .reynolds = p->reference_m * p->speed_m_s / p->viscosity_m2_s,
        .sample_rate_hz = p->rate_hz,
        .cells_per_length = p->reference_m / p->cell_m,
        .rotation_order = b->rotation_order,
        .mirror = b->mirror,
        .mirror_angle_rad = b->mirror_angle_rad,
        .sources = p->sources,
        .source = src,
        .directions = j->count,
        .direction = dir,
    };
    fg_result r = fg_aero_texture_create(&d, out);
    free(src);
    free(dir);
    return r;
}

fg_result fg_aero_generate(const fg_aero_config *c, fg_aero_progress_fn progress, void *user,
                           fg_aero_texture **out)
{
    if (!c || !out)
        return FG_ERR_NULL;
    fg_aero_body body;
    fg_aero_plan plan;
    fg_aero_check why;
    fg_result r = check(c, &body, &plan, &why);
    if (r != FG_OK)
        return r;
    double angles[FG_AERO_MAX_DIRECTIONS];
    uint32_t count = fg_aero_body_directions(&body, c, angles);
    job j = {.plan = &plan, .body = &body, .angles = angles, .count = count};
    atomic_init(&j.next, 0);
    atomic_init(&j.done, 0);
    atomic_init(&j.failed, FG_OK);
    if (r == FG_OK) {
        j.result = calloc(count, sizeof *j.result);
        j.watch = calloc(count, sizeof *j.watch);
        if (!j.result || !j.watch)
            r = FG_ERR_NO_MEMORY;
    }
    uint32_t threads = c->threads > 0 ? c->threads : 1, started = 0;
    if (threads > count)
        threads = count;
    /* pthreads, not thrd_create: ThreadSanitizer (clang 14) does not see
     * threads that glibc's thrd_create starts, and fails in them. */
    pthread_t t[MAX_THREADS];
    if (r == FG_OK) {
        double guess = plan.transient_s + (plan.periods + 1.5) * plan.reference_m /
                                              (FG_AERO_GUESSED_STROUHAL * plan.speed_m_s);
        for (uint32_t i = 0; i < count; i++) {
            atomic_init(&j.watch[i].phase, FG_AERO_TRANSIENT);
            atomic_init(&j.watch[i].steps, 0);
            atomic_init(&j.watch[i].planned, (long long)(guess / plan.dt_s));
            atomic_init(&j.watch[i].cells, 0);
        }
        for (; started < threads; started++)
            if (pthread_create(&t[started], NULL, worker, &j) != 0)
                break;
        if (started == 0)
            r = FG_ERR_NO_MEMORY;
    }
    if (r == FG_OK && progress) {
        while (atomic_load(&j.done) < count && atomic_load(&j.failed) == FG_OK) {
            report(&j, progress, user);
            thrd_sleep(&(struct timespec){.tv_nsec = 100000000}, NULL);
        }
    }
    for (uint32_t i = 0; i < started; i++)
        pthread_join(t[i], NULL);
    if (r == FG_OK)
        r = atomic_load(&j.failed);
    if (r == FG_OK && progress)
        report(&j, progress, user);
    if (r == FG_OK)
        r = assemble(c, &body, &plan, &j, out);
    for (uint32_t i = 0; j.result && i < count; i++)
        free(j.result[i].samples);
    free(j.result);
    free(j.watch);
    fg_aero_body_deinit(&body);
    return r;
}
