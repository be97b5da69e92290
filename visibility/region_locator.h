// Point -> region, fast: the BSP walk started part-way down the tree.
//
// A Quake tree is deep (e1m1: mean leaf depth 43) and each level of the walk waits for the
// previous one (load the node, dot product, pick the child), so a plain walk costs ~0.4 µs on a
// random point. The locator lays a uniform grid over the zone and stores, per cell, the deepest
// node whose subtree holds the whole cell (found by walking down while the cell lies strictly on
// one side of each plane, with a safety margin). A lookup finds its cell in O(1) and walks only
// the rest of the way. The result is exactly locate_point()'s: every point of a cell takes the
// same branches down to the stored node. Points outside the grid (or NaN) start at the root.
//
// The locator borrows the tree: it must outlive neither the tree nor any change to it.
#pragma once

#include "visibility/math/aabb.h"
#include "visibility/region_lookup.h"

#include <glm/vec3.hpp>
#include <glm/ext/vector_int3.hpp>
#include <vector>

namespace pvs {

class RegionLocator {
public:
    // `bounds` is the space to cover (the zone's bounds); about `target_cells` cells are made.
    RegionLocator(const BspTree& tree, const Aabb& bounds, uint32_t target_cells = 32768);

    PointLocation locate(const glm::vec3& point) const;

    size_t memory_bytes() const { return sizeof(*this) + start_.capacity() * sizeof(int32_t); }
    glm::ivec3 grid_size() const { return dims_; }
    // Mean depth of the stored start nodes: how many levels a lookup skips on average.
    double mean_skipped_depth() const { return mean_skipped_depth_; }

private:
    const BspTree* tree_;
    glm::vec3 origin_{0.0f};
    glm::vec3 inv_cell_{0.0f};
    glm::ivec3 dims_{0};
    std::vector<int32_t> start_; // per cell: node index, or ~leaf when the cell lies in one leaf
    double mean_skipped_depth_ = 0.0;
};

} // namespace pvs
