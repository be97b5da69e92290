#include "visibility/geometry/bsp_volume.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <utility>

namespace pvs {

namespace {

// The square every plane starts from: centred on the box centre's projection, with a half size
// covering the box's slice of any plane (every point of the box is within half a diagonal of the
// centre, so of its projection too), plus slack.
struct BaseSquare {
    glm::vec3 center{0.0f};
    float half_size = 0.0f;
};

BaseSquare base_square(const Aabb& world)
{
    BaseSquare s;
    s.center = world.center();
    s.half_size = 0.5f * glm::length(world.size()) * 1.01f + 1.0f;
    return s;
}

// Inward planes of the box faces: -x, +x, -y, +y, -z, +z sides.
void box_planes(const Aabb& world, std::vector<Plane>& out)
{
    for (int k = 0; k < 3; ++k) {
        glm::vec3 n(0.0f);
        n[k] = 1.0f;
        out.push_back({n, world.min[k]});
        out.push_back({-n, -world.max[k]});
    }
}

bool same_plane(const Plane& a, const Plane& b, float epsilon)
{
    return glm::dot(a.normal, b.normal) >= 1.0f - 1e-6f && std::abs(a.dist - b.dist) <= epsilon;
}

ConvexCell cell_of_planes(const std::vector<Plane>& planes, const Aabb& world, float epsilon)
{
    ConvexCell cell;
    if (world.empty())
        return cell;
    const BaseSquare base = base_square(world);
    Winding w, scratch;
    for (size_t i = 0; i < planes.size(); ++i) {
        w = base_winding_for_plane(planes[i], base.half_size, base.center);
        for (size_t j = 0; j < planes.size() && !w.empty(); ++j) {
            if (j == i)
                continue;
            if (same_plane(planes[i], planes[j], epsilon)) {
                if (j < i)
                    w.points.clear(); // the first copy owns the face
                continue;
            }
            w.clip_in_place(planes[j], epsilon, scratch);
        }
        if (!w.empty()) {
            cell.planes.push_back(planes[i]);
            cell.faces.push_back(std::move(w));
            w = Winding();
        }
    }
    return cell;
}

// Every child slot of the reached tree that holds `leaf`, as root-first paths of (node, side).
struct Step {
    int32_t node;
    uint8_t side;
    bool operator==(const Step&) const = default;
};

std::vector<std::vector<Step>> leaf_paths(const BspTree& tree, int32_t leaf)
{
    std::vector<std::vector<Step>> paths;
    if (leaf < 0 || size_t(leaf) >= tree.leaf_region.size())
        return paths;
    if (BspTree::is_leaf(tree.root)) {
        if (BspTree::leaf_index(tree.root) == leaf)
            paths.emplace_back();
        return paths;
    }
    // Parent links from one walk; a node reached twice keeps its first parent.
    const size_t n = tree.nodes.size();
    std::vector<int32_t> parent(n, -1);
    std::vector<uint8_t> parent_side(n, 0), reached(n, 0);
    std::vector<Step> slots; // (node, side) of every slot holding the leaf
    std::vector<int32_t> stack;
    if (size_t(tree.root) < n)
        stack.push_back(tree.root);
    while (!stack.empty()) {
        const int32_t node = stack.back();
        stack.pop_back();
        if (reached[node])
            continue;
        reached[node] = 1;
        for (uint8_t side = 0; side < 2; ++side) {
            const int32_t child = tree.nodes[node].children[side];
            if (BspTree::is_leaf(child)) {
                if (BspTree::leaf_index(child) == leaf)
                    slots.push_back({node, side});
            } else if (size_t(child) < n && !reached[child]) {
                if (parent[child] < 0 && child != tree.root) {
                    parent[child] = node;
                    parent_side[child] = side;
                }
                stack.push_back(child);
            }
        }
    }
    for (const Step& slot : slots) {
        std::vector<Step>& path = paths.emplace_back();
        path.push_back(slot);
        for (int32_t node = slot.node; node != tree.root && parent[node] >= 0; node = parent[node])
            path.push_back({parent[node], parent_side[node]});
        std::reverse(path.begin(), path.end());
    }
    return paths;
}

Plane step_plane(const BspTree& tree, const Step& step)
{
    const BspNode& node = tree.nodes[step.node];
    const Plane plane{node.normal, node.dist};
    return step.side == 0 ? plane : plane.flipped();
}

std::vector<Plane> path_planes(const BspTree& tree, const std::vector<Step>& path)
{
    std::vector<Plane> planes;
    planes.reserve(path.size());
    for (const Step& step : path)
        planes.push_back(step_plane(tree, step));
    return planes;
}

// The half-spaces shared by every path: those above the paths' deepest common node.
std::vector<Plane> common_planes(const BspTree& tree, const std::vector<std::vector<Step>>& paths)
{
    if (paths.empty())
        return {};
    size_t common = paths[0].size();
    for (size_t i = 1; i < paths.size(); ++i) {
        size_t k = 0;
        while (k < common && k < paths[i].size() && paths[i][k] == paths[0][k])
            ++k;
        common = k;
    }
    return path_planes(tree, std::vector<Step>(paths[0].begin(), paths[0].begin() + std::ptrdiff_t(common)));
}

// Splits `cell` (consumed) by `plane` into the front and back children's cells, `polygon` being
// the plane's polygon clipped to the cell. A cell that does not straddle the plane by more than
// the epsilon goes whole to one side, so no flat sliver cell or duplicated face is made.
std::pair<ConvexCell, ConvexCell> split_cell(ConvexCell&& cell, const Plane& plane, const Winding& polygon,
                                             float epsilon)
{
    std::pair<ConvexCell, ConvexCell> out;
    if (cell.empty())
        return out;
    bool any_front = false, any_back = false;
    const glm::dvec3 normal(plane.normal);
    for (const Winding& face : cell.faces)
        for (const glm::vec3& p : face.points) {
            const double d = glm::dot(normal, glm::dvec3(p)) - double(plane.dist); // as Winding::split does
            any_front |= d > double(epsilon);
            any_back |= d < -double(epsilon);
        }
    if (!any_back || !any_front) {
        // Also a NaN plane (no side at all): everything to the front, like Winding::split.
        (any_back ? out.second : out.first) = std::move(cell);
        return out;
    }
    auto& [front, back] = out;
    for (size_t i = 0; i < cell.faces.size(); ++i) {
        WindingSplit parts = cell.faces[i].split(plane, epsilon);
        if (!parts.front.empty()) {
            front.planes.push_back(cell.planes[i]);
            front.faces.push_back(std::move(parts.front));
        }
        if (!parts.back.empty()) {
            back.planes.push_back(cell.planes[i]);
            back.faces.push_back(std::move(parts.back));
        }
    }
    if (!polygon.empty()) {
        front.planes.push_back(plane);
        front.faces.push_back(polygon);
        back.planes.push_back(plane.flipped());
        back.faces.push_back(polygon.reversed());
    }
    return out;
}

// The top-down traversal: on_node(node, polygon) for every reached node, on_leaf(leaf, cell) for
// every child slot holding a leaf. Depth first with an explicit stack (no recursion limit on
// deep trees); at most depth + 1 cells are pending.
template <class OnNode, class OnLeaf>
void walk_cells(const BspTree& tree, const Aabb& world, float epsilon, OnNode&& on_node, OnLeaf&& on_leaf)
{
    struct Pending {
        int32_t child;
        ConvexCell cell;
    };
    std::vector<Plane> box;
    box_planes(world, box);
    std::vector<Pending> stack;
    stack.push_back({tree.root, cell_of_planes(box, world, epsilon)});
    std::vector<uint8_t> reached(tree.nodes.size(), 0);
    const BaseSquare base = base_square(world);
    Winding polygon, scratch;
    while (!stack.empty()) {
        Pending item = std::move(stack.back());
        stack.pop_back();
        if (BspTree::is_leaf(item.child)) {
            const int32_t leaf = BspTree::leaf_index(item.child);
            if (size_t(leaf) < tree.leaf_region.size())
                on_leaf(leaf, item.cell);
            continue;
        }
        if (size_t(item.child) >= tree.nodes.size() || reached[item.child])
            continue;
        reached[item.child] = 1;
        const BspNode& node = tree.nodes[item.child];
        const Plane plane{node.normal, node.dist};
        polygon.points.clear();
        if (!item.cell.empty()) {
            polygon = base_winding_for_plane(plane, base.half_size, base.center);
            for (const Plane& bound : item.cell.planes)
                if (!polygon.clip_in_place(bound, epsilon, scratch))
                    break;
        }
        on_node(item.child, polygon);
        auto [front, back] = split_cell(std::move(item.cell), plane, polygon, epsilon);
        stack.push_back({node.children[1], std::move(back)});
        stack.push_back({node.children[0], std::move(front)});
    }
}

Aabb grown(Aabb box, float margin)
{
    if (!box.empty()) {
        box.min -= glm::vec3(margin);
        box.max += glm::vec3(margin);
    }
    return box;
}

} // namespace

Aabb ConvexCell::bounds() const
{
    Aabb box;
    for (const Winding& face : faces)
        box.grow(face.bounds());
    return box;
}

ConvexCell convex_cell(std::span<const Plane> half_spaces, const Aabb& world, float epsilon)
{
    std::vector<Plane> planes;
    planes.reserve(6 + half_spaces.size());
    box_planes(world, planes);
    planes.insert(planes.end(), half_spaces.begin(), half_spaces.end());
    return cell_of_planes(planes, world, epsilon);
}

std::vector<Plane> leaf_bounding_planes(const BspTree& tree, int32_t leaf)
{
    return common_planes(tree, leaf_paths(tree, leaf));
}

Winding clip_to_planes(const Winding& polygon, std::span<const Plane> half_spaces, float epsilon)
{
    Winding out = polygon, scratch;
    for (const Plane& plane : half_spaces)
        if (!out.clip_in_place(plane, epsilon, scratch))
            break;
    return out;
}

Winding clip_to_leaf(const Winding& polygon, const BspTree& tree, int32_t leaf, float epsilon)
{
    const auto paths = leaf_paths(tree, leaf);
    if (paths.empty())
        return {};
    return clip_to_planes(polygon, common_planes(tree, paths), epsilon);
}

std::vector<Winding> node_plane_polygons(const BspTree& tree, const Aabb& world)
{
    std::vector<Winding> out(tree.nodes.size());
    walk_cells(
        tree, world, kCellEpsilon, [&](int32_t node, const Winding& polygon) { out[size_t(node)] = polygon; },
        [](int32_t, const ConvexCell&) {});
    return out;
}

Aabb leaf_volume_bounds(const BspTree& tree, int32_t leaf, const Aabb& world)
{
    Aabb box;
    for (const auto& path : leaf_paths(tree, leaf)) {
        const std::vector<Plane> planes = path_planes(tree, path);
        box.grow(convex_cell(planes, world, kCellEpsilon).bounds());
    }
    return grown(box, kCellEpsilon);
}

std::vector<Aabb> all_leaf_volume_bounds(const BspTree& tree, const Aabb& world)
{
    std::vector<Aabb> out(tree.leaf_region.size());
    walk_cells(
        tree, world, kCellEpsilon, [](int32_t, const Winding&) {},
        [&](int32_t leaf, const ConvexCell& cell) { out[size_t(leaf)].grow(cell.bounds()); });
    for (Aabb& box : out)
        box = grown(box, kCellEpsilon);
    return out;
}

void for_each_leaf_cell(const BspTree& tree, const Aabb& world,
                        const std::function<void(int32_t leaf, const ConvexCell& cell)>& visit)
{
    walk_cells(
        tree, world, kCellEpsilon, [](int32_t, const Winding&) {}, visit);
}

} // namespace pvs
