/* Designer thunder: the skeleton is cut into pieces at the features' ends.
 * Clap and rumble pieces are rebuilt as an arc or a line starting where the
 * channel is; runs of the other pieces keep the original shape, sheared
 * linearly along their length so that they join the rebuilt ones and still
 * end at the strike point. */
#include "designer_internal.h"

/* Spacing of the points that sample an arc or a line. */
#define SAMPLE_M 10.0
#define RUMBLE_MIN_DEG 5.0
#define RUMBLE_SPAN_DEG 30.0

typedef struct piece {
    double u0, u1;      /* fractions of the original length */
    int feature;          /* index into features, or -1 for plain */
} piece;

static int is_rebuilt(const fg_thunder_feature *features, const piece *pc)
{
    return pc->feature >= 0 && features[pc->feature].kind != FG_THUNDER_ROAR;
}

/* Cuts [0, 1] into pieces in order; returns how many. */
static size_t cut(const fg_thunder_feature *features, size_t count, piece *pieces)
{
    size_t n = 0;
    double u = 0;
    for (;;) {
        int next = -1;
        for (size_t i = 0; i < count; i++)
            if (features[i].start >= u && (next < 0 || features[i].start < features[next].start))
                next = (int)i;
        if (next < 0)
            break;
        if (features[next].start > u)
            pieces[n++] = (piece){u, features[next].start, -1};
        pieces[n++] = (piece){features[next].start, features[next].end, next};
        u = features[next].end;
    }
    if (u < 1)
        pieces[n++] = (piece){u, 1, -1};
    return n;
}

/* The run of free pieces [first, last] from *from (the current end) to
 * where the next rebuilt piece starts on the original (or the strike). */
static fg_result shear_run(const fg_skeleton *in, const piece *pieces, size_t first, size_t last,
                           fg_skeleton *out, fg_stretch *stretches)
{
    double len = fg_skeleton_length(in);
    double ua = pieces[first].u0, ub = pieces[last].u1;
    fg_vec3 from = out->p[out->n - 1];
    fg_vec3 da = fg_v3_sub(from, fg_skeleton_at(in, ua * len));
    /* the end of the run stays where the original is: zero offset there */
    fg_result r = FG_OK;
    for (size_t j = first; j <= last && r == FG_OK; j++) {
        const piece *pc = &pieces[j];
        if (pc->feature >= 0)
            stretches[pc->feature].s0 = fg_skeleton_length(out);
        for (size_t i = 0; i < in->n && r == FG_OK; i++) {
            double u = in->s[i] / len;
            if (u <= pc->u0 || u >= pc->u1)
                continue;
            double w = (u - ua) / (ub - ua);
            r = fg_skeleton_push(out, fg_v3_add(in->p[i], fg_v3_scale(da, 1 - w)));
        }
        double w = (pc->u1 - ua) / (ub - ua);
        if (r == FG_OK)
            r = fg_skeleton_push(out, fg_v3_add(fg_skeleton_at(in, pc->u1 * len),
                                                fg_v3_scale(da, 1 - w)));
        if (pc->feature >= 0)
            stretches[pc->feature].s1 = fg_skeleton_length(out);
    }
    return r;
}

/* A clap arc or a rumble line of the piece's length from the current end. */
static fg_result rebuild(const fg_skeleton *in, const fg_thunder_feature *b, const piece *pc,
                         fg_vec3 listener, fg_skeleton *out, fg_stretch *st)
{
    double len = fg_skeleton_length(in), lambda = (pc->u1 - pc->u0) * len;
    fg_vec3 from = out->p[out->n - 1];
    fg_vec3 chord = fg_v3_sub(fg_skeleton_at(in, pc->u1 * len), fg_skeleton_at(in, pc->u0 * len));
    fg_vec3 rv = fg_v3_sub(from, listener);
    double radius = fg_v3_len(rv);
    if (!(radius > 0))
        return FG_ERR_ARGUMENT;
    fg_vec3 n = fg_v3_scale(rv, 1 / radius);
    st->s0 = fg_skeleton_length(out);
    st->radius_m = radius;
    size_t samples = (size_t)ceil(lambda / SAMPLE_M);
    fg_result r = FG_OK;
    if (b->kind == FG_THUNDER_CLAP) {
        if (lambda > FG_PI * radius)
            return FG_ERR_ARGUMENT;
        fg_vec3 t = fg_v3_sub(chord, fg_v3_scale(n, fg_v3_dot(chord, n)));
        t = fg_v3_len(t) > 1e-9 * fg_v3_len(chord) ? fg_v3_unit(t) : fg_v3_perp(n);
        for (size_t j = 1; j <= samples && r == FG_OK; j++) {
            double phi = lambda / radius * (double)j / (double)samples;
            fg_vec3 dir = fg_v3_add(fg_v3_scale(n, cos(phi)), fg_v3_scale(t, sin(phi)));
            r = fg_skeleton_push(out, fg_v3_add(listener, fg_v3_scale(dir, radius)));
        }
    } else {
        /* Toward the listener only when the channel was going that way and
         * the line stops well short of the listener. */
        fg_vec3 radial = fg_v3_dot(chord, n) < 0 && lambda <= 0.5 * radius ? fg_v3_scale(n, -1) : n;
        fg_vec3 w = fg_v3_sub(chord, fg_v3_scale(radial, fg_v3_dot(chord, radial)));
        w = fg_v3_len(w) > 1e-9 * fg_v3_len(chord) ? fg_v3_unit(w) : fg_v3_perp(radial);
        double delta = ((1 - fg_thunder_amplitude(b)) * RUMBLE_SPAN_DEG + RUMBLE_MIN_DEG) * FG_PI / 180;
        fg_vec3 dir = fg_v3_add(fg_v3_scale(radial, cos(delta)), fg_v3_scale(w, sin(delta)));
        for (size_t j = 1; j <= samples && r == FG_OK; j++)
            r = fg_skeleton_push(out, fg_v3_add(from, fg_v3_scale(dir, lambda * (double)j /
                                                                      (double)samples)));
    }
    st->s1 = fg_skeleton_length(out);
    return r;
}

fg_result fg_designer_shape(const fg_skeleton *in, const fg_thunder_feature *features, size_t count,
                            fg_vec3 listener, fg_skeleton *out, fg_stretch *stretches)
{
    piece pieces[2 * FG_THUNDER_MAX_FEATURES + 1];
    size_t n = cut(features, count, pieces);
    fg_result r = fg_skeleton_push(out, in->p[0]);
    for (size_t j = 0; j < n && r == FG_OK; j++) {
        if (pieces[j].feature >= 0)
            stretches[pieces[j].feature].radius_m =
                fg_v3_len(fg_v3_sub(out->p[out->n - 1], listener));
        if (is_rebuilt(features, &pieces[j])) {
            r = rebuild(in, &features[pieces[j].feature], &pieces[j], listener, out,
                        &stretches[pieces[j].feature]);
            continue;
        }
        size_t last = j;
        while (last + 1 < n && !is_rebuilt(features, &pieces[last + 1]))
            last++;
        r = shear_run(in, pieces, j, last, out, stretches);
        j = last;
    }
    for (size_t i = 0; i + 1 < out->n && r == FG_OK; i++)
        if (out->p[i].z < 0)
            r = FG_ERR_ARGUMENT;
    return r;
}
