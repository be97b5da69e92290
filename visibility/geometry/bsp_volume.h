// BSP node and leaf volumes: the convex cells a BspTree cuts a world box into.
//
// A node's cell is the world box intersected with the half-spaces on the path from the root
// (front child: the split plane as is; back child: flipped). A leaf's cell is its parent's cell
// on the leaf's side. These are what the inspector draws for "BSP split planes" (each node's
// plane clipped to its cell), what converting Quake faces into region meshes clips against, and
// the first step of portalization (the node polygons, split further, are the portals).
//
// Conventions:
//  - Half-spaces are closed: {p : plane.distance(p) >= 0}, planes oriented INTO the cell. A point
//    exactly on a split plane satisfies both children's half-spaces; the tree's TieRule, not
//    the geometry, decides which leaf it belongs to.
//  - A cell is given by its faces: one Winding per bounding plane that touches it, lying on the
//    plane and counter-clockwise seen from inside (the winding's normal is the plane's normal).
//  - Cells are computed with kCellEpsilon (Winding's ON rule): vertices within the epsilon of a
//    plane are kept where they are, so cells and polygons may reach up to the epsilon outside
//    the exact volume; never less than the exact volume, up to float round-off.
//  - Leaves reached from several child slots (Quake's shared solid leaf 0 is every solid child
//    of the tree) have a volume that is a union of cells, not one convex cell: functions below
//    say what they return for them. Leaves the tree never reaches have no volume.
//  - The tree is expected to be a tree (loaders check it); a node reached a second time, or a
//    child index out of range, is skipped rather than followed, so bad trees cannot hang or
//    read out of bounds.
#pragma once

#include "visibility/geometry/winding.h"
#include "visibility/math/aabb.h"
#include "visibility/math/plane.h"
#include "visibility/zone.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace pvs {

// Side tolerance for building cells, in zone units. Well above float round-off of coordinates
// up to ~50 000 (ulp 0.004) once clips are done in double, well below any real feature size.
inline constexpr float kCellEpsilon = 0.01f;

// A convex cell by its boundary: faces[i] lies on planes[i], planes point inward. Planes that do
// not touch the cell are not listed. Empty (no faces) when the intersection has no volume in
// reach of the epsilon.
struct ConvexCell {
    std::vector<Plane> planes;
    std::vector<Winding> faces;

    bool empty() const { return faces.empty(); }
    // Bounds of the face vertices (not grown); empty box for an empty cell.
    Aabb bounds() const;
};

// The cell world ∩ every half-space, computed directly: the six box faces' and each plane's base
// winding (base_winding_for_plane, sized to cover the box) clipped by all the other planes, with
// `epsilon`. A plane repeated (same normal and dist within epsilon) gives one face. A plane with
// a non-finite normal or dist constrains nothing; an empty world box gives an empty cell.
// O(k^2) clips for k planes: for one cell; a whole tree goes through for_each_leaf_cell.
ConvexCell convex_cell(std::span<const Plane> half_spaces, const Aabb& world, float epsilon = kCellEpsilon);

// The half-spaces on the root -> leaf path, root first, each oriented INTO the leaf; the leaf's
// volume is their intersection with the world box. For a leaf reached from several child slots:
// the half-spaces common to all its paths (those above their deepest shared node), a convex
// bound of the union. Empty when the leaf is the root (a one-leaf tree) or never reached.
std::vector<Plane> leaf_bounding_planes(const BspTree& tree, int32_t leaf);

// `polygon` clipped to each of `half_spaces` in turn, keeping the inside (Winding::clip rules).
Winding clip_to_planes(const Winding& polygon, std::span<const Plane> half_spaces, float epsilon);
// The part of `polygon` inside the leaf's volume: clip_to_planes with leaf_bounding_planes (so,
// for a leaf with several slots, inside their common bound). Empty for a leaf the tree never
// reaches. A polygon lying on one of the leaf's planes (a face on the leaf's boundary) is kept
// whole by that plane, as long as it is within `epsilon` of it: pass at least the data's own
// vertex noise (kWindingOnEpsilon, 0.1, for Quake).
Winding clip_to_leaf(const Winding& polygon, const BspTree& tree, int32_t leaf, float epsilon);

// For every node (indexed like tree.nodes): its split plane's polygon clipped to the node's cell,
// counter-clockwise seen from the front child. Empty for a node whose cell is empty in `world`,
// whose plane misses its cell, or that the root never reaches. One top-down traversal.
std::vector<Winding> node_plane_polygons(const BspTree& tree, const Aabb& world);

// Bounds of the leaf's volume in `world`: the vertex bounds of its cell (the union over all its
// cells for a leaf with several slots) grown by kCellEpsilon on every side, so that every point
// of the volume is inside despite round-off. Empty box for a leaf never reached or with no
// volume in `world`. Each cell is computed directly (convex_cell on its path's planes): the
// polytope's vertices are exactly the vertices of its clipped faces, so their bounds are the
// polytope's. O(nodes) to find the path(s), then O(k^2) clips. For many leaves use
// all_leaf_volume_bounds.
Aabb leaf_volume_bounds(const BspTree& tree, int32_t leaf, const Aabb& world);

// leaf_volume_bounds for every leaf (indexed like tree.leaf_region), in one top-down traversal.
std::vector<Aabb> all_leaf_volume_bounds(const BspTree& tree, const Aabb& world);

// The top-down traversal itself: each node's cell is split by its plane into its children's
// cells (faces split, the node polygon added to both sides), so no path is recomputed. Calls
// `visit(leaf, cell)` once per child slot that holds a leaf (a shared leaf is visited once per
// slot, with that slot's cell, possibly empty), front children first.
void for_each_leaf_cell(const BspTree& tree, const Aabb& world,
                        const std::function<void(int32_t leaf, const ConvexCell& cell)>& visit);

} // namespace pvs
