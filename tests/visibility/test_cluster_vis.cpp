// Clustered portal vis (visibility/portal/cluster_vis.h): known answers from hand-built geometry
// (a bent corridor no line passes through, but whose two ends see each other once the bend is
// one cluster), the identity grouping against bake_portal_vis, and on real portal files (the
// visdemo example.prt, Quake end.bsp's portals) for arbitrary groupings: clustered rows hold the
// leaf-level rows (conservative), rows are constant within a cluster, and the rows equal an
// independent expansion (the test maps the portals to clusters itself, bakes them with
// bake_portal_vis and expands bit by bit). Bad cluster maps throw std::invalid_argument. What
// "holds the leaf-level row" can mean exactly is written at check_portal_set.
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/portal/cluster_vis.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portalize.h"
#include "wld/quake/prt_file.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace pvs {
namespace {

using Method = VisParams::Method;

VisParams params_for(Method method)
{
    VisParams params;
    params.method = method;
    params.threads = 1; // ctest runs tests in parallel already
    return params;
}

// Adds a quad portal, ordered so that its PRT1 plane normal points into `front` (regions[0]),
// whose centre is `front_centre`.
void add_portal(PortalSet& set, int32_t front, int32_t back, const glm::vec3& front_centre,
                std::vector<glm::vec3> quad)
{
    const glm::vec3 n = glm::cross(quad[0] - quad[1], quad[2] - quad[1]);
    if (glm::dot(n, front_centre - quad[0]) < 0.0f)
        std::reverse(quad.begin(), quad.end());
    Portal portal;
    portal.regions[0] = front;
    portal.regions[1] = back;
    portal.first_point = uint32_t(set.points.size());
    portal.point_count = 4;
    set.points.insert(set.points.end(), quad.begin(), quad.end());
    set.portals.push_back(portal);
}

// A bent corridor, 1 unit high (z in [0, 1]), seen from above:
//   A = [0,1]x[0,1], B = [1,3]x[0,1], C = [2,3]x[1,3], D = [2,3]x[3,4]
//   portal AB at x = 1 (y 0..1), BC at y = 1 (x 2..3), CD at y = 3 (x 2..3).
// A line from portal AB into C must cross y = 1 at x = 1 + (x1 - 1)(1 - y0)/(y1 - y0) for its
// points (1, y0) on AB and (x1, y1) beyond; reaching CD (y1 = 3, x1 <= 3) it crosses y = 1 at
// x <= 1 + 2 (1 - y0)/(3 - y0) < 2, left of the BC opening: A cannot see D. Without the wall
// between B and C (the bend one cluster), the line from (1, 0.5) to (2.5, 3) joins AB and CD.
PortalSet bent_corridor()
{
    PortalSet set;
    const glm::vec3 a(0.5f, 0.5f, 0.5f), b(2.0f, 0.5f, 0.5f), c(2.5f, 2.0f, 0.5f), d(2.5f, 3.5f, 0.5f);
    add_portal(set, 0, 1, a, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}});
    add_portal(set, 1, 2, b, {{2, 1, 0}, {3, 1, 0}, {3, 1, 1}, {2, 1, 1}});
    add_portal(set, 2, 3, c, {{2, 3, 0}, {3, 3, 0}, {3, 3, 1}, {2, 3, 1}});
    (void)d;
    return set;
}

TEST(ClusterVis, BentCorridorEndsSeeEachOtherOnlyWhenTheBendIsOneCluster)
{
    const PortalSet corridor = bent_corridor();
    const Pvs leaves = bake_portal_vis(corridor, 4, params_for(Method::Full));
    EXPECT_FALSE(leaves.visible(0, 3));
    EXPECT_FALSE(leaves.visible(3, 0));
    EXPECT_TRUE(leaves.visible(0, 2));

    const std::vector<uint32_t> bend_merged{0, 1, 1, 2}; // A | B+C | D
    ClusterReport cluster_report;
    VisReport report;
    const Pvs clustered =
        bake_clustered_portal_vis(corridor, bend_merged, 3, params_for(Method::Full), &report, &cluster_report);
    ASSERT_EQ(clustered.region_count(), 4u);
    for (uint32_t from = 0; from < 4; ++from)
        for (uint32_t to = 0; to < 4; ++to)
            EXPECT_TRUE(clustered.visible(from, to)) << from << " -> " << to;
    EXPECT_EQ(cluster_report.regions, 4u);
    EXPECT_EQ(cluster_report.clusters, 3u);
    EXPECT_EQ(cluster_report.region_portals, 3u);
    EXPECT_EQ(cluster_report.cluster_portals, 2u);
    EXPECT_EQ(cluster_report.portals_inside_clusters, 1u);
    EXPECT_DOUBLE_EQ(report.mean_visible, 4.0);
    EXPECT_DOUBLE_EQ(cluster_report.cluster_mean_visible, 3.0);
}

TEST(ClusterVis, OneClusterSeesEverythingAndLeavesNoPortal)
{
    const std::vector<uint32_t> all_one(4, 0);
    ClusterReport cluster_report;
    const Pvs pvs = bake_clustered_portal_vis(bent_corridor(), all_one, 1, params_for(Method::Full), nullptr,
                                              &cluster_report);
    EXPECT_EQ(cluster_report.cluster_portals, 0u);
    for (uint32_t from = 0; from < 4; ++from)
        for (uint32_t to = 0; to < 4; ++to)
            EXPECT_TRUE(pvs.visible(from, to));
}

TEST(ClusterVis, RegionsWithoutPortalsSeeTheirClusterOnly)
{
    const PortalSet none;
    const std::vector<uint32_t> map{1, 0, 1, 2};
    const Pvs pvs = bake_clustered_portal_vis(none, map, 3, params_for(Method::Fast));
    EXPECT_TRUE(pvs.visible(0, 2));
    EXPECT_TRUE(pvs.visible(2, 0));
    EXPECT_FALSE(pvs.visible(0, 1));
    EXPECT_FALSE(pvs.visible(3, 0));
    EXPECT_TRUE(pvs.visible(3, 3));
}

TEST(ClusterVis, BadClusterMapsGiveClearErrors)
{
    const PortalSet corridor = bent_corridor();
    const auto message = [&](std::vector<uint32_t> map, uint32_t clusters) -> std::string {
        try {
            bake_clustered_portal_vis(corridor, map, clusters, params_for(Method::Fast));
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_NE(message({0, 1, 5, 2}, 3).find("region 2 has cluster 5, out of range [0, 3)"), std::string::npos);
    EXPECT_NE(message({0, 0, 0, 0}, 0).find("cluster_count is 0"), std::string::npos);
    // The corridor's portals name region 3: a map of three regions is too short.
    EXPECT_NE(message({0, 1, 2}, 3).find("portal 2 names region 3"), std::string::npos);
    // No region and no portal: nothing to check, nothing to bake.
    const Pvs empty = bake_clustered_portal_vis(PortalSet{}, {}, 0, params_for(Method::Fast));
    EXPECT_EQ(empty.region_count(), 0u);
}

// The rows a clustering must give, computed independently: the test maps the portals itself,
// bakes the clusters with bake_portal_vis and expands bit by bit.
Pvs expected_clustered(const PortalSet& portals, const std::vector<uint32_t>& map, uint32_t clusters,
                       const VisParams& params)
{
    PortalSet mapped;
    mapped.points = portals.points;
    for (Portal portal : portals.portals) {
        for (int32_t& region : portal.regions)
            region = region < 0 ? -1 : int32_t(map[size_t(region)]);
        if (portal.regions[0] != portal.regions[1])
            mapped.portals.push_back(portal);
    }
    const Pvs cluster_pvs = bake_portal_vis(mapped, clusters, params);
    const uint32_t regions = uint32_t(map.size());
    return Pvs::build(regions, [&](uint32_t from, std::span<uint64_t> row) {
        for (uint32_t to = 0; to < regions; ++to)
            if (cluster_pvs.visible(map[from], map[to]))
                bits::set(row, to);
        return true;
    });
}

// Bits set in `leaves` and not in `clustered`, over all rows.
size_t bits_missing(const Pvs& clustered, const Pvs& leaves)
{
    std::vector<uint64_t> row(clustered.words_per_row()), leaf_row(leaves.words_per_row());
    size_t missing = 0;
    for (uint32_t r = 0; r < clustered.region_count(); ++r) {
        clustered.decode_row(r, row);
        leaves.decode_row(r, leaf_row);
        for (size_t w = 0; w < row.size(); ++w)
            missing += size_t(std::popcount(leaf_row[w] & ~row[w]));
    }
    return missing;
}

size_t bits_set(const Pvs& pvs)
{
    std::vector<uint64_t> row(pvs.words_per_row());
    size_t total = 0;
    for (uint32_t r = 0; r < pvs.region_count(); ++r) {
        pvs.decode_row(r, row);
        total += bits::count(row);
    }
    return total;
}

// Rows of one cluster are equal.
void expect_constant_within_clusters(const Pvs& clustered, const std::vector<uint32_t>& map, const std::string& what)
{
    std::vector<uint64_t> row(clustered.words_per_row());
    std::vector<std::vector<uint64_t>> cluster_row(map.empty() ? 0 : *std::max_element(map.begin(), map.end()) + 1);
    size_t differing = 0;
    for (uint32_t r = 0; r < clustered.region_count(); ++r) {
        clustered.decode_row(r, row);
        auto& first = cluster_row[map[r]];
        if (first.empty())
            first = row;
        else
            differing += first != row;
    }
    EXPECT_EQ(differing, 0u) << what << ": rows that differ from their cluster's first row";
}

void expect_same_rows(const Pvs& a, const Pvs& b, const std::string& what)
{
    ASSERT_EQ(a.region_count(), b.region_count());
    std::vector<uint64_t> row_a(a.words_per_row()), row_b(b.words_per_row());
    size_t differing = 0;
    for (uint32_t r = 0; r < a.region_count(); ++r) {
        a.decode_row(r, row_a);
        b.decode_row(r, row_b);
        differing += row_a != row_b;
    }
    EXPECT_EQ(differing, 0u) << what;
}

// Groupings to try: consecutive pairs, and random groups of 1 to 6 regions (not convex, not
// even connected: the result must still be conservative).
std::vector<uint32_t> pairs_map(uint32_t regions, uint32_t& clusters)
{
    std::vector<uint32_t> map(regions);
    for (uint32_t r = 0; r < regions; ++r)
        map[r] = r / 2;
    clusters = (regions + 1) / 2;
    return map;
}

std::vector<uint32_t> random_map(uint32_t regions, uint64_t seed, uint32_t& clusters)
{
    std::mt19937_64 random(seed);
    clusters = std::max(1u, regions / 3);
    std::vector<uint32_t> map(regions);
    for (uint32_t& c : map)
        c = uint32_t(random() % clusters);
    return map;
}

// What "conservative" can be checked against. Real sight lines are what the clustered bake keeps
// (cluster_vis.h); the leaf-level rows hold a little more than real lines, and not the same
// little more:
//  - leaf-level portal-fast tests each portal against the source portal only, so a region's
//    mightsee can hold regions no line reaches; the clustered bake, whose sources are the
//    cluster's outgoing portals, drops some of them. So clustered portal-fast is compared with
//    leaf-level portal-full (which holds every pair a line joins): it must hold all of it.
//  - portal-full prunes with other portals' finished visbits, which depends on the portals'
//    ranking (portal_vis.h, Determinism): the flow's approximations then keep slightly
//    different extras (the leaf-level bake of e1m1 with its portal list reversed differs from the
//    original in a few bits). A different portal graph ranks differently, so clustered
//    portal-full must hold the leaf-level rows but for such a handful: at most 0.1 % of their
//    bits. The image-space test (tests/ui/test_accuracy_walk_clustered.cpp) checks real lines.
void check_portal_set(const PortalSet& portals, uint32_t regions, const std::string& name)
{
    const VisParams fast = params_for(Method::Fast), full = params_for(Method::Full);
    const Pvs leaves_fast = bake_portal_vis(portals, regions, fast);
    const Pvs leaves_full = bake_portal_vis(portals, regions, full);

    std::vector<uint32_t> identity(regions);
    std::iota(identity.begin(), identity.end(), 0u);
    expect_same_rows(bake_clustered_portal_vis(portals, identity, regions, fast), leaves_fast, name + " fast identity");
    expect_same_rows(bake_clustered_portal_vis(portals, identity, regions, full), leaves_full, name + " full identity");

    uint32_t clusters = 0;
    for (int grouping = 0; grouping < 2; ++grouping) {
        const std::vector<uint32_t> map =
            grouping == 0 ? pairs_map(regions, clusters) : random_map(regions, 2026, clusters);
        const std::string what = name + (grouping == 0 ? " pairs" : " random");
        const Pvs clustered_fast = bake_clustered_portal_vis(portals, map, clusters, fast);
        const Pvs clustered_full = bake_clustered_portal_vis(portals, map, clusters, full);
        expect_constant_within_clusters(clustered_fast, map, what + " fast");
        expect_constant_within_clusters(clustered_full, map, what + " full");
        expect_same_rows(clustered_fast, expected_clustered(portals, map, clusters, fast), what + " fast expansion");
        expect_same_rows(clustered_full, expected_clustered(portals, map, clusters, full), what + " full expansion");

        EXPECT_EQ(bits_missing(clustered_fast, leaves_full), 0u) << what << ": clustered fast lacks leaf-level full bits";
        EXPECT_EQ(bits_missing(clustered_fast, clustered_full), 0u) << what << ": the flow left mightsee";
        const size_t missing = bits_missing(clustered_full, leaves_full);
        EXPECT_LE(missing, bits_set(leaves_full) / 1000) << what << ": clustered full lacks leaf-level full bits";
        EXPECT_GT(bits_set(clustered_full), bits_set(leaves_full)) << what << ": grouping costs accuracy";
    }
}

TEST(ClusterVis, VisdemoExamplePrtAnyGroupingIsConservative)
{
    SHARED_DATA_OR_SKIP(path, "visdemo/example.prt");
    const quake::PrtFile prt = quake::load_prt(path);
    ASSERT_GT(prt.portals.portals.size(), 0u);
    check_portal_set(prt.portals, prt.leaf_count, "example.prt");
}

TEST(ClusterVis, QuakeEndAnyGroupingIsConservative)
{
    // end.bsp: the smallest of the maps (337 regions), so that the dozen bakes stay quick.
    SHARED_DATA_OR_SKIP(path, "quake/end.bsp");
    const Zone& zone = *test::shared_zone("quake/end.bsp");
    check_portal_set(build_zone_portals(zone), uint32_t(zone.region_count()), "end");
}

} // namespace
} // namespace pvs
