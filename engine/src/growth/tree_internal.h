/* Tree helpers shared by the generators. */
#ifndef FULGUR_TREE_INTERNAL_H
#define FULGUR_TREE_INTERNAL_H

#include <stddef.h>

#include "fulgur/tree.h"

/* Flags node and its ancestors up to the root with FG_NODE_MAIN (the main
 * channel, root -> the node that reached the target); returns how many. */
size_t fg_nodes_mark_main(fg_node *nodes, size_t node);

#endif
