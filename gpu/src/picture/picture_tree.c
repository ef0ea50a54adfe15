/* A discharge tree into segment instances: path lengths for the leader,
 * and the channel level (branching depth) for width and brightness.
 *
 * Depth: 0 on the main channel (nodes flagged FG_NODE_MAIN, or, when none
 * is, the path from the root to the node farthest from it — the engine's
 * rule). A child of a main node that is not itself main starts a branch of
 * depth 1. Off the main channel, the child of a node that continues the
 * branch is the one leading to the longest path below it (first wins a
 * tie); every other child starts a new branch one level deeper. */
#include <math.h>
#include <stdlib.h>

#include "picture_internal.h"

/* Half-width radius * 0.6^depth, brightness 0.4^depth: branches are
 * thinner and dimmer than the channel they leave (the current divides).
 * A glow discharge (a plasma ball's filaments, continuous) carries current
 * in every filament that reaches the glass: 0.8^depth and 0.7^depth. */
#define LEVEL_WIDTH_RATIO 0.6
#define LEVEL_BRIGHTNESS_RATIO 0.4
#define GLOW_WIDTH_RATIO 0.8
#define GLOW_BRIGHTNESS_RATIO 0.7
/* The default main-channel half-width, a fraction of the extent: a glow
 * discharge's filaments are diffuse, wider. */
#define DEFAULT_RADIUS_FRACTION 0.01
#define GLOW_RADIUS_FRACTION 0.02

double fgg_picture_level_width(int depth, int continuous)
{
    return pow(continuous ? GLOW_WIDTH_RATIO : LEVEL_WIDTH_RATIO, depth);
}

double fgg_picture_level_brightness(int depth, int continuous)
{
    return pow(continuous ? GLOW_BRIGHTNESS_RATIO : LEVEL_BRIGHTNESS_RATIO, depth);
}

static double seg_length(const fg_node *nodes, size_t i)
{
    const fg_node *a = &nodes[nodes[i].parent], *b = &nodes[i];
    return sqrt((b->x - a->x) * (b->x - a->x) + (b->y - a->y) * (b->y - a->y) +
                (b->z - a->z) * (b->z - a->z));
}

/* Marks the main channel into main[]. */
static void find_main(const fg_node *nodes, size_t count, unsigned char *main)
{
    int any = 0;
    for (size_t i = 0; i < count; i++) {
        main[i] = (nodes[i].flags & FG_NODE_MAIN) != 0;
        any |= main[i];
    }
    main[0] = 1;
    if (any)
        return;
    size_t far = 0;
    double best = -1;
    for (size_t i = 1; i < count; i++) {
        double dx = nodes[i].x - nodes[0].x, dy = nodes[i].y - nodes[0].y,
               dz = nodes[i].z - nodes[0].z, d = dx * dx + dy * dy + dz * dz;
        if (d > best) {
            best = d;
            far = i;
        }
    }
    for (size_t i = far; i != 0; i = (size_t)nodes[i].parent)
        main[i] = 1;
}

/* The light points: FGG_FLASH_LIGHTS places at even steps of the summed
 * length x brightness of the segments (in node order), each on the
 * segment where its step falls. */
static void light_points(const float *seg, size_t n, fgg_flash_rec *rec)
{
    double total = 0;
    for (size_t i = 0; i < n; i++) {
        const float *s = &seg[i * FGG_SEGMENT_FLOATS];
        total += (s[7] - s[3]) * s[9];
    }
    rec->light_count = rec->light_main_count = 0;
    if (!(total > 0))
        return;
    double sum = 0;
    size_t k = 0;
    for (size_t i = 0; i < n && k < FGG_FLASH_LIGHTS; i++) {
        const float *s = &seg[i * FGG_SEGMENT_FLOATS];
        double w = (s[7] - s[3]) * s[9];
        while (k < FGG_FLASH_LIGHTS && sum + w >= (k + 0.5) * total / FGG_FLASH_LIGHTS) {
            double u = w > 0 ? ((k + 0.5) * total / FGG_FLASH_LIGHTS - sum) / w : 0.5;
            for (int c = 0; c < 3; c++)
                rec->light_m[k][c] = s[c] + u * (s[4 + c] - s[c]);
            rec->light_path_m[k] = s[3] + u * (s[7] - s[3]);
            rec->light_main[k] = s[10] > 0.5f;
            rec->light_main_count += rec->light_main[k];
            k++;
        }
        sum += w;
    }
    rec->light_count = k;
}

fg_result fgg_picture_tree_segments(const fg_node *nodes, size_t count, double radius_m,
                                    int continuous, fgg_flash_rec *rec)
{
    size_t n = count - 1;
    double *path = calloc(count, sizeof *path);
    double *below = calloc(count, sizeof *below); /* the longest path under the node */
    long *cont = malloc(count * sizeof *cont);    /* the child continuing the branch */
    int *depth = calloc(count, sizeof *depth);
    unsigned char *main = calloc(count, 1), *has_child = calloc(count, 1);
    float *seg = malloc(n * FGG_SEGMENT_FLOATS * sizeof *seg);
    if (!path || !below || !cont || !depth || !main || !has_child || !seg) {
        free(path), free(below), free(cont), free(depth), free(main), free(has_child), free(seg);
        return fgg_fail(FG_ERR_NO_MEMORY, "picture: no memory for %zu segments", n);
    }
    find_main(nodes, count, main);
    double lo[3] = {nodes[0].x, nodes[0].y, nodes[0].z}, hi[3] = {lo[0], lo[1], lo[2]};
    for (size_t i = 1; i < count; i++) {
        path[i] = path[nodes[i].parent] + seg_length(nodes, i);
        has_child[nodes[i].parent] = 1;
        const double p[3] = {nodes[i].x, nodes[i].y, nodes[i].z};
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], p[k]);
            hi[k] = fmax(hi[k], p[k]);
        }
    }
    /* Parents come before children: backwards, every child is done first. */
    for (size_t i = count - 1; i > 0; i--) {
        size_t p = (size_t)nodes[i].parent;
        below[p] = fmax(below[p], below[i] + seg_length(nodes, i));
    }
    for (size_t i = 0; i < count; i++)
        cont[i] = -1;
    for (size_t i = 1; i < count; i++) {
        size_t p = (size_t)nodes[i].parent;
        double reach = below[i] + seg_length(nodes, i);
        if (cont[p] < 0 || reach > below[cont[p]] + seg_length(nodes, (size_t)cont[p]))
            cont[p] = (long)i;
    }
    double extent = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                         (hi[2] - lo[2]) * (hi[2] - lo[2]));
    double radius = radius_m > 0 ? radius_m
                    : (continuous ? GLOW_RADIUS_FRACTION : DEFAULT_RADIUS_FRACTION) * extent;
    double longest = 0;
    for (size_t i = 1; i < count; i++) {
        size_t p = (size_t)nodes[i].parent;
        if (main[i])
            depth[i] = 0;
        else if (main[p])
            depth[i] = 1;
        else
            depth[i] = depth[p] + (cont[p] == (long)i ? 0 : 1);
        longest = fmax(longest, path[i]);
        float *s = &seg[(i - 1) * FGG_SEGMENT_FLOATS];
        s[0] = (float)(nodes[p].x - nodes[0].x);
        s[1] = (float)(nodes[p].y - nodes[0].y);
        s[2] = (float)(nodes[p].z - nodes[0].z);
        s[3] = (float)path[p];
        s[4] = (float)(nodes[i].x - nodes[0].x);
        s[5] = (float)(nodes[i].y - nodes[0].y);
        s[6] = (float)(nodes[i].z - nodes[0].z);
        s[7] = (float)path[i];
        s[8] = (float)(radius * fgg_picture_level_width(depth[i], continuous));
        s[9] = (float)fgg_picture_level_brightness(depth[i], continuous);
        s[10] = main[i] ? 1.0f : 0.0f;
        s[11] = has_child[i] ? 0.0f : 1.0f;
        s[12] = s[13] = s[14] = s[15] = 0.0f;
    }
    rec->origin_m[0] = nodes[0].x;
    rec->origin_m[1] = nodes[0].y;
    rec->origin_m[2] = nodes[0].z;
    rec->path_m = longest;
    rec->extent_m = extent;
    rec->segments = seg;
    rec->segment_count = n;
    light_points(seg, n, rec);
    free(path), free(below), free(cont), free(depth), free(main), free(has_child);
    return FG_OK;
}
