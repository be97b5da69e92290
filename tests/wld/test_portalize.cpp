// Portals from a BSP tree (visibility/portal/portalize.h):
//  1. hand-built box rooms: one portal with PRT1 orientation and the right area; sky/water rules;
//     rooms with no open neighbour, a one-leaf tree and an empty tree give no portal; a leaking
//     tree (a room open to the world box, or bordering an outside leaf) is reported;
//  2. vis.py's example.bsp: the portals built from its tree are example.prt's (qbsp's own);
//  3. real Quake maps: every portal on its node plane, between the two regions on its sides,
//     never at a solid leaf, inside the baked PVS both ways, no air <-> sky portal; and the
//     portals are checked against an independent brute-force count: every pair of open leaf
//     cells (from for_each_leaf_cell, and a pairing that does not use the split walk) sharing
//     a face of positive area. The shipped maps' PVS turns out to have been made with no portal
//     at any sky leaf (each sky leaf sees only itself), which SkyPortals::None reproduces.
#include "visibility/portal/portalize.h"

#include "tests/support/test_data.h"
#include "visibility/geometry/bsp_volume.h"
#include "visibility/region_lookup.h"
#include "wld/quake/prt_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace pvs {
namespace {

// ---------------------------------------------------------------------------------------------
// Hand-built trees

// Builds trees of closed axis-aligned rooms: each room is a chain of six nodes whose front
// children lead inward and whose back children are a wall leaf (solid unless told otherwise).
struct TreeBuilder {
    BspTree tree;

    int32_t leaf(int32_t region)
    {
        tree.leaf_region.push_back(region);
        return ~int32_t(tree.leaf_region.size() - 1);
    }
    int32_t node(glm::vec3 normal, float dist, int32_t front, int32_t back)
    {
        tree.nodes.push_back({normal, dist, {front, back}});
        return int32_t(tree.nodes.size() - 1);
    }
    // The room [lo, hi] holding `inside` (a child); `wall_region` for the six outside leaves,
    // except that `open_side` (0..5: -x, +x, -y, +y, -z, +z), when given, gets `open_region`.
    int32_t room(glm::vec3 lo, glm::vec3 hi, int32_t inside, int open_side = -1, int32_t open_region = kLeafSolid)
    {
        int32_t child = inside;
        for (int side = 5; side >= 0; --side) {
            const int axis = side / 2;
            glm::vec3 n(0.0f);
            n[axis] = side % 2 == 0 ? 1.0f : -1.0f; // inward
            const float dist = side % 2 == 0 ? lo[axis] : -hi[axis];
            const int32_t wall = leaf(side == open_side ? open_region : kLeafSolid);
            child = node(n, dist, child, wall);
        }
        return child;
    }
};

std::vector<Region> air_regions(size_t n) { return std::vector<Region>(n); }

Winding portal_winding(const PortalSet& set, const Portal& p)
{
    Winding w;
    for (uint32_t i = 0; i < p.point_count; ++i)
        w.points.push_back(set.points[p.first_point + i]);
    return w;
}

float portal_area(const PortalSet& set, const Portal& p) { return portal_winding(set, p).area(); }

// Two rooms side by side, [0,10]^3 (region 0) and [10,20]x[0,10]x[0,10] (region 1), split by
// the root plane x = 10 (front = +x = room 1).
BspTree two_rooms()
{
    TreeBuilder b;
    const int32_t leaf0 = b.leaf(0), leaf1 = b.leaf(1);
    const int32_t room1 = b.room({10, 0, 0}, {20, 10, 10}, leaf1);
    const int32_t room0 = b.room({0, 0, 0}, {10, 10, 10}, leaf0);
    b.tree.root = b.node({1, 0, 0}, 10.0f, room1, room0);
    return b.tree;
}

const Aabb kWorld{{-50, -50, -50}, {70, 60, 60}};

TEST(Portalize, TwoRoomsOnePortalWithPrtOrientation)
{
    const BspTree tree = two_rooms();
    PortalStats stats;
    const PortalSet set = build_portals(tree, air_regions(2), kWorld, {}, &stats);
    ASSERT_EQ(set.portals.size(), 1u);
    const Portal& p = set.portals[0];
    EXPECT_EQ(p.regions[0], 1); // the front of x = 10
    EXPECT_EQ(p.regions[1], 0);
    EXPECT_NEAR(portal_area(set, p), 100.0f, 1e-3f);
    const Plane plane = quake::portal_plane(set, p);
    EXPECT_NEAR(plane.normal.x, 1.0f, 1e-6f); // into regions[0], as PRT1 §2.5
    EXPECT_NEAR(plane.dist, 10.0f, 1e-5f);
    EXPECT_EQ(p.point_count, 4u); // no colinear points
    EXPECT_EQ(stats.portals, 1u);
    EXPECT_FALSE(stats.leaks());
    ASSERT_EQ(stats.origins.size(), 1u);
    EXPECT_EQ(stats.origins[0].node, tree.root);
    EXPECT_EQ(stats.origins[0].leaves[0], 1);
    EXPECT_EQ(stats.origins[0].leaves[1], 0);
    EXPECT_GT(stats.pieces_solid, 0u);

    // Deterministic: the same input gives the same bytes.
    const PortalSet again = build_portals(tree, air_regions(2), kWorld);
    ASSERT_EQ(again.points.size(), set.points.size());
    for (size_t i = 0; i < set.points.size(); ++i)
        EXPECT_EQ(again.points[i], set.points[i]);
}

TEST(Portalize, ContentsRuleSkyAndLiquids)
{
    const BspTree tree = two_rooms();
    auto count = [&](uint32_t flags0, uint32_t flags1, SkyPortals sky = SkyPortals::SkyToSky) {
        std::vector<Region> regions(2);
        regions[0].flags = flags0;
        regions[1].flags = flags1;
        PortalOptions options;
        options.sky = sky;
        PortalStats stats;
        const size_t n = build_portals(tree, regions, kWorld, options, &stats).portals.size();
        EXPECT_EQ(stats.pieces_sky, 1u - n) << flags0 << " " << flags1;
        return n;
    };
    EXPECT_EQ(count(0, kRegionWater), 1u);                          // air <-> water: liquids are translucent
    EXPECT_EQ(count(kRegionLava, 0), 1u);                           // air <-> lava
    EXPECT_EQ(count(kRegionSlime, kRegionWater), 1u);               // liquid <-> other liquid
    EXPECT_EQ(count(kRegionVWater, 0), 1u);                         // EverQuest vwater is a liquid
    EXPECT_EQ(count(kRegionSky, kRegionSky), 1u);                   // sky <-> sky
    EXPECT_EQ(count(0, kRegionSky), 0u);                            // air <-> sky: not written
    EXPECT_EQ(count(kRegionWater, kRegionSky), 0u);                 // sky is not translucent
    EXPECT_EQ(count(0, kRegionSky, SkyPortals::All), 1u);           // unless asked (ericw -transsky)
    EXPECT_EQ(count(kRegionWater, kRegionSky, SkyPortals::All), 1u);
    EXPECT_EQ(count(kRegionSky, kRegionSky, SkyPortals::None), 0u); // sky opaque to vis
    EXPECT_EQ(count(0, kRegionWater, SkyPortals::None), 1u);
    EXPECT_EQ(count(kRegionZoneLine, kRegionPvp), 1u);              // other flags do not matter
}

TEST(Portalize, NoOpenNeighboursNoPortals)
{
    // Two closed rooms 10 units apart: the root plane's polygon meets only walls.
    TreeBuilder b;
    const int32_t leaf0 = b.leaf(0), leaf1 = b.leaf(1);
    const int32_t room1 = b.room({20, 0, 0}, {30, 10, 10}, leaf1);
    const int32_t room0 = b.room({0, 0, 0}, {10, 10, 10}, leaf0);
    b.tree.root = b.node({1, 0, 0}, 15.0f, room1, room0);
    PortalStats stats;
    const PortalSet set = build_portals(b.tree, air_regions(2), kWorld, {}, &stats);
    EXPECT_TRUE(set.portals.empty());
    EXPECT_TRUE(set.points.empty());
    EXPECT_FALSE(stats.leaks());
    EXPECT_GT(stats.node_polygons, 0u);

    // Two leaves of one region on both sides of a plane: no portal to itself.
    TreeBuilder same;
    const int32_t a = same.leaf(0), c = same.leaf(0);
    same.tree.root = same.room({0, 0, 0}, {10, 10, 10}, same.node({1, 0, 0}, 5.0f, a, c));
    const PortalSet self = build_portals(same.tree, air_regions(1), kWorld, {}, &stats);
    EXPECT_TRUE(self.portals.empty());
    EXPECT_EQ(stats.pieces_same_region, 1u);
}

TEST(Portalize, DegenerateTreesNoCrash)
{
    PortalStats stats;
    // A one-leaf zone: no node, no portal; its only leaf is open and is the whole world box.
    BspTree single;
    single.leaf_region = {0};
    single.root = ~0;
    EXPECT_TRUE(build_portals(single, air_regions(1), kWorld, {}, &stats).portals.empty());
    EXPECT_EQ(stats.leaves_touching_world, std::vector<int32_t>{0});
    Zone one;
    one.regions.resize(1);
    one.regions[0].bounds = {{0, 0, 0}, {10, 10, 10}};
    one.tree = single;
    EXPECT_TRUE(build_zone_portals(one, {}, &stats).portals.empty());
    EXPECT_TRUE(stats.leaks());
    EXPECT_TRUE(build_zone_portals(Zone{}, {}, &stats).portals.empty()); // no bounds, no tree
    EXPECT_FALSE(stats.leaks());
    // The same leaf solid: nothing at all.
    single.leaf_region = {kLeafSolid};
    EXPECT_TRUE(build_portals(single, {}, kWorld, {}, &stats).portals.empty());
    EXPECT_FALSE(stats.leaks());
    // An empty tree, an empty world box, a leaf naming a region that does not exist (solid),
    // a child index out of range: defined, empty results.
    EXPECT_TRUE(build_portals(BspTree{}, {}, kWorld, {}, &stats).portals.empty());
    EXPECT_TRUE(build_portals(two_rooms(), air_regions(2), Aabb{}, {}, &stats).portals.empty());
    EXPECT_EQ(stats.node_polygons, 0u);
    EXPECT_TRUE(build_portals(two_rooms(), air_regions(1), kWorld, {}, &stats).portals.empty());
    BspTree bad = two_rooms();
    bad.nodes[size_t(bad.root)].children[0] = 999;
    EXPECT_TRUE(build_portals(bad, air_regions(2), kWorld, {}, &stats).portals.empty());
    // A cycle (a child pointing back at the root): the walk ends.
    BspTree cycle = two_rooms();
    cycle.nodes[size_t(cycle.root) - 1].children[0] = cycle.root;
    build_portals(cycle, air_regions(2), kWorld, {}, &stats);
}

TEST(Portalize, LeakingTreesAreReported)
{
    // Room 1's +x wall is open: its outside leaf (region 2) reaches the world box. The portal
    // graph is still made (1 <-> 0 and 1 <-> 2) and the stats name the leaf touching the world.
    TreeBuilder b;
    const int32_t leaf0 = b.leaf(0), leaf1 = b.leaf(1);
    const int32_t room1 = b.room({10, 0, 0}, {20, 10, 10}, leaf1, /*+x*/ 1, 2);
    const int32_t room0 = b.room({0, 0, 0}, {10, 10, 10}, leaf0);
    b.tree.root = b.node({1, 0, 0}, 10.0f, room1, room0);
    const int32_t open_leaf = int32_t(std::find(b.tree.leaf_region.begin(), b.tree.leaf_region.end(), 2) -
                                      b.tree.leaf_region.begin());
    PortalStats stats;
    PortalSet set = build_portals(b.tree, air_regions(3), kWorld, {}, &stats);
    EXPECT_EQ(set.portals.size(), 2u);
    EXPECT_TRUE(stats.leaks());
    EXPECT_EQ(stats.leaves_touching_world, std::vector<int32_t>{open_leaf});
    EXPECT_TRUE(stats.leaves_touching_outside.empty());

    // The same leaf outside the world (an EverQuest region-less leaf): no portal to it; room 1
    // is reported as bordering the outside.
    b.tree.leaf_region[size_t(open_leaf)] = kLeafOutside;
    set = build_portals(b.tree, air_regions(2), kWorld, {}, &stats);
    ASSERT_EQ(set.portals.size(), 1u);
    EXPECT_EQ(set.portals[0].regions[0], 1);
    EXPECT_TRUE(stats.leaks());
    EXPECT_TRUE(stats.leaves_touching_world.empty());
    EXPECT_EQ(stats.leaves_touching_outside, std::vector<int32_t>{1}); // leaf 1 = region 1
    EXPECT_GT(stats.pieces_outside, 0u);
}

// ---------------------------------------------------------------------------------------------
// example.bsp against qbsp's example.prt

// A polygon as a point set: colinear points and near-duplicates removed.
std::vector<glm::vec3> corner_set(Winding w)
{
    w.remove_degenerate_points(0.01f);
    return w.points;
}

bool same_point_set(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b, float tolerance)
{
    if (a.size() != b.size())
        return false;
    for (const glm::vec3& p : a)
        if (std::none_of(b.begin(), b.end(), [&](const glm::vec3& q) { return glm::length(p - q) <= tolerance; }))
            return false;
    return true;
}

// qbsp's portals are exact leaf-cell faces too (id qbsp's CutNodePortals_r splits each node's
// polygon by the node's cell boundary, like node_plane_polygons plus the split walk; it never
// clips them to brush faces), so the polygons must match, not just the pairs. Vertex order,
// starting point and colinear points may differ; qbsp's coordinates are written rounded.
TEST(Portalize, ExampleMatchesQbspPrt)
{
    SHARED_DATA_OR_SKIP(bsp_path, "visdemo/example.bsp");
    SHARED_DATA_OR_SKIP(prt_path, "visdemo/example.prt");
    const Zone* zone = test::shared_zone("visdemo/example.bsp");
    ASSERT_NE(zone, nullptr);
    const quake::PrtFile prt = quake::load_prt(prt_path);
    ASSERT_EQ(prt.leaf_count, zone->region_count());

    PortalStats stats;
    const PortalSet ours = build_zone_portals(*zone, {}, &stats);
    EXPECT_FALSE(stats.leaks());
    ASSERT_EQ(ours.portals.size(), prt.portals.portals.size());
    ASSERT_EQ(ours.portals.size(), 12u);

    std::set<std::pair<int32_t, int32_t>> ours_pairs, prt_pairs;
    for (const Portal& p : ours.portals)
        ours_pairs.insert(std::minmax(p.regions[0], p.regions[1]));
    for (const Portal& p : prt.portals.portals)
        prt_pairs.insert(std::minmax(p.regions[0], p.regions[1]));
    EXPECT_EQ(ours_pairs, prt_pairs);
    EXPECT_EQ(ours_pairs.size(), 12u); // one portal per pair

    for (const Portal& q : prt.portals.portals) {
        const auto it = std::find_if(ours.portals.begin(), ours.portals.end(), [&](const Portal& p) {
            return std::minmax(p.regions[0], p.regions[1]) == std::minmax(q.regions[0], q.regions[1]);
        });
        ASSERT_NE(it, ours.portals.end());
        const Portal& p = *it;
        // Orientation: the same leaf0, and portal_plane's normal into it for both.
        EXPECT_EQ(p.regions[0], q.regions[0]) << "PRT portal " << q.regions[0] << " " << q.regions[1];
        EXPECT_EQ(p.regions[1], q.regions[1]);
        const Plane a = quake::portal_plane(ours, p), b = quake::portal_plane(prt.portals, q);
        EXPECT_GT(glm::dot(a.normal, b.normal), 0.9999f) << q.regions[0] << " " << q.regions[1];
        EXPECT_NEAR(a.dist, b.dist, 0.01f);
        // Polygons: the same corners within 0.01 units.
        const auto pa = corner_set(portal_winding(ours, p)), pb = corner_set(portal_winding(prt.portals, q));
        EXPECT_TRUE(same_point_set(pa, pb, 0.01f)) << "portal " << q.regions[0] << " " << q.regions[1];
    }
    // The file's leaf count and our portals write and read back as a PRT1.
    quake::PrtFile written{uint32_t(zone->region_count()), ours};
    const quake::PrtFile back = quake::parse_prt(quake::format_prt(written), "ours.prt");
    EXPECT_EQ(back.portals.portals.size(), 12u);
}

// ---------------------------------------------------------------------------------------------
// Real Quake maps

using PairSet = std::map<std::pair<int32_t, int32_t>, double>; // unordered leaf pair -> shared area

// Brute force, independent of the split walk: every pair of open leaf cells (each computed by
// for_each_leaf_cell) with faces on opposite sides of one plane, the first face clipped to the
// second cell: a piece of positive area is a shared face, hence a portal before §2.6.
PairSet shared_faces(const BspTree& tree, const Aabb& world)
{
    std::vector<ConvexCell> cells(tree.leaf_region.size());
    std::vector<Aabb> bounds(tree.leaf_region.size());
    for_each_leaf_cell(tree, world, [&](int32_t leaf, const ConvexCell& cell) {
        if (tree.leaf_region[size_t(leaf)] >= 0 && !cell.empty()) {
            cells[size_t(leaf)] = cell;
            bounds[size_t(leaf)] = cell.bounds();
        }
    });
    PairSet out;
    for (size_t a = 0; a < cells.size(); ++a) {
        if (cells[a].empty())
            continue;
        Aabb grown_a = bounds[a];
        grown_a.min -= glm::vec3(0.1f);
        grown_a.max += glm::vec3(0.1f);
        for (size_t b = a + 1; b < cells.size(); ++b) {
            if (cells[b].empty() || !grown_a.overlaps(bounds[b]))
                continue;
            for (size_t i = 0; i < cells[a].faces.size(); ++i) {
                const Plane& pa = cells[a].planes[i];
                for (size_t j = 0; j < cells[b].faces.size(); ++j) {
                    const Plane& pb = cells[b].planes[j];
                    if (glm::dot(pa.normal, pb.normal) > -0.99999f || std::abs(pa.dist + pb.dist) > 0.01f)
                        continue;
                    std::vector<Plane> others;
                    for (size_t k = 0; k < cells[b].planes.size(); ++k)
                        if (k != j)
                            others.push_back(cells[b].planes[k]);
                    const float area = clip_to_planes(cells[a].faces[i], others, kCellEpsilon).area();
                    if (area > 0.01f)
                        out[{int32_t(a), int32_t(b)}] += area;
                }
            }
        }
    }
    return out;
}

class PortalizeQuake : public ::testing::TestWithParam<std::string> {};

bool is_sky(const Zone& zone, int32_t region) { return (zone.regions[size_t(region)].flags & kRegionSky) != 0; }

// The region on each side of a portal: its centroid probed `nudge` units along the normal.
bool separates(const BspTree& tree, const Portal& p, const glm::vec3& centroid, const glm::vec3& normal, float nudge)
{
    return locate_point(tree, centroid + nudge * normal).region == p.regions[0] &&
           locate_point(tree, centroid - nudge * normal).region == p.regions[1];
}

TEST_P(PortalizeQuake, PortalsAreSharedFacesBetweenOpenLeaves)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone* zone = test::shared_zone(GetParam());
    ASSERT_NE(zone, nullptr);
    const BspTree& tree = zone->tree;
    const Aabb world = zone_portal_world(*zone);

    PortalStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    const PortalSet set = build_portals(tree, zone->regions, world, {}, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(stats.origins.size(), set.portals.size());
    EXPECT_FALSE(stats.leaks()) << "a shipped Quake map is sealed";
    EXPECT_EQ(stats.pieces_tiny, 0u);
    EXPECT_EQ(stats.pieces_same_region, 0u);

    size_t thin = 0, sky_sky = 0, sky_sky_in_pvs = 0;
    uint32_t min_points = ~0u, max_points = 0;
    std::set<std::pair<int32_t, int32_t>> pairs;
    for (size_t i = 0; i < set.portals.size(); ++i) {
        const Portal& p = set.portals[i];
        const PortalOrigin& o = stats.origins[i];
        ASSERT_GE(p.regions[0], 0);
        ASSERT_GE(p.regions[1], 0);
        ASSERT_LT(size_t(p.regions[0]), zone->region_count());
        ASSERT_LT(size_t(p.regions[1]), zone->region_count());
        // Never at a solid or outside leaf: both origin leaves are the regions' leaves.
        ASSERT_EQ(tree.leaf_region[size_t(o.leaves[0])], p.regions[0]);
        ASSERT_EQ(tree.leaf_region[size_t(o.leaves[1])], p.regions[1]);
        pairs.insert(std::minmax(p.regions[0], p.regions[1]));

        // On its node's plane, portal_plane's normal into regions[0] (the front child's side).
        const BspNode& node = tree.nodes[size_t(o.node)];
        const Plane node_plane{node.normal, node.dist};
        const Winding w = portal_winding(set, p);
        for (const glm::vec3& v : w.points)
            ASSERT_LE(std::abs(node_plane.distance(v)), 0.02f) << "portal " << i;
        ASSERT_GT(glm::dot(quake::portal_plane(set, p).normal, node.normal), 0.999f) << "portal " << i;
        ASSERT_LE(p.point_count, quake::kPrtMaxPoints);
        min_points = std::min(min_points, p.point_count);
        max_points = std::max(max_points, p.point_count);

        // It separates the two regions: its centroid nudged 0.1 along the normal is in
        // regions[0], against it in regions[1]. A portal on the thin edge of a wedge-shaped cell
        // (e2m1 has one 0.33 units wide, on a plane at an acute angle to the next face of its
        // front cell) is probed at 0.01.
        const glm::vec3 c = w.centroid();
        if (!separates(tree, p, c, node.normal, 0.1f)) {
            ++thin;
            EXPECT_TRUE(separates(tree, p, c, node.normal, 0.01f))
                << "portal " << i << " " << p.regions[0] << "|" << p.regions[1] << " area " << w.area();
        }

        // No portal between sky and anything else (§2.6).
        ASSERT_EQ(is_sky(*zone, p.regions[0]), is_sky(*zone, p.regions[1])) << "portal " << i;

        // A vis PVS includes the neighbours, both ways. Except that the shipped maps' vis made no
        // portal at a sky leaf at all (every sky leaf sees only itself): sky <-> sky neighbours,
        // which ericw's rule keeps, are counted, and checked with SkyPortals::None below.
        ASSERT_TRUE(zone->baked_pvs.has_value());
        const bool both_ways = zone->baked_pvs->visible(uint32_t(p.regions[0]), uint32_t(p.regions[1])) &&
                               zone->baked_pvs->visible(uint32_t(p.regions[1]), uint32_t(p.regions[0]));
        if (is_sky(*zone, p.regions[0])) {
            ++sky_sky;
            sky_sky_in_pvs += both_ways;
        } else {
            EXPECT_TRUE(both_ways) << "portal " << i << " " << p.regions[0] << "|" << p.regions[1];
        }
    }
    EXPECT_LE(thin, 2u);
    EXPECT_EQ(pairs.size(), set.portals.size()) << "two convex cells share at most one face";

    // Sky opaque to vis: the sky <-> sky portals go, and then every portal is in the baked PVS.
    PortalOptions no_sky;
    no_sky.sky = SkyPortals::None;
    PortalStats no_sky_stats;
    const PortalSet opaque_sky = build_portals(tree, zone->regions, world, no_sky, &no_sky_stats);
    EXPECT_EQ(opaque_sky.portals.size(), set.portals.size() - sky_sky);
    for (const Portal& p : opaque_sky.portals) {
        EXPECT_FALSE(is_sky(*zone, p.regions[0]) || is_sky(*zone, p.regions[1]));
        EXPECT_TRUE(zone->baked_pvs->visible(uint32_t(p.regions[0]), uint32_t(p.regions[1])));
        EXPECT_TRUE(zone->baked_pvs->visible(uint32_t(p.regions[1]), uint32_t(p.regions[0])));
    }
    for (size_t r = 0; r < zone->region_count(); ++r) {
        if (!is_sky(*zone, int32_t(r)))
            continue;
        for (size_t t = 0; t < zone->region_count(); ++t) {
            ASSERT_EQ(zone->baked_pvs->visible(uint32_t(r), uint32_t(t)), r == t)
                << "sky region " << r << ": the baked PVS is not the one SkyPortals::None describes";
        }
    }

    // The independent count: faces shared by two open leaf cells, with §2.6 applied; the same
    // pairs and areas.
    const PairSet shared = shared_faces(tree, world);
    size_t expected = 0, sky_other = 0;
    std::map<std::pair<int32_t, int32_t>, double> ours_area;
    for (const Portal& p : set.portals)
        ours_area[std::minmax(p.regions[0], p.regions[1])] = portal_area(set, p);
    double area_error = 0.0;
    for (const auto& [leaves, area] : shared) {
        const int32_t r0 = tree.leaf_region[size_t(leaves.first)], r1 = tree.leaf_region[size_t(leaves.second)];
        if (is_sky(*zone, r0) != is_sky(*zone, r1)) {
            ++sky_other;
            continue;
        }
        ++expected;
        const auto it = ours_area.find(std::minmax(r0, r1));
        if (it == ours_area.end()) {
            ADD_FAILURE() << "the cells of regions " << r0 << " and " << r1 << " share " << area << " but no portal";
            continue;
        }
        area_error = std::max(area_error, std::abs(it->second - area) / std::max(area, 1.0));
    }
    EXPECT_EQ(expected, set.portals.size());
    EXPECT_EQ(sky_other, stats.pieces_sky);
    EXPECT_LT(area_error, 1e-3);

    std::printf("[ portals  ] %s: %zu portals (%zu sky|sky, %zu of them in the baked PVS; %zu with SkyPortals::None) "
                "from %zu node polygons in %.3f s. Brute force: %zu shared faces between open cells, %zu of them "
                "sky|non-sky; max relative area difference %.2g. Pieces dropped at solid leaves: %zu. Probed at "
                "0.01: %zu. Points per portal: %u..%u\n",
                test::param_name(GetParam()).c_str(), set.portals.size(), sky_sky, sky_sky_in_pvs,
                opaque_sky.portals.size(), stats.node_polygons, seconds, shared.size(), sky_other, area_error,
                stats.pieces_solid, thin, min_points, max_points);
}

INSTANTIATE_TEST_SUITE_P(Maps, PortalizeQuake,
                         ::testing::Values(std::string("quake/e1m1.bsp"), std::string("quake/e2m1.bsp"),
                                           std::string("quake/end.bsp")),
                         [](const ::testing::TestParamInfo<std::string>& param) { return test::param_name(param.param); });

} // namespace
} // namespace pvs
