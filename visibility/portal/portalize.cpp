#include "visibility/portal/portalize.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <tuple>
#include <utility>

namespace pvs {

namespace {

// What a piece's side has resolved to.
enum class LeafKind : uint8_t { Open, Solid, Outside };

// Every point within `epsilon` of the plane (computed in double, as Winding does).
bool lies_on(const Winding& w, const Plane& plane, float epsilon)
{
    const glm::dvec3 n(plane.normal);
    for (const glm::vec3& p : w.points)
        if (!(std::abs(glm::dot(n, glm::dvec3(p)) - double(plane.dist)) <= double(epsilon)))
            return false;
    return true;
}

// A side of a piece that is not a tree child: the world box's outside (for the box faces).
constexpr int32_t kVoidSide = 0x7fffffff;

struct Context {
    const BspTree& tree;
    const std::vector<Region>& regions;
    float epsilon;

    LeafKind kind(int32_t leaf) const
    {
        if (leaf < 0 || size_t(leaf) >= tree.leaf_region.size())
            return LeafKind::Solid;
        const int32_t region = tree.leaf_region[size_t(leaf)];
        if (region == kLeafOutside)
            return LeafKind::Outside;
        if (region < 0 || size_t(region) >= regions.size())
            return LeafKind::Solid;
        return LeafKind::Open;
    }
    bool is_node(int32_t child) const { return child != kVoidSide && !BspTree::is_leaf(child); }
};

// A polygon on its way down: `sides[0]` is the child (node or ~leaf) on the front of its plane,
// `sides[1]` the one on the back, or kVoidSide.
struct Piece {
    Winding polygon;
    int32_t sides[2];
    size_t depth; // nodes passed: in a tree at most nodes.size()
};

// Splits `polygon` down the subtrees of `front` and `back` (front first), calling
// emit(front_leaf, back_leaf, polygon) for every piece that reaches a leaf on both sides (a side
// given as kVoidSide stays kVoidSide and is passed as such), and on_solid() for every piece
// dropped on reaching a solid leaf. A node index out of range resolves like a solid leaf, and
// so does a piece that has passed more nodes than the tree has (only a tree with a cycle, which
// loaders refuse, can do that): bad trees cannot hang the walk.
template <class Emit, class OnSolid>
void split_down(const Context& ctx, Winding polygon, int32_t front, int32_t back, std::vector<Piece>& stack,
                Emit&& emit, OnSolid&& on_solid)
{
    stack.clear();
    stack.push_back({std::move(polygon), {front, back}, 0});
    while (!stack.empty()) {
        Piece piece = std::move(stack.back());
        stack.pop_back();
        // A side already resolved to a solid leaf ends the piece: nothing shows through a wall.
        bool solid = false;
        for (const int32_t side : piece.sides)
            if (side != kVoidSide && BspTree::is_leaf(side) && ctx.kind(BspTree::leaf_index(side)) == LeafKind::Solid)
                solid = true;
        if (solid) {
            on_solid();
            continue;
        }
        const int s = ctx.is_node(piece.sides[0]) ? 0 : ctx.is_node(piece.sides[1]) ? 1 : -1;
        if (s < 0) {
            emit(piece.sides[0] == kVoidSide ? kVoidSide : BspTree::leaf_index(piece.sides[0]),
                 piece.sides[1] == kVoidSide ? kVoidSide : BspTree::leaf_index(piece.sides[1]), piece.polygon);
            continue;
        }
        const int32_t node_index = piece.sides[s];
        if (size_t(node_index) >= ctx.tree.nodes.size() || piece.depth >= ctx.tree.nodes.size()) {
            on_solid();
            continue;
        }
        const BspNode& node = ctx.tree.nodes[size_t(node_index)];
        const Plane plane{node.normal, node.dist};
        // A piece lying on a plane below it (a tree that cuts a cell again on one of its own
        // boundary planes) goes whole to the child whose side it bounds: the side its normal
        // faces in the front side's walk, the side it faces away from in the back side's
        // (Winding::split alone would send it the way its normal faces in both).
        WindingSplit parts;
        if (lies_on(piece.polygon, plane, ctx.epsilon)) {
            const bool faces_front = glm::dot(piece.polygon.normal(), plane.normal) >= 0.0f;
            (faces_front == (s == 0) ? parts.front : parts.back) = std::move(piece.polygon);
        } else {
            parts = piece.polygon.split(plane, ctx.epsilon);
        }
        // Back part first on the stack, so the front part is finished first.
        if (!parts.back.empty()) {
            Piece back_piece{std::move(parts.back), {piece.sides[0], piece.sides[1]}, piece.depth + 1};
            back_piece.sides[s] = node.children[1];
            stack.push_back(std::move(back_piece));
        }
        if (!parts.front.empty()) {
            Piece front_piece{std::move(parts.front), {piece.sides[0], piece.sides[1]}, piece.depth + 1};
            front_piece.sides[s] = node.children[0];
            stack.push_back(std::move(front_piece));
        }
    }
}

// Inward faces of the world box, counter-clockwise seen from inside.
std::vector<Winding> box_faces(const Aabb& world)
{
    std::vector<Winding> faces;
    const glm::vec3 lo = world.min, hi = world.max;
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    // Each quad counter-clockwise seen from inside the box (normal pointing inward).
    const int quads[6][4] = {{0, 3, 7, 4},  // x = min, normal +x
                             {1, 5, 6, 2},  // x = max, normal -x
                             {0, 4, 5, 1},  // y = min, normal +y
                             {3, 2, 6, 7},  // y = max, normal -y
                             {0, 1, 2, 3},  // z = min, normal +z
                             {4, 7, 6, 5}}; // z = max, normal -z
    for (const auto& q : quads)
        faces.push_back(Winding{c[q[0]], c[q[1]], c[q[2]], c[q[3]]});
    return faces;
}

void sort_unique(std::vector<int32_t>& v)
{
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

} // namespace

float portal_epsilon(const Aabb& world)
{
    if (world.empty())
        return kMinPortalEpsilon;
    float largest = 0.0f;
    for (int a = 0; a < 3; ++a)
        largest = std::max({largest, std::abs(world.min[a]), std::abs(world.max[a])});
    if (!std::isfinite(largest))
        return kMinPortalEpsilon;
    const float step = std::nextafter(largest, std::numeric_limits<float>::infinity()) - largest;
    return std::max(kMinPortalEpsilon, 4.0f * step);
}

PortalSet build_portals(const BspTree& tree, const std::vector<Region>& regions, const Aabb& world,
                        const PortalOptions& options, PortalStats* stats_out)
{
    PortalStats stats;
    PortalSet set;
    const float epsilon = options.epsilon ? std::max(*options.epsilon, 0.0f) : portal_epsilon(world);
    const Context ctx{tree, regions, epsilon};
    const float min_area = options.min_area > 0.0f ? options.min_area : 0.0f;
    std::vector<Piece> stack;

    // Open leaves reaching the world box: the box faces split down the whole tree.
    if (!world.empty()) {
        for (Winding& face : box_faces(world))
            split_down(
                ctx, std::move(face), tree.root, kVoidSide, stack,
                [&](int32_t leaf, int32_t, Winding& piece) {
                    if (ctx.kind(leaf) != LeafKind::Open)
                        return;
                    piece.remove_degenerate_points(ctx.epsilon);
                    if (!piece.empty() && piece.area() > min_area)
                        stats.leaves_touching_world.push_back(leaf);
                },
                [] {});
    }

    // The node polygons split down both subtrees.
    struct Found {
        PortalOrigin origin;
        int32_t regions[2];
        Winding polygon;
    };
    std::vector<Found> found; // one node's portals
    const std::vector<Winding> polygons = node_plane_polygons(tree, world);
    for (size_t n = 0; n < polygons.size(); ++n) {
        if (polygons[n].empty())
            continue;
        ++stats.node_polygons;
        const BspNode& node = tree.nodes[n];
        found.clear();
        split_down(
            ctx, polygons[n], node.children[0], node.children[1], stack,
            [&](int32_t front_leaf, int32_t back_leaf, Winding& piece) {
                const LeafKind kf = ctx.kind(front_leaf), kb = ctx.kind(back_leaf);
                if (kf == LeafKind::Outside || kb == LeafKind::Outside) {
                    ++stats.pieces_outside;
                    if (kf == LeafKind::Open || kb == LeafKind::Open) {
                        piece.remove_degenerate_points(ctx.epsilon);
                        if (!piece.empty() && piece.area() > min_area)
                            stats.leaves_touching_outside.push_back(kf == LeafKind::Open ? front_leaf : back_leaf);
                    }
                    return;
                }
                const int32_t rf = tree.leaf_region[size_t(front_leaf)], rb = tree.leaf_region[size_t(back_leaf)];
                if (rf == rb) {
                    ++stats.pieces_same_region;
                    return;
                }
                piece.remove_degenerate_points(ctx.epsilon);
                if (piece.empty() || !(piece.area() > min_area)) {
                    ++stats.pieces_tiny;
                    return;
                }
                if (!regions_see_through(regions[size_t(rf)], regions[size_t(rb)], options.sky)) {
                    ++stats.pieces_sky;
                    return;
                }
                Found f;
                f.origin.node = int32_t(n);
                f.origin.leaves[0] = front_leaf;
                f.origin.leaves[1] = back_leaf;
                f.regions[0] = rf;
                f.regions[1] = rb;
                f.polygon = std::move(piece);
                found.push_back(std::move(f));
            },
            [&] { ++stats.pieces_solid; });

        std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
            return std::tie(a.origin.leaves[0], a.origin.leaves[1]) < std::tie(b.origin.leaves[0], b.origin.leaves[1]);
        });
        for (const Found& f : found) {
            Portal portal;
            portal.regions[0] = f.regions[0];
            portal.regions[1] = f.regions[1];
            portal.first_point = uint32_t(set.points.size());
            portal.point_count = uint32_t(f.polygon.size());
            // Clockwise seen from the front: id's order, so portal_plane's normal points into regions[0].
            for (size_t i = f.polygon.size(); i-- > 0;)
                set.points.push_back(f.polygon[i]);
            set.portals.push_back(portal);
            stats.origins.push_back(f.origin);
        }
    }
    stats.portals = set.portals.size();
    sort_unique(stats.leaves_touching_world);
    sort_unique(stats.leaves_touching_outside);
    if (stats_out)
        *stats_out = std::move(stats);
    return set;
}

Aabb zone_portal_world(const Zone& zone)
{
    Aabb box = zone.bounds();
    if (!box.empty()) {
        box.min -= glm::vec3(kPortalWorldMargin);
        box.max += glm::vec3(kPortalWorldMargin);
    }
    return box;
}

PortalSet build_zone_portals(const Zone& zone, const PortalOptions& options, PortalStats* stats)
{
    return build_portals(zone.tree, zone.regions, zone_portal_world(zone), options, stats);
}

} // namespace pvs
