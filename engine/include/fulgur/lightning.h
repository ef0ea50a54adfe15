/* fulgur — statistical lightning and designer thunder (Glassner, "The
 * Digital Ceraunoscope", parts 1 and 2).
 *
 * A skeleton (a polyline from the cloud end, the root, to the strike point
 * on the ground; given, or drawn at random) is walked with straight
 * segments of segment_m (3 m: twice the lightning preset's half-step l,
 * Glassner's "fine-structure length"). At every step the direction turns by
 * an angle theta drawn from a half-normal law of mean turn_mean_deg (16
 * degrees: Hill's measured mean direction change, which Glassner's part 1
 * uses) toward an azimuth that is uniform while the walk heads within
 * max_deviation_deg of its heading, and is pulled toward the heading as the
 * deviation grows (azimuth = that of the heading + pi (1 - k) U(-1,1),
 * k = deviation / max_deviation_deg, at most 1). The heading of the main
 * channel points at the skeleton lookahead_m ahead of the walk's projection
 * on it, so the channel is tortuous yet follows the skeleton. The turn law
 * is exact: the angles between consecutive segments are the drawn thetas
 * (except on clap stretches, below, and within 4 segments of the skeleton's
 * end, which the walk joins in a straight line).
 *
 * The random skeleton: its root at height_m, drifted up to 0.2 height_m
 * sideways from the strike point, then eight pieces down to the strike, each
 * joint jittered up to 0.08 height_m sideways and 0.04 height_m up or down.
 *
 * Branches: every node of a channel of depth below branch_depth (the main
 * channel has depth 0) starts a branch with probability branch_probability.
 * The turn law's mean and the branch probability are given for the 3 m
 * step; at another segment_m they are scaled by sqrt(segment_m / 3) and
 * segment_m / 3 (at most 1), so that a tree turns and branches as much per
 * metre of channel, and sounds the same (the line integral,
 * docs/sound-model.md), whatever its step.
 * A branch leaves its parent's direction turned by an angle uniform in
 * [20, 50] degrees at a uniform azimuth, keeps that heading with the same
 * turn law, and runs for a length drawn from an exponential law of mean
 * branch_length_m / 2^(depth - 1); it stops early at the ground. Branches
 * are grown after the main channel, first-come first-grown, so the main
 * channel is nodes 0 .. main_nodes - 1, each flagged FG_NODE_MAIN.
 *
 * The in-cloud channel (in_cloud_m >= segment_m; none by default): a
 * cloud-to-ground flash also runs for kilometres horizontally inside the
 * cloud. After the main channel and all its branches, a second channel is
 * walked from the root (node 0) along a horizontal course of length
 * L = in_cloud_m at the root's height toward in_cloud_azimuth_deg
 * (counter-clockwise from +x), cut into the random skeleton's eight pieces
 * with its joints jittered up to 0.08 L in x and in y and up to
 * 0.04 min(L, root height) up or down, with the main channel's rules: the
 * same turn law, lookahead and straight finish on the course's end, so its
 * far end lies exactly L from the root horizontally, at the root's height,
 * and the same branching (its branches are first order, grown last). It is
 * not flagged FG_NODE_MAIN: the return stroke climbs the main channel and
 * then runs out along it like a branch (so its sound arrives later), and
 * the later strokes, which re-emit the main channel only, leave it out. It
 * stops early at the ground, if it reaches it. Nothing of it is drawn when
 * in_cloud_m is below segment_m (0 included), so the tree is then the one
 * grown without the option, node for node; with it, that tree is kept as
 * nodes 0 .. in_cloud_first - 1 and the in-cloud channel and its branches
 * follow.
 *
 * Designer thunder (Glassner part 2): features placed along the skeleton
 * (start and end as fractions of its length from the root) reshape it
 * before the walk:
 *   clap   the stretch becomes an arc of a circle centred on the listener,
 *          of the radius of the skeleton's point at `start`, heading the way
 *          the original stretch went. On it the walk keeps the tortuous turns
 *          but not their radial part: it closes on the radius by at most
 *          0.7 segment_m per step and then stays on it, so every arrival from
 *          the stretch coincides (at distance_m / c).
 *   rumble the stretch becomes a straight line (1 - a) 30 + 5 degrees off the
 *          line of sight (a = amplitude): nearly end-on, so its arrivals are
 *          spread over about its length / c.
 *   roar   the stretch keeps its course but turns harder: the mean turn is
 *          multiplied by 1 + 3 a.
 * A clap or rumble stretch starts at the skeleton's own point at `start`
 * (or where the feature before it ended, if they touch); the plain stretches
 * between them are the original skeleton sheared linearly to join the ends,
 * so the channel still ends at the strike point.
 */
#ifndef FULGUR_LIGHTNING_H
#define FULGUR_LIGHTNING_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/result.h"
#include "fulgur/tree.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Features of one design at most. */
#define FG_THUNDER_MAX_FEATURES 16
/* Skeleton points at most. */
#define FG_LIGHTNING_MAX_SKELETON 65536

typedef enum fg_thunder_kind {
    FG_THUNDER_CLAP = 1,
    FG_THUNDER_RUMBLE = 2,
    FG_THUNDER_ROAR = 3
} fg_thunder_kind;

typedef struct fg_thunder_feature {
    fg_thunder_kind kind;
    double start, end;  /* fractions of the skeleton's length from the root:
                           0 <= start < end <= 1 */
    double amplitude;   /* strength of the shaping, (0, 1]; 0 means 1 */
} fg_thunder_feature;

/* Zero in any field means the default given in its comment. */
typedef struct fg_lightning_config {
    const double *skeleton_m;   /* x,y,z triples, root first; borrowed for the call.
                                   NULL: a random cloud-to-ground skeleton */
    size_t skeleton_points;     /* 2 .. FG_LIGHTNING_MAX_SKELETON when given */
    double strike_m[2];         /* random skeleton: x, y of the strike point (z = 0) */
    double height_m;            /* random skeleton: height of the root: 5000 */
    double in_cloud_m;          /* horizontal course of the in-cloud channel from the
                                   root, m: 0 (none; so is any length below segment_m) */
    double in_cloud_azimuth_deg; /* its direction, counter-clockwise from +x: 0 */
    double segment_m;           /* walk step: 3 (2 l of the lightning preset) */
    double turn_mean_deg;       /* mean direction change per 3 m segment: 16; < 90;
                                   times sqrt(segment_m / 3) at another step */
    double max_deviation_deg;   /* free wander from the heading: 45; < 180 */
    double lookahead_m;         /* main channel's heading target ahead on the skeleton: 60 */
    double branch_probability;  /* per node of a 3 m segment: 0.0137; times
                                   segment_m / 3 (at most 1) at another step;
                                   negative: no branches; <= 1 */
    double branch_length_m;     /* mean length of a first-order branch: 400 */
    uint32_t branch_depth;      /* deepest branch order: 2; at most 8 */
    const fg_thunder_feature *features; /* borrowed for the call; NULL if feature_count is 0 */
    size_t feature_count;       /* at most FG_THUNDER_MAX_FEATURES */
    double listener_m[3];       /* where the designed thunder is heard */
    uint32_t max_nodes;         /* refuse to grow past this many nodes: 1000000 */
    uint64_t seed;              /* same seed, same tree */
} fg_lightning_config;

/* Where each feature ended up on the main channel. */
typedef struct fg_lightning_stretch {
    size_t first_node, last_node; /* main-channel nodes whose projection on the
                                     skeleton falls in the feature (inclusive);
                                     first_node = main_nodes if none does */
    double distance_m;            /* listener to the skeleton at the feature's start;
                                     for a clap, the arc's radius */
} fg_lightning_stretch;

typedef struct fg_lightning_report {
    size_t main_nodes;        /* nodes 0 .. main_nodes - 1: root to the strike */
    size_t segments;          /* all nodes but the root */
    double main_length_m;     /* length of the main channel */
    double skeleton_length_m; /* length of the (reshaped) skeleton */
    size_t in_cloud_first;    /* the in-cloud channel is nodes in_cloud_first ..
                                 in_cloud_first + in_cloud_nodes - 1, root side first; */
    size_t in_cloud_nodes;    /* 0 without one (in_cloud_first is then the node count) */
    double in_cloud_length_m; /* its length along the channel */
    fg_lightning_stretch features[FG_THUNDER_MAX_FEATURES]; /* in the order given */
} fg_lightning_report;

/* Copies *in to *out with every zero field replaced by its default (the
 * pointers are copied, not the arrays). [any-thread]
 * Errors: FG_ERR_NULL in/out, or skeleton_m NULL with skeleton_points > 0,
 * or features NULL with feature_count > 0; FG_ERR_NOT_FINITE a NaN/inf number,
 * skeleton point or feature field; FG_ERR_ARGUMENT a negative length or
 * angle (in_cloud_azimuth_deg may be any finite angle), turn_mean_deg >= 90,
 * max_deviation_deg >= 180, branch_probability > 1, branch_depth > 8, fewer than 2 or more than
 * FG_LIGHTNING_MAX_SKELETON skeleton points, a skeleton point below the
 * ground or the root on it, two consecutive skeleton points equal, more
 * than FG_THUNDER_MAX_FEATURES features, an unknown kind, a feature outside
 * 0 <= start < end <= 1, amplitude outside [0, 1], two features
 * overlapping. *out is written only on success. */
FG_API FG_NODISCARD fg_result fg_lightning_config_resolve(const fg_lightning_config *in,
                                                          fg_lightning_config *out);

/* Reshapes the skeleton for the features, walks it and grows the branches,
 * appending the bolt to out, which must be empty (root = node 0, at the
 * skeleton's root). report (may be NULL) receives the figures above. out
 * stays owned by the caller. Deterministic for a given seed. [sim-thread]
 * Errors: those of fg_lightning_config_resolve; FG_ERR_NULL out;
 * FG_ERR_ARGUMENT out not empty, or a clap/rumble shape that would take
 * the skeleton below the ground; FG_ERR_UNREACHABLE the walk did not reach
 * the skeleton's end within 50 times its length; FG_ERR_CAPACITY more than
 * max_nodes nodes; FG_ERR_NO_MEMORY. On any error out is left empty and
 * *report untouched. */
FG_API FG_NODISCARD fg_result fg_lightning_generate(const fg_lightning_config *config,
                                                    fg_tree *out, fg_lightning_report *report);

#ifdef __cplusplus
}
#endif

#endif
