// Degenerate zones through the whole bake (tree -> build_zone_portals -> bake_portal_vis, both
// methods), as `pvscope bake` runs it. tests/wld/test_portal_vis.cpp covers hand-made portal
// sets (no portals, unusable portals, tiny and near-coplanar portals) and test_portalize.cpp the
// portalization of degenerate trees; here the same situations start from a zone's tree:
//  - a single-leaf zone: no portal, a leak reported, the one region sees itself;
//  - two rooms walled off from each other: no portal, each room sees only itself;
//  - a leaking corridor (its open leaves reach the world box): the portals between the open
//    leaves only, the leak reported, a straight corridor sees all of itself;
//  - an opening far below min_area: no portal, the rooms stay apart; a 0.5-unit opening: a
//    portal, and the rooms see each other through it;
//  - near-coplanar split planes around a slab thinner than the epsilons: defined rows (each
//    holds its region), Full within Fast, the same for 1 and 2 threads, no hang.
// The zones are corridors of cells along x, built here as BSP trees.
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"

#include "visibility/bit_row.h"

#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <glm/geometric.hpp>

namespace pvs {
namespace {

using Method = VisParams::Method;
using Rows = std::vector<std::vector<uint64_t>>;

struct Cell {
    int32_t content;          // region id, or kLeafSolid
    float half_width = 32.0f; // y in [-half_width, half_width]
};

struct Boundary {
    glm::vec3 normal{1, 0, 0}; // front = the next cell
    float dist;
};

// A corridor: cell k lies between boundary k-1 and boundary k (boundaries.size() = cells - 1),
// z in [-32, 32]. Sealed: each open cell is closed in y and z by solid leaves (Quake's walls),
// and the two end cells in x at x_min / x_max; unsealed: open cells reach the world box.
struct Corridor {
    std::vector<Cell> cells;
    std::vector<Boundary> boundaries;
    bool sealed = true;
    float x_min = 0.0f, x_max = 0.0f;

    BspTree tree;

    int32_t leaf(int32_t content)
    {
        tree.leaf_region.push_back(content);
        return ~int32_t(tree.leaf_region.size() - 1);
    }
    int32_t node(glm::vec3 normal, float dist, int32_t front, int32_t back)
    {
        BspNode n;
        n.normal = normal;
        n.dist = dist;
        n.children[0] = front;
        n.children[1] = back;
        tree.nodes.push_back(n);
        return int32_t(tree.nodes.size() - 1);
    }
    // Wraps `inside` in a solid leaf beyond the plane (normal, dist).
    int32_t wall(glm::vec3 normal, float dist, int32_t inside) { return node(normal, dist, leaf(kLeafSolid), inside); }
    int32_t cell_subtree(size_t c)
    {
        const Cell& cell = cells[c];
        if (cell.content == kLeafSolid)
            return leaf(kLeafSolid);
        int32_t t = leaf(cell.content);
        if (!sealed)
            return t;
        t = wall({0, 1, 0}, cell.half_width, t);
        t = wall({0, -1, 0}, cell.half_width, t);
        t = wall({0, 0, 1}, 32.0f, t);
        t = wall({0, 0, -1}, 32.0f, t);
        if (c == 0)
            t = wall({-1, 0, 0}, -x_min, t);
        if (c + 1 == cells.size())
            t = wall({1, 0, 0}, x_max, t);
        return t;
    }
    int32_t subtree(size_t c)
    {
        if (c + 1 == cells.size())
            return cell_subtree(c);
        const int32_t back = cell_subtree(c);
        const int32_t front = subtree(c + 1);
        return node(boundaries[c].normal, boundaries[c].dist, front, back);
    }

    Zone zone(uint32_t region_count)
    {
        tree = {};
        tree.root = subtree(0);
        Zone z;
        z.tree = tree;
        z.regions.resize(region_count);
        // Region bounds: the corridor's box, so the world box (bounds + margin) encloses it.
        for (Region& r : z.regions)
            r.bounds = {{x_min, -32, -32}, {x_max, 32, 32}};
        return z;
    }
};

Corridor straight_corridor(const std::vector<int32_t>& contents, bool sealed)
{
    Corridor c;
    c.sealed = sealed;
    c.x_min = 0.0f;
    c.x_max = 64.0f * float(contents.size());
    for (size_t k = 0; k < contents.size(); ++k) {
        c.cells.push_back({contents[k]});
        if (k + 1 < contents.size())
            c.boundaries.push_back({{1, 0, 0}, 64.0f * float(k + 1)});
    }
    return c;
}

Rows rows_of(const Pvs& pvs)
{
    Rows rows(pvs.region_count(), std::vector<uint64_t>(pvs.words_per_row()));
    for (uint32_t r = 0; r < pvs.region_count(); ++r)
        pvs.decode_row(r, rows[r]);
    return rows;
}

Rows bake_rows(const PortalSet& set, uint32_t regions, Method method, unsigned threads = 2, VisReport* report = nullptr)
{
    VisParams params;
    params.method = method;
    params.threads = threads;
    return rows_of(bake_portal_vis(set, regions, params, report));
}

std::vector<uint32_t> members(const std::vector<uint64_t>& row)
{
    std::vector<uint32_t> out;
    bits::for_each_set(row, [&](size_t i) { out.push_back(uint32_t(i)); });
    return out;
}

void expect_only_self(const Rows& rows)
{
    for (uint32_t r = 0; r < rows.size(); ++r)
        EXPECT_EQ(members(rows[r]), std::vector<uint32_t>{r}) << "region " << r;
}

TEST(PortalVisDegenerate, ASingleLeafZoneSeesItselfAndIsReportedAsLeaking)
{
    Zone zone;
    zone.regions.resize(1);
    zone.regions[0].bounds = {{0, 0, 0}, {64, 64, 64}};
    zone.tree.leaf_region = {0};
    zone.tree.root = ~0;
    PortalStats stats;
    const PortalSet set = build_zone_portals(zone, {}, &stats);
    EXPECT_TRUE(set.portals.empty());
    EXPECT_EQ(stats.leaves_touching_world, std::vector<int32_t>{0});
    for (Method m : {Method::Fast, Method::Full}) {
        VisReport report;
        const Rows rows = bake_rows(set, 1, m, 2, &report);
        expect_only_self(rows);
        EXPECT_EQ(report.portals, 0u);
        EXPECT_DOUBLE_EQ(report.mean_visible, 1.0);
        EXPECT_FALSE(report.cancelled);
    }
}

TEST(PortalVisDegenerate, RoomsWalledOffFromEachOtherHaveNoPortals)
{
    Corridor c = straight_corridor({0, kLeafSolid, 1}, true);
    const Zone zone = c.zone(2);
    PortalStats stats;
    const PortalSet set = build_zone_portals(zone, {}, &stats);
    EXPECT_TRUE(set.portals.empty());
    EXPECT_FALSE(stats.leaks());
    for (Method m : {Method::Fast, Method::Full})
        expect_only_self(bake_rows(set, 2, m));
}

TEST(PortalVisDegenerate, ALeakingCorridorIsReportedAndStillBaked)
{
    Corridor c = straight_corridor({0, 1, 2}, false);
    const Zone zone = c.zone(3);
    PortalStats stats;
    const PortalSet set = build_zone_portals(zone, {}, &stats);
    EXPECT_TRUE(stats.leaks());
    EXPECT_EQ(stats.leaves_touching_world.size(), 3u); // every open leaf reaches the world box
    ASSERT_EQ(set.portals.size(), 2u);                  // 0|1 and 1|2, nothing to the outside
    for (Method m : {Method::Fast, Method::Full}) {
        const Rows rows = bake_rows(set, 3, m);
        for (uint32_t r = 0; r < 3; ++r) // a straight corridor: everything sees everything
            EXPECT_EQ(members(rows[r]), (std::vector<uint32_t>{0, 1, 2})) << r;
    }

    // The sealed corridor gives the same portals and rows, with no leak.
    Corridor sealed = straight_corridor({0, 1, 2}, true);
    const PortalSet sealed_set = build_zone_portals(sealed.zone(3), {}, &stats);
    EXPECT_FALSE(stats.leaks());
    EXPECT_EQ(sealed_set.portals.size(), 2u);
    EXPECT_EQ(bake_rows(sealed_set, 3, Method::Full), bake_rows(set, 3, Method::Full));
}

// Room 0 | hole 1 | room 2, the hole `width` wide in y and 64 high.
PortalSet rooms_through_a_hole(float width, PortalStats& stats)
{
    Corridor c = straight_corridor({0, 1, 2}, true);
    c.cells[1].half_width = width * 0.5f;
    return build_zone_portals(c.zone(3), {}, &stats);
}

TEST(PortalVisDegenerate, AnOpeningBelowMinAreaIsNoPortalAndAHalfUnitOneIs)
{
    PortalStats stats;
    const PortalSet none = rooms_through_a_hole(0.0001f, stats); // 0.0064 square units < min_area 0.01
    EXPECT_TRUE(none.portals.empty());
    for (Method m : {Method::Fast, Method::Full})
        expect_only_self(bake_rows(none, 3, m));

    const PortalSet half = rooms_through_a_hole(0.5f, stats);
    ASSERT_EQ(half.portals.size(), 2u);
    for (Method m : {Method::Fast, Method::Full}) {
        const Rows rows = bake_rows(half, 3, m);
        EXPECT_EQ(members(rows[0]), (std::vector<uint32_t>{0, 1, 2})); // straight through the slot
        EXPECT_EQ(members(rows[2]), (std::vector<uint32_t>{0, 1, 2}));
    }
}

size_t bits_not_in(const Rows& a, const Rows& b)
{
    size_t n = 0;
    for (size_t r = 0; r < a.size(); ++r)
        for (size_t w = 0; w < a[r].size(); ++w)
            n += size_t(std::popcount(a[r][w] & ~b[r][w]));
    return n;
}

TEST(PortalVisDegenerate, NearCoplanarSplitsAroundAThinSlabGiveDefinedRows)
{
    // Cells 0 | 1 | 2 | 3 where cell 1 is a slab 0.001 thick (far below the split epsilon)
    // between x = 64 and a plane tilted by 1e-4 rad, and cell 2 an ordinary room.
    for (float thickness : {0.001f, 0.02f, 0.2f}) {
        Corridor c = straight_corridor({0, 1, 2, 3}, true);
        c.boundaries[1].normal = glm::normalize(glm::vec3(1.0f, 1e-4f, 0.0f));
        c.boundaries[1].dist = 64.0f + thickness;
        const Zone zone = c.zone(4);
        const auto start = std::chrono::steady_clock::now();
        PortalStats stats;
        const PortalSet set = build_zone_portals(zone, {}, &stats);
        const Rows fast = bake_rows(set, 4, Method::Fast);
        const Rows full1 = bake_rows(set, 4, Method::Full, 1);
        const Rows full2 = bake_rows(set, 4, Method::Full, 2);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
        EXPECT_EQ(full1, full2) << "thickness " << thickness;
        EXPECT_EQ(bits_not_in(full1, fast), 0u) << "thickness " << thickness;
        for (uint32_t r = 0; r < 4; ++r)
            EXPECT_TRUE(bits::test(full1[r], r)) << "thickness " << thickness << ", region " << r;
        // Every portal made joins regions that then see each other.
        for (const Portal& p : set.portals) {
            const auto a = uint32_t(p.regions[0]), b = uint32_t(p.regions[1]);
            EXPECT_TRUE(bits::test(full1[a], b) && bits::test(full1[b], a)) << a << " | " << b;
        }
        // Rooms 0 and 3 are ordinary rooms on one straight line: if a portal chain joins them
        // (the slab kept as a region with portals), they see each other; if the slab's faces
        // were dropped as slivers, they are apart. Either way the rows say it consistently.
        EXPECT_EQ(bits::test(full1[0], 3), bits::test(full1[3], 0)) << "thickness " << thickness;
    }
}

} // namespace
} // namespace pvs
