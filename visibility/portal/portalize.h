// Portals from a BSP tree: the classic recursive portalization (id qbsp's PortalizeWorld /
// CutNodePortals_r, ericw-tools qbsp's portals.cc), the first step of a portal-vis bake
// (../shared/formats/quake-doom-hepvs.md §2, §3.1).
//
// Algorithm. For every node the root reaches, in node index order, its split plane's polygon
// clipped to the node's cell (node_plane_polygons, bsp_volume.h) is split down both subtrees:
// first down the front child's subtree by each node plane it meets, then each front piece down
// the back child's subtree, until every piece lies between one leaf on the front side and one
// on the back side. A piece is the face two leaf cells share on that plane (cells are convex,
// so it is convex and there is at most one per leaf pair and node). Splits use
// Winding::split with PortalOptions::epsilon (kCellEpsilon by default, as the cells): a piece
// that straddles a plane by less than the epsilon goes whole to one side, so no sliver is made;
// a piece lying on a plane further down (a tree cutting a cell again on its own boundary) goes
// to the child whose side it bounds. Cost: each node polygon is split only by the planes it
// straddles (e1m1: 2513 node polygons, 3406 portals, 0.3 s in a Debug + sanitizer build); no
// recursion (an explicit stack), so deep trees are fine, and a walk deeper than the node count
// (only a tree with a cycle) is cut off, so bad trees cannot hang it.
//
// Which pieces become portals (§2.6, with the region flags standing for Quake contents):
//  - a piece with a solid leaf (kLeafSolid, or a leaf whose region id is out of range) on
//    either side: dropped, as early as that leaf is reached;
//  - a piece with an outside leaf (kLeafOutside) on either side: dropped (see leaks below);
//  - a piece between two leaves of the same region (a region reached from several leaves or
//    slots): dropped, a region needs no portal to itself;
//  - a piece whose polygon, once points closer than the epsilon to their neighbours' line are
//    removed (Winding::remove_degenerate_points), has fewer than three points or an area of at
//    most PortalOptions::min_area: dropped (it touches the other leaf along an edge or a
//    point, or is round-off);
//  - media (media.h, the one content rule shared with the reference and the popping check): a
//    piece between two regions whose media do not see through each other is dropped. By
//    default sky sees only sky, air and liquids see each other (PortalOptions::sky changes the
//    sky rule).
//
// Orientation, as PRT1 (§2.5): regions[0] is the region on the FRONT side of the node plane
// (the front child's subtree), regions[1] the back one, and the points are clockwise seen from
// the front (id's winding order; a Winding's reversed() of our counter-clockwise convention),
// so that quake::portal_plane(set, portal) gives the node plane with its normal pointing into
// regions[0]. The points are the piece's points after the degenerate-point removal above (no
// colinear points, none closer than the epsilon). For Quake zones region r is PRT leaf r, so
// the set can be written with quake::format_prt unchanged (leaf_count = regions.size()); PRT1
// allows at most 64 points per portal, which build_portals does not enforce (Quake maps'
// portals have 3 to 16 points).
//
// Order: deterministic, independent of anything but the input: by node index, then by the
// (front leaf, back leaf) pair, then in the order the split walk met them.
//
// Leaks (an open leaf with points outside the world, e.g. a Quake map whose outside void was
// not filled because it leaks, or an EverQuest tree whose open leaves border region-less ones):
// such a leaf shows up either as a cell touching the world box (its cell has a face on one of
// the box's six faces: the tree does not close it off) or as a cell sharing a face with a
// kLeafOutside leaf. No portal is made to the outside or to the box, so the portal graph of a
// leaking zone is the graph of its open leaves only, exactly as for a sealed one, and a flood
// through it never reaches "outside". The open leaves found are reported in PortalStats
// (leaves_touching_world, leaves_touching_outside), so a caller can warn, as qbsp does with
// its leak file; build_portals itself never fails on a leak. The world-box test descends each
// of the box's six faces through the whole tree the same way as a node polygon. Pass a world
// box that encloses the whole zone with a margin (zone_portal_world does): a box cutting
// through the open space reports the leaves it cuts as touching the world.
//
// Degenerate input gives defined results: an empty world box or a tree with no node gives no
// portal (a one-leaf tree's open leaf is reported as touching the world); a tree the root
// does not fully reach portalizes the part it reaches; a node whose cell is empty contributes
// nothing.
#pragma once

#include "visibility/geometry/bsp_volume.h"
#include "visibility/geometry/winding.h"
#include "visibility/portal/media.h"
#include "visibility/math/aabb.h"
#include "visibility/zone.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace pvs {

// The portal epsilon for a world box: kMinPortalEpsilon, or 4 float steps at the box's largest
// coordinate where that is more. The floor absorbs a 1e-3 jitter of planes and points; the float
// steps absorb rounding far from the origin (2^16 units: 0.0078 a step, epsilon 0.031). The
// cells' kCellEpsilon (0.01) was the old fixed value: it lost the 0.01-unit crack of the stability
// cases (the crack straddles a plane by no more than the epsilon, so it went whole to one side),
// and a fixed 0.001 instead lost bits on e1m1 moved by 2^16 and changed 6 574 bits under the
// jitter (docs/stability.md).
inline constexpr float kMinPortalEpsilon = 0.004f;
float portal_epsilon(const Aabb& world);

// Portals at sky regions (§2.6): SkyPortals, in media.h with the rest of the content rule.
struct PortalOptions {
    // Side tolerance of the splits and of the degenerate-point removal, in zone units. Unset:
    // portal_epsilon(world) (below). An opening narrower than the epsilon, or with less than
    // min_area, gets no portal, so no portal method sees through it.
    std::optional<float> epsilon;
    // Pieces with at most this area (squared zone units) are not portals.
    float min_area = 1e-4f;
    SkyPortals sky = SkyPortals::SkyToSky;
};

// Where a portal came from: its node and BSP leaves (front leaf first, like regions[0]).
struct PortalOrigin {
    int32_t node = -1;
    int32_t leaves[2] = {-1, -1};
};

struct PortalStats {
    size_t node_polygons = 0;        // nodes whose plane polygon is not empty (the walk's inputs)
    size_t pieces_solid = 0;         // pieces dropped on reaching a solid leaf
    size_t pieces_outside = 0;       // pieces between an open or outside leaf and an outside leaf
    size_t pieces_same_region = 0;   // pieces with one region on both sides
    size_t pieces_tiny = 0;          // pieces between two open leaves with no area (see min_area)
    size_t pieces_sky = 0;           // pieces sight cannot cross (media.h: a sky leaf, PortalOptions::sky; a Quake 2 content boundary)
    size_t portals = 0;              // pieces kept: PortalSet::portals.size()
    // Open leaves (leaf_region >= 0) whose cell has a face, of more than min_area, on the world
    // box or shared with a kLeafOutside leaf. Sorted, no duplicates. Empty for a sealed zone.
    std::vector<int32_t> leaves_touching_world;
    std::vector<int32_t> leaves_touching_outside;
    // One entry per portal, parallel to PortalSet::portals.
    std::vector<PortalOrigin> origins;

    bool leaks() const { return !leaves_touching_world.empty() || !leaves_touching_outside.empty(); }
};

// The portals between the open leaves of `tree` inside `world` (see above). `regions` gives the
// flags of the region ids in tree.leaf_region; a leaf naming a region id outside `regions` is
// treated as solid. `stats`, when given, is overwritten.
PortalSet build_portals(const BspTree& tree, const std::vector<Region>& regions, const Aabb& world,
                        const PortalOptions& options = {}, PortalStats* stats = nullptr);

// The world box to portalize a zone in: zone.bounds() grown by kPortalWorldMargin on every side,
// so that no split plane of a sealed zone lies on it. Empty for a zone with no bounds.
inline constexpr float kPortalWorldMargin = 64.0f;
Aabb zone_portal_world(const Zone& zone);

// build_portals(zone.tree, zone.regions, zone_portal_world(zone), ...).
PortalSet build_zone_portals(const Zone& zone, const PortalOptions& options = {}, PortalStats* stats = nullptr);

} // namespace pvs
