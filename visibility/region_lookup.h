// Point -> region: the BSP walk every frame starts with.
//
// An iterative walk from the root: at each node the signed distance d to the split plane picks
// the front child (d > 0) or the back child (d < 0). A point exactly on a plane (d == 0) goes
// where the zone's TieRule says, so each format matches its own engine:
//   Quake   (TieRule::OnPlaneGoesBack):  d > 0 front, else back   (Mod_PointInLeaf)
//   EverQuest (TieRule::OnPlaneGoesFront): d >= 0 front, else back (every EverQuest reader)
// A NaN coordinate compares false everywhere and so follows the back children: the walk still
// ends in a leaf. The tree must be acyclic (loaders validate that), so the walk always ends.
#pragma once

#include "visibility/zone.h"

#include <glm/vec3.hpp>

namespace pvs {

struct PointLocation {
    int32_t leaf = -1;   // index into BspTree::leaf_region
    int32_t region = -1; // region id, or kLeafSolid / kLeafOutside when the point is not in a region

    bool in_region() const { return region >= 0; }
};

PointLocation locate_point(const BspTree& tree, const glm::vec3& point);
// The same walk from an inner node (or ~leaf) instead of the root; see RegionLocator.
PointLocation locate_point_from(const BspTree& tree, int32_t start, const glm::vec3& point);

// The nodes the walk for `point` passes through, root first, with the child taken at each
// (0 front, 1 back): what the inspector highlights as the camera's path. Replaces `out`.
struct PathStep {
    uint32_t node;
    uint8_t side;
};
PointLocation trace_point(const BspTree& tree, const glm::vec3& point, std::vector<PathStep>& out);

} // namespace pvs
