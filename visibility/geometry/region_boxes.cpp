#include "visibility/geometry/region_boxes.h"

#include <algorithm>
#include <cmath>

namespace pvs {
namespace {

// The axis of a plane whose normal has one non-zero component, or -1.
int split_axis(const BspNode& node)
{
    const int axes = (node.normal.x != 0.0f) + (node.normal.y != 0.0f) + (node.normal.z != 0.0f);
    if (axes != 1)
        return -1;
    return node.normal.x != 0.0f ? 0 : node.normal.y != 0.0f ? 1 : 2;
}

} // namespace

std::vector<Aabb> region_volume_boxes(const BspTree& tree, size_t region_count, const Aabb& world)
{
    std::vector<Aabb> boxes(region_count);
    if (!tree.exists() || world.empty())
        return boxes;
    struct Item {
        int32_t child;
        Aabb box;
    };
    std::vector<Item> stack{{tree.root, world}};
    size_t visits = 0;
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (BspTree::is_leaf(item.child)) {
            const int32_t leaf = BspTree::leaf_index(item.child);
            if (size_t(leaf) < tree.leaf_region.size()) {
                const int32_t region = tree.leaf_region[size_t(leaf)];
                if (region >= 0 && size_t(region) < region_count)
                    boxes[size_t(region)].grow(item.box);
            }
            continue;
        }
        if (size_t(item.child) >= tree.nodes.size() || ++visits > tree.nodes.size())
            continue;
        const BspNode& node = tree.nodes[size_t(item.child)];
        Aabb front = item.box, back = item.box;
        if (const int axis = split_axis(node); axis >= 0) {
            // normal[axis] * p[axis] = dist: the plane at dist / normal[axis], computed in double
            // and rounded outward on both sides so neither child loses a point.
            const double at = double(node.dist) / double(node.normal[axis]);
            const float below = std::nextafter(float(at), -INFINITY), above = std::nextafter(float(at), INFINITY);
            const bool front_is_above = node.normal[axis] > 0.0f;
            Aabb& upper = front_is_above ? front : back;
            Aabb& lower = front_is_above ? back : front;
            // Exact when the plane is a float (at == float(at)): no rounding needed.
            const float cut_lo = double(float(at)) == at ? float(at) : below;
            const float cut_hi = double(float(at)) == at ? float(at) : above;
            upper.min[axis] = std::max(upper.min[axis], cut_lo);
            lower.max[axis] = std::min(lower.max[axis], cut_hi);
        }
        if (!front.empty())
            stack.push_back({node.children[0], front});
        if (!back.empty())
            stack.push_back({node.children[1], back});
    }
    return boxes;
}

} // namespace pvs
