/* The shapes a texture is computed for: validation, signed distances,
 * symmetry, frontal widths and the flow directions to sample. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aero_internal.h"
#include "fg_math.h"

#define SYMMETRY_POINTS 256
#define SYMMETRY_TOLERANCE 1e-9 /* of the radius */
#define DEFAULT_STEP (5.0 * FG_PI / 180.0)

static int finite_all(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* --- polygons ----------------------------------------------------------- */

static double polygon_area(const double *p, uint32_t n)
{
    double a = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t j = (i + 1) % n;
        a += p[2 * i] * p[2 * j + 1] - p[2 * j] * p[2 * i + 1];
    }
    return 0.5 * a;
}

static double cross2(double ax, double ay, double bx, double by)
{
    return ax * by - ay * bx;
}

/* Do segments ab and cd share a point? */
static int segments_meet(const double *a, const double *b, const double *c, const double *d,
                         double eps)
{
    double d1 = cross2(b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]);
    double d2 = cross2(b[0] - a[0], b[1] - a[1], d[0] - a[0], d[1] - a[1]);
    double d3 = cross2(d[0] - c[0], d[1] - c[1], a[0] - c[0], a[1] - c[1]);
    double d4 = cross2(d[0] - c[0], d[1] - c[1], b[0] - c[0], b[1] - c[1]);
    if (((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) &&
        ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps)))
        return 1;
    /* touching: an end point on the other segment */
    const double *pts[4] = {c, d, a, b};
    const double *s0[4] = {a, a, c, c}, *s1[4] = {b, b, d, d};
    double ds[4] = {d1, d2, d3, d4};
    for (int i = 0; i < 4; i++) {
        if (fabs(ds[i]) > eps)
            continue;
        const double *p = pts[i], *u = s0[i], *v = s1[i];
        if (p[0] >= fmin(u[0], v[0]) - 1e-15 && p[0] <= fmax(u[0], v[0]) + 1e-15 &&
            p[1] >= fmin(u[1], v[1]) - 1e-15 && p[1] <= fmax(u[1], v[1]) + 1e-15)
            return 1;
    }
    return 0;
}

static fg_result polygon_fault(fg_aero_check *why, fg_aero_polygon_fault fault,
                               uint32_t index, uint32_t other)
{
    why->field = FG_AERO_FIELD_POLYGON;
    why->polygon = fault;
    why->index = index;
    why->other = other;
    return fault == FG_AERO_POLYGON_NOT_FINITE ? FG_ERR_NOT_FINITE : FG_ERR_ARGUMENT;
}

/* Is in[2n] a simple polygon with area? */
static fg_result polygon_check(const double *in, uint32_t n, fg_aero_check *why)
{
    if (n < 3 || n > FG_AERO_MAX_POLYGON)
        return polygon_fault(why, FG_AERO_POLYGON_COUNT, n, 0);
    for (uint32_t i = 0; i < n; i++)
        if (!isfinite(in[2 * i]) || !isfinite(in[2 * i + 1]))
            return polygon_fault(why, FG_AERO_POLYGON_NOT_FINITE, i, 0);
    double lo[2] = {in[0], in[1]}, hi[2] = {in[0], in[1]};
    for (uint32_t i = 0; i < n; i++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], in[2 * i + a]);
            hi[a] = fmax(hi[a], in[2 * i + a]);
        }
    double size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(size > 0.0))
        return polygon_fault(why, FG_AERO_POLYGON_NO_AREA, 0, 0);
    for (uint32_t i = 0; i < n; i++) {
        uint32_t j = (i + 1) % n;
        if (hypot(in[2 * j] - in[2 * i], in[2 * j + 1] - in[2 * i + 1]) <= 1e-9 * size)
            return polygon_fault(why, FG_AERO_POLYGON_REPEATED, j, 0);
    }
    double eps = 1e-12 * size * size;
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t k = i + 1; k < n; k++) {
            uint32_t i1 = (i + 1) % n, k1 = (k + 1) % n;
            if (k == i1 || i == k1)
                continue; /* neighbours share a vertex */
            if (segments_meet(&in[2 * i], &in[2 * i1], &in[2 * k], &in[2 * k1], eps))
                return polygon_fault(why, FG_AERO_POLYGON_CROSSING, i, k);
        }
    if (!(fabs(polygon_area(in, n)) > 1e-9 * size * size))
        return polygon_fault(why, FG_AERO_POLYGON_NO_AREA, 0, 0);
    return FG_OK;
}

/* A checked polygon made counter-clockwise and centred on its area
 * centroid, into out[2n]. */
static void polygon_normalise(const double *in, uint32_t n, double *out)
{
    double area = polygon_area(in, n), cx = 0.0, cy = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t j = (i + 1) % n;
        double w = in[2 * i] * in[2 * j + 1] - in[2 * j] * in[2 * i + 1];
        cx += (in[2 * i] + in[2 * j]) * w;
        cy += (in[2 * i + 1] + in[2 * j + 1]) * w;
    }
    cx /= 6.0 * area;
    cy /= 6.0 * area;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t s = area > 0.0 ? i : n - 1 - i;
        out[2 * i] = in[2 * s] - cx;
        out[2 * i + 1] = in[2 * s + 1] - cy;
    }
}

static double polygon_sdf(const double *p, uint32_t n, double x, double y)
{
    double best = DBL_MAX;
    int inside = 0;
    for (uint32_t i = 0, j = n - 1; i < n; j = i++) {
        double ax = p[2 * j], ay = p[2 * j + 1], bx = p[2 * i], by = p[2 * i + 1];
        double ex = bx - ax, ey = by - ay, wx = x - ax, wy = y - ay;
        double t = (wx * ex + wy * ey) / (ex * ex + ey * ey);
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        double dx = wx - t * ex, dy = wy - t * ey, d = dx * dx + dy * dy;
        best = d < best ? d : best;
        if ((ay > y) != (by > y) && x < ax + (y - ay) * ex / ey)
            inside = !inside;
    }
    return inside ? -sqrt(best) : sqrt(best);
}

/* --- the club: the convex hull of two spheres on the z axis -------------- */

/* In the meridian half-plane (rho >= 0, z): exact outside, and exact near
 * the surface inside (which is what the grid samples). */
static double club_sdf(const fg_aero_body *b, double rho, double z)
{
    double r0 = b->club_r[0], r1 = b->club_r[1], z0 = b->club_z[0], z1 = b->club_z[1];
    double len = z1 - z0;
    /* unit normal of the tangent line, pointing out: n_z L = r0 - r1 */
    double nz = (r0 - r1) / len, nr = sqrt(1.0 - nz * nz);
    /* coordinate along the tangent direction t = (-nz, nr) in (rho, z) */
    double pr = rho, pz = z - z0;
    double s = -nz * pr + nr * pz;
    if (s < 0.0)
        return hypot(pr, pz) - r0;
    if (s > nr * len) /* (b - a) . t = nr * len */
        return hypot(rho, z - z1) - r1;
    return pr * nr + pz * nz - r0;
}

double fg_aero_body_sdf(const double x[3], void *body)
{
    const fg_aero_body *b = body;
    switch (b->shape) {
    case FG_AERO_CIRCLE:
        return hypot(x[0], x[1]) - b->radius_m;
    case FG_AERO_SPHERE:
        return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - b->radius_m;
    case FG_AERO_CLUB:
        return club_sdf(b, hypot(x[0], x[1]), x[2]);
    default:
        return polygon_sdf(b->placed, b->vertices, x[0], x[1]);
    }
}

/* --- symmetry ------------------------------------------------------------ */

static double unplaced_sdf(const fg_aero_body *b, double x, double y)
{
    return polygon_sdf(b->polygon, b->vertices, x, y);
}

/* Is the polygon unchanged by the map p -> M p (2x2, row-major)? */
static int invariant(const fg_aero_body *b, const double m[4], double radius)
{
    double tol = SYMMETRY_TOLERANCE * radius;
    for (int i = 0; i < SYMMETRY_POINTS; i++) {
        double r = 1.3 * radius * sqrt((i + 0.5) / SYMMETRY_POINTS), th = 2.399963229728653 * i;
        double x = r * cos(th), y = r * sin(th);
        double tx = m[0] * x + m[1] * y, ty = m[2] * x + m[3] * y;
        if (fabs(unplaced_sdf(b, tx, ty) - unplaced_sdf(b, x, y)) > tol)
            return 0;
    }
    return 1;
}

static double wrap(double a, double period)
{
    a = fmod(a, period);
    return a < 0.0 ? a + period : a;
}

static void find_symmetry(fg_aero_body *b)
{
    double radius = fg_aero_body_radius(b);
    static const uint32_t orders[] = {12, 10, 8, 6, 5, 4, 3, 2};
    b->rotation_order = 1;
    for (size_t k = 0; k < sizeof orders / sizeof orders[0]; k++) {
        double a = 2.0 * FG_PI / orders[k], m[4] = {cos(a), -sin(a), sin(a), cos(a)};
        if (invariant(b, m, radius)) {
            b->rotation_order = orders[k];
            break;
        }
    }
    /* A mirror line passes through the centroid and maps the vertices
     * farthest from it onto each other: through one, or between two. */
    double period = FG_PI / b->rotation_order;
    double far_angle[64];
    int far = 0;
    for (uint32_t i = 0; i < b->vertices && far < 64; i++) {
        double x = b->polygon[2 * i], y = b->polygon[2 * i + 1];
        if (hypot(x, y) >= radius * (1.0 - 1e-9))
            far_angle[far++] = atan2(y, x);
    }
    double tried[4096];
    int ntried = 0;
    b->mirror = 0;
    b->mirror_angle_rad = 0.0;
    for (int i = 0; i < far && !b->mirror; i++)
        for (int j = i; j < far && !b->mirror; j++) {
            /* the bisector of the pair, and the line across it */
            double beta = 0.5 * (far_angle[i] + far_angle[j]);
            for (int half = 0; half < 2 && !b->mirror; half++) {
                double cand = wrap(beta + half * 0.5 * FG_PI, period);
                int seen = 0;
                for (int t = 0; t < ntried; t++)
                    seen |= fabs(tried[t] - cand) < 1e-9;
                if (seen || ntried == 4096)
                    continue;
                tried[ntried++] = cand;
                double c2 = cos(2.0 * cand), s2 = sin(2.0 * cand);
                double m[4] = {c2, s2, s2, -c2};
                if (invariant(b, m, radius)) {
                    b->mirror = 1;
                    b->mirror_angle_rad = cand < period * (1.0 - 1e-12) ? cand : 0.0;
                }
            }
        }
}

/* --- the body ------------------------------------------------------------ */

static fg_result size_fault(fg_aero_check *why, fg_result r)
{
    why->field = FG_AERO_FIELD_SIZE;
    return r;
}

fg_result fg_aero_body_init(fg_aero_body *b, const fg_aero_config *c, fg_aero_check *why)
{
    memset(b, 0, sizeof *b);
    b->shape = c->shape;
    double params[4] = {c->length_m, c->height_m, c->diameter_m[0], c->diameter_m[1]};
    if (!finite_all(params, 4))
        return size_fault(why, FG_ERR_NOT_FINITE);
    if (!isfinite(c->reference_m)) {
        why->field = FG_AERO_FIELD_REFERENCE;
        return FG_ERR_NOT_FINITE;
    }
    if (c->reference_m < 0.0) {
        why->field = FG_AERO_FIELD_REFERENCE;
        return FG_ERR_ARGUMENT;
    }
    if (c->length_m < 0.0 || c->height_m < 0.0 || c->diameter_m[0] < 0.0 ||
        c->diameter_m[1] < 0.0)
        return size_fault(why, FG_ERR_ARGUMENT);
    switch (c->shape) {
    case FG_AERO_CIRCLE:
    case FG_AERO_SPHERE:
        if (!(c->length_m > 0.0))
            return size_fault(why, FG_ERR_ARGUMENT);
        b->dims = c->shape == FG_AERO_CIRCLE ? 2 : 3;
        b->radius_m = 0.5 * c->length_m;
        b->reference_m = c->length_m;
        b->mirror = 1;
        break;
    case FG_AERO_RECTANGLE:
    case FG_AERO_POLYGON: {
        b->dims = 2;
        double rect[8];
        const double *in = c->polygon_xy;
        uint32_t n = c->polygon_vertices;
        if (c->shape == FG_AERO_RECTANGLE) {
            double w = c->length_m, h = c->height_m > 0.0 ? c->height_m : c->length_m;
            if (!(w > 0.0))
                return size_fault(why, FG_ERR_ARGUMENT);
            double r[8] = {-w / 2, -h / 2, w / 2, -h / 2, w / 2, h / 2, -w / 2, h / 2};
            memcpy(rect, r, sizeof r);
            in = rect;
            n = 4;
        } else if (!in) {
            why->field = FG_AERO_FIELD_POLYGON;
            return FG_ERR_NULL;
        }
        fg_result r = polygon_check(in, n, why);
        if (r != FG_OK)
            return r;
        b->polygon = malloc(2 * (size_t)n * sizeof(double));
        b->placed = malloc(2 * (size_t)n * sizeof(double));
        if (!b->polygon || !b->placed) {
            fg_aero_body_deinit(b);
            return FG_ERR_NO_MEMORY;
        }
        polygon_normalise(in, n, b->polygon);
        b->vertices = n;
        b->reference_m = fg_aero_body_frontal(b, 0.0);
        find_symmetry(b);
        break;
    }
    case FG_AERO_CLUB: {
        double len = c->length_m, r0 = 0.5 * c->diameter_m[0], r1 = 0.5 * c->diameter_m[1];
        if (!(r0 > 0.0) || !(r1 > 0.0) || !(len > 2.0 * fmax(r0, r1) * (1.0 + 1e-6)))
            return size_fault(why, FG_ERR_ARGUMENT);
        b->dims = 3;
        b->length_m = len;
        b->club_r[0] = r0;
        b->club_r[1] = r1;
        b->club_z[0] = r0;
        b->club_z[1] = len - r1;
        b->reference_m = 2.0 * fmax(r0, r1);
        b->mirror = 1;
        break;
    }
    default:
        why->field = FG_AERO_FIELD_SHAPE;
        return FG_ERR_ARGUMENT;
    }
    if (c->reference_m > 0.0)
        b->reference_m = c->reference_m;
    fg_aero_body_place(b, 0.0);
    return FG_OK;
}

void fg_aero_body_deinit(fg_aero_body *b)
{
    free(b->polygon);
    free(b->placed);
    b->polygon = b->placed = NULL;
}

fg_result fg_aero_body_copy(const fg_aero_body *from, fg_aero_body *to)
{
    *to = *from;
    to->polygon = to->placed = NULL;
    if (!from->vertices)
        return FG_OK;
    size_t bytes = 2 * (size_t)from->vertices * sizeof(double);
    to->polygon = malloc(bytes);
    to->placed = malloc(bytes);
    if (!to->polygon || !to->placed) {
        fg_aero_body_deinit(to);
        return FG_ERR_NO_MEMORY;
    }
    memcpy(to->polygon, from->polygon, bytes);
    memcpy(to->placed, from->placed, bytes);
    return FG_OK;
}

void fg_aero_body_place(fg_aero_body *b, double angle)
{
    b->angle_rad = angle;
    double c = cos(-angle), s = sin(-angle);
    for (uint32_t i = 0; i < b->vertices; i++) {
        double x = b->polygon[2 * i], y = b->polygon[2 * i + 1];
        b->placed[2 * i] = c * x - s * y;
        b->placed[2 * i + 1] = s * x + c * y;
    }
}

double fg_aero_body_radius(const fg_aero_body *b)
{
    if (b->shape == FG_AERO_CLUB)
        return fmax(b->club_r[0], b->club_r[1]);
    if (!b->vertices)
        return b->radius_m;
    double r = 0.0;
    for (uint32_t i = 0; i < b->vertices; i++)
        r = fmax(r, hypot(b->polygon[2 * i], b->polygon[2 * i + 1]));
    return r;
}

double fg_aero_body_frontal(const fg_aero_body *b, double angle)
{
    if (b->shape == FG_AERO_CLUB)
        return 2.0 * fmax(b->club_r[0], b->club_r[1]);
    if (!b->vertices)
        return 2.0 * b->radius_m;
    double ex = -sin(angle), ey = cos(angle), lo = DBL_MAX, hi = -DBL_MAX;
    for (uint32_t i = 0; i < b->vertices; i++) {
        double p = b->polygon[2 * i] * ex + b->polygon[2 * i + 1] * ey;
        lo = fmin(lo, p);
        hi = fmax(hi, p);
    }
    return hi - lo;
}

/* The club's silhouette across the flow, integrated over its length: the
 * profile radius at each z found by bisection on the distance. */
static double club_area(const fg_aero_body *b)
{
    const int samples = 2000;
    double rmax = fmax(b->club_r[0], b->club_r[1]), dz = b->length_m / samples, area = 0.0;
    for (int i = 0; i < samples; i++) {
        double z = (i + 0.5) * dz, lo = 0.0, hi = rmax * 1.01;
        if (club_sdf(b, 0.0, z) >= 0.0)
            continue;
        for (int k = 0; k < 60; k++) {
            double mid = 0.5 * (lo + hi);
            if (club_sdf(b, mid, z) < 0.0)
                lo = mid;
            else
                hi = mid;
        }
        area += 2.0 * lo * dz;
    }
    return area;
}

double fg_aero_body_area(const fg_aero_body *b)
{
    switch (b->shape) {
    case FG_AERO_SPHERE:
        return FG_PI * b->radius_m * b->radius_m;
    case FG_AERO_CLUB:
        return club_area(b);
    default:
        return b->reference_m;
    }
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

uint32_t fg_aero_body_directions(const fg_aero_body *b, const fg_aero_config *c, double *out)
{
    if (b->dims == 3 || b->rotation_order == 0) {
        out[0] = 0.0;
        return 1;
    }
    double lo, span;
    fg_aero_symmetry_range(b->rotation_order, b->mirror, b->mirror_angle_rad, &lo, &span);
    uint32_t n = 0;
    if (c->directions_rad && c->direction_count > 0) {
        for (uint32_t i = 0; i < c->direction_count && n < FG_AERO_MAX_DIRECTIONS; i++) {
            int flip;
            out[n++] = fg_aero_symmetry_map(b->rotation_order, b->mirror, b->mirror_angle_rad,
                                            c->directions_rad[i], &flip);
        }
        qsort(out, n, sizeof *out, compare_double);
        uint32_t kept = 0;
        for (uint32_t i = 0; i < n; i++)
            if (kept == 0 || out[i] - out[kept - 1] > 1e-9)
                out[kept++] = out[i];
        return kept;
    }
    double step = c->direction_step_rad > 0.0 ? c->direction_step_rad : DEFAULT_STEP;
    /* whole steps over the range; a mirrored range includes both ends */
    uint32_t steps = (uint32_t)fmax(1.0, round(span / step));
    if (steps > FG_AERO_MAX_DIRECTIONS - 1)
        steps = FG_AERO_MAX_DIRECTIONS - 1;
    uint32_t count = b->mirror ? steps + 1 : steps;
    for (uint32_t i = 0; i < count; i++)
        out[i] = lo + span * i / steps;
    return count;
}
