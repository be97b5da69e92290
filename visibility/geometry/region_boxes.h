// Boxes that hold each region's volume, from the BSP tree alone (a region's `bounds` may be the
// box of its geometry only, as EverQuest files give it, smaller than the space a camera can be
// in).
//
// The world box goes down the tree: an axis-aligned split cuts it exactly into its children's
// boxes; any other plane leaves the box whole on both sides (a superset). A region's box is the
// union of its leaves' boxes. So every point of a region inside `world` is inside its box, and on
// zones whose trees split on axes only (EverQuest zones, generated zones) the box is the region's
// leaf box exactly. Leaves reached from several slots get the union of their slots' boxes. An
// empty box for a region with no leaf in `world`. Walks a tree with a cycle or a bad child no
// further than its node count.
#pragma once

#include "visibility/math/aabb.h"
#include "visibility/zone.h"

#include <vector>

namespace pvs {

std::vector<Aabb> region_volume_boxes(const BspTree& tree, size_t region_count, const Aabb& world);

} // namespace pvs
