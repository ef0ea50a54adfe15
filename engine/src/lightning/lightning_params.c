/* The statistical-lightning parameters: checks and defaults (rules in
 * fulgur/lightning.h). */
#include <math.h>

#include "fg_rules.h"
#include "fulgur/lightning.h"
#include "fulgur/sound.h"

#define DEFAULT_HEIGHT_M 5000.0
#define DEFAULT_TURN_MEAN_DEG 16.0
#define DEFAULT_MAX_DEVIATION_DEG 45.0
#define DEFAULT_LOOKAHEAD_M 60.0
#define DEFAULT_BRANCH_PROBABILITY 0.0137
#define DEFAULT_BRANCH_LENGTH_M 400.0
#define DEFAULT_BRANCH_DEPTH 2
#define DEFAULT_MAX_NODES 1000000
#define MAX_BRANCH_DEPTH 8

static int finite_n(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

static fg_result check_skeleton(const double *k, size_t n)
{
    if (n < 2 || n > FG_LIGHTNING_MAX_SKELETON)
        return FG_ERR_ARGUMENT;
    if (!finite_n(k, 3 * n))
        return FG_ERR_NOT_FINITE;
    if (k[2] <= 0)
        return FG_ERR_ARGUMENT;
    for (size_t i = 0; i < n; i++) {
        const double *p = &k[3 * i];
        if (p[2] < 0 || (i > 0 && p[0] == p[-3] && p[1] == p[-2] && p[2] == p[-1]))
            return FG_ERR_ARGUMENT;
    }
    return FG_OK;
}

static fg_result check_features(const fg_thunder_feature *b, size_t n)
{
    if (n > FG_THUNDER_MAX_FEATURES)
        return FG_ERR_ARGUMENT;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(b[i].start) || !isfinite(b[i].end) || !isfinite(b[i].amplitude))
            return FG_ERR_NOT_FINITE;
        if (b[i].kind < FG_THUNDER_CLAP || b[i].kind > FG_THUNDER_ROAR ||
            !(b[i].start >= 0 && b[i].start < b[i].end && b[i].end <= 1) ||
            b[i].amplitude < 0 || b[i].amplitude > 1)
            return FG_ERR_ARGUMENT;
        /* the channel must keep a free stretch after a rebuilt one to reach
         * the strike point */
        if (b[i].kind != FG_THUNDER_ROAR && b[i].end == 1)
            return FG_ERR_ARGUMENT;
        for (size_t j = 0; j < i; j++)
            if (b[i].start < b[j].end && b[j].start < b[i].end)
                return FG_ERR_ARGUMENT;
    }
    return FG_OK;
}

fg_result fg_lightning_config_resolve(const fg_lightning_config *in, fg_lightning_config *out)
{
    if (!in || !out)
        return FG_ERR_NULL;
    fg_lightning_config p = *in;
    if ((!p.skeleton_m && p.skeleton_points > 0) || (!p.features && p.feature_count > 0))
        return FG_ERR_NULL;
    double nums[] = {p.strike_m[0], p.strike_m[1], p.height_m, p.in_cloud_m,
                     p.in_cloud_azimuth_deg, p.segment_m, p.turn_mean_deg,
                     p.max_deviation_deg, p.lookahead_m, p.branch_probability,
                     p.branch_length_m, p.listener_m[0], p.listener_m[1], p.listener_m[2]};
    if (!finite_n(nums, sizeof nums / sizeof nums[0]))
        return FG_ERR_NOT_FINITE;
    if (p.height_m < 0 || p.in_cloud_m < 0 || p.segment_m < 0 || p.turn_mean_deg < 0 ||
        p.turn_mean_deg >= 90 || p.max_deviation_deg < 0 || p.max_deviation_deg >= 180 ||
        p.lookahead_m < 0 || p.branch_probability > 1 || p.branch_length_m < 0 ||
        p.branch_depth > MAX_BRANCH_DEPTH)
        return FG_ERR_ARGUMENT;
    fg_result r;
    if (p.skeleton_m && (r = check_skeleton(p.skeleton_m, p.skeleton_points)) != FG_OK)
        return r;
    if ((r = check_features(p.features, p.feature_count)) != FG_OK)
        return r;
    p.height_m = FG_DEF(p.height_m, DEFAULT_HEIGHT_M);
    fg_preset_scale scale;
    if (fg_preset_get_scale(FG_PRESET_LIGHTNING, &scale) != FG_OK)
        return FG_ERR_ARGUMENT;
    p.segment_m = FG_DEF(p.segment_m, 2 * scale.half_step_m); /* a segment is 2 l long */
    p.turn_mean_deg = FG_DEF(p.turn_mean_deg, DEFAULT_TURN_MEAN_DEG);
    p.max_deviation_deg = FG_DEF(p.max_deviation_deg, DEFAULT_MAX_DEVIATION_DEG);
    p.lookahead_m = FG_DEF(p.lookahead_m, DEFAULT_LOOKAHEAD_M);
    p.branch_probability = FG_DEF(p.branch_probability, DEFAULT_BRANCH_PROBABILITY);
    p.branch_length_m = FG_DEF(p.branch_length_m, DEFAULT_BRANCH_LENGTH_M);
    p.branch_depth = FG_DEF(p.branch_depth, DEFAULT_BRANCH_DEPTH);
    p.max_nodes = FG_DEF(p.max_nodes, DEFAULT_MAX_NODES);
    *out = p;
    return FG_OK;
}

