/* fulgur — the discharge tree: what is drawn and what is heard.
 *
 * A tree is an array of nodes. Node 0 is the root (where the leader
 * started, parent -1); every other node names a parent that comes before it,
 * so an array that passes fg_tree_check has no cycles. Each non-root node and
 * its parent form one segment. Positions are metres, z up, ground at z = 0.
 */
#ifndef FULGUR_TREE_H
#define FULGUR_TREE_H

#include <stddef.h>
#include <stdint.h>

#include "fulgur/defs.h"
#include "fulgur/result.h"

#ifdef __cplusplus
extern "C" {
#endif
/* The engine's limits on a tree's geometry (docs/limits.md), checked by
 * fg_tree_check:
 *   every coordinate within +-FG_TREE_MAX_COORDINATE_M: 10 000 km from the
 *   origin, beyond the Earth's radius (6371 km): no ear hears a discharge
 *   farther, and every distance and its square stay finite;
 *   every segment at least FG_TREE_MIN_SEGMENT_M long: 15 times the mean
 *   free path of air (68 nm at 20 degC and 1 atm), below which the
 *   continuum acoustics every wave model here rests on means nothing; the
 *   shortest preset segment (spark_balls, 2 mm) is 2000 times longer. */
#define FG_TREE_MAX_COORDINATE_M 1e7
#define FG_TREE_MIN_SEGMENT_M 1e-6

/* Node flags. */
enum {
    /* The node lies on the main channel (root -> the node that reached the
     * target). Dart leaders of later strokes re-emit only segments whose
     * child node carries this flag. If no node of a tree carries it, the
     * engine takes the path from the root to the node farthest from it. */
    FG_NODE_MAIN = 1u << 0
};

typedef struct fg_node {
    double x, y, z;   /* metres */
    int32_t parent;   /* index of the parent node, -1 for the root */
    uint32_t flags;   /* FG_NODE_* */
} fg_node;

/* What is wrong with a tree, for messages that name the node. */
typedef enum fg_tree_fault_kind {
    FG_TREE_FAULT_NONE = 0,
    FG_TREE_FAULT_TOO_FEW_NODES,  /* fewer than 2 nodes: no segment */
    FG_TREE_FAULT_ROOT,           /* node 0 has a parent, or another node has none */
    FG_TREE_FAULT_PARENT_ORDER,   /* parent is not before the node (would allow cycles) */
    FG_TREE_FAULT_NOT_FINITE,     /* a coordinate is NaN or infinite */
    FG_TREE_FAULT_ZERO_LENGTH,    /* the node coincides with its parent */
    FG_TREE_FAULT_TOO_FAR,        /* a coordinate beyond +-FG_TREE_MAX_COORDINATE_M */
    FG_TREE_FAULT_TOO_SHORT       /* its segment is shorter than FG_TREE_MIN_SEGMENT_M */
} fg_tree_fault_kind;

typedef struct fg_tree_fault {
    fg_tree_fault_kind kind;
    size_t node;        /* index of the offending node */
    int32_t parent;     /* its parent, for FG_TREE_FAULT_PARENT_ORDER */
    double value;       /* the coordinate (TOO_FAR) or the segment's length (TOO_SHORT), m */
} fg_tree_fault;

/* Checks a node array against the rules and limits above. On failure fills *fault (if
 * not NULL) with the first offending node. Reads only; owns nothing.
 * [any-thread]
 * Errors: FG_ERR_NULL nodes is NULL; FG_ERR_TREE a rule is broken. */
FG_API FG_NODISCARD fg_result fg_tree_check(const fg_node *nodes, size_t count,
                                            fg_tree_fault *fault);

/* A human-readable sentence for a fault, e.g. "parent 9 is not before node 7",
 * written into buf (always NUL-terminated, truncated to size). [any-thread] */
FG_API void fg_tree_fault_describe(const fg_tree_fault *fault, char *buf, size_t size);

/* Moves every node of nodes[0..count) by offset_m (metres): x += offset_m[0]
 * and so on, parents and flags untouched. The caller owns nodes. NULL nodes
 * with count > 0, or a NULL offset, is a programmer error. [any-thread] */
FG_API void fg_tree_translate(fg_node *nodes, size_t count, const double offset_m[3]);

/* A growable tree owned by the caller, used by the generators. */
typedef struct fg_tree fg_tree;

/* Creates an empty tree with room for capacity_hint nodes (it grows as
 * needed). *out is owned by the caller until fg_tree_destroy. [sim-thread]
 * Errors: FG_ERR_NULL out is NULL; FG_ERR_NO_MEMORY. */
FG_API FG_NODISCARD fg_result fg_tree_create(size_t capacity_hint, fg_tree **out);

/* Frees the tree; NULL is a no-op. [sim-thread] */
FG_API void fg_tree_destroy(fg_tree *tree);

/* Appends a node and returns its index in *index (may be NULL). The parent
 * must be -1 for the first node and an existing index otherwise.
 * [sim-thread]
 * Errors: FG_ERR_NULL tree; FG_ERR_NOT_FINITE a coordinate; FG_ERR_TREE bad
 * parent; FG_ERR_NO_MEMORY. On error the tree is unchanged. */
FG_API FG_NODISCARD fg_result fg_tree_add(fg_tree *tree, double x, double y, double z,
                                          int32_t parent, uint32_t flags, size_t *index);

/* Removes every node, keeping the storage. [sim-thread] */
FG_API void fg_tree_clear(fg_tree *tree);

/* The nodes, valid until the next fg_tree_add, fg_tree_clear or
 * fg_tree_destroy. Callers may change flags in place. [sim-thread] */
FG_API fg_node *fg_tree_nodes(fg_tree *tree);
FG_API size_t fg_tree_count(const fg_tree *tree);

#ifdef __cplusplus
}
#endif

#endif
