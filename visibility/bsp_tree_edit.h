// Edits of a BSP tree that make a different view of the same zone.
#pragma once

#include "visibility/zone.h"

namespace pvs {

// The tree of an extruded 2-D map with its floors and ceilings walked past (BspTree::
// first_height_node): each height node is replaced by its child that is not solid, so every
// region becomes a column as high as the world, as a 2-D method (glVIS) sees it. Nodes from
// first_height_node on are dropped. A tree without height nodes is returned unchanged.
// Throws std::invalid_argument when a height node has no solid child or refers to a later
// height node in a cycle (not a tree a loader makes).
BspTree without_height_nodes(const BspTree& tree);

} // namespace pvs
