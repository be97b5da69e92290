#include "visibility/region_lookup.h"

#include <glm/geometric.hpp>

namespace pvs {

namespace {
// The two tie rules as separate loops, so the per-node branch does not test the rule.
template <bool kOnPlaneGoesFront>
int32_t walk(const BspNode* nodes, int32_t child, const glm::vec3& p)
{
    while (child >= 0) {
        const BspNode& node = nodes[child];
        const float d = glm::dot(node.normal, p) - node.dist;
        const bool back = kOnPlaneGoesFront ? !(d >= 0.0f) : !(d > 0.0f);
        child = node.children[back];
    }
    return ~child;
}
} // namespace

PointLocation locate_point_from(const BspTree& tree, int32_t start, const glm::vec3& point)
{
    const int32_t leaf = tree.tie_rule == TieRule::OnPlaneGoesFront ? walk<true>(tree.nodes.data(), start, point)
                                                                    : walk<false>(tree.nodes.data(), start, point);
    // No tree at all (an OBJ zone: no node, no leaf): nowhere is a region.
    return {leaf, size_t(leaf) < tree.leaf_region.size() ? tree.leaf_region[size_t(leaf)] : kLeafOutside};
}

PointLocation locate_point(const BspTree& tree, const glm::vec3& point)
{
    return locate_point_from(tree, tree.root, point);
}

PointLocation trace_point(const BspTree& tree, const glm::vec3& point, std::vector<PathStep>& out)
{
    out.clear();
    const bool front_on_plane = tree.tie_rule == TieRule::OnPlaneGoesFront;
    int32_t child = tree.root;
    while (child >= 0) {
        const BspNode& node = tree.nodes[child];
        const float d = glm::dot(node.normal, point) - node.dist;
        const bool back = front_on_plane ? !(d >= 0.0f) : !(d > 0.0f);
        out.push_back({static_cast<uint32_t>(child), static_cast<uint8_t>(back)});
        child = node.children[back];
    }
    return {~child, size_t(~child) < tree.leaf_region.size() ? tree.leaf_region[size_t(~child)] : kLeafOutside};
}

} // namespace pvs
