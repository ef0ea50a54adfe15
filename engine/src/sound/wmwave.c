/* The WM-wave (Wright & Medendorp 1968; Matsuyama eq. 5).
 *
 * A point N-wave of peak ps and half-duration T, averaged along a segment of
 * half-length l whose ends arrive s*l/c apart, in tau = c (t - t_a) / l:
 *   p(tau) = (1/2s) int_{-s}^{s} N(tau - u) du,  N(x) = -(ps/psi) x on |x| < psi.
 * Eq. 5 is this box average written out; with B = ps/(4 psi) its s >= psi
 * middle piece is 0 (Glassner's printed -4 B tau there is a typo).
 *
 * p is odd, so its integral P is even. For x = |tau| >= 0:
 *   x >= psi + s:            P = 0
 *   |psi - s| <= x < psi + s: P = (B/3s) (x - s - psi)^2 (x - s + 2 psi)
 *   x < psi - s (s < psi):    P = (4Bs/3)(3 psi - 2s) + 2B ((psi - s)^2 - x^2)
 *   x < s - psi (s >= psi):   P = 4 B psi^3 / (3s)
 * s -> 0 needs no special case: the cubic shell is then empty. */
#include <math.h>

#include "wmwave_internal.h"

fg_wm_shape fg_wm_shape_at(const fg_sound_config *p, double t0_s, double r_m, double s, double l_m,
                     double c_m_s, double *t_s)
{
    double r = r_m > p->r0_m ? r_m : p->r0_m;
    double stretch = sqrt(1.0 + p->sigma0 * log(r / p->r0_m));
    double t = t0_s * stretch;
    double ps = p->r0_m * p->ps0_pa / (r * stretch);
    double psi = c_m_s * t / l_m;
    if (t_s)
        *t_s = t;
    return (fg_wm_shape){.b = ps / (4.0 * psi), .s = s, .psi = psi};
}

double fg_wm_pressure(const fg_wm_shape *w, double tau)
{
    double s = w->s, psi = w->psi, b = w->b;
    double x = fabs(tau);
    double sign = tau < 0 ? -1.0 : 1.0;
    if (x >= psi + s)
        return 0.0;
    if (x > fabs(psi - s))
        return sign * (b / s) * ((x - s) * (x - s) - psi * psi);
    if (s < psi)
        return -4.0 * b * tau;
    return 0.0;
}

double fg_wm_integral(const fg_wm_shape *w, double tau)
{
    double s = w->s, psi = w->psi, b = w->b;
    double x = fabs(tau);
    if (x >= psi + s)
        return 0.0;
    if (x >= fabs(psi - s)) {
        double u = x - s - psi;
        return (b / (3.0 * s)) * u * u * (x - s + 2.0 * psi);
    }
    if (s < psi) {
        double m = psi - s;
        return (4.0 * b * s / 3.0) * (3.0 * psi - 2.0 * s) + 2.0 * b * (m * m - x * x);
    }
    return 4.0 * b * psi * psi * psi / (3.0 * s);
}

/* Which quadratic piece of p holds tau, for the breakpoints inner =
 * |psi - s| and outer = psi + s: 0 before the wave, 1 the rising shell, 2
 * the middle, 3 the falling shell, 4 after. */
static int piece(double inner, double outer, double tau)
{
    return tau <= -outer ? 0 : tau <= -inner ? 1 : tau <= inner ? 2 : tau <= outer ? 3 : 4;
}

/* The average over a sample from tau = a to z in the middle piece, -inner
 * < a <= z <= inner, given slope = -4 B (0 when s >= psi): fg_wm_pressure
 * at its midpoint bit for bit, slope tau there but 0 on the outer
 * breakpoint (which inner equals when s is below psi's rounding, or where
 * the midpoint overflows). The piece is linear: its curvature term, 0 h h
 * / 24 with h = z - a >= 0, is +0. */
static double middle_average(double slope, double outer, double a, double z)
{
    double mid = 0.5 * (a + z);
    return (fabs(mid) < outer ? slope * mid : 0.0) + 0.0;
}

/* The average over the sample from tau = a (in piece pa) to z (in pz),
 * accurate to rounding of the peak. A difference of P at the two edges
 * loses digits when the wave spans many samples (P is ~ psi times the
 * peak, the difference ~ 1/width of it), and the block accumulator
 * extrapolates those errors quadratically across the block. So inside one
 * piece the average of the quadratic is taken directly: p(mid) + p'' h^2
 * / 24, h = 1/width; across a breakpoint, the P difference (that sample's
 * error is not extrapolated: the samples after it are). The middle piece
 * (2) is middle_average's. */
static double sample_average(const fg_wm_event *e, double a, double z, int pa, int pz)
{
    const fg_wm_shape *w = &e->shape;
    if (pa != pz)
        return e->width * (fg_wm_integral(w, z) - fg_wm_integral(w, a));
    if (pa == 0 || pa == 4)
        return 0.0;
    double h = z - a;
    double curvature = pa == 1 ? -2.0 * w->b / w->s : 2.0 * w->b / w->s;
    return fg_wm_pressure(w, 0.5 * (a + z)) + curvature * h * h / 24.0;
}

/* a merged range is at most the state (3) plus 4 breakpoints (7 each) */
_Static_assert(FG_WM_RANGE_MAX >= 3 + 4 * 7 && FG_WM_RANGES_MAX >= 5, "fg_wm_taps' ranges");

/* Samples lo..hi (lo >= -3) evaluated exactly into y[0 .. hi - lo].
 * Sample k covers tau from (k - 1/2 - centre) / width to (k + 1/2 -
 * centre) / width; its right edge is the next one's left, the same number
 * (k + 1/2 and (k + 1) - 1/2 are exact), so each edge is computed once. */
static bool eval_range(const fg_wm_event *e, long lo, long hi, double *y)
{
    const fg_wm_shape *w = &e->shape;
    const double inner = fabs(w->psi - w->s), outer = w->psi + w->s;
    const double slope = w->s < w->psi ? -4.0 * w->b : 0.0;
    double a = ((double)lo - 0.5 - e->center) / e->width;
    int pa = piece(inner, outer, a);
    bool finite = true;
    for (long k = lo; k <= hi; k++) {
        double z = ((double)k + 0.5 - e->center) / e->width;
        int pz = piece(inner, outer, z);
        y[k - lo] = pa == 2 && pz == 2 ? middle_average(slope, outer, a, z)
                                       : sample_average(e, a, z, pa, pz);
        finite = finite && isfinite(y[k - lo]);
        a = z;
        pa = pz;
    }
    return finite;
}

/* The state, samples -3 .. -1, as eval_range(e, -3, -1, y) gives it, bit
 * for bit. A wave sounding through the block's start is evaluated there in
 * every block it spans, mostly inside one piece: when the four edges
 * (ascending) lie in the middle piece, each sample is its middle_average;
 * when they lie in one shell, its sample_average, with the shell's
 * curvature divided once; either without placing each edge. The edges and
 * their piece do not depend on B (state_edges), the values do
 * (fg_wm_state_values). */
static void state_edges(const fg_wm_event *e, fg_wm_state_edges *s)
{
    const fg_wm_shape *w = &e->shape;
    const double inner = fabs(w->psi - w->s), outer = w->psi + w->s;
    for (int j = 0; j < 4; j++)
        s->edge[j] = ((double)(j - 3) - 0.5 - e->center) / e->width;
    const int first = piece(inner, outer, s->edge[0]), last = piece(inner, outer, s->edge[3]);
    s->piece = first == last && first >= 1 && first <= 3 ? first : -1;
}

bool fg_wm_state_values(const fg_wm_state_edges *s, const fg_wm_shape *w, double y[3])
{
    const double *edge = s->edge;
    if (s->piece == 2) {
        const double outer = w->psi + w->s;
        const double slope = w->s < w->psi ? -4.0 * w->b : 0.0;
        for (int j = 0; j < 3; j++)
            y[j] = middle_average(slope, outer, edge[j], edge[j + 1]);
    } else {
        const double curvature = s->piece == 1 ? -2.0 * w->b / w->s : 2.0 * w->b / w->s;
        for (int j = 0; j < 3; j++) {
            double h = edge[j + 1] - edge[j];
            y[j] = fg_wm_pressure(w, 0.5 * (edge[j] + edge[j + 1])) + curvature * h * h / 24.0;
        }
    }
    return isfinite(y[0]) && isfinite(y[1]) && isfinite(y[2]);
}

/* The state of e, from its edges or, where they straddle a breakpoint,
 * its exact range. */
static bool eval_state(const fg_wm_event *e, double y[3])
{
    fg_wm_state_edges s;
    state_edges(e, &s);
    return s.piece < 0 ? eval_range(e, -3, -1, y) : fg_wm_state_values(&s, &e->shape, y);
}

/* Adds the range eval_range gave: state for k < 0, third differences for
 * k >= lo + 3 (earlier ones in the range lie on one quadratic piece and
 * have none). */
static void add_range(fg_accum *b, long lo, long hi, const double *y, double gain)
{
    for (long k = lo; k <= hi && k < 0; k++)
        b->state[-1 - k] += gain * y[k - lo];
    for (long k = lo + 3 > 0 ? lo + 3 : 0; k <= hi; k++)
        b->d3[k] += gain * (y[k - lo] - 3.0 * y[k - lo - 1] + 3.0 * y[k - lo - 2] - y[k - lo - 3]);
}

/* The third differences of one breakpoint at sample position x, in sample
 * m, where the pressure gains a0 + a1 (x' - x) + a2 (x' - x)^2 (per sample
 * units): its running integral G(u) = a0 u + a1 u^2/2 + a2 u^3/3 from x,
 * sampled at sample edges, has a fourth difference that vanishes past four
 * samples. Writes them, at m .. m + 3, to taps; false when they are not
 * finite. */
static bool breakpoint(double x, long m, double a0, double a1, double a2, double taps[4])
{
    double f = (double)m + 0.5 - x, g[4];
    for (int j = 0; j < 4; j++) {
        double u = j + f;
        g[j] = u * (a0 + u * (0.5 * a1 + u * a2 / 3.0));
    }
    taps[0] = g[0];
    taps[1] = g[1] - 4.0 * g[0];
    taps[2] = g[2] - 4.0 * g[1] + 6.0 * g[0];
    taps[3] = g[3] - 4.0 * g[2] + 6.0 * g[1] - 4.0 * g[0];
    return isfinite(taps[0]) && isfinite(taps[1]) && isfinite(taps[2]) && isfinite(taps[3]);
}

/* The sample holding a wave's breakpoint i (0 .. 3, ascending) at x =
 * centre + tau_i width: the outer two are its span's ends first and last
 * (fg_wm_event_span: the same sums), the inner two are placed. */
static long breakpoint_sample(double x, int i, long first, long last)
{
    return i == 0 ? first : i == 3 ? last : fg_wm_sample_at(x);
}

/* Whether a breakpoint in sample m changes the third differences of a
 * block of n (those of m .. m + 3). */
static bool breakpoint_in_block(long m, long n)
{
    return m <= n - 1 && m + 3 >= 0;
}

static void add_breakpoint(fg_accum *b, long m, const double *taps, double gain)
{
    long n = (long)b->n;
    if (!breakpoint_in_block(m, n))
        return;
    for (long q = m < 0 ? -m : 0; q < 4 && m + q < n; q++)
        b->d3[m + q] += gain * taps[q];
}

/* The four breakpoints in closed form, when they lie at least a sample
 * apart in pairs (s w >= 2): jumps of p' and p'' from eq. 5, per tau,
 * scaled to samples. Nearer pairs (broadside, s -> 0) would cancel large
 * terms, so those waves take the exact evaluation around each breakpoint. */
#define CLOSED_FORM_MIN_SW 2.0

/* A wave's numbers are moderate when |B|, psi, the width and its inverse
 * are at most this and s at least its inverse. With s width >= 2 (the
 * closed form's) each jump, scaled to samples, is then at most |B| psi or
 * |B| / (2 width), within 1e200, and every tap finite: u = j + f lies
 * within 2^11 (f is within a sample, or the rounding of an index below
 * 2^62), so each G stays within 2^32 times the jump and each tap within
 * 2^36 times it. */
#define TAP_MODERATE 1e100

static bool moderate(const fg_wm_event *e)
{
    const fg_wm_shape *w = &e->shape;
    return fabs(w->b) <= TAP_MODERATE && w->psi <= TAP_MODERATE && w->s >= 1.0 / TAP_MODERATE &&
           e->width <= TAP_MODERATE && e->width >= 1.0 / TAP_MODERATE;
}

/* Whether e, whose span is first .. last, sounds through the block of n
 * with none of its breakpoints in it. A long wave sounds through most of
 * its blocks so: the outer two's samples are the span's ends, and the
 * sample floor(x + 1/2) holding an inner one lies in the block's -3 .. n
 * - 1 exactly when x + 1/2 lies in [-3, n). */
static bool sounds_through(const fg_wm_event *e, long first, long last, long n)
{
    if (!(first < -3 && last > n - 1))
        return false;
    const double inner = fabs(e->shape.psi - e->shape.s);
    double rising = e->center + -inner * e->width + 0.5;
    double falling = e->center + inner * e->width + 0.5;
    return !(rising >= -3.0 && rising < (double)n) && !(falling >= -3.0 && falling < (double)n);
}

/* The taps of the breakpoints of e, whose span is first .. last, into
 * t->m and t->taps [0 .. t->count); false when one is not finite. When
 * the wave's numbers are moderate (TAP_MODERATE), so that every tap is
 * finite, a breakpoint that falls outside the block of n, which would add
 * nothing (add_breakpoint), is left out: a wave sounding through a block
 * without a breakpoint in it costs its state alone. */
static bool eval_breakpoints(const fg_wm_event *e, long first, long last, long n, fg_wm_taps *t)
{
    const fg_wm_shape *w = &e->shape;
    double s = w->s, psi = w->psi, wd = e->width;
    double inner = fabs(psi - s), outer = psi + s;
    const bool moderate_taps = moderate(e);
    t->count = 0;
    if (moderate_taps && sounds_through(e, first, last, n))
        return true;
    /* in ascending tau: where, and the signs of the jumps of p' and p''
     * there */
    const double taus[4] = {-outer, -inner, inner, outer};
    const double jump1[4] = {1.0, s < psi ? -1.0 : 1.0, s < psi ? 1.0 : -1.0, -1.0};
    const double jump2[4] = {-1.0, 1.0, 1.0, -1.0};
    /* the jumps' sizes in samples, 2 B psi / s and 2 B / s per tau, divided
     * once for every breakpoint: a sign times a quotient is exactly the
     * quotient of the sign times the dividend */
    double a1 = 0.0, a2 = 0.0;
    bool finite = true;
    for (int i = 0; i < 4; i++) {
        double x = e->center + taus[i] * wd;
        long m = breakpoint_sample(x, i, first, last);
        if (moderate_taps && !breakpoint_in_block(m, n))
            continue;
        if (t->count == 0) {
            a1 = 2.0 * w->b * psi / s / wd;
            a2 = 0.5 * (2.0 * w->b / s) / (wd * wd);
        }
        t->m[t->count] = m;
        finite = breakpoint(x, m, 0.0, jump1[i] * a1, jump2[i] * a2, t->taps[t->count++]) &&
                 finite;
    }
    return finite;
}

/* Every value is computed before any is added, so that a wave whose
 * numbers overflow adds nothing (fg_wave_status FG_WAVE_NON_FINITE). */
fg_wave_status fg_wm_accum_add(fg_accum *b, const fg_wm_event *e)
{
    if (!fg_wm_event_in_range(e))
        return FG_WAVE_NON_FINITE;
    long first, last;
    fg_wm_event_span(e, &first, &last);
    fg_wm_taps t;
    fg_wave_status st = fg_wm_taps_eval(e, first, last, (long)b->n, &t);
    if (st == FG_WAVE_SOUNDING)
        fg_wm_taps_add(b, &t, 1.0);
    return st;
}

/* fg_wm_event_in_range but for B is what the caller knows; the span does
 * not depend on B. */
fg_wave_status fg_wm_taps_eval(const fg_wm_event *e, long first, long last, long n,
                               fg_wm_taps *t)
{
    if (!isfinite(e->shape.b))
        return FG_WAVE_NON_FINITE;
    const fg_wm_shape *w = &e->shape;
    if (fg_wm_event_ended(last))
        return FG_WAVE_DONE;
    if (first >= n)
        return FG_WAVE_PENDING;
    t->end = last + 4; /* the last breakpoint's taps reach last + 3 */

    if (w->s * e->width >= CLOSED_FORM_MIN_SW) {
        t->closed_form = true;
        t->state = first < 0;
        if ((t->state && !eval_state(e, t->y[0])) || !eval_breakpoints(e, first, last, n, t))
            return FG_WAVE_NON_FINITE;
        return FG_WAVE_SOUNDING;
    }
    /* Breakpoints, ascending; each disturbs the samples m-3..m+3 around the
     * sample m that holds it. The overlapping neighbourhoods merge. */
    double inner = fabs(w->psi - w->s), outer = w->psi + w->s;
    double taus[4] = {-outer, -inner, inner, outer};
    int ranges = 0;
    t->closed_form = false;
    if (first < 0) {
        t->lo[0] = -3;
        t->hi[0] = -1;
        ranges = 1;
    }
    for (int i = 0; i < 4; i++) {
        long m = breakpoint_sample(e->center + taus[i] * e->width, i, first, last);
        long a = m - 3 < -3 ? -3 : m - 3;
        long z = m + 3 > n - 1 ? n - 1 : m + 3;
        if (a > z)
            continue;
        if (ranges > 0 && a <= t->hi[ranges - 1] + 1) {
            if (z > t->hi[ranges - 1])
                t->hi[ranges - 1] = z;
            continue;
        }
        t->lo[ranges] = a;
        t->hi[ranges] = z;
        ranges++;
    }
    t->count = ranges;
    for (int r = 0; r < ranges; r++)
        if (!(t->lo[r] == -3 && t->hi[r] == -1 ? eval_state(e, t->y[r])
                                               : eval_range(e, t->lo[r], t->hi[r], t->y[r])))
            return FG_WAVE_NON_FINITE;
    return FG_WAVE_SOUNDING;
}

bool fg_wm_through(const fg_wm_event *e, long first, long last, long n, fg_wm_state_edges *s)
{
    if (!sounds_through(e, first, last, n) || !(e->shape.s * e->width >= CLOSED_FORM_MIN_SW) ||
        !moderate(e))
        return false;
    state_edges(e, s);
    return s->piece >= 0;
}

/* add_range's of -3 .. -1: the state alone */
void fg_wm_state_add(fg_accum *b, const double y[3], double gain)
{
    b->state[2] += gain * y[0];
    b->state[1] += gain * y[1];
    b->state[0] += gain * y[2];
}

void fg_wm_taps_add(fg_accum *b, const fg_wm_taps *t, double gain)
{
    fg_accum_hold(b, t->end);
    if (t->closed_form) {
        if (t->state)
            fg_wm_state_add(b, t->y[0], gain);
        for (int i = 0; i < t->count; i++)
            add_breakpoint(b, t->m[i], t->taps[i], gain);
        return;
    }
    for (int r = 0; r < t->count; r++)
        add_range(b, t->lo[r], t->hi[r], t->y[r], gain);
}
