#include "visibility/region_locator.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace pvs {

namespace {

// Walks down from the root while the box lies strictly on one side of the node's plane, with a
// margin that covers float rounding of both the point's plane distance and its cell index.
int32_t deepest_enclosing(const BspTree& tree, const glm::vec3& center, const glm::vec3& half, float margin,
                          uint32_t& depth)
{
    int32_t child = tree.root;
    depth = 0;
    while (child >= 0) {
        const BspNode& node = tree.nodes[child];
        const float d = glm::dot(node.normal, center) - node.dist;
        const float r = glm::dot(glm::abs(node.normal), half) + margin;
        if (d - r > 0.0f)
            child = node.children[0];
        else if (d + r < 0.0f)
            child = node.children[1];
        else
            break;
        ++depth;
    }
    return child;
}

} // namespace

RegionLocator::RegionLocator(const BspTree& tree, const Aabb& bounds, uint32_t target_cells) : tree_(&tree)
{
    if (bounds.empty() || tree.root < 0 || target_cells == 0)
        return; // every lookup starts at the root
    const glm::vec3 size = glm::max(bounds.size(), glm::vec3(1.0f));
    // Cubic cells sized so the grid has about target_cells cells.
    const float cell = std::cbrt(size.x * size.y * size.z / float(target_cells));
    dims_ = glm::max(glm::ivec3(glm::ceil(size / cell)), glm::ivec3(1));
    origin_ = bounds.min;
    inv_cell_ = glm::vec3(1.0f / cell);

    const float extent = std::max({std::abs(bounds.min.x), std::abs(bounds.min.y), std::abs(bounds.min.z),
                                   std::abs(bounds.max.x), std::abs(bounds.max.y), std::abs(bounds.max.z)});
    const float margin = 0.01f + extent * 1e-5f;
    const glm::vec3 half(cell * 0.5f);
    start_.resize(size_t(dims_.x) * size_t(dims_.y) * size_t(dims_.z));
    uint64_t depth_sum = 0;
    size_t i = 0;
    for (int z = 0; z < dims_.z; ++z)
        for (int y = 0; y < dims_.y; ++y)
            for (int x = 0; x < dims_.x; ++x, ++i) {
                const glm::vec3 center = origin_ + (glm::vec3(x, y, z) + 0.5f) * cell;
                uint32_t depth = 0;
                start_[i] = deepest_enclosing(tree, center, half, margin, depth);
                depth_sum += depth;
            }
    mean_skipped_depth_ = double(depth_sum) / double(start_.size());
}

PointLocation RegionLocator::locate(const glm::vec3& point) const
{
    int32_t start = tree_->root;
    const glm::vec3 f = (point - origin_) * inv_cell_;
    // The comparisons are written so that NaN fails them and falls back to the root.
    if (f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f && f.x < float(dims_.x) && f.y < float(dims_.y) &&
        f.z < float(dims_.z)) {
        const size_t cell = (size_t(f.z) * size_t(dims_.y) + size_t(f.y)) * size_t(dims_.x) + size_t(f.x);
        start = start_[cell];
    }
    return locate_point_from(*tree_, start, point);
}

} // namespace pvs
