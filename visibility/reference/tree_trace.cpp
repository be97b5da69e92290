#include "visibility/reference/tree_trace.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace pvs {

bool TreeTracer::open_beam(const glm::dvec3& from, const glm::dvec3& direction, double length, double margin,
                           Scratch& scratch) const
{
    auto open = [&](const glm::dvec3& start) {
        return !trace(start, direction, length, scratch, [](int32_t, double, double) {}).blocked;
    };
    const glm::dvec3 helper = std::abs(direction.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 across1 = glm::normalize(glm::cross(direction, helper));
    const glm::dvec3 across2 = glm::cross(direction, across1);
    for (const glm::dvec3& offset : {across1, -across1, across2, -across2})
        if (!open(from + margin * offset))
            return false;
    return true;
}

TreeTracer::TreeTracer(const BspTree& tree, const std::vector<Region>& regions, SkyPortals sky)
    : leaf_region_(tree.leaf_region), ties_go_front_(tree.tie_rule == TieRule::OnPlaneGoesFront), sky_(sky)
{
    nodes_.reserve(tree.nodes.size());
    for (const BspNode& n : tree.nodes)
        nodes_.push_back({double(n.normal.x), double(n.normal.y), double(n.normal.z), double(n.dist),
                          {n.children[0], n.children[1]}});
    medium_.reserve(regions.size());
    for (const Region& r : regions)
        medium_.push_back({uint8_t(medium_of(r.flags)), r.vis_contents});
    // A tree with no node and no leaf has nothing to walk; a one-leaf tree's root is ~0.
    const bool root_ok = BspTree::is_leaf(tree.root) ? !tree.leaf_region.empty() : size_t(tree.root) < tree.nodes.size();
    root_ = root_ok ? tree.root : kNoRoot;
}

int32_t TreeTracer::region_at(const glm::dvec3& p) const
{
    if (root_ == kNoRoot)
        return kLeafSolid;
    int32_t child = root_;
    // A tree is acyclic (loaders check it); the bound only keeps a corrupt one from hanging us.
    for (size_t steps = 0; child >= 0 && steps <= nodes_.size(); ++steps) {
        if (size_t(child) >= nodes_.size())
            return kLeafSolid;
        const Node& n = nodes_[size_t(child)];
        const double d = n.nx * p.x + n.ny * p.y + n.nz * p.z - n.dist;
        child = n.children[d > 0.0 || (d == 0.0 && ties_go_front_) ? 0 : 1];
    }
    if (child >= 0)
        return kLeafSolid;
    const int32_t leaf = ~child;
    if (size_t(leaf) >= leaf_region_.size())
        return kLeafSolid;
    const int32_t region = leaf_region_[size_t(leaf)];
    return region >= 0 && size_t(region) >= medium_.size() ? kLeafSolid : region;
}

} // namespace pvs
